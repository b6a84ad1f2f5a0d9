"""Reading YADE's state into the arrays of the dump schema (runs inside
YADE; numpy only). Conventions of ``postproc/schema.py``: SI units, forces on
id2 by id1, quaternions (w, x, y, z).
"""
from __future__ import annotations

import numpy as np


def wxyz(q):
    """YADE Quaternion (iterates x, y, z, w) -> (w, x, y, z)."""
    x, y, z, w = tuple(q)
    return (w, x, y, z)


def outward_triangles(vertices, flat):
    """(T, 3) triangles from YADE's flat triangulation list, each turned
    counter-clockwise seen from outside (the local origin is inside)."""
    t = np.asarray(flat, np.int64).reshape(-1, 3)
    v = np.asarray(vertices, float)
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    inward = np.einsum("ij,ij->i", n, v[t[:, 0]] + v[t[:, 1]] + v[t[:, 2]]) < 0
    t[inward] = t[inward][:, [0, 2, 1]]
    return t


def coplanar_faces(vertices, triangles, tol_deg=1.0):
    """(T,) geometric face of each triangle: edge-adjacent triangles whose
    normals differ by less than ``tol_deg`` share a face (union-find)."""
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    n /= np.linalg.norm(n, axis=1)[:, None]
    parent = list(range(len(t)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    owner = {}
    cos_tol = np.cos(np.radians(tol_deg))
    for k, tri in enumerate(t.tolist()):
        for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            key = (min(a, b), max(a, b))
            if key in owner:
                j = owner[key]
                if n[j] @ n[k] > cos_tol:
                    parent[find(k)] = find(j)
            else:
                owner[key] = k
    roots = [find(k) for k in range(len(t))]
    relabel = {}
    return np.array([relabel.setdefault(r, len(relabel)) for r in roots], np.int64)


def polyhedra_shapes(O, ids):
    """(vertices list, triangles list, triangle_faces list) in each body's
    local frame, one entry per id."""
    verts, tris, faces = [], [], []
    for i in ids:
        sh = O.bodies[int(i)].shape
        v = np.array([tuple(x) for x in sh.v], float)
        t = outward_triangles(v, sh.GetSurfaceTriangulation())
        verts.append(v)
        tris.append(t)
        faces.append(coplanar_faces(v, t))
    return verts, tris, faces


def gather_bodies(O, ids, kind, shape_index, sizes, volumes=None):
    """bodies dict of the schema for particle ``ids``; ``volumes`` (m^3, one
    per id) when known (a resumed run keeps its first attempt's: YADE
    re-initialises Polyhedra after O.load, which changes GetVolume() in the
    last bit), else from the shapes."""
    pos, ori, vel, vol, mass = [], [], [], [], []
    for i in ids:
        b = O.bodies[int(i)]
        st = b.state
        pos.append(tuple(st.pos))
        ori.append(wxyz(st.ori))
        vel.append(tuple(st.vel))
        mass.append(st.mass)
        if volumes is None:
            vol.append(b.shape.GetVolume() if kind == 1 else 4.0 / 3.0 * np.pi * b.shape.radius ** 3)
    if volumes is not None:
        vol = np.asarray(volumes, float)
    n = len(ids)
    return {"id": np.asarray(ids, np.int64), "kind": np.full(n, kind, np.int8),
            "position": np.array(pos, float).reshape(n, 3),
            "orientation": np.array(ori, float).reshape(n, 4),
            "volume": np.array(vol, float), "mass": np.array(mass, float),
            "shape_index": np.asarray(shape_index, np.int32),
            "size": np.asarray(sizes, float), "velocity": np.array(vel, float).reshape(n, 3)}


def gather_contacts(O, polyhedra):
    """contacts dict of the schema: every real interaction whose normal force
    is not zero."""
    rows = []
    for i in O.interactions:
        if not i.isReal:
            continue
        p = i.phys
        fn = p.normalForce
        if fn.squaredNorm() == 0:
            continue
        g = i.geom
        overlap = g.penetrationVolume if polyhedra else g.penetrationDepth
        rows.append((i.id1, i.id2, *g.contactPoint, *g.normal, *fn, *p.shearForce, overlap))
    a = np.array(rows, float).reshape(-1, 15)
    return {"id1": a[:, 0].astype(np.int64), "id2": a[:, 1].astype(np.int64),
            "point": a[:, 2:5], "normal": a[:, 5:8], "force_normal": a[:, 8:11],
            "force_tangential": a[:, 11:14], "overlap": a[:, 14]}
