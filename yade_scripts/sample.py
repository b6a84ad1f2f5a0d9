"""Drawing a sample: sizes, shapes, orientations and non-overlapping initial
positions. numpy only (runs inside YADE on the system Python).
"""
from __future__ import annotations

import numpy as np


def random_quaternions(n, rng):
    """(n, 4) unit quaternions (w, x, y, z) uniform over rotations (Shoemake)."""
    u1, u2, u3 = rng.random((3, n))
    a, b = np.sqrt(1 - u1), np.sqrt(u1)
    return np.column_stack([b * np.cos(2 * np.pi * u3), a * np.sin(2 * np.pi * u2),
                            a * np.cos(2 * np.pi * u2), b * np.sin(2 * np.pi * u3)])


def box_for(diameters, solid_fraction, aspect=2.0):
    """Box lengths (3,) m with a square base of side L and height aspect * L
    whose volume holds the bounding spheres of ``diameters`` (m) at the given
    sphere packing fraction."""
    v = np.sum(np.pi / 6 * np.asarray(diameters, float) ** 3) / solid_fraction
    L = (v / aspect) ** (1 / 3)
    return np.array([L, L, aspect * L])


def place_spheres(diameters, box, rng, max_attempts=2000):
    """Random sequential addition of non-overlapping spheres (largest first)
    in the box [0, box]; returns (n, 3) centres in the input order.

    Raises RuntimeError naming the particle that found no room: the box is
    too small for the requested fraction (random sequential addition jams
    near 0.38 for equal spheres; keep the fraction below about 0.3).
    """
    d = np.asarray(diameters, float)
    box = np.asarray(box, float)
    n = len(d)
    cell = d.max()
    shape = np.maximum((box // cell).astype(int), 1)
    grid = {}
    pos = np.full((n, 3), np.nan)
    for k in np.argsort(-d, kind="stable"):
        r = d[k] / 2
        lo, hi = r, box - r
        if np.any(hi < lo):
            raise RuntimeError(f"particle {k} (d = {d[k]:.4g} m) is larger than the box {box}")
        for _ in range(max_attempts):
            x = lo + (hi - lo) * rng.random(3)
            c = np.minimum((x // cell).astype(int), shape - 1)
            ok = True
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for dz in (-1, 0, 1):
                        for j in grid.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                            if np.sum((pos[j] - x) ** 2) < ((d[j] + d[k]) / 2) ** 2:
                                ok = False
                                break
                        if not ok:
                            break
                    if not ok:
                        break
                if not ok:
                    break
            if ok:
                pos[k] = x
                grid.setdefault(tuple(c), []).append(k)
                break
        else:
            raise RuntimeError(f"no room for particle {k} after {max_attempts} attempts: "
                               "lower the initial packing fraction")
    return pos


def place_in_box(diameters, fraction, aspect, rng, grow=1.05, tries=20):
    """Box (3,) and centres (n, 3) of non-overlapping spheres: start from
    :func:`box_for` at ``fraction`` and enlarge the box by ``grow`` whenever
    random sequential addition jams (likely with few particles, where the
    walls take a large share of the volume). Raises RuntimeError after
    ``tries`` enlargements."""
    box = box_for(diameters, fraction, aspect)
    for _ in range(tries):
        try:
            return box, place_spheres(diameters, box, rng)
        except RuntimeError:
            box = box * grow
    raise RuntimeError(f"could not place {len(diameters)} particles even in a box {box}")
