"""Make the real-LMGC90 fixtures of tests/test_lmgc90_fixtures.py.

    python3.11 -m venv /work/lmgc-venv
    /work/lmgc-venv/bin/pip install numpy h5py
    /work/lmgc-venv/bin/pip install --no-deps compas_lmgc90==0.1.11
    /work/lmgc-venv/bin/python tests/data/lmgc90/make_fixtures.py pairs
    /work/lmgc-venv/bin/python tests/data/lmgc90/make_fixtures.py packing DUMP.h5 SNAPSHOT [SNAPSHOT ...]

The committed packings: ``packing runs/study/polyhedra-ensemble/polyhedra-seed1.h5 15 -1``
on the default study (``make study``, 1000 grains, seed 1): its snapshots
000015 (shear, eps1 = 0.15) and 000030 (the last, eps1 = 0.30).

(the ``compas_lmgc90`` wheel from the Python registry, version 0.1.11,
cp311: its ``_lmgc90`` extension binds today's LMGC90 Fortran core and runs
with numpy alone; the package's own Python layer needs COMPAS and is not
used). Not run by the test suite: its outputs, written next to this script,
are committed. The wheel is a fixture maker only; the LMGC90 code it carries
is under the CeCILL licence.

What it runs. Each case is one LMGC90 simulation in its own process (LMGC90
keeps one simulation per process, and a Fortran STOP ends the process): the
grains are given as rigid POLYR bodies with their world vertices and their
triangles (counter-clockwise seen from outside, as in our dumps), one
contact law (IQS_CLB, friction 0.5), one see table RBDY3/POLYR/REDxx with
the alert distance of the case, gravity set to zero through the exported
``set_gravity`` of the bulk-behaviour module, and one step is computed. The
interactions LMGC90 stores at that step are those of its detection at the
initial positions (velocities are zero, so the predicted positions are the
given ones); they are recorded: candidate and antagonist body (1-based, in
the order given), contact point, local frame (t, n, s), gap, status.

The detection. The wheel's Fortran glue selects the PRPRx detection by a
private 21-character module string (``'STO'`` in this build: explicit
face-to-face detection at the first step only, which finds no edge-face or
vertex-face contact). This script rewrites that string to ``'CpCundall'``
in the loaded library before the solver is initialised (the string is
located in the library's .data section and checked before it is written),
so the glue takes its CpCundall branch: ``set_cundall_iteration_PRPRx(200)``,
``set_clipper_parameters(0, 0, 0)``, ``with_nodal_contact_PRPRx()`` and
``wcp_compute_contact_PRPRx`` (Cundall's common plane). Two routes:

* ``new``: LMGC90's default point stage (``new_ccpm = .true.``);
* ``old``: the older planplan route, selected by the exported
  ``use_old_ccpm_PRPRx`` before the first step.

Outputs (``.npz``, compressed): ``pairs.npz`` (the hand-built cases) and
``packing-<snapshot>.npz`` (a snapshot of a real dump: the bodies' poses,
shape rows, the dumped contacts and LMGC90's interactions for both routes).
Every file records the wheel's version and the SHA-256 of its ``_lmgc90``
library, the route, the alert distance and the Cundall iteration count.
"""
import hashlib
import json
import os
import re
import struct
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
WHEEL_VERSION = "0.1.11"
CUNDALL_ITER = 200          # the glue's cundall_it, passed to set_cundall_iteration_PRPRx
ROUTES = ("new", "old")


# --------------------------------------------------------------------------- the worker

def _library_path():
    import importlib.util
    spec = importlib.util.find_spec("compas_lmgc90")
    if spec is None or not spec.submodule_search_locations:
        raise SystemExit("make_fixtures: compas_lmgc90 is not installed in this Python")
    d = list(spec.submodule_search_locations)[0]
    libs = [f for f in os.listdir(d) if f.startswith("_lmgc90") and f.endswith(".so")]
    if len(libs) != 1:
        raise SystemExit(f"make_fixtures: expected one _lmgc90*.so in {d}, found {libs}")
    return os.path.join(d, libs[0])


def _sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for chunk in iter(lambda: fh.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _data_offset(path, pattern):
    """Virtual address (relative to the load base) of the unique occurrence
    of ``pattern`` inside the .data section of the ELF64 library."""
    blob = open(path, "rb").read()
    if blob[:4] != b"\x7fELF" or blob[4] != 2:
        raise SystemExit("make_fixtures: the library is not a 64-bit ELF file")
    shoff, = struct.unpack_from("<Q", blob, 0x28)
    shentsize, shnum, shstrndx = struct.unpack_from("<HHH", blob, 0x3A)
    sections = [struct.unpack_from("<IIQQQQIIQQ", blob, shoff + k * shentsize) for k in range(shnum)]
    strtab = sections[shstrndx]
    names = {}
    for s in sections:
        start = strtab[4] + s[0]
        names[blob[start:blob.index(b"\0", start)].decode()] = s
    data = names[".data"]                          # name, type, flags, addr, offset, size, ...
    lo, hi = data[4], data[4] + data[5]
    hits = [m.start() for m in re.finditer(re.escape(pattern), blob) if lo <= m.start() < hi]
    if len(hits) != 1:
        raise SystemExit(f"make_fixtures: found {len(hits)} copies of {pattern!r} in .data (expected 1)")
    return hits[0] - data[4] + data[3]


def _symbol_value(path, name):
    out = subprocess.run(["nm", "-D", "--defined-only", path], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == name:
            return int(parts[0], 16)
    raise SystemExit(f"make_fixtures: symbol {name} not exported by {path}")


def _get(x):
    return x() if callable(x) else x


def worker(inp, out):
    """Run one LMGC90 simulation on the case in ``inp`` (npz) and write its
    interactions to ``out`` (npz)."""
    import ctypes
    import importlib.machinery
    import importlib.util

    case = np.load(inp, allow_pickle=False)
    route = str(case["route"])
    path = _library_path()
    loader = importlib.machinery.ExtensionFileLoader("_lmgc90", path)
    spec = importlib.util.spec_from_loader("_lmgc90", loader)
    lm = importlib.util.module_from_spec(spec)
    loader.exec_module(lm)
    lib = ctypes.CDLL(path)
    base = ctypes.cast(lib.lmgc90_initialize, ctypes.c_void_p).value - _symbol_value(path, "lmgc90_initialize")
    old, new = b"STO".ljust(21), b"CpCundall".ljust(21)
    addr = base + _data_offset(path, old)
    if ctypes.string_at(addr, 21) != old:
        raise SystemExit("make_fixtures: the detection string is not where it was found in the file")
    ctypes.memmove(addr, new, 21)

    solver = lm.LMGC90Solver()
    solver.initialize(1e-4, 0.5, False)
    if route == "old":
        lib.__prprx_MOD_use_old_ccpm_prprx()
    solver.set_materials([2750.0])
    grav = (ctypes.c_double * 3)(0.0, 0.0, 0.0)
    lib.__bulk_behaviour_MOD_set_gravity(grav)
    solver.add_one_tact_behav("iqsc0", "IQS_CLB", [0.5])
    solver.set_see_tables(float(case["alert"]))
    voff, toff = case["vertex_offsets"], case["triangle_offsets"]
    verts, tris, centres = case["vertices"], case["triangles"], case["centres"]
    solver.set_nb_bodies(len(centres))
    for b in range(len(centres)):
        v = verts[voff[b]:voff[b + 1]] - centres[b]
        t = tris[toff[b]:toff[b + 1]] + 1
        solver.set_one_polyr("s0001", centres[b].tolist(), t.ravel().tolist(), v.ravel().tolist(), 0, 0)
    solver.close_before_computing()
    init = solver.get_initial_state()
    res = solver.compute_one_step()
    n = len(res.interaction_gap)
    uc = np.array(res.interaction_uc, float).reshape(n, 9) if n else np.zeros((0, 9))
    # interaction_bodies holds (candidate, antagonist) body numbers; check it
    # against the antagonist's own accessor
    cdan = np.array(res.interaction_bodies, np.int64).reshape(n, 2)
    ian = np.array(_get(res.interaction_ianbdy), np.int64).reshape(n)
    if not np.array_equal(cdan[:, 1], ian):
        raise SystemExit(f"make_fixtures: interaction_bodies {cdan[:3].tolist()} disagrees with ianbdy {ian[:3].tolist()}")
    np.savez(out,
             cd=cdan[:, 0], an=cdan[:, 1],
             point=np.array(res.interaction_coords, float).reshape(n, 3),
             t=uc[:, 0:3], n=uc[:, 3:6], s=uc[:, 6:9],
             gap=np.array(res.interaction_gap, float).reshape(n),
             status=np.array([str(x).strip() for x in res.interaction_status], dtype="U5").reshape(n),
             body_centre=np.array(init.init_bodies, float).reshape(-1, 3))
    solver.finalize()


# --------------------------------------------------------------------------- the driver

def run_case(vertices, triangles, centres, alert, route):
    """LMGC90's interactions for bodies with world ``vertices`` (list of
    (V, 3)), ``triangles`` (list of (T, 3)), centres of mass ``centres``
    (B, 3), the alert distance and the route, from a fresh process."""
    voff = np.cumsum([0] + [len(v) for v in vertices])
    toff = np.cumsum([0] + [len(t) for t in triangles])
    with tempfile.TemporaryDirectory() as tmp:
        inp, out = os.path.join(tmp, "in.npz"), os.path.join(tmp, "out.npz")
        np.savez(inp, vertices=np.concatenate(vertices), triangles=np.concatenate(triangles).astype(np.int64),
                 vertex_offsets=voff, triangle_offsets=toff, centres=np.asarray(centres, float),
                 alert=float(alert), route=route)
        p = subprocess.run([sys.executable, os.path.abspath(__file__), "worker", inp, out],
                           capture_output=True, text=True, cwd=tmp)
        if p.returncode != 0 or not os.path.exists(out):
            tail = (p.stdout + p.stderr).strip().splitlines()[-5:]
            raise RuntimeError(f"LMGC90 worker failed (exit {p.returncode}): {' | '.join(tail)}")
        with np.load(out) as r:
            return {k: r[k] for k in r.files}


def provenance():
    path = _library_path()
    import importlib.metadata
    version = importlib.metadata.version("compas_lmgc90")
    if version != WHEEL_VERSION:
        raise SystemExit(f"make_fixtures: compas_lmgc90 {version} installed, the fixtures are made with {WHEEL_VERSION}")
    return {"wheel": f"compas_lmgc90=={version}", "library": os.path.basename(path),
            "library_sha256": _sha256(path), "detection": "CpCundall (wcp_compute_contact_PRPRx)",
            "cundall_iterations": CUNDALL_ITER, "cundall_neighbor": 0.1,
            "routes": {"new": "default point stage (new_ccpm = .true.)",
                       "old": "planplan route (use_old_ccpm_PRPRx)"}}


def _rot(axis, deg):
    a = np.radians(deg)
    c, s = np.cos(a), np.sin(a)
    x, y, z = np.asarray(axis, float) / np.linalg.norm(axis)
    return np.array([[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                     [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                     [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]])


def cube(h):
    """Cube of half side h centred at the origin: vertices (8, 3), outward
    counter-clockwise triangles (12, 3)."""
    v = np.array([[x, y, z] for z in (-h, h) for y in (-h, h) for x in (-h, h)], float)
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tri = []
    for a, b, c, d in quads:
        tri += [(a, b, c), (a, c, d)]
    return v, np.array(tri, np.int64)


def _lowest(v, R):
    return float(np.min((v @ R.T)[:, 2]))


def hand_cases(alert, h=0.01):
    """The hand-built pairs: (name, [(local vertices, triangles, R, x)]).
    Body 1 is a large cube (half side 2h) whose top face is the plane
    z = 0; body 2 (a cube of half side h) is placed by its lowest point."""
    V, T = cube(h)
    VB, TB = cube(2 * h)
    base = (VB, TB, np.eye(3), np.array([0.0, 0.0, -2 * h]))
    pen = 1e-3 * h                  # interpenetration of the touching cases

    def on(R, dz, dx=(0.0, 0.0)):
        return (V, T, R, np.array([dx[0], dx[1], dz - _lowest(V, R)]))

    cases = [
        ("face on face, flush", [base, on(np.eye(3), -pen, (0.3 * h, 0.2 * h))]),
        ("face on face, tilted 1 deg", [base, on(_rot((1, 0, 0), 1.0), -pen)]),
        ("face on face, tilted 3 deg", [base, on(_rot((1, 0, 0), 3.0), -pen)]),
        ("face on face, tilted 6 deg", [base, on(_rot((1, 0, 0), 6.0), -pen)]),
        ("face on face, tilted 10 deg", [base, on(_rot((1, 0, 0), 10.0), -pen)]),
        ("edge on face", [base, on(_rot((1, 0, 0), 45.0), -pen)]),
        ("edge on face, skew", [base, on(_rot((0, 0, 1), 30.0) @ _rot((1, 0, 0), 45.0), -pen, (0.2 * h, 0.0))]),
        ("vertex on face", [base, on(_rot((1, 1, 0), np.degrees(np.arctan(np.sqrt(2)))), -pen)]),
        ("vertex on face, tilted", [base, on(_rot((1, 0, 0), 20.0) @ _rot((0, 1, 0), 35.0), -pen)]),
        ("face on face, within alert", [base, on(np.eye(3), 0.5 * alert)]),
        ("face on face, beyond alert", [base, on(np.eye(3), 2.0 * alert)]),
        ("vertex on face, within alert", [base, on(_rot((1, 1, 0), np.degrees(np.arctan(np.sqrt(2)))), 0.5 * alert)]),
        ("vertex on face, beyond alert", [base, on(_rot((1, 1, 0), np.degrees(np.arctan(np.sqrt(2)))), 2.0 * alert)]),
    ]
    # crossed edges: two equal cubes, each turned 45 deg so an edge is
    # lowest / highest, the edges at right angles
    Ra = _rot((1, 0, 0), 45.0)
    Rb = _rot((0, 1, 0), 45.0)
    za = -float(np.max((V @ Ra.T)[:, 2]))
    zb = -_lowest(V, Rb) - pen
    cases.append(("crossed edges", [(V, T, Ra, np.array([0.0, 0.0, za])), (V, T, Rb, np.array([0.0, 0.0, zb]))]))
    Rs = _rot((0, 0, 1), 20.0) @ Rb
    cases.append(("crossed edges, skew", [(V, T, Ra, np.array([0.0, 0.0, za])),
                                          (V, T, Rs, np.array([0.1 * h, 0.0, -_lowest(V, Rs) - pen]))]))
    cases.append(("crossed edges, within alert", [(V, T, Ra, np.array([0.0, 0.0, za])),
                                                  (V, T, Rb, np.array([0.0, 0.0, zb + pen + 0.5 * alert]))]))
    return cases


def make_pairs(alert=1e-5):
    prov = provenance()
    out = {"provenance": json.dumps(prov), "alert": alert}
    names = []
    shapes_v, shapes_t = [], []
    rec = {k: [] for k in ("case", "route", "cd", "an", "point", "n", "t", "s", "gap", "status")}
    poses = {k: [] for k in ("case", "body", "shape", "R", "x")}
    for ci, (name, bodies) in enumerate(hand_cases(alert)):
        names.append(name)
        wv, wt, cen = [], [], []
        for bi, (v, t, R, x) in enumerate(bodies):
            key = len(shapes_v)
            shapes_v.append(v)
            shapes_t.append(t)
            poses["case"].append(ci)
            poses["body"].append(bi)
            poses["shape"].append(key)
            poses["R"].append(R)
            poses["x"].append(x)
            wv.append(v @ R.T + x)
            wt.append(t)
            cen.append(x)
        for route in ROUTES:
            r = run_case(wv, wt, cen, alert, route)
            k = len(r["gap"])
            print(f"{name:32s} {route}: {k} points, gaps {np.round(r['gap'] / alert, 3).tolist()} alert")
            rec["case"] += [ci] * k
            rec["route"] += [route] * k
            for key in ("cd", "an", "point", "n", "t", "s", "gap", "status"):
                rec[key] += list(r[key])
    out["names"] = np.array(names)
    out["shape_vertices"] = np.concatenate(shapes_v)
    out["shape_vertex_offsets"] = np.cumsum([0] + [len(v) for v in shapes_v])
    out["shape_triangles"] = np.concatenate(shapes_t)
    out["shape_triangle_offsets"] = np.cumsum([0] + [len(t) for t in shapes_t])
    for k, v in poses.items():
        out["body_" + k] = np.array(v)
    for k, v in rec.items():
        out["lmgc_" + k] = np.array(v)
    np.savez_compressed(os.path.join(HERE, "pairs.npz"), **out)


ALERTS = (0.1, 0.002)      # alert distances, in units of the smallest grain radius (d_min / 2)


def make_packing(dump, snapshots, alerts=ALERTS):
    """LMGC90 on every grain of the dump's snapshots (walls left out), at
    each alert distance of ``alerts`` (units of the smallest grain radius:
    0.1 is what LMGC90's granular examples set, 0.002 about 1e-3 of the
    mean grain size)."""
    sys.path.insert(0, os.path.abspath(os.path.join(HERE, "..", "..", "..")))
    from postproc.schema import DumpReader
    prov = provenance()
    with DumpReader(dump) as r:
        sv, st, _ = r.shapes()
        for which in snapshots:
            i = int(which) % len(r)
            snap = r.read(i)
            keep = snap.shape_index >= 0
            ids, pos, q, shp = (snap.body_ids[keep], snap.positions[keep], snap.orientations[keep],
                                snap.shape_index[keep])
            r_min = 0.5 * float(np.min(snap.sizes[keep]))
            wv, wt = [], []
            for b in range(len(ids)):
                w, x, y, z = q[b] / np.linalg.norm(q[b])
                R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                              [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                              [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
                wv.append(sv[shp[b]] @ R.T + pos[b])
                wt.append(st[shp[b]])
            out = {"provenance": json.dumps(prov), "alerts": np.array(alerts) * r_min,
                   "alerts_rel": np.array(alerts), "r_min": r_min,
                   "dump": os.path.basename(dump), "snapshot": snap.name, "step": snap.step,
                   "stage": snap.stage, "body_ids": ids, "positions": pos, "orientations": q,
                   "shape_index": shp, "sizes": snap.sizes[keep],
                   "contact_id1": snap.id1, "contact_id2": snap.id2, "contact_normal": snap.normal}
            used = np.unique(shp)
            out["shape_rows"] = used
            out["shape_vertices"] = np.concatenate([sv[s] for s in used])
            out["shape_vertex_offsets"] = np.cumsum([0] + [len(sv[s]) for s in used])
            out["shape_triangles"] = np.concatenate([st[s] for s in used])
            out["shape_triangle_offsets"] = np.cumsum([0] + [len(st[s]) for s in used])
            for ia, a in enumerate(alerts):
                for route in ROUTES:
                    res = run_case(wv, wt, pos, a * r_min, route)
                    print(f"{snap.name} alert {a} r_min, {route}: {len(res['gap'])} points")
                    for k in ("cd", "an", "point", "n", "gap"):
                        out[f"{route}{ia}_{k}"] = res[k]
                    out[f"{route}{ia}_body_centre"] = res["body_centre"]
            np.savez_compressed(os.path.join(HERE, f"packing-{snap.name}.npz"), **out)


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "worker":
        worker(sys.argv[2], sys.argv[3])
    elif len(sys.argv) >= 2 and sys.argv[1] == "pairs":
        make_pairs()
    elif len(sys.argv) >= 4 and sys.argv[1] == "packing":
        make_packing(sys.argv[2], sys.argv[3:])
    else:
        raise SystemExit(__doc__)
