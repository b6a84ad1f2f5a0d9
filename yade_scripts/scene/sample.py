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


class _CellGrid:
    """Placed grains binned in cubic cells of side ``cell`` (at least the
    largest sum of two bounding radii), so that the grains whose bounding
    spheres may meet a trial centre are those of its 27 neighbouring cells:
    the candidates of one trial cost O(1), not O(placed grains)."""

    def __init__(self, box, cell):
        self.cell = float(cell)
        self.shape = np.maximum(np.ceil(np.asarray(box, float) / self.cell).astype(np.int64), 1)
        self.members = np.full((int(np.prod(self.shape)), 4), -1, np.int64)   # grain ids per cell
        self.count = np.zeros(len(self.members), np.int64)
        off = np.array([(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])
        self.offsets = off

    def _cells(self, X):
        return np.clip((X // self.cell).astype(np.int64), 0, self.shape - 1)

    def add(self, k, x):
        c = self._cells(x[None])[0]
        flat = int(np.ravel_multi_index(tuple(c), tuple(self.shape)))
        if self.count[flat] == self.members.shape[1]:
            self.members = np.concatenate([self.members, np.full_like(self.members, -1)], axis=1)
        self.members[flat, self.count[flat]] = k
        self.count[flat] += 1

    def candidates(self, X):
        """(trial index, grain id) of every placed grain in the 27 cells
        around each trial centre X (b, 3)."""
        nb = self._cells(X)[:, None, :] + self.offsets[None]          # (b, 27, 3)
        inside = np.all((nb >= 0) & (nb < self.shape), axis=2)
        flat = np.ravel_multi_index(tuple(np.clip(nb, 0, self.shape - 1).transpose(2, 0, 1)), tuple(self.shape))
        m = self.members[flat]                                        # (b, 27, cap)
        ok = (m >= 0) & inside[:, :, None]
        rows = np.broadcast_to(np.arange(len(X))[:, None, None], m.shape)[ok]
        return rows, m[ok]


def place_exact(volumes, radii, fraction, aspect, rng, overlaps, batch=64, max_batches=2000):
    """Random sequential addition of convex grains tested with their exact
    shapes: box (3,) m and centres (n, 3) m.

    volumes (n,) m^3 the grains' volumes; radii (n,) m their bounding radii
    (largest centre-vertex distance); fraction the solid fraction of the
    grains themselves in the box (a square base of side L, height aspect x
    L); overlaps(k, X, J, Y) -> (m,) bool: whether grain k centred at X[i]
    (m, 3) overlaps the placed grain J[i] (m,) centred at Y[i] (the
    caller's exact test, e.g. :meth:`shapes.overlap.OrientedGrains.overlaps`;
    the orientations are the caller's). Grains go in, largest
    first, each at the first of its trial centres (drawn ``batch`` at a time,
    uniform where its bounding sphere fits in the box) that overlaps no placed
    grain: only placed grains whose bounding spheres meet it are tested
    exactly, and those are found in a grid of cells (:class:`_CellGrid`), so
    the cost grows as n, not n^2 (the same pairs as testing every placed
    grain, hence the same sample). Convex grains fill about a quarter of
    their bounding sphere, so this reaches solid fractions three to four
    times those of :func:`place_spheres` (about 0.06 for our polyhedra at a
    bounding-sphere fraction of 0.25). Raises RuntimeError naming the grain
    that found no room after ``max_batches`` x ``batch`` trials (the
    fraction is too high for random sequential addition)."""
    vol = np.asarray(volumes, float)
    r = np.asarray(radii, float)
    n = len(vol)
    L = (vol.sum() / fraction / aspect) ** (1 / 3)
    box = np.array([L, L, aspect * L])
    pos = np.full((n, 3), np.nan)
    grid = _CellGrid(box, 2 * r.max() if n else 1.0)
    first = True
    for k in np.argsort(-r, kind="stable"):
        lo, hi = np.full(3, r[k]), box - r[k]
        if np.any(hi < lo):
            raise RuntimeError(f"grain {k} (bounding radius {r[k]:.4g} m) is larger than the box {box}")
        for _ in range(max_batches):
            X = lo + (hi - lo) * rng.random((batch, 3))
            if first:
                pos[k] = X[0]
                first = False
                break
            rows, cols = grid.candidates(X)
            near = np.linalg.norm(X[rows] - pos[cols], axis=1) < r[k] + r[cols]
            rows, cols = rows[near], cols[near]
            busy = np.zeros(batch, bool)
            busy[rows] = True
            last = int(np.argmin(busy)) if not busy.all() else batch - 1   # the trials up to the first free one
            keep = rows <= last
            rows, cols = rows[keep], cols[keep]
            hit = np.zeros(last + 1, bool)
            if len(rows):
                hit[rows[overlaps(k, X[rows], cols, pos[cols])]] = True
            ok = np.flatnonzero(~hit)
            if len(ok):
                pos[k] = X[ok[0]]
                break
        else:
            raise RuntimeError(f"no room for grain {k} after {max_batches * batch} trials: "
                               f"lower the initial fraction ({fraction:g})")
        grid.add(k, pos[k])
    return box, pos


def place_exact_in_box(volumes, radii, fraction, aspect, rng, overlaps, grow=1.05, tries=20, **kw):
    """:func:`place_exact`, with the box enlarged by ``grow`` (the fraction
    lowered by grow^3) whenever random sequential addition jams (likely with
    few grains, where the walls take a large share of the volume). Raises
    RuntimeError after ``tries`` enlargements. ``kw`` goes to
    :func:`place_exact`."""
    for _ in range(tries):
        try:
            return place_exact(volumes, radii, fraction, aspect, rng, overlaps, **kw)
        except RuntimeError:
            fraction /= grow ** 3
    raise RuntimeError(f"could not place {len(volumes)} grains even at a solid fraction of {fraction:.3g}")
