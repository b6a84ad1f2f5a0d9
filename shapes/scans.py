"""Synthetic scans of generated grains, to try and to calibrate the import
of scanned grains (``python -m shapes import``, :mod:`shapes.meshimport`).

::

    python -m shapes.scans --write-scans DIR [--n 40]
    python -m shapes.scans --calibrate [--n 40]

A scan (:func:`scan_mesh`) is a generated grain ray-cast from its centre onto
the vertices of an icosphere (a dense mesh of its flat faces and sharp
edges), with radial scanner noise (0.1 % of d, uniform) and three dents
(Gaussian, 3 % of d deep): non-convex, with a hull of a few percent of its
vertices.

``--write-scans DIR`` writes ``--n`` scans of generated grains (seed 11,
20 480 triangles each, d = 40 mm) as binary STL into DIR, to try the import
on. ``--calibrate`` is the default error target's calibration
(:func:`calibrate`): ``--n`` scans of generated grains (seed 3, their vertex
counts known), imported at several error targets, the vertex counts found
against the grains' own; then three noisy ellipsoids at the default budget.
(The import's speed is timed by ``benchmarks/bench_import.py``.)
"""
from __future__ import annotations

import argparse
import os
import sys

import numpy as np

from shapes.generate import generate_library
from shapes.hullreduce import Budget
from shapes.meshimport import import_mesh
from shapes.polyhedron import triangle_normals


def ray_cast_convex(directions, vertices, triangles):
    """Distances from the origin to the surface of a convex polyhedron
    along given directions.

    Parameters
    ----------
    directions : ndarray, shape (M, 3)
        Unit directions.
    vertices : ndarray, shape (V, 3)
        The polyhedron's vertices (the origin inside).
    triangles : ndarray of int, shape (T, 3)
        Its outward triangles.

    Returns
    -------
    ndarray, shape (M,)
        min over the faces facing each ray of offset / (n . u), in the
        vertices' unit.
    """
    n, _ = triangle_normals(vertices, triangles)
    off = np.einsum("ij,ij->i", n, vertices[triangles[:, 0]])      # > 0: origin inside
    out = np.empty(len(directions))
    for s in range(0, len(directions), 65536):
        c = directions[s:s + 65536] @ n.T
        with np.errstate(divide="ignore"):
            out[s:s + 65536] = np.where(c > 1e-12, off / c, np.inf).min(axis=1)
    return out


def scan_mesh(poly, subdivisions, noise=1e-3, dents=3, depth=0.03, rng=None):
    """A synthetic scan of a convex grain.

    Parameters
    ----------
    poly : shapes.polyhedron.Polyhedron
        The grain, d = 1.
    subdivisions : int
        Of the icosphere: 20 x 4^subdivisions triangles.
    noise : float
        Uniform radial noise, +-noise (units of d).
    dents : int
        Gaussian dents, width 0.25 rad.
    depth : float
        Their depth (units of d).
    rng : numpy.random.Generator, optional
        Draws the dents and the noise (default seed 0).

    Returns
    -------
    tuple of ndarray
        (vertices (V, 3), triangles (T, 3)) of the scan.
    """
    import trimesh

    rng = rng or np.random.default_rng(0)
    s = trimesh.creation.icosphere(subdivisions=subdivisions)
    u = s.vertices / np.linalg.norm(s.vertices, axis=1)[:, None]
    r = ray_cast_convex(u, poly.vertices, poly.triangles)
    for _ in range(dents):
        c = rng.normal(size=3)
        c /= np.linalg.norm(c)
        r -= depth * np.exp(-np.sum((u - c) ** 2, axis=1) / 0.25 ** 2)
    r += noise * rng.uniform(-1, 1, len(r))
    return u * r[:, None], np.asarray(s.faces)


def smooth_mesh(subdivisions, axes=(1.0, 0.75, 0.5)):
    """An ellipsoid without noise: every vertex on its hull.

    Parameters
    ----------
    subdivisions : int
        Of the icosphere: 20 x 4^subdivisions triangles.
    axes : tuple of float
        Its semi-axes.

    Returns
    -------
    tuple of ndarray
        (vertices (V, 3), triangles (T, 3)).
    """
    import trimesh

    s = trimesh.creation.icosphere(subdivisions=subdivisions)
    return np.asarray(s.vertices) * np.asarray(axes), np.asarray(s.faces)


def write_stl(path, v, t):
    """Write a mesh as binary STL.

    Parameters
    ----------
    path : str
        The .stl file.
    v : ndarray, shape (V, 3)
        Vertices.
    t : ndarray of int, shape (T, 3)
        Triangles.

    Returns
    -------
    None
    """
    import trimesh

    trimesh.Trimesh(v, t, process=False).export(path)


def write_scans(folder, n=40):
    """Synthetic scans to try the import on.

    Parameters
    ----------
    folder : str
        Made if missing; receives ``stone000.stl``, ...
    n : int
        Scans: generated grains (seed 11), 20 480 triangles each, scaled to
        d = 40 mm.

    Returns
    -------
    list of str
        The files written.
    """
    os.makedirs(folder, exist_ok=True)
    rng = np.random.default_rng(11)
    out = []
    for k, g in enumerate(generate_library(n, seed=11)[0]):
        v, t = scan_mesh(g, 5, rng=rng)
        out.append(os.path.join(folder, f"stone{k:03d}.stl"))
        write_stl(out[-1], v * 40.0, t)   # d = 40 mm
    return out


def calibrate(n, targets=(0.01, 0.015, 0.02, 0.03, 0.05)):
    """Scans of n generated grains (their vertex counts known: the paper's
    8-37, mean 20), imported at each error target: the mean count found,
    its correlation with the true count, the errors and the misses; then
    three ellipsoids with 0.1 % noise at the default budget. Printed.

    Parameters
    ----------
    n : int
        Grains (seed 3), each scanned at 20 480 triangles.
    targets : sequence of float
        Error targets (``--max-error``, units of d).

    Returns
    -------
    None
    """
    shapes = generate_library(n, seed=3)[0]
    rng = np.random.default_rng(0)
    meshes = [scan_mesh(s, 5, rng=rng) for s in shapes]
    true = np.array([s.n_vertices for s in shapes])
    print(f"{n} generated grains: vertices {true.min()}-{true.max()}, mean {true.mean():.1f}")
    for e in targets:
        gs = [import_mesh(v, t, Budget(max_error=e)) for v, t in meshes]
        nv = np.array([g.polyhedron.n_vertices for g in gs])
        err = np.array([g.reduction_hausdorff for g in gs])
        print(f"max error {e:<5g}: vertices {nv.min()}-{nv.max()}, mean {nv.mean():.1f}, correlation with the "
              f"true counts {np.corrcoef(nv, true)[0, 1]:.2f}; error median {np.median(err):.4f} d, max "
              f"{err.max():.4f} d; target missed {sum(not g.target_met for g in gs)}; volume change mean "
              f"{np.mean([g.reduction_volume_change for g in gs]):+.3f}", flush=True)
    axes = [(1.0, e, e * f) for e, f in ((0.6, 0.6), (0.75, 0.7), (0.9, 0.85))]
    for a in axes:
        v, t = smooth_mesh(5, a)
        g = import_mesh(v * (1 + 1e-3 * rng.uniform(-1, 1, (len(v), 1))), t, Budget())
        print(f"ellipsoid {a[0]:.2f} : {a[1]:.2f} : {a[2]:.2f} with 0.1 % noise, default budget: "
              f"{g.polyhedron.n_vertices} vertices, error {g.reduction_hausdorff:.4f} d")


def main(argv=None):
    """The command (see the module docstring).

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        0.
    """
    ap = argparse.ArgumentParser(prog="python -m shapes.scans", description=__doc__.splitlines()[0])
    what = ap.add_mutually_exclusive_group(required=True)
    what.add_argument("--write-scans", metavar="DIR",
                      help="write --n synthetic scans of generated grains (seed 11, 20 480 triangles each) "
                           "as binary STL into DIR, to try the import on")
    what.add_argument("--calibrate", action="store_true",
                      help="the default error target's calibration: --n scans of generated grains (seed 3, "
                           "20 480 triangles each) imported at several error targets, the vertex counts "
                           "found against the grains' own")
    ap.add_argument("--n", type=int, default=40)
    args = ap.parse_args(argv)
    if args.calibrate:
        calibrate(args.n)
        return 0
    write_scans(args.write_scans, args.n)
    print(f"shapes.scans: {args.n} scans in {args.write_scans}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
