"""Grains from meshes: scans (STL, OBJ, PLY, OFF) become library polyhedra.

A researcher's grains arrive as triangle meshes, from a laser scanner or a
segmented CT volume, with thousands to millions of triangles and some
concavities. Each grain (one file, or one connected piece of a file with
``components=True``) becomes a valid library polyhedron, like the generated
ones (:mod:`shapes.polyhedron`):

1. **Read** with trimesh's loaders (``.stl`` ASCII or binary, ``.obj``,
   ``.ply``, ``.off``), no processing; then our own checks, each refusal an
   :class:`ImportRefused` with a one-line reason: finite coordinates, at
   least 4 distinct vertices, exact duplicate vertices merged (STL stores
   each triangle's corners apart; with a tolerance, near ones too),
   triangles with a repeated corner after the merge dropped, one connected
   piece, closed (every edge in exactly two triangles), manifold,
   consistently oriented (every directed edge once), enclosed volume not
   zero. A wholly inside-out mesh (negative volume) is turned round. A
   broken surface names its cause where one is seen: float32 coordinates
   far from the origin, or a seam of near-duplicate vertices; several
   pieces name the scan artefacts among them (:func:`piece_artefacts`).
2. **Hull**: the convex hull of the vertices (qhull), its volume V_hull, its
   centre of mass and its size d_hull = 2 x the largest distance from that
   centre to a hull vertex; the **convexity deficit** 1 - V_mesh / V_hull
   (0 for a convex mesh).
3. **Reduction** to a vertex budget (:func:`shapes.hullreduce.reduce_hull`): the reduced
   grain's vertices are hull vertices, chosen along one sequence of sets,
   the same whatever the budget. From four extreme points, a valid set
   grows by the hull vertex furthest outside its hull (quickhull's order);
   a set that fails the validity checks of :mod:`shapes.polyhedron` (two
   vertices closer than 0.02 d, an edge bending by 1-3 deg, a sliver
   triangle) is repaired by removing the vertex of the defect whose removal
   leaves the hull nearest to the points, and banning the points within
   ``shapes.hullreduce.BAN_RADIUS`` (0.005 d_hull) of it. Points within 0.02 d of a chosen
   vertex are never chosen (they could not be vertices of a valid grain).
   A second pass starts again and repairs only at the cap. The budget picks
   the first valid set that meets it:

   * ``vertices=N``: N vertices (fewer when the hull has fewer);
   * ``max_error=E``: within E d_hull of the full hull (Hausdorff), at
     most ``max_vertices`` (default 37, the paper's largest grain).

   Points within ``shapes.hullreduce.ZERO_ERROR`` (1e-6 d_hull) of the chosen hull count as on
   it (a float32 STL rounds coordinates by 6e-8 d). When no valid set
   meets the budget, the valid set of least error is kept, and the grain
   says why (``miss``): the cap, or the validity checks. A stricter target
   so never gives a larger error. Above ``shapes.hullreduce.MAX_CANDIDATES`` hull vertices
   the greedy runs on a grid-thinned subset (:func:`shapes.hullreduce.thin_points`).
4. **Error of the reduction**, measured exactly: the reduced hull lies inside
   the full hull (its vertices are hull vertices), so their Hausdorff
   distance is the largest distance from a full-hull vertex to the reduced
   polyhedron (:func:`shapes.hullreduce.distance_to_convex`, :func:`shapes.hullreduce.hausdorff_to_convex`),
   reported relative to d_hull;
   and the volume change V_reduced / V_hull - 1 (<= 0).
5. **Normalised** as the generated grains are
   (:func:`shapes.polyhedron.normalise`): centre of mass, principal frame,
   d = 1. The reduced grain's size in the file's units (``source_d``) is
   kept, and d_hull.

Pure functions over arrays, and :func:`import_paths` for files and folders
(what ``python -m shapes import`` runs). Units: any (the mesh's); every
relative quantity is scale-free.
"""
from __future__ import annotations

import io
import os
import time
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from .hullreduce import Budget, _hull_of, reduce_hull
from .polyhedron import Polyhedron, ShapeError, check_polyhedron, normalise

#: file extensions read, and trimesh's name for each format
FORMATS = {".stl": "stl", ".obj": "obj", ".ply": "ply", ".off": "off"}
#: a piece of a mesh enclosing less than this fraction of the largest piece's volume is a sliver
SLIVER_VOLUME = 1e-3
#: vertices closer than this fraction of the median edge length are near-duplicates (they break a
#: surface that is non-manifold or oriented both ways)
NEAR_DUPLICATE = 0.01
#: a seam (boundary vertices nearer one another than this fraction of the median edge) is closed by
#: a merge that suggests itself: such a tolerance joins the seam and no real edge of the mesh
SEAM_EDGE_FRACTION = 0.25
#: float32 coordinates whose step at the largest coordinate exceeds this fraction of the mesh's
#: size have lost the precision a scan needs
FLOAT32_STEP = 1e-5


class ImportRefused(ValueError):
    """A mesh that cannot become a grain; the message is one line naming the
    reason (the caller adds the file name)."""


@dataclass
class ImportedGrain:
    """One imported grain: the library polyhedron (d = 1) and what the
    import measured (module docstring). Made by :func:`import_mesh`.
    Lengths are in the mesh's units unless relative.

    Parameters
    ----------
    polyhedron : shapes.polyhedron.Polyhedron
        The reduced grain in its normalised frame (d = 1).
    source : str
        Its name: the file, or ``file#k`` for the k-th piece of a file.
    mesh_triangles, mesh_vertices : int
        The mesh's counts after the merge of duplicate vertices.
    mesh_volume, hull_volume : float
        units^3, the volumes enclosed by the mesh and by its convex hull.
    hull_vertices : int
        The vertex count of the full hull.
    d_hull : float
        units, twice the largest distance from the full hull's centre of
        mass to its vertices.
    source_d : float
        units, d of the reduced grain (twice the largest distance from its
        centre of mass to its vertices): the grain's size in the file.
    convexity_deficit : float
        1 - V_mesh / V_hull (0 for a convex mesh; never below 0).
    reduction_hausdorff : float
        The Hausdorff distance between the reduced and the full hull,
        relative to d_hull.
    reduction_volume_change : float
        V_reduced / V_hull - 1 (<= 0).
    target_met : bool
        False when an error target was not met (at ``max_vertices``, or
        where the validity checks forbade the nearer choices).
    miss : str
        Why the target was missed, in one line ("" when it was met): the
        vertex cap, or the validity checks, with the repairs by defect
        (:func:`shapes.hullreduce.reduce_hull`'s ``details["why"]``).
    seconds : dict
        Timings of the steps, s: ``check``, ``hull``, ``reduce`` (wall
        clock) and the same with ``_cpu`` (process time); :func:`import_paths`
        adds ``load``.

    Attributes
    ----------
    polyhedron, source, mesh_triangles, mesh_vertices
        The parameters, as given.
    mesh_volume, hull_volume, hull_vertices, d_hull, source_d
        The parameters, as given.
    convexity_deficit, reduction_hausdorff, reduction_volume_change, target_met, miss, seconds
        The parameters, as given.

    Examples
    --------
    A cube of side 2, its triangles split in four, with the centre of its
    top face pushed in by 0.5 (a concave mesh), reduced to its hull's 8
    corners:

    >>> import trimesh
    >>> box = trimesh.creation.box(extents=(2, 2, 2))
    >>> v, t = trimesh.remesh.subdivide(box.vertices, box.faces)
    >>> v[np.all(np.isclose(v, [0, 0, 1]), axis=1)] = [0, 0, 0.5]
    >>> g = import_mesh(v, t, source="dented")
    >>> g.polyhedron.n_vertices, g.mesh_vertices, g.mesh_triangles, g.hull_vertices
    (8, 26, 48, 8)
    >>> round(g.mesh_volume, 9), round(g.hull_volume, 9), round(g.convexity_deficit, 9)
    (7.5, 8.0, 0.0625)
    >>> round(g.d_hull, 6), round(g.reduction_hausdorff, 12), g.target_met      # d = 2 sqrt(3)
    (3.464102, 0.0, True)
    """

    polyhedron: Polyhedron
    source: str
    mesh_triangles: int
    mesh_vertices: int
    mesh_volume: float
    hull_volume: float
    hull_vertices: int
    d_hull: float
    source_d: float
    convexity_deficit: float
    reduction_hausdorff: float
    reduction_volume_change: float
    target_met: bool = True
    miss: str = ""
    seconds: dict = field(default_factory=dict)


# ---------------------------------------------------------------- reading

def read_mesh(path):
    """Read a mesh file as it is stored (no merge, no repair), with
    trimesh's loaders.

    Parameters
    ----------
    path : str
        A ``.stl`` (ASCII or binary), ``.obj``, ``.ply`` or ``.off`` file
        (the extension decides, in any case). A file of several objects
        gives one mesh, their transforms applied. A PLY header whose
        lines end in a bare carriage return (old Mac line ends, as some
        CAD exports write) is read as if they were line feeds.

    Returns
    -------
    vertices : (V, 3) float64
        The file's units. An STL file stores each triangle's corners apart
        (V = 3T): :func:`merge_vertices` joins them.
    triangles : (T, 3) int64
        Vertex indices, as the file orders them.

    Raises
    ------
    ImportRefused
        An unknown extension, a file the parser cannot read, no triangles,
        or faces that are not triangles.

    Examples
    --------
    >>> import os, tempfile, trimesh
    >>> path = os.path.join(tempfile.mkdtemp(), "ball.stl")
    >>> _ = trimesh.creation.icosphere(subdivisions=1).export(path)
    >>> v, t = read_mesh(path)
    >>> v.shape, t.shape, v.dtype, t.dtype
    ((240, 3), (80, 3), dtype('float64'), dtype('int64'))
    >>> read_mesh("grain.xyz")
    Traceback (most recent call last):
    ...
    shapes.meshimport.ImportRefused: unknown format '.xyz' (reads .obj, .off, .ply, .stl)
    """
    import trimesh

    ext = os.path.splitext(path)[1].lower()
    if ext not in FORMATS:
        raise ImportRefused(f"unknown format '{ext or '(no extension)'}' (reads "
                            f"{', '.join(sorted(FORMATS))})")
    source = path
    if FORMATS[ext] == "obj":
        try:
            with open(path, "rb") as fh:
                fault = _obj_index_fault(fh.read())
        except OSError as exc:
            raise ImportRefused(f"unreadable OBJ file ({exc.strerror})") from None
        if fault:
            raise ImportRefused(f"OBJ file: {fault}")
    if FORMATS[ext] == "ply":
        try:
            with open(path, "rb") as fh:
                data = fh.read()
        except OSError as exc:
            raise ImportRefused(f"unreadable PLY file ({exc.strerror})") from None
        fixed = _ply_newlines(data)
        if fixed is not data:
            source = io.BytesIO(fixed)
    try:
        m = trimesh.load(source, file_type=FORMATS[ext], process=False)
        if isinstance(m, trimesh.Scene):          # several objects: one mesh, transforms applied
            m = m.dump(concatenate=True) if m.geometry else None
    except Exception as exc:          # any failure of a foreign parser is one line
        msg = str(exc).strip().splitlines()[0] if str(exc).strip() else exc.__class__.__name__
        raise ImportRefused(f"unreadable {FORMATS[ext].upper()} file ({msg[:120]})") from None
    faces = getattr(m, "faces", None)
    verts = getattr(m, "vertices", None)
    if faces is None or verts is None or len(faces) == 0:
        raise ImportRefused("no triangles in the file (empty, or a point cloud)")
    v = np.asarray(verts, np.float64)
    t = np.asarray(faces, np.int64)
    if t.ndim != 2 or t.shape[1] != 3:
        raise ImportRefused(f"faces are not triangles (shape {t.shape})")
    return v, t


def _obj_index_fault(data):
    """None when every face of the OBJ text ``data`` (bytes) names vertices
    that exist, else what is wrong, by face and line: an index 0 (OBJ
    counts vertices from 1), a positive index past the file's vertices, a
    negative one before the first vertex defined so far, or an index that
    is not a whole number. Lines continued with a backslash are one line.

    >>> _obj_index_fault(b"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\nf -1 -2 -3\\n") is None
    True
    >>> _obj_index_fault(b"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 \\\\\\n 0\\n")
    'face 1 (line 4) names vertex 0; OBJ counts vertices from 1'
    """
    text = data.decode("utf-8", "replace").replace("\r\n", "\n").replace("\r", "\n")
    lines = text.split("\n")
    n_total = sum(1 for x in lines if x.split(None, 1)[:1] == ["v"])
    seen, face, k = 0, 0, 0
    while k < len(lines):
        start, line = k + 1, lines[k]
        while line.rstrip().endswith("\\") and k + 1 < len(lines):   # continued on the next line
            k += 1
            line = line.rstrip()[:-1] + " " + lines[k]
        k += 1
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        if words[0] == "v":
            seen += 1
        elif words[0] == "f":
            face += 1
            for w in words[1:]:
                head = w.split("/", 1)[0]
                try:
                    i = int(head)
                except ValueError:
                    return f"face {face} (line {start}) has the index {head!r}, not a whole number"
                if i == 0:
                    return f"face {face} (line {start}) names vertex 0; OBJ counts vertices from 1"
                if i > n_total:
                    return f"face {face} (line {start}) names vertex {i}; the file has {n_total}"
                if i < 0 and -i > seen:
                    return (f"face {face} (line {start}) names vertex {i}, before the first "
                            f"({seen} defined so far)")
    return None


def _ply_newlines(data):
    """A PLY file's bytes with a header whose lines end in a bare carriage
    return (as some CAD programs write it) rewritten with line feeds; the
    bytes themselves (the same object) when the header has line feeds or
    no ``end_header``. The body (binary or ASCII) is left as it is."""
    end = data.find(b"end_header")
    if end < 0 or b"\r" not in data[:end] or b"\n" in data[:end]:
        return data
    after = end + len(b"end_header")
    tail = data[after + 1:] if data[after:after + 1] == b"\r" else data[after:]
    if tail[:1] == b"\n":
        tail = tail[1:]
    return data[:end].replace(b"\r", b"\n") + b"end_header\n" + tail


def _mix64(x):
    """splitmix64's finaliser on a uint64 array (a bijection that spreads
    every input bit over the output)."""
    x = x ^ (x >> np.uint64(30))
    x = x * np.uint64(0xBF58476D1CE4E5B9)
    x = x ^ (x >> np.uint64(27))
    x = x * np.uint64(0x94D049BB133111EB)
    return x ^ (x >> np.uint64(31))


def merge_vertices(vertices, triangles, tolerance=0.0):
    """Merge vertices with exactly equal coordinates (and, with a
    tolerance, vertices closer than it) and drop triangles left with a
    repeated corner (and vertices no triangle uses).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units (-0.0 and 0.0 count as equal).
    triangles : (T, 3) int
        Vertex indices.
    tolerance : float
        The mesh's units: vertices closer than this are merged too (as
        chains: a vertex within it of one merged with a third joins both),
        each group into its vertex of the lowest index after the exact
        merge (``python -m shapes import --merge-tolerance``). Default 0:
        exact duplicates only.

    Returns
    -------
    vertices : (V', 3) float64
        The distinct vertices used by a triangle, in an order fixed by
        their coordinates.
    triangles : (T', 3) int64
        The triangles without a repeated corner, indices into the merged
        vertices.

    Notes
    -----
    A 64-bit hash of the coordinates' bits groups the rows (one sort of V
    keys rather than of V x 3 floats); every row is then compared with its
    group's representative, and a hash collision falls back to numpy's exact
    row unique, so the result is exact either way.

    Examples
    --------
    A cube stored as an STL stores it, each triangle's corners apart:

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), repeat=3)), float))
    >>> corners = v[t].reshape(-1, 3)
    >>> mv, mt = merge_vertices(corners, np.arange(len(corners)).reshape(-1, 3))
    >>> corners.shape, mv.shape, mt.shape
    ((36, 3), (8, 3), (12, 3))

    A seam: one corner's copies 1e-9 apart, merged by a tolerance.

    >>> corners[0] += 1e-9
    >>> len(merge_vertices(corners, np.arange(36).reshape(-1, 3))[0])
    9
    >>> len(merge_vertices(corners, np.arange(36).reshape(-1, 3), tolerance=1e-6)[0])
    8
    """
    v = np.asarray(vertices, np.float64) + 0.0               # a contiguous copy; -0.0 -> 0.0
    t = np.asarray(triangles, np.int64)
    with np.errstate(over="ignore"):
        bits = v.view(np.uint64)
        h = _mix64(_mix64(_mix64(bits[:, 0]) ^ bits[:, 1]) ^ bits[:, 2])
    order = np.argsort(h)
    hs = h[order]
    start = np.empty(len(hs), bool)
    start[:1] = True
    np.not_equal(hs[1:], hs[:-1], out=start[1:])
    first = order[start]
    inv = np.empty(len(v), np.int64)
    inv[order] = np.cumsum(start) - 1
    if not (bits[first[inv]] == bits).all():          # bitwise: NaN rows compare too
        _, first, inv = np.unique(v, axis=0, return_index=True, return_inverse=True)
        inv = inv.ravel()
    t = inv[t]
    if tolerance > 0 and np.isfinite(v).all():
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import connected_components
        from scipy.spatial import cKDTree

        pairs = cKDTree(v[first]).query_pairs(tolerance, output_type="ndarray")
        if len(pairs):
            m = len(first)
            _, lab = connected_components(coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                                                     shape=(m, m)), directed=False)
            rep = np.full(lab.max() + 1, m)
            np.minimum.at(rep, lab, np.arange(m))
            t = rep[lab][t]
    keep = (t[:, 0] != t[:, 1]) & (t[:, 1] != t[:, 2]) & (t[:, 2] != t[:, 0])
    if not keep.all():
        t = t[keep]
    used = np.zeros(len(first), bool)
    used[t.ravel()] = True
    if used.all():
        return v[first], t
    new = np.cumsum(used) - 1
    return v[first[used]], new[t]


def components(vertices, triangles):
    """The connected pieces of a mesh (triangles sharing a vertex are in
    one piece): what ``python -m shapes import --components`` imports as
    separate grains.

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, merged (:func:`merge_vertices`): pieces that
        share a vertex index are one.
    triangles : (T, 3) int
        Vertex indices.

    Returns
    -------
    list of (vertices, triangles)
        One (V_k, 3) and (T_k, 3) pair per piece, indices local to it,
        largest first by triangle count (ties in the order of the pieces'
        labels); the input itself when it is in one piece.

    Examples
    --------
    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), repeat=3)), float))
    >>> tet = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float) + 5
    >>> both_v = np.vstack([tet, v])
    >>> both_t = np.vstack([[[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]], t + 4])
    >>> [(len(pv), len(pt)) for pv, pt in components(both_v, both_t)]      # the cube first
    [(8, 12), (4, 4)]
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    n = len(vertices)
    t = np.asarray(triangles)
    a, b = np.concatenate([t[:, 0], t[:, 1]]), np.concatenate([t[:, 1], t[:, 2]])
    k, labels = connected_components(coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n)), directed=False)
    if k == 1:
        return [(vertices, t)]
    tl = labels[t[:, 0]]
    out = []
    for c in np.argsort(-np.bincount(tl, minlength=k), kind="stable"):
        sub = t[tl == c]
        used, local = np.unique(sub, return_inverse=True)
        out.append((vertices[used], local.reshape(-1, 3)))
    return out


def piece_artefacts(pieces):
    """Which connected pieces of a mesh are scan artefacts rather than
    grains: an inward-facing shell (signed volume negative, or zero, while
    the largest piece's is positive: e.g. the inner wall of a scan), or a
    sliver (a volume below ``SLIVER_VOLUME`` of the largest piece's, e.g.
    a flap of a few triangles).

    Parameters
    ----------
    pieces : list of (vertices, triangles)
        The pieces (:func:`components`): (V_k, 3) float and (T_k, 3) int
        each, any units.

    Returns
    -------
    list of str or None
        Per piece, None for a grain, or the one-line reason it is an
        artefact. The piece of the largest absolute volume is always a
        grain (a wholly inside-out mesh is turned round later).

    Examples
    --------
    A cube of side 2 (volume 8), the same cube 0.9 times smaller inside it
    facing inwards (an inner shell), and a flap of 4 nearly flat
    triangles:

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(2.0 * np.array(list(itertools.product((0, 1), repeat=3)), float))
    >>> inner = (0.1 + 0.9 * v, t[:, ::-1])
    >>> flap_v = np.array([[5, 0, 0], [6, 0, 0], [5, 1, 0], [6, 1, 0.01], [5.5, 0.5, 0.001]])
    >>> flap = (flap_v, np.array([[0, 1, 4], [1, 3, 4], [3, 2, 4], [2, 0, 4]]))
    >>> for why in piece_artefacts([(v, t), inner, flap]):
    ...     print(why)
    None
    inward-facing shell: signed volume -5.83 against +8 for the largest piece (a scan artefact, e.g. an inner wall)
    sliver: 4 triangles enclosing 0.0004, 5e-05 of the largest piece (a scan artefact)
    """
    vols = np.array([mesh_volume(pv, pt) for pv, pt in pieces])
    ref = int(np.argmax(np.abs(vols)))
    big = vols[ref]
    out = []
    for k, ((pv, pt), vol) in enumerate(zip(pieces, vols)):
        if k == ref or big == 0:
            out.append(None)
        elif vol * np.sign(big) < 0 and abs(vol) >= SLIVER_VOLUME * abs(big):
            out.append(f"inward-facing shell: signed volume {vol * np.sign(big):+.3g} against "
                       f"{abs(big):+.3g} for the largest piece (a scan artefact, e.g. an inner wall)")
        elif abs(vol) < SLIVER_VOLUME * abs(big):
            out.append(f"sliver: {len(pt)} triangles enclosing {abs(vol):.3g}, {abs(vol) / abs(big):.2g} of "
                       "the largest piece (a scan artefact)")
        else:
            out.append(None)
    return out


def mesh_volume(vertices, triangles):
    """The signed volume enclosed by a closed triangle mesh: the divergence
    theorem, the sum of a . (b x c) / 6 over the triangles (a, b, c their
    corners relative to the vertices' mean, for round-off).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units.
    triangles : (T, 3) int
        A closed mesh.

    Returns
    -------
    float
        units^3, positive for outward (counter-clockwise from outside)
        triangles, negative for a mesh inside out.

    Examples
    --------
    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), (0, 1), (0, 2))), float))
    >>> mesh_volume(v, t), mesh_volume(v, t[:, ::-1])
    (2.0, -2.0)
    """
    v = np.asarray(vertices, float)
    v = v - v.mean(axis=0)
    t = np.asarray(triangles)
    a, b, c = v[t[:, 0]].T, v[t[:, 1]].T, v[t[:, 2]].T     # (3, T) each: columns are cheap
    det = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    return float(det.sum() / 6.0)


def check_closed(vertices, triangles):
    """Raise ImportRefused unless the mesh is finite, closed, manifold,
    consistently oriented and in one piece, with a non-zero volume (module
    docstring, step 1).

    One sort of the 3T directed edges, keyed (smaller index, larger index,
    direction), decides the edge conditions: every undirected edge must
    occur exactly twice, once in each direction. Its edges then give the
    connected pieces.

    Parameters
    ----------
    vertices : (V, 3) float
        Merged vertex positions (:func:`merge_vertices`), any units.
    triangles : (T, 3) int
        Vertex indices.

    Returns
    -------
    float
        The signed volume (units^3, :func:`mesh_volume`): positive for
        outward triangles, negative for a mesh inside out as a whole (which
        passes: :func:`import_mesh` turns it round).

    Raises
    ------
    ImportRefused
        With a one-line reason: non-finite coordinates, fewer than 4
        vertices or triangles, an open mesh (boundary edges), a non-manifold
        edge, inconsistent orientation, several pieces, or no volume.

    Examples
    --------
    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), repeat=3)), float))
    >>> check_closed(v, t), check_closed(v, t[:, ::-1])
    (1.0, -1.0)
    >>> check_closed(v, t[1:])
    Traceback (most recent call last):
    ...
    shapes.meshimport.ImportRefused: open mesh: 3 boundary edges (each in one triangle), the boundary's vertices up to 1 from their nearest ...
    """
    v, t = vertices, triangles
    if not np.isfinite(v).all():
        raise ImportRefused(f"{int((~np.isfinite(v).all(axis=1)).sum())} vertices have NaN or "
                            "infinite coordinates")
    if len(v) < 4 or len(t) < 4:
        raise ImportRefused(f"degenerate: {len(v)} distinct vertices and {len(t)} proper triangles "
                            "(a closed solid needs at least 4 of each)")
    n = np.int64(len(v))
    key, und, cut, counts = _edge_counts(t, n)
    if np.any(counts == 1):
        boundary = und[np.concatenate([[0], cut])][counts == 1]
        raise ImportRefused(_topology_cause(v, t, boundary, n) or _open_mesh(v, boundary, n))
    if np.any(counts > 2):
        raise ImportRefused(_topology_cause(v, t) or f"non-manifold: {int((counts > 2).sum())} edges are "
                            "shared by more than two triangles")
    rep = int(np.count_nonzero((key[0::2] & 1) == (key[1::2] & 1)))
    if rep:
        raise ImportRefused(_topology_cause(v, t) or f"inconsistently oriented: {rep} edges run the same way "
                            "in both their triangles (some triangles face inwards)")
    pieces = _count_pieces(und[0::2], n)
    if pieces > 1:
        why = piece_artefacts(components(v, t))
        junk = Counter(w.split(":")[0] for w in why if w)
        listed = ", ".join(f"{c} {k}{'s' if c > 1 else ''}" for k, c in junk.items())
        if len(why) - sum(junk.values()) == 1:
            n_junk = sum(junk.values())
            raise ImportRefused(f"{pieces} separate pieces in one mesh: one grain and {n_junk} scan "
                                f"artefact{'s' if n_junk > 1 else ''} ({listed}); remove "
                                f"{'them' if n_junk > 1 else 'it'} from the mesh (keep its largest piece)")
        raise ImportRefused(f"{pieces} separate pieces in one mesh (import each as a grain with --components"
                            + (f", which refuses the {listed}" if junk else "") + ")")
    vol = mesh_volume(v, t)
    ext = np.ptp(v, axis=0).max()
    # |V| within the round-off of the summed triple products: no volume at all
    if not np.isfinite(vol) or abs(vol) <= 1e-12 * ext ** 3 * max(1.0, len(t) ** 0.5):
        raise ImportRefused(f"no volume: the closed surface encloses {vol:.3g} (units^3), "
                            "a flat or collapsed mesh")
    return vol


def _topology_cause(v, t, boundary=None, n=None):
    """The likely cause of a mesh that is open, non-manifold or
    inconsistently oriented, as the one-line refusal, or "" when none is
    found: float32 coordinates far from the origin (their rounding joins
    vertices), a seam along the boundary edges (``boundary``: their keys
    a * n + b) whose vertices lie closer to one another than
    SEAM_EDGE_FRACTION x the median edge length, named with the
    ``--merge-tolerance`` checked to close it, or pairs of near-duplicate
    vertices (closer than NEAR_DUPLICATE x the median edge length)."""
    from scipy.spatial import cKDTree

    big = float(np.abs(v).max())
    size = float(np.ptp(v, axis=0).max())
    step = float(np.spacing(np.float32(big)))
    if size > 0 and step > FLOAT32_STEP * size and np.array_equal(v.astype(np.float32).astype(np.float64), v):
        return (f"float32 coordinates far from the origin: up to {big:.3g} for a mesh of size {size:.3g}, where "
                f"float32 steps are {step:.2g} ({step / size:.1g} of the size), so nearby vertices were "
                "joined and the surface broken; export it centred at the origin, or in double precision "
                "(OBJ, PLY)")
    e = np.linalg.norm(v[t[:, 0]] - v[t[:, 1]], axis=1)
    tol = NEAR_DUPLICATE * float(np.median(e))
    if boundary is not None and len(boundary):
        dist = _boundary_gaps(v, boundary, n)
        near = dist < SEAM_EDGE_FRACTION * float(np.median(e))
        if near.mean() >= 0.5:
            worst = float(dist[near].max())
            sugg = _tolerance_above(worst) if worst > 0 else tol
            if _closes(v, t, sugg):
                return (f"open mesh along a seam of near-duplicate vertices: {int(near.sum())} of the "
                        f"{len(dist)} boundary vertices lie within {worst:.2g} of another ({worst / size:.1g} of "
                        f"the mesh's size), unjoined; merge them with --merge-tolerance {sugg:g} (the mesh's "
                        "units), which closes it")
        return ""
    pairs = cKDTree(v).query_pairs(tol, output_type="ndarray")
    if len(pairs):
        worst = float(np.linalg.norm(v[pairs[:, 0]] - v[pairs[:, 1]], axis=1).max())
        sugg = float(f"{2 * worst:.0e}") if worst > 0 else tol
        return (f"{len(pairs)} pairs of near-duplicate vertices (within {worst:.2g}, {worst / size:.1g} of the mesh's "
                f"size) break the surface; merge them with --merge-tolerance {sugg:g} (the mesh's units)")
    return ""


def _edge_counts(t, n):
    """The edges of triangles ``t`` (T, 3) on ``n`` vertices: ``key`` (3T,)
    sorted, each undirected edge a * n + b (a < b) doubled plus 1 where the
    triangle runs a -> b; ``und`` = key >> 1; ``cut``, the starts of each
    distinct edge's run after the first; ``counts``, the triangles of each
    distinct edge (1: a boundary edge, 2: manifold)."""
    i = t.T.ravel()
    j = t[:, [1, 2, 0]].T.ravel()
    key = np.sort((np.minimum(i, j) * n + np.maximum(i, j)) * 2 + (i < j))
    und = key >> 1
    cut = np.flatnonzero(und[1:] != und[:-1]) + 1
    counts = np.diff(np.concatenate([[0], cut, [len(und)]]))
    return key, und, cut, counts


def _boundary_gaps(v, boundary, n):
    """(B,) distance (the mesh's units) from each of the B vertices of the
    boundary edges ``boundary`` (keys a * n + b) to the nearest other
    boundary vertex: across a seam, the width of the seam there."""
    from scipy.spatial import cKDTree

    ends = np.unique(np.concatenate([boundary // n, boundary % n]))
    return cKDTree(v[ends]).query(v[ends], k=2)[0][:, 1]


def _tolerance_above(width):
    """The smallest number of one significant digit 1, 2 or 5 at or above
    1.5 x ``width``: a merge tolerance that joins vertices ``width`` apart,
    with a margin of half that width."""
    exp = np.floor(np.log10(1.5 * width))
    return next(float(f"{m * 10.0 ** exp:.0e}") for m in (1, 2, 5, 10) if m * 10.0 ** exp >= 1.5 * width)


def _closes(v, t, tolerance):
    """True when merging the vertices of the mesh (v, t) closer than
    ``tolerance`` (:func:`merge_vertices`) leaves a surface without
    boundary edges of at least 4 triangles."""
    mv, mt = merge_vertices(v, t, tolerance)
    return len(mt) >= 4 and not np.any(_edge_counts(mt, np.int64(len(mv)))[3] == 1)


def _open_mesh(v, boundary, n):
    """The one-line refusal of an open mesh whose cause
    :func:`_topology_cause` did not name (no seam that a merge closes): how
    many boundary edges (``boundary``, keys a * n + b) and how far the
    boundary's vertices lie from their nearest, the tolerance a merge would
    need."""
    widest, size = float(_boundary_gaps(v, boundary, n).max()), float(np.ptp(v, axis=0).max())
    return (f"open mesh: {len(boundary)} boundary edges (each in one triangle), the boundary's vertices up to "
            f"{widest:.2g} from their nearest ({widest / size:.1g} of the mesh's size); a grain must be a "
            "closed surface")


def _count_pieces(edge_keys, n):
    """Connected components of the graph on n vertices whose edges are the
    sorted keys a * n + b (a < b): the keys sorted by a are a CSR matrix as
    they stand."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components

    a = edge_keys // n
    indptr = np.concatenate([[0], np.cumsum(np.bincount(a, minlength=n))])
    g = csr_matrix((np.ones(len(edge_keys), np.int8), edge_keys % n, indptr), shape=(n, n))
    return connected_components(g, directed=False)[0]


# ---------------------------------------------------------------- one grain

def import_mesh(vertices, triangles, budget=None, source="", merge_tolerance=0.0):
    """One closed mesh to a library grain: checked, its hull reduced,
    measured and normalised (module docstring, steps 1-5).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units; duplicates (as an STL stores them) are
        merged here.
    triangles : (T, 3) int
        Vertex indices; a mesh inside out as a whole is turned round.
    budget : Budget, optional
        The reduction's budget (default ``Budget()``: within 0.02 d_hull,
        at most 37 vertices).
    source : str
        The grain's name, kept in the result.
    merge_tolerance : float
        The mesh's units: vertices closer than this are merged
        (:func:`merge_vertices`; default 0, exact duplicates only).

    Returns
    -------
    ImportedGrain
        The normalised polyhedron (d = 1) and the measures of the import.

    Raises
    ------
    ImportRefused
        With a one-line reason: the mesh fails :func:`check_closed`, its
        hull is flat, or no valid polyhedron comes out of the reduction.

    Examples
    --------
    A geodesic sphere of 320 triangles (d = 2): the default budget stops
    at 37 vertices, above the error target.

    >>> import trimesh
    >>> ball = trimesh.creation.icosphere(subdivisions=2)
    >>> g = import_mesh(ball.vertices, ball.faces, source="ball")
    >>> g.source, g.mesh_triangles, g.hull_vertices, g.polyhedron.n_vertices, round(g.polyhedron.size, 12)
    ('ball', 320, 162, 37, 1.0)
    >>> round(g.d_hull, 6), round(g.reduction_hausdorff, 3), g.target_met, round(g.reduction_volume_change, 3)
    (2.0, 0.049, False, -0.137)
    """
    budget = budget or Budget()
    sec = {}
    t0, p0 = time.perf_counter(), time.process_time()
    v, t = merge_vertices(vertices, triangles, merge_tolerance)
    if not np.isfinite(v).all():
        raise ImportRefused(f"{int((~np.isfinite(v).all(axis=1)).sum())} vertices have NaN or "
                            "infinite coordinates")
    vol = check_closed(v, t)
    if vol < 0:                                    # inside-out as a whole: turn round
        t = t[:, [0, 2, 1]]
        vol = -vol
    sec["check"], sec["check_cpu"] = time.perf_counter() - t0, time.process_time() - p0
    t0, p0 = time.perf_counter(), time.process_time()
    c0 = v.mean(axis=0)
    scale = float(np.ptp(v, axis=0).max())
    hq = _hull_of((v - c0) / scale)
    if hq is None:
        raise ImportRefused("degenerate: all vertices on a plane or a line (the hull has no "
                            "volume)")
    hv = v[hq[0]]
    hull_volume, com = _volume_and_centre(hv, hq[1])
    d_hull = 2 * float(np.max(np.linalg.norm(hv - com, axis=1)))
    sec["hull"], sec["hull_cpu"] = time.perf_counter() - t0, time.process_time() - p0
    t0, p0 = time.perf_counter(), time.process_time()
    try:
        info = {}
        idx, rt, err, met = reduce_hull(hv, budget, d=d_hull, details=info)
        rv = hv[idx]
        check_polyhedron(rv, rt)
        poly = normalise(rv - rv.mean(axis=0), rt)      # centred first: no cancellation far from the origin
    except ShapeError as exc:
        raise ImportRefused(f"no valid library polyhedron: {exc}") from None
    sec["reduce"], sec["reduce_cpu"] = time.perf_counter() - t0, time.process_time() - p0
    reduced_volume, rcom = _volume_and_centre(rv, rt)
    return ImportedGrain(polyhedron=poly, source=source, mesh_triangles=len(t), mesh_vertices=len(v),
                         mesh_volume=vol, hull_volume=hull_volume, hull_vertices=len(hv), d_hull=d_hull,
                         source_d=2 * float(np.max(np.linalg.norm(rv - rcom, axis=1))),
                         convexity_deficit=max(0.0, 1 - vol / hull_volume),
                         reduction_hausdorff=err, reduction_volume_change=reduced_volume / hull_volume - 1,
                         target_met=bool(met), miss=info.get("why") or "", seconds=sec)


def _volume_and_centre(v, t):
    """Volume (units^3) and centre of mass (3,) of a closed outward mesh of
    uniform density (signed tetrahedra from the vertices' mean)."""
    c = v.mean(axis=0)
    a, b, e = v[t[:, 0]] - c, v[t[:, 1]] - c, v[t[:, 2]] - c
    w = np.einsum("ij,ij->i", a, np.cross(b, e)) / 6.0
    vol = float(w.sum())
    return vol, c + (w[:, None] * (a + b + e)).sum(axis=0) / (4.0 * vol)


# ---------------------------------------------------------------- files

def mesh_files(path):
    """The mesh files a command-line argument names: the file itself, or a
    folder's files with a known extension (sorted, not recursive).

    Parameters
    ----------
    path : str
        A file (any extension: :func:`read_mesh` decides) or a folder.

    Returns
    -------
    files : list of str
        The file, or the folder's files with an extension of ``FORMATS``
        (any case), sorted by name.
    ignored : int
        The folder's other entries (0 for a file).

    Raises
    ------
    ImportRefused
        A path that does not exist, or a folder without mesh files.

    Examples
    --------
    >>> import tempfile
    >>> folder = tempfile.mkdtemp()
    >>> for name in ("b.STL", "a.obj", "notes.txt"):
    ...     open(os.path.join(folder, name), "w").close()
    >>> files, ignored = mesh_files(folder)
    >>> [os.path.basename(f) for f in files], ignored
    (['a.obj', 'b.STL'], 1)
    """
    if os.path.isdir(path):
        names = sorted(os.listdir(path))
        files = [os.path.join(path, n) for n in names
                 if os.path.splitext(n)[1].lower() in FORMATS and os.path.isfile(os.path.join(path, n))]
        if not files:
            raise ImportRefused(f"no {', '.join(sorted(FORMATS))} file in this folder"
                                + (f" ({len(names)} other entries)" if names else " (empty)"))
        return files, len(names) - len(files)
    if not os.path.exists(path):
        raise ImportRefused("no such file or folder")
    return [path], 0


def import_paths(paths, budget=None, split=False, log=None, merge_tolerance=0.0):
    """Import every mesh named by files and folders (what ``python -m
    shapes import`` runs). Nothing raises for a bad file: it is refused and
    the others go on.

    Parameters
    ----------
    paths : list of str
        Files and folders (:func:`mesh_files`).
    budget : Budget, optional
        The reduction's budget (default ``Budget()``).
    split : bool
        Each connected piece of a file is a grain, named ``file#k`` (k = 0
        the largest; :func:`components`), except the pieces that are scan
        artefacts (:func:`piece_artefacts`: inward-facing shells and
        slivers), refused with their reason. Default False: one file, one
        grain.
    log : callable, optional
        ``log(name, reason)`` is called at each refusal as it happens.
    merge_tolerance : float
        The meshes' units: vertices closer than this are merged
        (:func:`merge_vertices`; default 0, exact duplicates only).

    Returns
    -------
    grains : list of ImportedGrain
        The imported grains, in the order of the paths and files.
    refused : list of (str, str)
        (name, one-line reason) of every path, file or piece refused.
    ignored : int
        The count of non-mesh files in the folders.

    Examples
    --------
    A folder with a sphere, a cube, a broken file and a note:

    >>> import tempfile, trimesh
    >>> folder = tempfile.mkdtemp()
    >>> _ = trimesh.creation.icosphere(subdivisions=1).export(os.path.join(folder, "ball.stl"))
    >>> _ = trimesh.creation.box().export(os.path.join(folder, "cube.obj"))
    >>> with open(os.path.join(folder, "broken.off"), "w") as fh:
    ...     _ = fh.write("not a mesh")
    >>> open(os.path.join(folder, "notes.txt"), "w").close()
    >>> grains, refused, ignored = import_paths([folder, "missing.stl"])
    >>> [(os.path.basename(g.source), g.polyhedron.n_vertices) for g in grains], ignored
    ([('ball.stl', 30), ('cube.obj', 8)], 1)
    >>> [(os.path.basename(name), reason[:18]) for name, reason in refused]
    [('broken.off', 'unreadable OFF fil'), ('missing.stl', 'no such file or fo')]
    """
    budget = budget or Budget()
    grains, refused, ignored = [], [], 0

    def refuse(name, reason):
        refused.append((name, reason))
        if log:
            log(name, reason)

    for arg in paths:
        try:
            files, n_ignored = mesh_files(arg)
            ignored += n_ignored
        except ImportRefused as exc:
            refuse(arg, str(exc))
            continue
        for f in files:
            t0 = time.perf_counter()
            try:
                v, t = read_mesh(f)
            except ImportRefused as exc:
                refuse(f, str(exc))
                continue
            load = time.perf_counter() - t0
            if split:
                try:
                    mv, mt = merge_vertices(v, t, merge_tolerance)
                    if not np.isfinite(mv).all():
                        raise ImportRefused(f"{int((~np.isfinite(mv).all(axis=1)).sum())} vertices have "
                                            "NaN or infinite coordinates")
                    pieces = components(mv, mt)
                except ImportRefused as exc:
                    refuse(f, str(exc))
                    continue
                why = piece_artefacts(pieces) if len(pieces) > 1 else [None]
                named = []
                for k, ((pv, pt), w) in enumerate(zip(pieces, why)):
                    if w:
                        refuse(f"{f}#{k}", w)
                    else:
                        named.append((f"{f}#{k}", pv, pt))
            else:
                named = [(f, v, t)]
            for name, pv, pt in named:
                try:
                    g = import_mesh(pv, pt, budget, source=name, merge_tolerance=merge_tolerance)
                except ImportRefused as exc:
                    refuse(name, str(exc))
                    continue
                g.seconds["load"] = load / len(named)
                grains.append(g)
    return grains, refused, ignored


def library_datasets(grains):
    """The per-grain datasets an imported library stores (the library file's
    module docstring, :mod:`shapes.library`), from the import's grains.

    Parameters
    ----------
    grains : list of ImportedGrain
        What :func:`import_paths` returned.

    Returns
    -------
    dict
        name -> (S,) array or list: ``source``, ``source_d``,
        ``source_d_hull``, ``mesh_triangles``, ``hull_vertices``,
        ``convexity_deficit``, ``reduction_hausdorff``,
        ``reduction_volume_change``; the ``extra`` of
        :func:`shapes.library.write_library`.
    """
    return {"source": [g.source for g in grains],
            "source_d": np.array([g.source_d for g in grains]),
            "source_d_hull": np.array([g.d_hull for g in grains]),
            "mesh_triangles": np.array([g.mesh_triangles for g in grains], np.int64),
            "hull_vertices": np.array([g.hull_vertices for g in grains], np.int64),
            "convexity_deficit": np.array([g.convexity_deficit for g in grains]),
            "reduction_hausdorff": np.array([g.reduction_hausdorff for g in grains]),
            "reduction_volume_change": np.array([g.reduction_volume_change for g in grains])}


def mixed_units(sizes):
    """A warning when a library's sizes in their files' units fall in
    clusters about 10, 100 or 1000 times apart: files that mix metres,
    centimetres and millimetres.

    The sorted log10 sizes are cut where consecutive ones differ by more
    than half a decade (a factor 3.2); the clusters' median sizes are
    then compared, and a ratio within a factor 10^0.25 (1.8) of 10, 100
    or 1000 is a warning.

    Parameters
    ----------
    sizes : (n,) float
        The grains' sizes in their files' units (``source_d``), > 0.

    Returns
    -------
    str
        One line naming the clusters (count, median size) and their
        ratio, or "" when the sizes do not fall so.

    Examples
    --------
    >>> print(mixed_units([41.0, 38.5, 45.2, 0.040, 0.043, 39.9]))
    sizes in the files fall in clusters about 1000x apart (2 grains near 0.0415, 4 near 40.4): the files
    may mix units (m, cm, mm); the grains are normalised to d = 1 but source_d is in each file's units
    >>> mixed_units([41.0, 38.5, 12.0, 70.0])
    ''
    """
    s = np.log10(np.asarray(sizes, float))
    s = np.sort(s[np.isfinite(s)])
    if len(s) < 2:
        return ""
    groups = np.split(s, np.flatnonzero(np.diff(s) > 0.5) + 1)
    if len(groups) < 2:
        return ""
    med = [float(np.median(g)) for g in groups]
    apart = [med[k + 1] - med[k] for k in range(len(med) - 1)]
    near = [a for a in apart if round(a) in (1, 2, 3) and abs(a - round(a)) <= 0.25]
    if not near:
        return ""
    ratio = "/".join(f"{10 ** k:d}x" for k in sorted({round(a) for a in near}))
    parts = ", ".join(f"{len(g)} grain{'s' if len(g) > 1 else ''} near {10 ** m:.3g}" if k == 0 else
                      f"{len(g)} near {10 ** m:.3g}" for k, (g, m) in enumerate(zip(groups, med)))
    return (f"sizes in the files fall in clusters about {ratio} apart ({parts}): the files may mix units "
            "(m, cm, mm); the grains are normalised to d = 1 but source_d is in each file's units")
