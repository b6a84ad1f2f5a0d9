"""Export dumps to VTK for ParaView: ``postproc export-vtk RUN.h5 OUTDIR``.

Per snapshot NAME two unstructured-grid files (VTU, binary, via meshio):

* ``particles_NAME.vtu``: polyhedra as their triangles in the global frame
  (cell data ``id``, ``shape``, ``size`` in m, ``force`` = sum of |f_n| on
  the particle, N); spheres as vertices with point data ``radius`` (m) for
  ParaView's Glyph filter (sphere glyph, scale by ``radius``, factor 1);
* ``contacts_NAME.vtu``: one line per contact from the centre of id1 to the
  centre of id2 (to the contact point for a wall), cell data ``fn``
  (normal force magnitude, N, compression positive), ``ft`` (tangential
  magnitude, N) and ``type`` (code of :data:`TYPE_CODES`).

``particles.pvd`` and ``contacts.pvd`` list the snapshots with their time, so
ParaView opens each series as one animated source.
"""
from __future__ import annotations

import os
from xml.sax.saxutils import quoteattr

import numpy as np

from .axes import quaternion_matrices
from .classify import check_options, classifier_for, snapshot_classes
from .contactset import lookup
from .contacttypes import PAIR_TYPES
from .errors import InputError
from .schema import DumpReader

TYPE_CODES = {**{t: k for k, t in enumerate(PAIR_TYPES)}, "sphere": 6, "wall": 7}


def particle_mesh(snap, shapes):
    """(points (P, 3) m, cells list of (meshio type, connectivity),
    cell_data dict, point_data dict) of the particles of ``snap``.
    ``shapes`` = (vertices, triangles, faces) lists of the dump, or None."""
    kind = snap.body_kind
    i1, i2 = lookup(snap.id1, snap.body_ids), lookup(snap.id2, snap.body_ids)
    fn = np.linalg.norm(snap.force_normal, axis=1)
    nb = len(snap.body_ids)
    load = (np.bincount(i1[i1 >= 0], fn[i1 >= 0], minlength=nb)
            + np.bincount(i2[i2 >= 0], fn[i2 >= 0], minlength=nb))
    poly = np.flatnonzero(kind == 1)
    sph = np.flatnonzero(kind == 0)
    pts, tris, cid, cshape, csize, cload = [], [], [], [], [], []
    n = 0
    if len(poly):
        if shapes is None:
            raise InputError(f"snapshot {snap.name}: polyhedra but the dump has no /shapes")
        verts, triangles = shapes[0], shapes[1]
        R = quaternion_matrices(snap.orientations[poly])
        for row, Rb in zip(poly, R):
            s = int(snap.shape_index[row])
            if not 0 <= s < len(verts):
                raise InputError(f"snapshot {snap.name}: body {int(snap.body_ids[row])} has shape "
                                 f"index {s} (0..{len(verts) - 1})")
            v = np.asarray(verts[s]) @ Rb.T + snap.positions[row]
            pts.append(v)
            tris.append(np.asarray(triangles[s]) + n)
            k = len(triangles[s])
            cid.append(np.full(k, snap.body_ids[row]))
            cshape.append(np.full(k, s))
            csize.append(np.full(k, snap.sizes[row]))
            cload.append(np.full(k, load[row]))
            n += len(v)
    cells, cdata = [], {"id": [], "shape": [], "size": [], "force": []}
    if tris:
        cells.append(("triangle", np.concatenate(tris)))
        cdata["id"].append(np.concatenate(cid))
        cdata["shape"].append(np.concatenate(cshape))
        cdata["size"].append(np.concatenate(csize))
        cdata["force"].append(np.concatenate(cload))
    radius = [np.zeros(n)]
    if len(sph):
        pts.append(snap.positions[sph])
        cells.append(("vertex", (n + np.arange(len(sph)))[:, None]))
        cdata["id"].append(snap.body_ids[sph])
        cdata["shape"].append(np.full(len(sph), -1))
        cdata["size"].append(snap.sizes[sph])
        cdata["force"].append(load[sph])
        radius.append(snap.sizes[sph] / 2)
    if not cells:
        raise InputError(f"snapshot {snap.name}: no particles")
    return np.concatenate(pts), cells, cdata, {"radius": np.concatenate(radius)}


def contact_mesh(snap, labels):
    """(points, cells, cell_data) of the contacts of ``snap`` as lines;
    ``labels`` (C,) class of each contact ("VV".."FF", "sphere", "wall")."""
    i1, i2 = lookup(snap.id1, snap.body_ids), lookup(snap.id2, snap.body_ids)
    a = np.where((i1 >= 0)[:, None], snap.positions[np.maximum(i1, 0)], snap.point)
    b = np.where((i2 >= 0)[:, None], snap.positions[np.maximum(i2, 0)], snap.point)
    C = len(a)
    pts = np.concatenate([a, b])
    lines = np.stack([np.arange(C), C + np.arange(C)], axis=1)
    fn = np.linalg.norm(snap.force_normal, axis=1)
    ft = np.linalg.norm(snap.force - snap.force_normal, axis=1)
    code = np.array([TYPE_CODES.get(str(k), -1) for k in labels], np.int32)
    return pts, [("line", lines)], {"fn": [fn], "ft": [ft], "type": [code]}


def _write_pvd(path, entries):
    with open(path, "w") as fh:
        fh.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n')
        for t, name in entries:
            fh.write(f'  <DataSet timestep="{t:.9g}" file={quoteattr(name)}/>\n')
        fh.write("</Collection>\n</VTKFile>\n")


def export_vtk(path, outdir, theta_deg=None, snapshots=None, progress=False, types="points",
               threshold=None, tolerance=None):
    """Write the VTK files of the dump ``path`` into ``outdir``; returns the
    list of files written. ``snapshots``: indices to export (default all).
    Contact types by ``types`` ("points", the default, tolerance alpha
    ``tolerance``; "footprint", threshold in units of d; or "angular",
    tolerance ``theta_deg``): :class:`postproc.classify.Classifier`."""
    import meshio  # only the VTK export needs it

    check_options(types, threshold, theta_deg, tolerance)
    os.makedirs(outdir, exist_ok=True)
    written, pvd_p, pvd_c = [], [], []
    with DumpReader(path) as reader:
        if len(reader) == 0:
            raise InputError(f"{path}: the dump holds no snapshots")
        shapes = reader.shapes()
        tables = classifier_for(shapes, types, threshold, theta_deg, tolerance)
        idx = range(len(reader)) if snapshots is None else snapshots
        for i in idx:
            snap = reader.read(i)
            pts, cells, cdata, pdata = particle_mesh(snap, shapes)
            fp = f"particles_{snap.name}.vtu"
            meshio.write(os.path.join(outdir, fp), meshio.Mesh(pts, cells, point_data=pdata,
                                                               cell_data=cdata), binary=True)
            pts, cells, cdata = contact_mesh(snap, snapshot_classes(snap, tables))
            fc = f"contacts_{snap.name}.vtu"
            meshio.write(os.path.join(outdir, fc), meshio.Mesh(pts, cells, cell_data=cdata), binary=True)
            pvd_p.append((snap.time, fp))
            pvd_c.append((snap.time, fc))
            written += [fp, fc]
            if progress:
                print(f"export-vtk: snapshot {snap.name} ({len(snap.id1)} contacts)", flush=True)
    _write_pvd(os.path.join(outdir, "particles.pvd"), pvd_p)
    _write_pvd(os.path.join(outdir, "contacts.pvd"), pvd_c)
    with open(os.path.join(outdir, "contact_types.txt"), "w") as fh:
        fh.write("contact 'type' codes in contacts_*.vtu\n")
        fh.write("".join(f"{v} {k}\n" for k, v in TYPE_CODES.items()))
    return written + ["particles.pvd", "contacts.pvd", "contact_types.txt"]
