// The kernel's step and the addition of its forces, shared by the two engines
// of this plugin (PolyhedraKernelEngine.cpp, PolyhedraContactEngine.cpp).
//
// Each engine reads the poses into the arrays it was bound to, then calls
// stepAndAdd: the kernel's pc_engine_step (shapes/polycontact.c) once, and,
// after a good step, each body's force and torque added to Scene::forces
// (those of a body whose force and torque are not all zero: the bodies the
// PyRunner path of the project's scene touches) and each wall's force.
#pragma once

#include <core/Scene.hpp>

#include <chrono>
#include <vector>

namespace yade {
namespace pke {

	typedef int (*StepFn)(void*, const double*, const double*, const double*, double*, double*, double*, double*);
	typedef std::chrono::steady_clock Clock;

	struct StepResult {
		int               err; // the kernel's code: 0 a good step (forces added), else nothing added
		Clock::time_point called, stepped, added; // before the kernel's call, after it, after the additions
	};

	// pos (N, 3), quat (N, 4), wallPos (nw): the step's input; force, torque
	// (N, 3), wallForce (nw, 3), stat: the kernel's output arrays; ids (N) and
	// walls (nw): the bodies of the kernel's rows and walls. allWallForces:
	// add a wall's force even when it is zero (the project's scene, as its
	// PyRunner path does), else only a non-zero one.
	inline StepResult stepAndAdd(StepFn stepFn, void* kernel, const double* pos, const double* quat, const double* wallPos, double* force,
	                             double* torque, double* wallForce, double* stat, const std::vector<int>& ids,
	                             const std::vector<int>& walls, bool allWallForces, Scene* scene)
	{
		StepResult r;
		r.called  = Clock::now();
		r.err     = stepFn(kernel, pos, quat, wallPos, force, torque, wallForce, stat);
		r.stepped = Clock::now();
		if (r.err) return r;
		ForceContainer& F = scene->forces;
		for (size_t k = 0; k < ids.size(); k++) {
			const double* f = force + 3 * k;
			const double* t = torque + 3 * k;
			if (f[0] != 0 || f[1] != 0 || f[2] != 0 || t[0] != 0 || t[1] != 0 || t[2] != 0) {
				F.addForce(ids[k], Vector3r(f[0], f[1], f[2]));
				F.addTorque(ids[k], Vector3r(t[0], t[1], t[2]));
			}
		}
		for (size_t k = 0; k < walls.size(); k++) {
			const double* f = wallForce + 3 * k;
			if (allWallForces || f[0] != 0 || f[1] != 0 || f[2] != 0) F.addForce(walls[k], Vector3r(f[0], f[1], f[2]));
		}
		r.added = Clock::now();
		return r;
	}

	inline double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

} // namespace pke
} // namespace yade
