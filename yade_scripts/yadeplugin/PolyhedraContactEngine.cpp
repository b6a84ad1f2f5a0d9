// Exact polyhedra contacts for a YADE user's own scene.
//
// PolyhedraContactEngine is a GlobalEngine placed between ForceResetter and
// NewtonIntegrator. It steps the compiled kernel (shapes/polycontact.c) on the
// bodies of the scene: Polyhedra grains, Facets (each a thin prism behind its
// face) and axis-aligned Walls. What the bodies are, their shapes and their
// materials is read by Python (yade_scripts/yadeplugin/contacts.py), which
// builds the kernel's engine and binds it here; this file does the per-step
// work without leaving C++:
//
//   1. checks that the bodies are still those it was bound to (a body added
//      or erased, an id given to another body, a body clumped or released
//      from its clump: its clumpId changed): if not, it calls the Python
//      scan again (under the GIL), which rebuilds the kernel's engine with the
//      pairs' histories carried over and binds it again;
//   2. reads the pose (State::pos, State::ori) of every kernel body and the
//      position of every wall along its axis;
//   3. steps the kernel and adds the forces and torques to Scene::forces;
//   4. every fillEvery steps (0: never), writes the touching contacts to
//      O.interactions as YADE's own PolyhedraGeom / PolyhedraPhys (normal,
//      contact point, overlap volume; normal and shear force, kn, ks,
//      tan(friction angle)), adds the new ones and erases those that stopped
//      touching. The fields are written at byte offsets that Python measured
//      on objects of the installed YADE (fieldOffsets) and checks after the
//      first fill against what YADE's Python reads.
//
// O.save / O.load: the class is registered with Boost.Serialization. While
// O.save runs (preSave) the engine asks Python for the state it holds beyond
// its attributes (contacts.SceneContacts.saved: the kernel's state with the
// shear histories, the shapes, the scan's choices) and keeps it in
// savedState; an engine read by O.load has no scan, and its first step calls
// contacts.adopt(), which gives it one with that state, and takes back the
// interactions of its kind in O.interactions as its own.
//
// Built with PolyhedraKernelEngine.cpp into one library by
// yade_scripts/yadeplugin (python -m yade_scripts.yadeplugin build), against
// the YADE headers vendored in include/ (GPL-2.0-or-later, include/ORIGIN.md).
//
// Error codes (attribute `error`): the kernel's (-2 positions not finite, -4
// workspace overflow, -5 a bad orientation quaternion, other negative: out of
// memory), -10 not bound, -13 the scan or, after O.load, the adoption raised
// (its message is thrown), -14 a wall position not finite, -15 O.interactions
// refused an interaction.

#include <core/Body.hpp>
#include <core/GlobalEngine.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>
#include <core/Interaction.hpp>
#include <core/InteractionContainer.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <lib/factory/ClassFactory.hpp>

#include "kernel_step.hpp"

#include <Python.h>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <dlfcn.h>
#include <stdexcept>
#include <unordered_map>

#ifndef PKE_SOURCE_HASH
#define PKE_SOURCE_HASH "unknown"
#endif

namespace yade {

#if !defined(PKE_SIZEOF_Interaction) || !defined(PKE_SIZEOF_InteractionContainer)
#error "build with python -m yade_scripts.yadeplugin build: it passes the installed YADE's class sizes"
#endif
static_assert(sizeof(Interaction) == PKE_SIZEOF_Interaction, "sizeof(Interaction) differs from the installed YADE's");
static_assert(sizeof(InteractionContainer) == PKE_SIZEOF_InteractionContainer, "sizeof(InteractionContainer) differs from the installed YADE's");

typedef int (*pce_count_fn)(const void*);

class PolyhedraContactEngine;
// O.save / O.load of a scene holding the engine (found by ADL from the serialize() of
// YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY): the kernel's state is put into savedState first
void preSave(PolyhedraContactEngine&);
typedef int (*pce_contacts_fn)(void*, int, int*, int*, double*, double*, double*, double*, double*);

class PolyhedraContactEngine : public GlobalEngine {
	pke::StepFn     stepFn { nullptr };
	pce_count_fn    countFn { nullptr };
	pce_contacts_fn contactsFn { nullptr };
	void*           kernel { nullptr };
	double *        posBuf { nullptr }, *quatBuf { nullptr }, *wallPosBuf { nullptr }, *forceBuf { nullptr }, *torqueBuf { nullptr },
	       *wallForceBuf { nullptr }, *statBuf { nullptr };
	std::vector<const Body*> rowBody, wallBody; // the bodies bound, to notice a change
	std::vector<int>         rowClump;          // their clumpId when bound (a body clumped or released: scan again)
	size_t                   nBodiesBound { 0 };
	boost::python::object    scanFn;            // Python: rescans the scene and binds again
	boost::python::object    saveFn;            // Python: the state for O.save, as a string
	bool                     scanning { false };
	bool                     idle { false };     // bound to no kernel: no polyhedra in the scene
	// O.interactions: the ones this engine made, by (id1, id2)
	struct Mine {
		shared_ptr<Interaction> I;
		char*                   g;
		char*                   p;
		long                    seen;
	};
	std::unordered_map<uint64_t, Mine> mine;
	std::vector<int>                   ci1, ci2;
	std::vector<double>                cpt, cn, cfn, cft, cvol;
	static uint64_t                    key(int a, int b) { return (uint64_t(uint32_t(a)) << 32) | uint32_t(b); }
	static double*                     ptr(uintptr_t p) { return reinterpret_cast<double*>(p); }
	static void put3(char* base, int off, const double* v)
	{
		if (off >= 0) std::memcpy(base + off, v, 3 * sizeof(double));
	}
	static void put1(char* base, int off, double v)
	{
		if (off >= 0) std::memcpy(base + off, &v, sizeof(double));
	}

	bool bodiesChanged() const
	{
		const BodyContainer& B = *scene->bodies;
		if (B.size() != nBodiesBound) return true;
		const long n = (long)B.size();
		for (size_t k = 0; k < ids.size(); k++) {
			const int id = ids[k];
			if (id < 0 || id >= n || B[id].get() != rowBody[k] || B[id]->clumpId != rowClump[k]) return true;
		}
		for (size_t k = 0; k < walls.size(); k++) {
			const int id = walls[k];
			if (id < 0 || id >= n || B[id].get() != wallBody[k]) return true;
		}
		// a body not bound that is now a polyhedron, a facet or a wall is caught by the size (bodies are appended)
		return false;
	}

	// the message of the Python exception being handled (cleared), or `fallback`
	static std::string pythonError(const std::string& fallback)
	{
		PyObject *t, *v, *tb;
		PyErr_Fetch(&t, &v, &tb);
		PyErr_NormalizeException(&t, &v, &tb);
		std::string why = fallback;
		if (v) {
			PyObject* s = PyObject_Str(v);
			if (s) {
				const char* c = PyUnicode_AsUTF8(s);
				if (c && *c) why = c;
				Py_DECREF(s);
			}
		}
		Py_XDECREF(t);
		Py_XDECREF(v);
		Py_XDECREF(tb);
		PyErr_Clear();
		return why;
	}

	// an engine read by O.load has no scan yet: Python's contacts.adopt() gives it one
	// (and the state O.save put into savedState)
	void adopt()
	{
		adoptPending         = true;
		PyGILState_STATE gil = PyGILState_Ensure();
		std::string      why;
		try {
			boost::python::import("yade_scripts.yadeplugin.contacts").attr("adopt")();
		} catch (boost::python::error_already_set&) {
			why = pythonError("the adoption failed");
		}
		PyGILState_Release(gil);
		if (!why.empty()) {
			error = -13;
			if (why.find("No module named") != std::string::npos) why += " (the project's clone must be on PYTHONPATH)";
			throw std::runtime_error("PolyhedraContactEngine (read by O.load): " + why);
		}
		if (scanFn.is_none()) {
			error = -13;
			throw std::runtime_error("PolyhedraContactEngine: no scan function (make it with yade_scripts.yadeplugin.contacts.PolyhedraContactEngine)");
		}
	}

	void scan()
	{
		if (scanFn.is_none()) adopt();
		scanning             = true;
		PyGILState_STATE gil = PyGILState_Ensure();
		std::string      why;
		try {
			scanFn();
		} catch (boost::python::error_already_set&) {
			why = pythonError("PolyhedraContactEngine: the scan failed");
		}
		PyGILState_Release(gil);
		scanning = false;
		if (!why.empty()) {
			error = -13;
			throw std::runtime_error(why);
		}
		if (adoptPending) adoptInteractions();
	}

	// after O.load: the saved scene's interactions of this engine's kind become this
	// engine's again (updated by the next fill, erased once they stop touching)
	bool adoptPending { false };
	void adoptInteractions()
	{
		adoptPending = false;
		if (!mine.empty()) return;
		for (const shared_ptr<Interaction>& I : *scene->interactions) {
			if (!I || !I->geom || !I->phys || I->geom->getClassName() != geomClass || I->phys->getClassName() != physClass) continue;
			Mine rec { I, static_cast<char*>(dynamic_cast<void*>(I->geom.get())), static_cast<char*>(dynamic_cast<void*>(I->phys.get())), -1 };
			mine.emplace(key(I->getId1(), I->getId2()), rec);
		}
	}

	void fill()
	{
		using clock       = std::chrono::steady_clock;
		const auto     t0 = clock::now();
		const int      n  = countFn(kernel);
		if ((int)ci1.size() < n) {
			const size_t c = size_t(n) + n / 2 + 16;
			ci1.resize(c);
			ci2.resize(c);
			cpt.resize(3 * c);
			cn.resize(3 * c);
			cfn.resize(3 * c);
			cft.resize(3 * c);
			cvol.resize(c);
		}
		const int m    = contactsFn(kernel, n, ci1.data(), ci2.data(), cpt.data(), cn.data(), cfn.data(), cft.data(), cvol.data());
		const long it  = scene->iter;
		InteractionContainer& IC = *scene->interactions;
		for (int k = 0; k < m; k++) {
			if (ci1[k] >= nGrains) continue; // facet-facet: not a contact of the user's scene
			const int id1 = ci1[k] >= 0 ? ids[ci1[k]] : walls[-1 - ci1[k]];
			const int id2 = ids[ci2[k]];
			const int kind = ci1[k] >= 0 ? 0 : 1; // 0 pair, 1 wall
			auto       f   = mine.find(key(id1, id2));
			if (f != mine.end()) { // still in O.interactions? (O.interactions.clear() or an erase in Python drop it)
				const shared_ptr<Interaction>& I  = f->second.I;
				const int                      ix = I->linIx;
				if (ix < 0 || ix >= (int)IC.size() || IC[ix].get() != I.get()) {
					mine.erase(f);
					f = mine.end();
				}
			}
			if (f == mine.end()) {
				shared_ptr<Interaction> I = IC.find(id1, id2);
				if (!I) {
					I = shared_ptr<Interaction>(new Interaction(id1, id2));
					if (!IC.insert(I)) {
						error = -15;
						return;
					}
				}
				shared_ptr<IGeom> g = boost::dynamic_pointer_cast<IGeom>(ClassFactory::instance().createShared(geomClass));
				shared_ptr<IPhys> p = boost::dynamic_pointer_cast<IPhys>(ClassFactory::instance().createShared(physClass));
				if (!g || !p) throw std::runtime_error("PolyhedraContactEngine: cannot create " + geomClass + " / " + physClass);
				I->geom         = g;
				I->phys         = p;
				I->iterMadeReal = it;
				Mine rec { I, static_cast<char*>(dynamic_cast<void*>(g.get())), static_cast<char*>(dynamic_cast<void*>(p.get())), it };
				f = mine.emplace(key(id1, id2), rec).first;
			}
			Mine& r = f->second;
			r.seen  = it;
			r.I->iterLastSeen = it;
			put3(r.g, geomOffsets[0], &cn[3 * k]);
			put3(r.g, geomOffsets[1], &cpt[3 * k]);
			put1(r.g, geomOffsets[2], cvol[k]);
			put3(r.p, physOffsets[0], &cfn[3 * k]);
			put3(r.p, physOffsets[1], &cft[3 * k]);
			put1(r.p, physOffsets[2], law[0]);
			put1(r.p, physOffsets[3], law[1]);
			put1(r.p, physOffsets[4], kind ? law[3] : law[2]);
		}
		for (auto f = mine.begin(); f != mine.end();) {
			if (f->second.seen != it) {
				eraseMine(f->second.I);
				f = mine.erase(f);
			} else
				++f;
		}
		nFilled = (int)mine.size();
		counters[3] += std::chrono::duration<double>(clock::now() - t0).count();
		counters[5] += 1;
	}

	// erase one of ours from O.interactions if it is still there (an erased
	// body took its interactions with it: nothing to do then)
	void eraseMine(const shared_ptr<Interaction>& I)
	{
		const BodyContainer&  B  = *scene->bodies;
		const long            n  = (long)B.size();
		const int             a  = I->getId1(), b = I->getId2();
		if (a < 0 || b < 0 || a >= n || b >= n || !B[a] || !B[b]) return;
		InteractionContainer& IC = *scene->interactions;
		if (IC.find(a, b).get() == I.get()) IC.erase(a, b, I->linIx); // YADE asserts the linear index
	}

	void forgetInteractions()
	{
		if (!scene) return;
		for (auto& f : mine)
			eraseMine(f.second.I);
		mine.clear();
	}

public:
	void bind(const std::string& lib, uintptr_t engine, uintptr_t pos, uintptr_t quat, uintptr_t wallPos, uintptr_t force, uintptr_t torque,
	          uintptr_t wallForce, uintptr_t stat)
	{
		scene = Omega::instance().getScene().get();
		if (!engine || !pos || !quat || !wallPos || !force || !torque || !wallForce || !stat)
			throw std::invalid_argument("PolyhedraContactEngine.bind: a null pointer");
		if (wallAxis.size() != walls.size()) throw std::invalid_argument("PolyhedraContactEngine.bind: one wallAxis per wall");
		const BodyContainer& B = *scene->bodies;
		const long           n = (long)B.size();
		rowBody.assign(ids.size(), nullptr);
		rowClump.assign(ids.size(), Body::ID_NONE);
		wallBody.assign(walls.size(), nullptr);
		for (size_t k = 0; k < ids.size(); k++) {
			if (ids[k] < 0 || ids[k] >= n || !B[ids[k]]) throw std::invalid_argument("PolyhedraContactEngine.bind: body id " + std::to_string(ids[k]) + " is not a body of the scene");
			rowBody[k]  = B[ids[k]].get();
			rowClump[k] = B[ids[k]]->clumpId;
		}
		for (size_t k = 0; k < walls.size(); k++) {
			if (walls[k] < 0 || walls[k] >= n || !B[walls[k]]) throw std::invalid_argument("PolyhedraContactEngine.bind: wall id " + std::to_string(walls[k]) + " is not a body of the scene");
			if (wallAxis[k] < 0 || wallAxis[k] > 2) throw std::invalid_argument("PolyhedraContactEngine.bind: wallAxis must be 0, 1 or 2");
			wallBody[k] = B[walls[k]].get();
		}
		void* h = dlopen(lib.c_str(), RTLD_NOW | RTLD_NOLOAD);
		if (!h) throw std::invalid_argument("PolyhedraContactEngine.bind: the kernel library " + lib + " is not loaded in this process");
		void* s = dlsym(h, "pc_engine_step");
		void* c = dlsym(h, "pc_engine_count");
		void* k = dlsym(h, "pc_engine_contacts_noshadow");
		dlclose(h);
		if (!s || !c || !k) throw std::invalid_argument("PolyhedraContactEngine.bind: " + lib + " lacks pc_engine_step, pc_engine_count or pc_engine_contacts_noshadow");
		stepFn       = reinterpret_cast<pke::StepFn>(s);
		countFn      = reinterpret_cast<pce_count_fn>(c);
		contactsFn   = reinterpret_cast<pce_contacts_fn>(k);
		kernel       = reinterpret_cast<void*>(engine);
		posBuf       = ptr(pos);
		quatBuf      = ptr(quat);
		wallPosBuf   = ptr(wallPos);
		forceBuf     = ptr(force);
		torqueBuf    = ptr(torque);
		wallForceBuf = ptr(wallForce);
		statBuf      = ptr(stat);
		nBodiesBound = B.size();
		idle         = false;
		library      = lib;
		error        = 0;
	}

	// no polyhedra yet: nothing to step until the bodies change
	void bindIdle()
	{
		scene = Omega::instance().getScene().get();
		unbind();
		ids.clear();
		walls.clear();
		wallAxis.clear();
		rowBody.clear();
		rowClump.clear();
		wallBody.clear();
		nBodiesBound = scene->bodies->size();
		idle         = true;
		error        = 0;
	}

	void unbind()
	{
		idle    = false;
		stepFn  = nullptr;
		kernel  = nullptr;
		library = "";
	}

	void setScan(boost::python::object f) { scanFn = f; }
	void setSave(boost::python::object f) { saveFn = f; }
	bool hasScan() const { return !scanFn.is_none(); }
	// whether this engine is one of the current scene's (or of those it takes from the next step on)
	bool inCurrentScene() const
	{
		const Scene* sc = Omega::instance().getScene().get();
		if (!sc) return false;
		for (const auto* list : { &sc->engines, &sc->_nextEngines })
			for (const shared_ptr<Engine>& e : *list)
				if (e.get() == this) return true;
		return false;
	}
	// called by O.save (preSave): the state Python gives (the kernel's, the scan's choices)
	void saveState()
	{
		if (saveFn.is_none()) return; // read by O.load and not stepped yet: savedState is as loaded
		PyGILState_STATE gil = PyGILState_Ensure();
		std::string      why;
		try {
			savedState = boost::python::extract<std::string>(saveFn())();
		} catch (boost::python::error_already_set&) {
			why = pythonError("the state could not be taken");
		}
		PyGILState_Release(gil);
		if (!why.empty()) throw std::runtime_error("PolyhedraContactEngine: O.save: " + why);
	}
	bool bound() const { return kernel != nullptr; }
	void clearInteractions() { forgetInteractions(); }
	// the byte offsets of the fields that fill() writes must be measured on this YADE: see contacts.py
	static boost::python::list fieldOffsets(shared_ptr<Serializable> obj, int size, double value)
	{
		boost::python::list out;
		const char*         base = static_cast<const char*>(dynamic_cast<const void*>(obj.get()));
		for (int off = 0; off + (int)sizeof(double) <= size; off += (int)sizeof(double)) {
			double v;
			std::memcpy(&v, base + off, sizeof(double));
			if (v == value) out.append(off);
		}
		return out;
	}

	void action() override
	{
		if (scanning) return;
		if (idle && !bodiesChanged()) return;
		if (!kernel || bodiesChanged()) {
			scan(); // binds, or throws with the scan's one-line reason
			if (idle) return;
			if (!kernel) {
				error = -10;
				throw std::runtime_error("PolyhedraContactEngine: the scan did not bind a kernel");
			}
		}
		error              = 0;
		const auto     t0  = pke::Clock::now();
		BodyContainer& B   = *scene->bodies;
		const size_t   n   = ids.size();
		for (size_t k = 0; k < n; k++) {
			const State&       st = *B[ids[k]]->state;
			const Vector3r&    x  = st.pos;
			const Quaternionr& q  = st.ori;
			posBuf[3 * k]         = x[0];
			posBuf[3 * k + 1]     = x[1];
			posBuf[3 * k + 2]     = x[2];
			quatBuf[4 * k]        = q.w();
			quatBuf[4 * k + 1]    = q.x();
			quatBuf[4 * k + 2]    = q.y();
			quatBuf[4 * k + 3]    = q.z();
		}
		for (size_t k = 0; k < walls.size(); k++) {
			wallPosBuf[k] = B[walls[k]]->state->pos[wallAxis[k]];
			if (!std::isfinite(wallPosBuf[k])) {
				error = -14;
				return;
			}
		}
		// a wall's force added only when it is not zero
		const pke::StepResult r = pke::stepAndAdd(stepFn, kernel, posBuf, quatBuf, wallPosBuf, forceBuf, torqueBuf, wallForceBuf, statBuf, ids,
		                                          walls, false, scene);
		if (r.err) {
			error = r.err;
			return;
		}
		counters[0] += pke::seconds(t0, r.called);
		counters[1] += pke::seconds(r.called, r.stepped);
		counters[2] += pke::seconds(r.stepped, r.added);
		counters[4] += 1;
		if (fillEvery > 0 && scene->iter % fillEvery == 0 && geomOffsets.size() == 3 && physOffsets.size() == 5) fill();
	}

	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(PolyhedraContactEngine, GlobalEngine,
		"Exact polyhedra contacts (the compiled kernel of this project) for any scene of Polyhedra, Facets and axis-aligned Walls, in place of a collider and an InteractionLoop; make it with yade_scripts.yadeplugin.contacts.PolyhedraContactEngine(...) and put it between ForceResetter and NewtonIntegrator. Every fillEvery steps the touching contacts are written to O.interactions (PolyhedraGeom, PolyhedraPhys).",
		((vector<int>, ids, , Attr::noSave, "Body ids of the kernel's bodies (polyhedra, then facets), in its row order (set by the scan)."))
		((vector<int>, walls, , Attr::noSave, "Body ids of the walls (set by the scan)."))
		((vector<int>, wallAxis, , Attr::noSave, "Axis of each wall (set by the scan)."))
		((int, nGrains, 0, Attr::noSave, "The first nGrains of ids are polyhedra, the others facets (set by the scan)."))
		((int, fillEvery, 1, , "Write the contacts to O.interactions every this many steps (0: never; the interactions then stay as last written)."))
		((int, nFilled, 0, (Attr::readonly | Attr::noSave), "Contacts written at the last fill."))
		((vector<int>, geomOffsets, , Attr::noSave, "Byte offsets of normal, contactPoint, penetrationVolume in the geometry class (measured by the scan)."))
		((vector<int>, physOffsets, , Attr::noSave, "Byte offsets of normalForce, shearForce, kn, ks, tangensOfFrictionAngle in the physics class (measured by the scan)."))
		((string, geomClass, "PolyhedraGeom", Attr::noSave, "YADE class of the interactions' geometry."))
		((string, physClass, "PolyhedraPhys", Attr::noSave, "YADE class of the interactions' physics."))
		((vector<Real>, law, vector<Real>(4, 0.), Attr::noSave, "kn (N/m^3), ks (N/m), tan(friction angle) of pairs, of wall contacts (set by the scan; written to each interaction's phys)."))
		((vector<Real>, counters, vector<Real>(6, 0.), Attr::noSave, "Seconds reading poses, in the kernel, adding forces, filling O.interactions; steps; fills."))
		((int, error, 0, (Attr::readonly | Attr::noSave), "0 after a good step; else why the last step stopped: the kernel's code (-2 positions not finite, -4 workspace overflow, -5 a bad orientation), -10 not bound, -13 the scan failed, -14 a wall position not finite, -15 O.interactions refused an interaction."))
		((string, library, "", (Attr::readonly | Attr::noSave), "The kernel library bound to (empty: not bound)."))
		((string, sourceHash, PKE_SOURCE_HASH, (Attr::readonly | Attr::noSave), "Hash of the sources this plugin was built from (yade_scripts/yadeplugin)."))
		((string, savedState, "", Attr::readonly, "What O.save keeps of the engine beyond its attributes (base64 of an npz: the kernel's state with the shear histories, the bodies' shapes, the scan's choices and options; written by O.save, read at the first step after O.load by yade_scripts.yadeplugin.contacts.adopt).")),
		/* ctor */,
		/* py */
		.def("bind", &PolyhedraContactEngine::bind, "bind(library, engine, pos, quat, wallPos, force, torque, wallForce, stat): the kernel library's path, the address of its engine and of the float64 arrays (C order).")
		.def("bindIdle", &PolyhedraContactEngine::bindIdle, "Bind to no kernel (no polyhedra yet): the engine does nothing until the bodies change.")
		.def("unbind", &PolyhedraContactEngine::unbind, "Forget the kernel (the next step scans the scene again).")
		.def("setScan", &PolyhedraContactEngine::setScan, "setScan(callable): what the engine calls (no arguments) when it is not bound or the bodies changed.")
		.def("setSave", &PolyhedraContactEngine::setSave, "setSave(callable): what O.save calls (no arguments) for the string it keeps in savedState.")
		.add_property("inCurrentScene", &PolyhedraContactEngine::inCurrentScene, "Whether this engine is in the current scene's O.engines.")
		.add_property("hasScan", &PolyhedraContactEngine::hasScan, "Whether a scan is set (False for an engine read by O.load that has not stepped: its first step calls contacts.adopt).")
		.def("clearInteractions", &PolyhedraContactEngine::clearInteractions, "Erase from O.interactions the interactions this engine wrote.")
		.def("fieldOffsets", &PolyhedraContactEngine::fieldOffsets, "fieldOffsets(obj, size, value): byte offsets (8-aligned, below size) where the double value lies in obj.").staticmethod("fieldOffsets")
		.add_property("bound", &PolyhedraContactEngine::bound, "Whether a kernel is bound.")
	);
	// clang-format on
};
void preSave(PolyhedraContactEngine& e) { e.saveState(); }

// Registered with Boost.Serialization too (REGISTER_SERIALIZABLE and the
// export below), so that O.save / O.load of a user's scene holding the engine
// work; the serialization singletons of its base classes are YADE's own at run
// time (docs/kernel.md: measured, and the exit of such processes).
REGISTER_SERIALIZABLE(PolyhedraContactEngine);

} // namespace yade
BOOST_CLASS_EXPORT_IMPLEMENT(yade::PolyhedraContactEngine);
BOOST_SERIALIZATION_FACTORY_0(yade::PolyhedraContactEngine);

namespace {
__attribute__((constructor)) void registerThisPluginClasses_PolyhedraContactEngine(void)
{
	const char* info[] = { __FILE__, "PolyhedraContactEngine", NULL };
	::yade::ClassFactory::instance().registerPluginClasses(info);
}
} // namespace

// For a YADE started without YADE_PREFIX: Python loads this library itself
// (ctypes, RTLD_GLOBAL) and calls this to give yade.wrapper its classes.
extern "C" int pke_register_python(void)
{
	try {
		boost::python::object w = boost::python::import("yade.wrapper");
		boost::python::scope  s(w);
		::yade::shared_ptr<::yade::PolyhedraContactEngine>(new ::yade::PolyhedraContactEngine)->pyRegisterClass(w);
		::yade::shared_ptr<::yade::Serializable> k = boost::static_pointer_cast<::yade::Serializable>(
		        ::yade::ClassFactory::instance().createShared("PolyhedraKernelEngine"));
		k->pyRegisterClass(w);
	} catch (boost::python::error_already_set&) {
		return -1;
	}
	return 0;
}
