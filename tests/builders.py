"""Hand-built configurations with exactly known answers, for the tests."""
from __future__ import annotations

import numpy as np

from postproc.schema import KIND_SPHERE, Snapshot


def lattice_snapshot(nx=3, ny=2, nz=4, r=0.01, F=(3.0, 5.0, 7.0), T=1.5):
    """Spheres of radius r on a simple cubic lattice filling a box exactly.

    Every contact along axis b carries the normal force F[b]; contacts along
    x also carry a tangential force T along y and contacts along y a
    tangential force T along x, which keeps every sphere in force and torque
    equilibrium. Walls (ids 0..5, order x-, x+, y-, y+, z-, z+) close the
    chains. The exact stress (compression positive) is

        sigma = [[F_x, T, 0], [T, F_y, 0], [0, 0, F_z]] / (2r)^2,

    the internal-moment and wall forms give it exactly, and the branch form
    over particle-particle contacts gives each column b scaled by
    (n_b - 1)/n_b.
    """
    n = np.array([nx, ny, nz])
    d = 2 * r
    grid = np.stack(np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij"), -1).reshape(-1, 3)
    ids = 6 + np.arange(len(grid))
    index = {tuple(g): i for g, i in zip(grid, ids)}
    pos = (grid + 0.5) * d
    tang = {0: np.array([0.0, T, 0.0]), 1: np.array([T, 0.0, 0.0]), 2: np.zeros(3)}
    id1, id2, point, force, normal = [], [], [], [], []
    for g, i in zip(grid, ids):
        for b in range(3):
            e = np.eye(3)[b]
            f = F[b] * e + tang[b]
            x = (g + 0.5) * d
            if g[b] == 0:                       # wall "b-" pushes the first sphere
                id1.append(2 * b); id2.append(i); point.append(x - r * e)
                force.append(f); normal.append(e)
            nxt = tuple(g + np.eye(3, dtype=int)[b])
            if nxt in index:
                id1.append(i); id2.append(index[nxt]); point.append(x + r * e)
                force.append(f); normal.append(e)
            else:                               # last sphere pushes wall "b+"
                id1.append(i); id2.append(2 * b + 1); point.append(x + r * e)
                force.append(f); normal.append(e)
    force = np.array(force)
    normal = np.array(normal)
    fn = np.einsum("ij,ij->i", force, normal)[:, None] * normal
    L = n * d
    A = np.array([L[1] * L[2], L[0] * L[2], L[0] * L[1]])
    wall_forces = np.zeros((6, 3))
    for b in range(3):
        f = F[b] * np.eye(3)[b] + tang[b]
        count = A[b] / d ** 2
        wall_forces[2 * b] = -count * f          # force on the b- wall
        wall_forces[2 * b + 1] = count * f
    sigma = np.array([[F[0], T, 0], [T, F[1], 0], [0, 0, F[2]]]) / d ** 2
    nb = len(ids)
    snap = Snapshot(
        name="000000", step=0, time=0.0, stage="shear", volume=float(np.prod(L)),
        box_lo=np.zeros(3), box_hi=L.astype(float), wall_ids=np.arange(6),
        wall_forces=wall_forces, body_ids=ids, positions=pos,
        id1=np.array(id1), id2=np.array(id2), point=np.array(point), force=force,
        force_normal=fn, normal=normal, overlap=np.zeros(len(force)),
        body_kind=np.full(nb, KIND_SPHERE), orientations=np.tile([1.0, 0, 0, 0], (nb, 1)),
        volumes=np.full(nb, 4 / 3 * np.pi * r ** 3), masses=np.full(nb, 1.0),
        shape_index=np.full(nb, -1), sizes=np.full(nb, d))
    return snap, sigma, n


def snapshot_dicts(snap):
    """(bodies, contacts) dicts for DumpWriter.write_snapshot from a Snapshot."""
    bodies = {"id": snap.body_ids, "kind": snap.body_kind, "position": snap.positions,
              "orientation": snap.orientations, "volume": snap.volumes, "mass": snap.masses,
              "shape_index": snap.shape_index, "size": snap.sizes}
    contacts = {"id1": snap.id1, "id2": snap.id2, "point": snap.point, "normal": snap.normal,
                "force_normal": snap.force_normal,
                "force_tangential": snap.force - snap.force_normal, "overlap": snap.overlap}
    return bodies, contacts


def write_snapshot(writer, snap, **override):
    bodies, contacts = snapshot_dicts(snap)
    kw = dict(step=snap.step, time=snap.time, stage=snap.stage, box_lo=snap.box_lo,
              box_hi=snap.box_hi, wall_ids=snap.wall_ids, wall_forces=snap.wall_forces,
              bodies=bodies, contacts=contacts)
    kw.update(override)
    return writer.write_snapshot(**kw)


def pressure_tensor(snap):
    """The pressure tensor P (3, 3) of a LAMMPS or LIGGGHTS fixture snapshot
    (``pressure.json``: "pxx_pyy_pzz_pxy_pxz_pyz", the pair part),
    P[a, b] = sum l_a f_b / V with l = x_i - x_j and f the force on i
    (Pair::ev_tally_xyz: v[3] = delx*fy, v[4] = delx*fz, v[5] = dely*fz),
    compression positive; the codes store only the upper triangle, so the
    lower one is left 0."""
    pxx, pyy, pzz, pxy, pxz, pyz = snap["pxx_pyy_pzz_pxy_pxz_pyz"]
    P = np.diag([pxx, pyy, pzz])
    P[0, 1], P[0, 2], P[1, 2] = pxy, pxz, pyz
    return P


def raw_rows(path):
    """Rows (N, K) of each block of a LAMMPS-style text dump, as numbers."""
    lines = open(path).read().splitlines()
    out, k = [], 0
    while k < len(lines):
        n = int(lines[k + 3])
        out.append(np.array([r.split() for r in lines[k + 9:k + 9 + n]], float))
        k += 9 + n
    return out
