"""The cost of a Contact Dynamics step in LMGC90 against the number of grains.

    python benchmarks/bench_cd.py [--grains 64 200 1000] [--steps 40] [--tol 1.666e-4]
                                  [--check-every 10] [--max-checks 500] [--folder runs/bench-cd]

For each N, one run in its own subprocess (LMGC90 keeps its state in the
process): N random convex polyhedra (``pre.rigidPolyhedron``, 12 vertices,
radius 5 mm +- 10 %, random orientations) on a cubic lattice of spacing
2.02 r_max in a box of six PLANx walls, zero gravity, mu = 0.5 between grains
and 0 at the walls, alert distance 0.1 r_min, CpCundall detection, dt = 1e-4 s.
The six walls first close in at 0.2 m/s (NLGS capped at 20 checks) until the
packing holds 7 interactions a grain (about the 500 of a 64-grain packing
after an isotropic compression); then the measured steps, the walls
moving inwards at 1 cm/s (the paper's shear speed). NLGS (``Stored_Delassus_Loops``,
QM/16, relaxation 1) is driven check by check (``nlgs_3D_ExIter`` of
``--check-every`` iterations, then ``nlgs_3D_AfterIterCheck``) to count the
iterations each step needs, up to ``--max-checks`` checks.

Printed per N: the median over the second half of the steps (the packing
loaded) of the seconds a step (wall clock, the whole step: detection, NLGS,
update), of the NLGS iterations and of the interactions, the share of those
steps whose NLGS converged, and the median detection time. To be run by hand;
dated numbers go in docs/measurements.md.
"""
import argparse
import json
import os
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
R, DT, SPEED = 0.005, 1e-4, 0.01       # m grain radius, s time step, m/s wall speed
COMPACTION = 0.2                        # m/s, the walls' speed while the lattice is compacted


def one_run(n, steps, tol, check_every, max_checks):
    """Build the scene in the current folder, run it, return the per-step
    records (seconds, iterations, interactions, converged, detection s)."""
    import numpy as np

    sys.path.insert(0, ROOT)
    from lmgc90.build import import_pylmgc90

    chipy, pre = import_pylmgc90()
    os.makedirs("DATBOX", exist_ok=True)
    bodies, mats, mods = pre.avatars(), pre.materials(), pre.models()
    svs, tacts = pre.see_tables(), pre.tact_behavs()
    grain = pre.material(name="PLEXx", materialType="RIGID", density=2600.0)
    wallm = pre.material(name="TDURx", materialType="RIGID", density=2600.0)
    mats.addMaterial(grain)
    mats.addMaterial(wallm)
    mod = pre.model(name="rigid", physics="MECAx", element="Rxx3D", dimension=3)
    mods.addModel(mod)
    rng = np.random.default_rng(n)
    np.random.seed(n)                     # pre's random polyhedra draw from numpy's global generator
    side = int(np.ceil(n ** (1 / 3) - 1e-9))
    rmax, rmin = 1.1 * R, 0.9 * R
    s = 2.02 * rmax
    L = side * s
    sites = [(i, j, k) for i in range(side) for j in range(side) for k in range(side)][:n]
    for i, j, k in sites:
        c = [(i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s]
        b = pre.rigidPolyhedron(radius=float(rng.uniform(rmin, rmax)), center=c, generation_type="random",
                                nb_vertices=12, model=mod, material=grain, color="BLUEx")
        b.rotate(description="axis", alpha=float(rng.uniform(0, np.pi)), axis=list(rng.normal(size=3)), center=c)
        bodies += b
    t, h = 0.1 * L, L / 2
    walls = []                            # (RBDY3 number, driven dof, inward sign)
    for centre, rot, comp, v in (([h, h, -t], None, 3, SPEED), ([h, h, L + t], (np.pi, [1.0, 0, 0]), 3, -SPEED),
                                 ([-t, h, h], (0.5 * np.pi, [0, 1.0, 0]), 1, SPEED),
                                 ([L + t, h, h], (-0.5 * np.pi, [0, 1.0, 0]), 1, -SPEED),
                                 ([h, -t, h], (-0.5 * np.pi, [1.0, 0, 0]), 2, SPEED),
                                 ([h, L + t, h], (0.5 * np.pi, [1.0, 0, 0]), 2, -SPEED)):
        w = pre.rigidPlan(axe1=L, axe2=L, axe3=t, center=centre, model=mod, material=wallm, color="WALLx")
        if rot is not None:
            w.rotate(description="axis", alpha=rot[0], axis=rot[1], center=w.nodes[1].coor)
        w.imposeDrivenDof(component=[1, 2, 3, 4, 5, 6], dofty="vlocy")
        bodies.addAvatar(w)
        walls.append((len(bodies), comp, np.sign(v)))
    lpp = pre.tact_behav(name="iqsc0", law="IQS_CLB", fric=0.5)
    lpw = pre.tact_behav(name="iqsc1", law="IQS_CLB", fric=0.0)
    tacts += lpp
    tacts += lpw
    for an, col, law in (("POLYR", "BLUEx", lpp), ("PLANx", "WALLx", lpw)):
        svs += pre.see_table(CorpsCandidat="RBDY3", candidat="POLYR", colorCandidat="BLUEx",
                             CorpsAntagoniste="RBDY3", antagoniste=an, colorAntagoniste=col, behav=law,
                             alert=0.1 * rmin)
    pre.writeDatbox(3, mats, mods, bodies, tacts, svs, gravy=np.zeros(3))
    c = chipy
    c.checkDirectories()
    c.utilities_DisableLogMes()
    c.SetDimension(3)
    c.nlgs_3D_DiagonalResolution()
    c.PRPRx_UseCpCundallDetection(50)
    c.TimeEvolution_SetTimeStep(DT)
    c.Integrator_InitTheta(0.5)
    c.ReadDatbox(deformable=False)
    c.ComputeMass()
    def step(speed, checks):
        t0 = time.perf_counter()
        c.IncrementStep()
        for body, dof, sign in walls:
            c.RBDY3_SetVlocyDrivenDof(body, dof, float(sign * speed))
        c.ComputeFext()
        c.ComputeBulk()
        c.ComputeFreeVelocity()
        t1 = time.perf_counter()
        c.SelectProxTactors()
        t2 = time.perf_counter()
        c.RecupRloc()
        c.nlgs_3D_SetCheckType("QM/16", float(tol), 1.0)
        c.nlgs_3D_ExPrep("Stored_Delassus_Loops")
        it, conv = 0, 1
        for _ in range(checks):
            c.nlgs_3D_ExIter(check_every)
            it += check_every
            conv = c.nlgs_3D_AfterIterCheck()
            if conv in (0, -1):
                break
        c.nlgs_3D_ExPost()
        c.StockRloc()
        c.ComputeDof()
        c.UpdateStep()
        t3 = time.perf_counter()
        return {"seconds": t3 - t0, "detection": t2 - t1, "iterations": it, "converged": conv == 0,
                "interactions": int(c.inter_handler_3D_tgetNb(c.PRPRx_ID) + c.inter_handler_3D_tgetNb(c.PRPLx_ID))}

    # compaction: the walls at COMPACTION m/s, NLGS capped at 20 checks, until
    # the packing holds 7 interactions a grain (at most 3000 steps)
    k = 0
    while k < 3000 and step(COMPACTION, 20)["interactions"] < 7 * n:
        k += 1
    out = [{"compaction_steps": k}]
    for _ in range(steps):
        out.append(step(SPEED, max_checks))
    c.Finalize()
    return out


def summary(n, records):
    import numpy as np

    head, records = records[0], records[1:]
    half = records[len(records) // 2:]
    med = {k: float(np.median([r[k] for r in half])) for k in ("seconds", "iterations", "interactions", "detection")}
    conv = float(np.mean([r["converged"] for r in half]))
    return (f"{n:5d} grains: {med['seconds']:.3f} s a step, {med['iterations']:.0f} NLGS iterations, "
            f"{med['interactions']:.0f} interactions, detection {med['detection']:.4f} s "
            f"(medians over steps {len(records) - len(half) + 1}-{len(records)}; NLGS converged on "
            f"{100 * conv:.0f} % of them; after {head['compaction_steps']} compaction steps)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--grains", type=int, nargs="+", default=[64, 200, 1000])
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--tol", type=float, default=1.666e-4)
    ap.add_argument("--check-every", type=int, default=10)
    ap.add_argument("--max-checks", type=int, default=500)
    ap.add_argument("--folder", default=os.path.join(ROOT, "runs", "bench-cd"))
    ap.add_argument("--one", type=int, help=argparse.SUPPRESS)      # the child: one N in the current folder
    args = ap.parse_args(argv)
    if args.one:
        rec = one_run(args.one, args.steps, args.tol, args.check_every, args.max_checks)
        with open("records.json", "w") as fh:
            json.dump(rec, fh)
        return 0
    for n in args.grains:
        folder = os.path.join(os.path.abspath(args.folder), f"n{n}")
        os.makedirs(folder, exist_ok=True)
        t0 = time.perf_counter()
        subprocess.run([sys.executable, os.path.abspath(__file__), "--one", str(n), "--steps", str(args.steps),
                        "--tol", str(args.tol), "--check-every", str(args.check_every),
                        "--max-checks", str(args.max_checks)], cwd=folder, check=True,
                       stdout=subprocess.DEVNULL)
        with open(os.path.join(folder, "records.json")) as fh:
            rec = json.load(fh)
        print(summary(n, rec) + f"; the run {time.perf_counter() - t0:.0f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
