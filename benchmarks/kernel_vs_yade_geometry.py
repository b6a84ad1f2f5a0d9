"""The same polyhedra pairs through YADE's stock Ig2 and through our kernel:
how far YADE's overlap volume, contact point and normal are from the exact
ones (on a contact's first step, when YADE searches a new inner point, and
after STEPS more steps), and the cost of both, in one run.

    yade -n -x benchmarks/kernel_vs_yade_geometry.py [N_PAIRS [STEPS [OUT.json]]]

(defaults 1000, 20, runs/kernel_vs_yade.json; run from the project root after
``make shapes``). N random touching pairs of library grains (d = 5 cm, random
orientations, overlaps from 1e-5 to 3e-2 of the smaller grain's volume, placed
by bisection on our volume) and N pairs whose bounding boxes overlap but
which do not touch, each pair far from the others. YADE builds every grain
(``polyhedra_utils.polyhedra``: it re-centres and re-orients the vertices);
our kernel is then given exactly YADE's local vertices, triangles and poses.
Reported, not asserted: per touching pair, YADE's relative volume
difference, the distance between the contact points (in units of d), the
angle between the normals (YADE's ``geom.normal`` against ours, both from id1
to id2); how many separated pairs each finds touching; the two unit cubes
face to face (overlap 0.01 of the side). Timing: YADE's InteractionLoop
(Ig2 + Ip2 + Law2) per pair-step over STEPS steps with bodies at rest, and our
``batch_overlap`` per pair (1 and 2 threads, median of STEPS calls less the
median of one-pair calls: the fixed set-up of the shape table), for the
touching and the separated pairs. ``batch_overlap`` has no cached separating
axis (the engine's first early-out), so a separated pair costs it the face
tests.
"""
import json
import math
import os
import sys
import time

import numpy as np
from yade import log, polyhedra_utils

ROOT = os.getcwd()
sys.path.insert(0, ROOT)
from shapes.library import ShapeLibrary  # noqa: E402
from shapes.overlap import ShapeTable, batch_overlap  # noqa: E402
from yade_scripts.scene.yadedump import outward_triangles  # noqa: E402

log.setLevel("Polyhedra_support.cpp", log.ERROR)
args = sys.argv[1:]
N = int(args[0]) if args else 1000
STEPS = int(args[1]) if len(args) > 1 else 20
OUT = args[2] if len(args) > 2 else os.path.join(ROOT, "runs", "kernel_vs_yade.json")
D = 0.05
rng = np.random.default_rng(2026)
lib = ShapeLibrary(os.path.join(ROOT, "runs", "shapes", "library.h5"))


def random_quats(n):
    q = rng.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1)[:, None]


def place(n, touching_only):
    """Shape indices, quaternions and B offsets for n pairs (A at the origin)."""
    table = ShapeTable([(lib[k][0] * D, lib[k][1]) for k in range(len(lib))])
    a, b = rng.integers(len(lib), size=n), rng.integers(len(lib), size=n)
    qa, qb = random_quats(n), random_quats(n)
    u = rng.normal(size=(n, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    vol = np.asarray(lib.volume) * D ** 3
    target = 0.0 if touching_only else 10 ** rng.uniform(-5, np.log10(3e-2), size=n) * np.minimum(vol[a], vol[b])
    lo, hi = np.zeros(n), np.full(n, 2 * D)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        over = batch_overlap(table, a, np.zeros((n, 3)), qa, b, mid[:, None] * u, qb)["volume"] > target
        lo, hi = np.where(over, mid, lo), np.where(over, hi, mid)
    return a, b, qa, qb, lo[:, None] * u


mat = PolyhedraMat(young=1e8, poisson=0.3, frictionAngle=0.5, density=2700)
O.materials.append(mat)


def build(a, b, qa, qb, xb, spacing=4 * D):
    """YADE bodies for the pairs, each pair at its own place; returns the
    pairs' body ids and YADE's own shapes and poses."""
    O.bodies.clear()
    O.interactions.clear()
    ids, shapes, poses = [], [], []
    for k in range(len(a)):
        origin = np.array([spacing * (k % 40), spacing * ((k // 40) % 40), spacing * (k // 1600)])
        pair = []
        for s, q, x in ((a[k], qa[k], origin), (b[k], qb[k], origin + xb[k])):
            body = polyhedra_utils.polyhedra(mat, v=[tuple(p) for p in lib[int(s)][0] * D])
            body.state.ori = Quaternion(*q) * body.state.ori
            body.state.pos = tuple(x)
            pair.append(O.bodies.append(body))
        ids.append(pair)
    for i in [x for p in ids for x in p]:
        body = O.bodies[i]
        v = np.array([tuple(p) for p in body.shape.v])
        shapes.append((v, outward_triangles(v, body.shape.GetSurfaceTriangulation())))
        x, y, z, w = tuple(body.state.ori)
        poses.append((np.array(tuple(body.state.pos)), np.array([w, x, y, z])))
    return ids, shapes, poses


def ours(ids, shapes, poses, threads=0):
    table = ShapeTable(shapes)
    i1 = np.array([p[0] for p in ids]) - ids[0][0]
    i2 = np.array([p[1] for p in ids]) - ids[0][0]
    pos = np.array([p for p, _ in poses])
    q = np.array([q for _, q in poses])
    return table, i1, i2, pos, q, batch_overlap(table, i1, pos[i1], q[i1], i2, pos[i2], q[i2], threads=threads)


def yade_geoms(ids):
    """YADE's (volume, contact point, normal, id1) per pair, or None."""
    out = []
    for p1, p2 in ids:
        i = O.interactions[p1, p2] if O.interactions.has(p1, p2) else None
        if i is None or not i.isReal or not (i.geom.penetrationVolume > 0):
            out.append(None)
            continue
        g = i.geom
        out.append((g.penetrationVolume, np.array(tuple(g.contactPoint)), np.array(tuple(g.normal)), i.id1))
    return out


def yade_run(steps, ids=None):
    """Run the stock loop; returns its seconds per step and, with ids, YADE's
    geometry after the first step (a new contact) and after the last."""
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polyhedra_Aabb()]),
                 InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()],
                                 [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                                 [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()], label="loop")]
    O.dt = 1e-8
    O.step()
    first = yade_geoms(ids) if ids is not None else None
    O.timingEnabled = True
    loop.execTime = 0
    O.run(steps, True)
    O.timingEnabled = False
    if ids is None:
        return loop.execTime * 1e-9 / steps
    return loop.execTime * 1e-9 / steps, first, yade_geoms(ids)


def kernel_time(table, i1, i2, pos, q, threads, reps):
    """Seconds per call for all the pairs, less the fixed cost of a call (the
    shape table's planes are set up at every batch_overlap call: timed with
    a single pair, in alternation)."""
    ts, t1 = [], []
    for _ in range(reps):
        t0 = time.perf_counter()
        batch_overlap(table, i1, pos[i1], q[i1], i2, pos[i2], q[i2], threads=threads)
        ts.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        batch_overlap(table, i1[:1], pos[i1[:1]], q[i1[:1]], i2[:1], pos[i2[:1]], q[i2[:1]], threads=threads)
        t1.append(time.perf_counter() - t0)
    return float(np.median(ts) - np.median(t1))


def pct(x):
    x = np.asarray(x, float)
    return {"median": float(np.median(x)), "p90": float(np.percentile(x, 90)),
            "p99": float(np.percentile(x, 99)), "max": float(x.max())}


out = {"pairs": N, "steps": STEPS, "d": D}
# --- touching pairs
a, b, qa, qb, xb = place(N, False)
ids, shapes, poses = build(a, b, qa, qb, xb)
table, i1, i2, pos, q, r = ours(ids, shapes, poses)
t_yade, geoms_first, geoms_last = yade_run(STEPS, ids)


def compare(geoms):
    rel, dist, ang, sign, missing = [], [], [], [], 0
    for k, ((p1, p2), gm) in enumerate(zip(ids, geoms)):
        if gm is None:
            missing += 1
            continue
        vol, cp, nrm, id1 = gm
        sgn = 1.0 if id1 == p1 else -1.0            # ours: from the pair's first body to its second
        rel.append(abs(vol - r["volume"][k]) / r["volume"][k])
        dist.append(np.linalg.norm(cp - r["centroid"][k]) / D)
        c = float(np.clip(sgn * nrm @ r["normal"][k], -1, 1))
        sign.append(c)
        ang.append(math.acos(abs(c)))
    return {"yade_missed": missing, "volume_rel_diff": pct(rel), "point_dist_over_d": pct(dist),
            "normal_angle_rad": pct(ang), "yade_normal_points_id1_to_id2": float(np.mean(np.array(sign) > 0)),
            "share_volume_off_by_1e-3_or_more": float(np.mean(np.array(rel) >= 1e-3))}


out["touching"] = {**compare(geoms_last), "yade_us_per_pair_step": t_yade * 1e6 / N,
                   "first_step": compare(geoms_first)}
for th in (1, 2):
    out["touching"][f"kernel_us_per_pair_{th}_threads"] = kernel_time(table, i1, i2, pos, q, th, STEPS) * 1e6 / N
# --- separated pairs
a, b, qa, qb, xb = place(int(N * 1.6), True)
u = xb / np.linalg.norm(xb, axis=1)[:, None]
xb = xb + u * D * 10 ** rng.uniform(-4, np.log10(0.15), size=(len(a), 1))
boxes = []
for k in range(len(a)):
    def world(s, qq, x):
        w, xx, y, z = qq
        R = np.array([[1 - 2 * (y * y + z * z), 2 * (xx * y - w * z), 2 * (xx * z + w * y)],
                      [2 * (xx * y + w * z), 1 - 2 * (xx * xx + z * z), 2 * (y * z - w * xx)],
                      [2 * (xx * z - w * y), 2 * (y * z + w * xx), 1 - 2 * (xx * xx + y * y)]])
        return lib[int(s)][0] * D @ R.T + x
    wa, wb = world(a[k], qa[k], np.zeros(3)), world(b[k], qb[k], xb[k])
    boxes.append(np.all(wa.max(0) > wb.min(0)) and np.all(wb.max(0) > wa.min(0)))
keep = np.flatnonzero(boxes)[:N]
ids, shapes, poses = build(a[keep], b[keep], qa[keep], qb[keep], xb[keep])
table, i1, i2, pos, q, r = ours(ids, shapes, poses)
t_yade = yade_run(STEPS)
yade_touch = sum(1 for p1, p2 in ids if O.interactions.has(p1, p2) and O.interactions[p1, p2].isReal
                 and O.interactions[p1, p2].geom.penetrationVolume > 0)
out["separated"] = {"pairs": int(len(keep)), "yade_touching": yade_touch, "kernel_touching": int((r["volume"] > 0).sum()),
                    "yade_us_per_pair_step": t_yade * 1e6 / len(keep)}
for th in (1, 2):
    out["separated"][f"kernel_us_per_pair_{th}_threads"] = kernel_time(table, i1, i2, pos, q, th, STEPS) * 1e6 / len(keep)
# --- two unit cubes face to face, overlap 0.01 of the side
cube = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
O.bodies.clear()
O.interactions.clear()
c1 = O.bodies.append(polyhedra_utils.polyhedra(mat, v=cube))
c2 = O.bodies.append(polyhedra_utils.polyhedra(mat, v=cube))
O.bodies[c2].state.pos = (0, 0, 0.99)
yade_run(1)
g = O.interactions[c1, c2].geom
n = np.array(tuple(g.normal))
out["cubes"] = {"yade_normal": n.tolist(), "yade_tilt_rad": math.acos(min(1.0, abs(n[2]) / np.linalg.norm(n))),
                "yade_volume": g.penetrationVolume, "exact_volume": 0.01}
shapes, poses = [], []
for i in (c1, c2):
    body = O.bodies[i]
    v = np.array([tuple(p) for p in body.shape.v])
    shapes.append((v, outward_triangles(v, body.shape.GetSurfaceTriangulation())))
    x, y, z, w = tuple(body.state.ori)
    poses.append((np.array(tuple(body.state.pos)), np.array([w, x, y, z])))
_, _, _, _, _, rc = ours([[0, 1]], shapes, poses)
out["cubes"]["kernel_normal"] = rc["normal"][0].tolist()
out["cubes"]["kernel_volume"] = float(rc["volume"][0])
os.makedirs(os.path.dirname(OUT), exist_ok=True)
with open(OUT, "w") as fh:
    json.dump(out, fh, indent=1)
t, s = out["touching"], out["separated"]
print(f"\n{N} touching pairs (d = {D} m), YADE against the exact kernel:")
for when, tt in (("first step (new contact)", t["first_step"]), (f"after {STEPS + 1} steps", t)):
    print(f" {when}: volume off by 1e-3 or more on {100 * tt['share_volume_off_by_1e-3_or_more']:.1f} % of pairs, "
          f"YADE missed {tt['yade_missed']}")
    for key in ("volume_rel_diff", "point_dist_over_d", "normal_angle_rad"):
        x = tt[key]
        print(f"  {key:20s} median {x['median']:.2e}  p90 {x['p90']:.2e}  p99 {x['p99']:.2e}  max {x['max']:.2e}")
print(f"  volume off by 1e-3 or more: {100 * t['share_volume_off_by_1e-3_or_more']:.1f} % of pairs; YADE missed {t['yade_missed']}; "
      f"YADE's normal points id1 -> id2 on {100 * t['yade_normal_points_id1_to_id2']:.0f} %")
print(f"  cost per pair-step: YADE InteractionLoop {t['yade_us_per_pair_step']:.1f} us; kernel "
      f"{t['kernel_us_per_pair_1_threads']:.2f} us (1 thread), {t['kernel_us_per_pair_2_threads']:.2f} us (2 threads)")
print(f"{s['pairs']} separated pairs with overlapping boxes: YADE touching {s['yade_touching']}, kernel {s['kernel_touching']}; "
      f"cost YADE {s['yade_us_per_pair_step']:.1f} us, kernel {s['kernel_us_per_pair_1_threads']:.2f} us (1 thread), "
      f"{s['kernel_us_per_pair_2_threads']:.2f} us (2 threads)")
cu = out["cubes"]
print(f"cubes face to face (0.01 overlap): YADE tilt {cu['yade_tilt_rad']:.4f} rad, volume {cu['yade_volume']:.6f}; "
      f"kernel normal {np.round(cu['kernel_normal'], 12)}, volume {cu['kernel_volume']:.6f}")
print(f"written {OUT}")
sys.exit(0)
