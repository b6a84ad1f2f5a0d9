// The compiled polyhedra contacts (shapes/polycontact.c) inside YADE's own step.
//
// PolyhedraKernelEngine is a GlobalEngine: once per step, between
// ForceResetter and NewtonIntegrator, it reads the pose of every polyhedron it
// is given (State::pos, State::ori) and the positions of the six box walls,
// calls the kernel's pc_engine_step once, and adds each body's contact force
// and torque to Scene::forces: the same reads, the same kernel call and the
// same additions as the PyRunner of yade_scripts/scene/kernel_contacts.py, without
// leaving C++.
//
// The kernel itself is not linked in: bind() takes the kernel library that
// YADE's Python loaded with ctypes (shapes/ckernel.py) and the engine that
// Python built in it (shapes/engine.py ContactEngine), so one engine state
// serves the step, the dumps (contacts), the friction switch and the
// checkpoints, on either path. The results land in that engine's own arrays
// (force, torque, wall force, step counters), which Python reads as before.
//
// Built and checked against the installed YADE by yade_scripts/yadeplugin
// (python -m yade_scripts.yadeplugin build), against the headers vendored in
// include/ (YADE's, GPL-2.0-or-later; see include/ORIGIN.md).
//
// Error codes (the attribute `error`, 0 after a good step): the kernel's own
// (-2 positions not finite, -4 a workspace overflow, -5 an orientation
// quaternion zero, not finite or out of range, other negative values: out of
// memory), and -10 not bound, -11 a body id that is not a body of the
// scene, -12 wall positions not finite or a low wall not below its high wall.

#include <core/Body.hpp>
#include <core/GlobalEngine.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>

#include "kernel_step.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <dlfcn.h>
#include <stdexcept>

#ifndef PKE_SOURCE_HASH
#define PKE_SOURCE_HASH "unknown"
#endif

namespace yade {

// The installed YADE's sizes of the classes read here (yade_scripts/yadeplugin
// reads them off libyade.so): a header that does not match the build fails here.
#if !defined(PKE_SIZEOF_Scene) || !defined(PKE_SIZEOF_Body) || !defined(PKE_SIZEOF_State) || !defined(PKE_SIZEOF_BodyContainer) \
        || !defined(PKE_SIZEOF_Engine) || !defined(PKE_SIZEOF_GlobalEngine)
#error "build with python -m yade_scripts.yadeplugin build: it passes the installed YADE's class sizes"
#endif
static_assert(sizeof(Scene) == PKE_SIZEOF_Scene, "sizeof(Scene) differs from the installed YADE's");
static_assert(sizeof(Body) == PKE_SIZEOF_Body, "sizeof(Body) differs from the installed YADE's");
static_assert(sizeof(State) == PKE_SIZEOF_State, "sizeof(State) differs from the installed YADE's");
static_assert(sizeof(BodyContainer) == PKE_SIZEOF_BodyContainer, "sizeof(BodyContainer) differs from the installed YADE's");
static_assert(sizeof(Engine) == PKE_SIZEOF_Engine, "sizeof(Engine) differs from the installed YADE's");
static_assert(sizeof(GlobalEngine) == PKE_SIZEOF_GlobalEngine, "sizeof(GlobalEngine) differs from the installed YADE's");

class PolyhedraKernelEngine : public GlobalEngine {
	pke::StepFn       stepFn { nullptr };
	void*             kernel { nullptr };
	double*           posBuf { nullptr };    // (N, 3) m
	double*           quatBuf { nullptr };   // (N, 4) w, x, y, z
	double*           massBuf { nullptr };   // (N,) kg, filled on a verifying step
	double*           wallPosBuf { nullptr }; // (6,) m
	double*           forceBuf { nullptr };  // (N, 3) N, written by the kernel
	double*           torqueBuf { nullptr }; // (N, 3) N m
	double*           wallForceBuf { nullptr }; // (6, 3) N
	double*           statBuf { nullptr };   // the kernel's step counters
	double*           counterBuf { nullptr }; // read s, kernel s, apply s, calls, touching contact-steps
	int               statA { 0 }, statB { 0 }; // counters summed into touching contact-steps

	static double* ptr(uintptr_t p) { return reinterpret_cast<double*>(p); }

public:
	// The kernel library (already loaded by Python: dlopen with RTLD_NOLOAD
	// finds it and does not load a second copy), its engine and the arrays.
	void bind(const std::string& lib, uintptr_t engine, uintptr_t pos, uintptr_t quat, uintptr_t mass, uintptr_t wallPos,
	          uintptr_t force, uintptr_t torque, uintptr_t wallForce, uintptr_t stat, uintptr_t counters, int touchA, int touchB)
	{
		unbind();
		scene = Omega::instance().getScene().get(); // the scene of this engine now (as YADE sets it before each step)
		if (!engine || !pos || !quat || !mass || !wallPos || !force || !torque || !wallForce || !stat || !counters)
			throw std::invalid_argument("PolyhedraKernelEngine.bind: a null pointer");
		if (!(walls.empty() || walls.size() == 6))
			throw std::invalid_argument("PolyhedraKernelEngine.bind: walls must hold six ids (x-, x+, y-, y+, z-, z+) or none");
		const long n = (long)scene->bodies->size();
		for (int id : ids)
			if (id < 0 || id >= n || !(*scene->bodies)[id])
				throw std::invalid_argument("PolyhedraKernelEngine.bind: body id " + std::to_string(id) + " is not a body of the scene");
		for (int id : walls)
			if (id < 0 || id >= n || !(*scene->bodies)[id])
				throw std::invalid_argument("PolyhedraKernelEngine.bind: wall id " + std::to_string(id) + " is not a body of the scene");
		void* h = dlopen(lib.c_str(), RTLD_NOW | RTLD_NOLOAD);
		if (!h) throw std::invalid_argument("PolyhedraKernelEngine.bind: the kernel library " + lib + " is not loaded in this process");
		void* f = dlsym(h, "pc_engine_step");
		dlclose(h); // drops only the reference taken here; Python's keeps it loaded
		if (!f) throw std::invalid_argument("PolyhedraKernelEngine.bind: " + lib + " has no pc_engine_step");
		stepFn       = reinterpret_cast<pke::StepFn>(f);
		kernel       = reinterpret_cast<void*>(engine);
		posBuf       = ptr(pos);
		quatBuf      = ptr(quat);
		massBuf      = ptr(mass);
		wallPosBuf   = ptr(wallPos);
		forceBuf     = ptr(force);
		torqueBuf    = ptr(torque);
		wallForceBuf = ptr(wallForce);
		statBuf      = ptr(stat);
		counterBuf   = ptr(counters);
		statA        = touchA;
		statB        = touchB;
		library      = lib;
		error        = 0;
	}

	void unbind()
	{
		stepFn  = nullptr;
		kernel  = nullptr;
		library = "";
	}

	bool bound() const { return kernel != nullptr; }

	void action() override
	{
		if (!kernel) {
			error = -10;
			return;
		}
		error                 = 0;
		const auto      t0    = pke::Clock::now();
		BodyContainer&  B     = *scene->bodies;
		const long      nBody = (long)B.size();
		const size_t    n     = ids.size();
		for (size_t k = 0; k < n; k++) {
			const int id = ids[k];
			if (id < 0 || id >= nBody || !B[id]) {
				error = -11;
				return;
			}
			const State&       s = *B[id]->state;
			const Vector3r&    x = s.pos;
			const Quaternionr& q = s.ori;
			posBuf[3 * k]        = x[0];
			posBuf[3 * k + 1]    = x[1];
			posBuf[3 * k + 2]    = x[2];
			quatBuf[4 * k]       = q.w();
			quatBuf[4 * k + 1]   = q.x();
			quatBuf[4 * k + 2]   = q.y();
			quatBuf[4 * k + 3]   = q.z();
			if (verifyNext) massBuf[k] = s.mass;
		}
		verifyNext = false; // what the start-up check compares is read
		for (size_t k = 0; k < walls.size(); k++) {
			const int id = walls[k];
			if (id < 0 || id >= nBody || !B[id]) {
				error = -11;
				return;
			}
			wallPosBuf[k] = B[id]->state->pos[k / 2];
		}
		for (size_t k = 0; k < walls.size(); k++)
			if (!std::isfinite(wallPosBuf[k]) || (k % 2 == 1 && !(wallPosBuf[k - 1] < wallPosBuf[k]))) {
				error = -12;
				return;
			}
		// every wall's force added, zero or not, as on the PyRunner path
		const pke::StepResult r = pke::stepAndAdd(stepFn, kernel, posBuf, quatBuf, wallPosBuf, forceBuf, torqueBuf, wallForceBuf, statBuf, ids,
		                                          walls, true, scene);
		if (r.err) {
			error = r.err;
			return;
		}
		counterBuf[0] += pke::seconds(t0, r.called);
		counterBuf[1] += pke::seconds(r.called, r.stepped);
		counterBuf[2] += pke::seconds(r.stepped, r.added);
		counterBuf[3] += 1;
		counterBuf[4] += statBuf[statA] + statBuf[statB];
	}

	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(PolyhedraKernelEngine, GlobalEngine,
		"Polyhedra contacts of the compiled kernel (shapes/polycontact.c) inside YADE's step: reads the poses of :yref:`ids` and the positions of :yref:`walls`, steps the kernel that :yref:`bind` names, adds the contact forces and torques. Place it between ForceResetter and NewtonIntegrator; yade_scripts.scene.kernel_contacts.KernelContacts builds and binds it. It is not saved with the scene (O.save raises unregistered class): checkpoints hold its PyRunner form.",
		((vector<int>, ids, , , "Body ids of the polyhedra, in the kernel's row order."))
		((vector<int>, walls, , , "Body ids of the six walls (x-, x+, y-, y+, z-, z+), or none."))
		((int, error, 0, (Attr::readonly | Attr::noSave), "0 after a good step; else why the last step stopped before adding forces: the kernel's code (-2 positions not finite, -4 workspace overflow, -5 an orientation quaternion zero, not finite or out of range, other: out of memory), -10 not bound, -11 a body id that is not a body of the scene, -12 bad wall positions."))
		((bool, verifyNext, false, Attr::noSave, "Also read every body's mass at the next step (into the bound mass array), for the start-up check; cleared after that step."))
		((string, library, "", (Attr::readonly | Attr::noSave), "The kernel library bound to (empty: not bound)."))
		((string, sourceHash, PKE_SOURCE_HASH, (Attr::readonly | Attr::noSave), "Hash of the sources this plugin was built from (yade_scripts/yadeplugin).")),
		/* ctor */,
		/* py */
		.def("bind", &PolyhedraKernelEngine::bind, "bind(library, engine, pos, quat, mass, wallPos, force, torque, wallForce, stat, counters, touchA, touchB): the kernel library's path, the address of its engine and of the float64 arrays (C order); touchA, touchB: the step counters summed into touching contact-steps.")
		.def("unbind", &PolyhedraKernelEngine::unbind, "Forget the kernel (the next step then only sets error = -10).")
		.add_property("bound", &PolyhedraKernelEngine::bound, "Whether a kernel is bound.")
	);
	// clang-format on
};
// Registered with YADE's class factory (so that YADE's Python knows the
// class), not with Boost.Serialization: the engine is never saved, a
// checkpoint swaps in its PyRunner form first (KernelContacts.portable,
// yade_scripts/scene/kernel_contacts.py), so that it loads in a YADE without
// the plugin; O.save of a scene that holds it raises "unregistered class".
// (In November, with this class registered, processes that had saved or
// loaded a scene aborted at exit, "double free or corruption"; not reproduced
// on 2026-12-02, this class and PolyhedraContactEngine registered: the
// serialization singletons of the base classes bind to libyade.so's, see
// docs/kernel.md. The scene still ends with yade_scripts/runs/attempt.py's
// leave, os._exit once all is written.)
REGISTER_FACTORABLE(PolyhedraKernelEngine);

} // namespace yade

namespace {
__attribute__((constructor)) void registerThisPluginClasses_PolyhedraKernelEngine(void)
{
	const char* info[] = { __FILE__, "PolyhedraKernelEngine", NULL };
	::yade::ClassFactory::instance().registerPluginClasses(info);
}
} // namespace
