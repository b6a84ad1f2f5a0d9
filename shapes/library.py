"""The shape library file: HDF5, readable with numpy + h5py alone (the YADE
scene scripts load it on Debian's system Python).

Layout (``schema`` = "ballast-shape-library", ``schema_version`` = 1):

file attributes  ``seed``, ``n_shapes``, ``recipe`` (JSON), ``tolerances``
                 (JSON), ``created_by``
``vertex_offsets``    (S+1,) int64  shape s owns vertices[vo[s]:vo[s+1]]
``vertices``          (V, 3) float64  in the normalised frame: centre of
                      mass at the origin, principal axes (x long), d = 1
``triangle_offsets``  (S+1,) int64
``triangles``         (T, 3) int32  local vertex indices, counter-clockwise
                      seen from outside
``triangle_face``     (T,) int32  geometric face of each triangle
``volume``            (S,) float64  d^3 (d = 1)
``inertia``           (S, 3, 3) float64  about the centre of mass, unit
                      density, d^5 (diagonal in this frame)
``dims``              (S, 3) float64  extents along the principal axes,
                      L >= I >= S
``sphericity``        (S,) float64  Wadell's
``n_vertices``, ``n_faces``, ``n_edges``  (S,) int32  geometric counts

Libraries imported from meshes (``python -m shapes import``, see
:mod:`shapes.meshimport`) also hold, per grain (S,):

``source``                   str  the file (``file#k``: its k-th piece)
``source_d``                 float64  d in the mesh file's units (the reduced grain's)
``source_d_hull``            float64  d of the mesh's full convex hull, same units
``mesh_triangles``           int64  triangles of the mesh (after the merge)
``hull_vertices``            int64  vertices of the mesh's convex hull
``convexity_deficit``        float64  1 - V_mesh / V_hull
``reduction_hausdorff``      float64  Hausdorff distance reduced-full hull / d_hull
``reduction_volume_change``  float64  V_reduced / V_hull - 1

and the file attribute ``name`` (every library written here has one). The
real-stone library (:mod:`shapes.stones`) adds ``licence`` (str) per grain
and the file attributes ``origin``, ``commit``, ``licence`` and ``refused``.
Any per-grain dataset of strings is stored as HDF5 strings (read as bytes);
``seed`` is -1 for an imported library. Readers ignore datasets they do not
know, so these stay within version 1.

A body of size d (m) and density rho (kg/m^3) has vertices d * v (m), volume
d^3 * volume (m^3), mass rho * d^3 * volume and inertia rho * d^5 * inertia.
"""
from __future__ import annotations

import json
import os

import h5py
import numpy as np

SCHEMA = "ballast-shape-library"
VERSION = 1


class LibraryError(ValueError):
    """A shape library file that cannot be read."""


def write_library(path, shapes, seed, recipe, tolerances, name=None, created_by="python -m shapes build",
                  extra=None):
    """Write a shape library (module docstring) atomically: to
    ``path + ".tmp"``, then renamed to ``path``, so a reader never sees a
    half-written file.

    Parameters
    ----------
    path : str
        The file to write (its folder must exist); an existing file is
        replaced.
    shapes : list of shapes.polyhedron.Polyhedron
        In the normalised frame, d = 1 (:func:`shapes.polyhedron.normalise`).
    seed : int
        The generator's seed (-1 for imported stones).
    recipe, tolerances : dict
        How the shapes were made and checked (stored as JSON).
    name : str, optional
        The library's name (default: the file's stem).
    created_by : str
        The command that made it.
    extra : dict, optional
        Per-shape datasets, name -> (S,) array (module docstring); a
        dataset without one row per shape raises ValueError.

    Returns
    -------
    None

    Raises
    ------
    LibraryError
        The file cannot be written (no such folder, no permission, disk
        full): one line naming it; no ``.tmp`` file is left behind.

    Examples
    --------
    Two grains with a per-grain dataset, read back with
    :class:`ShapeLibrary`:

    >>> import tempfile
    >>> from shapes.generate import generate_library
    >>> grains, _ = generate_library(2, seed=0)
    >>> path = os.path.join(tempfile.mkdtemp(), "two.h5")
    >>> write_library(path, grains, seed=0, recipe={"n": 2}, tolerances={},
    ...               extra={"source": ["a.stl", "b.stl"], "source_d": np.array([0.04, 0.05])})
    >>> lib = ShapeLibrary(path)
    >>> len(lib), lib.name, lib.attrs["seed"], json.loads(lib.attrs["recipe"])
    (2, 'two', 0, {'n': 2})
    >>> lib.source_d.tolist(), bool(np.array_equal(lib[1][0], grains[1].vertices))
    ([0.04, 0.05], True)
    """
    tmp = str(path) + ".tmp"
    name = name or os.path.splitext(os.path.basename(str(path)))[0]
    try:
        _write_tmp(tmp, shapes, seed, recipe, tolerances, name, created_by, extra)
        os.replace(tmp, path)
    except OSError as exc:
        if os.path.exists(tmp):
            os.remove(tmp)
        why = exc.strerror or str(exc).split("(")[0].strip() or exc.__class__.__name__
        raise LibraryError(f"{path}: cannot write the library ({why})") from None


def _write_tmp(tmp, shapes, seed, recipe, tolerances, name, created_by, extra):
    """:func:`write_library`'s file, written to ``tmp``."""
    with h5py.File(tmp, "w") as f:
        f.attrs.update({"schema": SCHEMA, "schema_version": VERSION, "seed": int(seed),
                        "n_shapes": len(shapes), "recipe": json.dumps(recipe),
                        "tolerances": json.dumps(tolerances), "name": name,
                        "created_by": created_by})
        for k, x in (extra or {}).items():
            if len(x) != len(shapes):
                raise ValueError(f"extra dataset {k} has {len(x)} rows for {len(shapes)} shapes")
            if k == "source" or (len(x) and isinstance(x[0], str)):
                f.create_dataset(k, data=np.array([str(s) for s in x], dtype=object),
                                 dtype=h5py.string_dtype())
            else:
                f[k] = np.asarray(x)
        f["vertex_offsets"] = np.concatenate([[0], np.cumsum([s.n_vertices for s in shapes])]).astype(np.int64)
        f["triangle_offsets"] = np.concatenate([[0], np.cumsum([len(s.triangles) for s in shapes])]).astype(np.int64)
        f["vertices"] = np.concatenate([s.vertices for s in shapes])
        f["triangles"] = np.concatenate([s.triangles for s in shapes]).astype(np.int32)
        f["triangle_face"] = np.concatenate([s.triangle_face for s in shapes]).astype(np.int32)
        f["volume"] = np.array([s.volume for s in shapes])
        f["inertia"] = np.array([s.inertia for s in shapes])
        f["dims"] = np.array([s.dims for s in shapes])
        f["sphericity"] = np.array([s.sphericity for s in shapes])
        for k in ("n_vertices", "n_faces", "n_edges"):
            f[k] = np.array([getattr(s, k) for s in shapes], np.int32)


class ShapeLibrary:
    """Read-only access to a library file (module docstring): ``lib[s]``
    gives shape s, and ``lib.volume``, ``lib.inertia``, ``lib.dims`` ...
    every dataset of the file, one row per shape.

    Parameters
    ----------
    path : str
        The library (``make shapes`` builds ``shapes/library.h5``;
        ``python -m shapes import`` makes one from scanned stones). A
        missing or unreadable file raises :class:`LibraryError` (one line).

    Attributes
    ----------
    path : str
        The file.
    attrs : dict
        Its attributes (seed, n_shapes, recipe, tolerances, name, ...).
    data : dict
        Its datasets, name -> array.

    Examples
    --------
    >>> import itertools, tempfile
    >>> from shapes.polyhedron import polyhedron_from_points
    >>> box = polyhedron_from_points(np.array(list(itertools.product((0, 1), (0, 1), (0, 2))), float))
    >>> path = os.path.join(tempfile.mkdtemp(), "box.h5")
    >>> write_library(path, [box], seed=0, recipe={}, tolerances={})
    >>> lib = ShapeLibrary(path)
    >>> vertices, triangles, faces = lib[0]                 # d = 1: 2 x the largest centre-vertex distance
    >>> len(lib), vertices.shape, triangles.shape, int(faces.max()) + 1, lib.name
    (1, (8, 3), (12, 3), 6, 'box')
    >>> lib.dims[0].round(4)                                 # L >= I >= S along the principal axes
    array([0.8165, 0.4082, 0.4082])
    """

    def __init__(self, path):
        if not os.path.exists(path):
            raise LibraryError(f"{path}: no such shape library (build it with 'make shapes')")
        try:
            with h5py.File(path, "r") as f:
                if f.attrs.get("schema") != SCHEMA or int(f.attrs.get("schema_version", -1)) != VERSION:
                    raise LibraryError(f"{path}: not a {SCHEMA} v{VERSION} file")
                self.attrs = {k: (v.item() if hasattr(v, "item") else v) for k, v in f.attrs.items()}
                self.data = {k: f[k][()] for k in f.keys()}
        except OSError as exc:
            raise LibraryError(f"{path}: unreadable ({exc.__class__.__name__})") from None
        self.path = path

    @property
    def name(self):
        """The library's name: its ``name`` attribute, else (older files)
        what built it (str)."""
        return str(self.attrs.get("name") or f"generated, seed {self.attrs.get('seed')}")

    def __len__(self):
        return len(self.data["volume"])

    def __getitem__(self, s):
        vo, to = self.data["vertex_offsets"], self.data["triangle_offsets"]
        return (self.data["vertices"][vo[s]:vo[s + 1]],
                self.data["triangles"][to[s]:to[s + 1]],
                self.data["triangle_face"][to[s]:to[s + 1]])

    def __getattr__(self, name):
        try:
            return self.__dict__["data"][name]
        except KeyError:
            raise AttributeError(name) from None
