"""The exact overlap of convex polyhedra (shapes/overlap.py, compiled kernel)
against an independent computation and exact hand-built answers.

Reference: the overlap is the intersection of the two sets of face
half-spaces; scipy's HalfspaceIntersection (Qhull) gives its vertices and
ConvexHull its volume, and the centroid comes from the hull's triangles
(tetrahedra from an inner point). Qhull works in double precision too, so both
sides carry round-off of order 1e-15 relative to the grain size d; for the
smallest overlaps (1e-5 of a grain's volume, depth about 0.01 d) that is
about 1e-12 relative in volume. The tolerances below (1e-6 relative in
volume at the 99th percentile, 1e-6 d for points, 1e-4 rad for the normal)
are the acceptance bounds of the issue, far above that round-off; the
measured errors are printed (pytest -s).

The normal n = S_A/|S_A| is checked against the gradient of the REFERENCE
volume, -grad_{x_B} V, by central differences with step 1e-6 d: V(x_B) is
piecewise cubic, so the truncation error is about step^2 / depth^2 ~ 1e-8,
and the round-off |dV| / (step |S|) ~ 1e-13 / 1e-6 = 1e-7: both far below
1e-4 rad.
"""
import numpy as np
import pytest
from scipy.optimize import linprog
from scipy.spatial import ConvexHull, HalfspaceIntersection
from scipy.spatial.transform import Rotation

from shapes.generate import generate_library
from shapes.overlap import (OverlapError, ShapeTable, batch_overlap, batch_wall, pair_overlap,
                            wall_overlap)


@pytest.fixture(scope="module")
def library():
    shapes, _ = generate_library(40, seed=21)
    return [(s.vertices, s.triangles, s.volume) for s in shapes]


def wxyz(rot):
    return np.roll(rot.as_quat(), 1, axis=-1)


def halfspaces(v, t, R, x):
    """Qhull form A x + b <= 0 of a posed convex polyhedron's faces."""
    w = v @ R.T + x
    n = np.cross(w[t[:, 1]] - w[t[:, 0]], w[t[:, 2]] - w[t[:, 0]])
    n /= np.linalg.norm(n, axis=1)[:, None]
    return np.hstack([n, -np.einsum("ij,ij->i", n, w[t[:, 0]])[:, None]])


def chebyshev(H):
    """Centre and radius of the largest ball inside {A x + b <= 0} (LP)."""
    A, b = H[:, :3], H[:, 3]
    norm = np.linalg.norm(A, axis=1)
    res = linprog([0, 0, 0, -1], A_ub=np.hstack([A, norm[:, None]]), b_ub=-b,
                  bounds=[(None, None)] * 3 + [(None, None)], method="highs")
    return (res.x[:3], res.x[3]) if res.status == 0 else (None, -np.inf)


def reference(H, inner):
    """Volume, centroid and vertices of {A x + b <= 0} from an inner point."""
    hs = HalfspaceIntersection(H, inner)
    pts = hs.intersections
    hull = ConvexHull(pts)
    o = pts.mean(axis=0)
    tri = pts[hull.simplices]
    vol6 = np.einsum("ij,ij->i", tri[:, 0] - o, np.cross(tri[:, 1] - o, tri[:, 2] - o))
    vol6 = np.abs(vol6)                          # o is inside: every tetrahedron counts positively
    cen = (vol6[:, None] * (tri.sum(axis=1) + o) / 4).sum(axis=0) / vol6.sum()
    return hull.volume, cen, pts


def pair_halfspaces(lib, a, b, Ra, Rb, xb):
    va, ta, _ = lib[a]
    vb, tb, _ = lib[b]
    return np.vstack([halfspaces(va, ta, Ra.as_matrix(), np.zeros(3)), halfspaces(vb, tb, Rb.as_matrix(), xb)])


def place_pairs(lib, n, seed, lo=-5, hi=np.log10(3e-2), touching=False):
    """n random pairs A at the origin, B along a random direction at the
    distance where the overlap is 10^U(lo, hi) of the smaller volume, or
    (touching=True) at the largest distance where they still overlap
    (bisection on the kernel's volume: it only places the pairs)."""
    rng = np.random.default_rng(seed)
    table = ShapeTable([(v, t) for v, t, _ in lib])
    a = rng.integers(len(lib), size=n)
    b = rng.integers(len(lib), size=n)
    Ra, Rb = Rotation.random(n, random_state=rng), Rotation.random(n, random_state=rng)
    u = rng.normal(size=(n, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    vols = np.array([v for _, _, v in lib])
    target = 0.0 if touching else 10 ** rng.uniform(lo, hi, size=n) * np.minimum(vols[a], vols[b])
    s_lo, s_hi = np.zeros(n), np.full(n, 2.0)
    zeros = np.zeros((n, 3))
    for _ in range(60):
        mid = 0.5 * (s_lo + s_hi)
        r = batch_overlap(table, a, zeros, wxyz(Ra), b, mid[:, None] * u, wxyz(Rb))
        over = r["volume"] > target
        s_lo = np.where(over, mid, s_lo)
        s_hi = np.where(over, s_hi, mid)
    return table, a, b, Ra, Rb, s_lo[:, None] * u


def test_random_pairs_against_halfspace_intersection(library):
    table, a, b, Ra, Rb, xb = place_pairs(library, 1000, seed=1)
    n = len(a)
    r = batch_overlap(table, a, np.zeros((n, 3)), wxyz(Ra), b, xb, wxyz(Rb))
    rel, dcen = np.zeros(n), np.zeros(n)
    for k in range(n):
        H = pair_halfspaces(library, a[k], b[k], Ra[k], Rb[k], xb[k])
        c = r["centroid"][k]
        assert np.max(H[:, :3] @ c + H[:, 3]) < 0            # the kernel's centroid is strictly inside
        V, C, _ = reference(H, c)
        rel[k] = abs(r["volume"][k] - V) / V
        dcen[k] = np.linalg.norm(r["centroid"][k] - C)       # d = 1
    print(f"\nvolume rel. error: median {np.median(rel):.1e}, p99 {np.percentile(rel, 99):.1e}, max {rel.max():.1e}; "
          f"centroid error / d: median {np.median(dcen):.1e}, max {dcen.max():.1e}")
    assert np.percentile(rel, 99) < 1e-6
    assert dcen.max() < 1e-6
    assert np.all(r["status"] == 0)


def test_normal_is_minus_the_gradient_of_the_volume(library):
    table, a, b, Ra, Rb, xb = place_pairs(library, 1000, seed=2)
    n = len(a)
    r = batch_overlap(table, a, np.zeros((n, 3)), wxyz(Ra), b, xb, wxyz(Rb))
    step = 1e-6
    ang = np.zeros(n)
    for k in range(n):
        c = r["centroid"][k]
        grad = np.zeros(3)
        for ax in range(3):
            e = np.zeros(3)
            e[ax] = step
            vp = reference(pair_halfspaces(library, a[k], b[k], Ra[k], Rb[k], xb[k] + e), c)[0]
            vm = reference(pair_halfspaces(library, a[k], b[k], Ra[k], Rb[k], xb[k] - e), c)[0]
            grad[ax] = (vp - vm) / (2 * step)
        g = -grad / np.linalg.norm(grad)
        ang[k] = np.arccos(np.clip(g @ r["normal"][k], -1, 1))
    print(f"\nnormal vs -grad V: median {np.median(ang):.1e} rad, max {ang.max():.1e} rad")
    assert ang.max() < 1e-4


def test_separated_pairs_give_no_contact(library):
    """1000 pairs whose axis-aligned boxes overlap but which do not touch
    (the LP finds no ball inside both): volume exactly 0, NaN point and normal."""
    rng = np.random.default_rng(3)
    table, a, b, Ra, Rb, xb = place_pairs(library, 1400, seed=3, touching=True)
    n = len(a)
    # push B out past contact: 1e-4 d to 0.15 d beyond the touching distance
    u = xb / np.linalg.norm(xb, axis=1)[:, None]
    xb = xb + u * 10 ** rng.uniform(-4, np.log10(0.15), size=(n, 1))
    boxes = []
    for k in range(n):
        wa = library[a[k]][0] @ Ra[k].as_matrix().T
        wb = library[b[k]][0] @ Rb[k].as_matrix().T + xb[k]
        boxes.append(np.all(wa.max(axis=0) > wb.min(axis=0)) and np.all(wb.max(axis=0) > wa.min(axis=0)))
    keep = np.flatnonzero(boxes)[:1000]
    assert len(keep) == 1000
    r = batch_overlap(table, a[keep], np.zeros((1000, 3)), wxyz(Ra[keep]), b[keep], xb[keep], wxyz(Rb[keep]))
    for k, p in enumerate(keep):
        _, radius = chebyshev(pair_halfspaces(library, a[p], b[p], Ra[p], Rb[p], xb[p]))
        assert radius <= 1e-12                                # independently: apart
    assert np.all(r["volume"] == 0) and np.all(np.isnan(r["centroid"])) and np.all(np.isnan(r["normal"]))


def test_wall_cut_against_halfspace_intersection(library):
    rng = np.random.default_rng(4)
    n = 300
    table = ShapeTable([(v, t) for v, t, _ in library])
    s = rng.integers(len(library), size=n)
    R = Rotation.random(n, random_state=rng)
    m = rng.normal(size=(n, 3))
    m /= np.linalg.norm(m, axis=1)[:, None]
    vols = np.array([v for _, _, v in library])[s]
    target = 10 ** rng.uniform(-5, np.log10(3e-2), size=n) * vols
    lo, hi = np.full(n, -1.0), np.zeros(n)          # wall plane at -h along m; bisect h
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        r = batch_wall(table, s, np.zeros((n, 3)), wxyz(R), mid[:, None] * m, m)
        over = r["volume"] > target
        hi = np.where(over, mid, hi)
        lo = np.where(over, lo, mid)
    point = hi[:, None] * m
    r = batch_wall(table, s, np.zeros((n, 3)), wxyz(R), point, m)
    for k in range(n):
        v, t, _ = library[s[k]]
        wall = np.append(m[k], -m[k] @ point[k])             # m.x - m.p <= 0: the part beyond the wall
        H = np.vstack([halfspaces(v, t, R[k].as_matrix(), np.zeros(3)), wall])
        V, C, _ = reference(H, r["centroid"][k])
        assert r["volume"][k] == pytest.approx(V, rel=1e-6)
        assert np.linalg.norm(r["centroid"][k] - C) < 1e-6
        np.testing.assert_allclose(r["normal"][k], m[k], atol=1e-15)


def shadow_reference(pts, n):
    """Area and principal widths of the convex shadow of pts on the plane
    normal to n, independently: 2D hull (Qhull), area moments by triangles."""
    a = np.array([1.0, 0, 0]) if abs(n[0]) < 0.6 else np.array([0, 1.0, 0])
    u = np.cross(n, a)
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    p = np.column_stack([pts @ u, pts @ v])
    hull = ConvexHull(p)
    poly = p[hull.vertices]
    o = poly.mean(axis=0)
    A, S = 0.0, np.zeros((2, 2))
    cen = np.zeros(2)
    tris = [(o, poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]
    for t0, t1, t2 in tris:
        ar = 0.5 * abs((t1[0] - t0[0]) * (t2[1] - t0[1]) - (t1[1] - t0[1]) * (t2[0] - t0[0]))
        A += ar
        cen += ar * (t0 + t1 + t2) / 3
    cen /= A
    for t0, t1, t2 in tris:
        ar = 0.5 * abs((t1[0] - t0[0]) * (t2[1] - t0[1]) - (t1[1] - t0[1]) * (t2[0] - t0[0]))
        q = np.array([t0, t1, t2]) - cen
        S += ar / 12 * (q.T @ q + np.outer(q.sum(0), q.sum(0)))
    w, e = np.linalg.eigh(S)
    widths = [np.ptp(poly @ e[:, k]) for k in (1, 0)]
    return A, np.sort(widths)[::-1], w


def test_footprint_against_an_independent_shadow(library):
    table, a, b, Ra, Rb, xb = place_pairs(library, 200, seed=5)
    n = len(a)
    r = batch_overlap(table, a, np.zeros((n, 3)), wxyz(Ra), b, xb, wxyz(Rb))
    checked = 0
    for k in range(n):
        H = pair_halfspaces(library, a[k], b[k], Ra[k], Rb[k], xb[k])
        _, _, pts = reference(H, r["centroid"][k])
        area, widths, moments = shadow_reference(pts, r["normal"][k])
        assert r["area"][k] == pytest.approx(area, rel=1e-6)
        if moments[1] > 1.01 * moments[0]:          # principal axes well defined
            np.testing.assert_allclose(r["footprint"][k], widths, atol=1e-6)
            checked += 1
    assert checked > 150


def cube():
    v = np.array([[x, y, z] for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)])
    t = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return v, t


Q0 = np.array([1.0, 0, 0, 0])


@pytest.mark.parametrize("h", [1e-4, 1e-3, 1e-2])
def test_built_contacts_with_exact_answers(h):
    """Unit cubes (d = sqrt 3); depths 1e-4 to 1e-2."""
    v, t = cube()
    # face-face, B shifted by (0.2, 0.1): a 0.8 x 0.9 x h box
    r = pair_overlap(v, t, [0, 0, 0], Q0, v, t, [0.2, 0.1, 1 - h], Q0)
    assert r["volume"] == pytest.approx(0.72 * h, rel=1e-12)
    np.testing.assert_allclose(r["centroid"], [0.1, 0.05, 0.5 - h / 2], atol=1e-14)
    # S_A: A's top (0.72, +z) and A's +x and +y side strips (0.9 h, 0.8 h)
    s_a = np.array([0.9 * h, 0.8 * h, 0.72])
    np.testing.assert_allclose(r["normal"], s_a / np.linalg.norm(s_a), atol=1e-14)
    # edge-face: B turned 45 deg about x, its lowest edge (length 1) h deep in A's top face
    qe = wxyz(Rotation.from_euler("x", 45, degrees=True))
    r = pair_overlap(v, t, [0, 0, 0], Q0, v, t, [0, 0, 0.5 + np.sqrt(0.5) - h], qe)
    assert r["volume"] == pytest.approx(h * h, rel=1e-10)          # prism: triangle (2h base, h high) x 1
    np.testing.assert_allclose(r["normal"], [0, 0, 1], atol=1e-14)
    np.testing.assert_allclose(r["footprint"], [1.0, 2 * h], rtol=1e-10)
    assert r["area"] == pytest.approx(2 * h, rel=1e-10)
    # vertex-face: B's body diagonal along z, its lowest vertex h deep
    qv = wxyz(Rotation.align_vectors([[0, 0, -1]], [[-1, -1, -1]])[0])
    r = pair_overlap(v, t, [0, 0, 0], Q0, v, t, [0, 0, 0.5 + np.sqrt(3) / 2 - h], qv)
    assert r["volume"] == pytest.approx(np.sqrt(3) / 2 * h ** 3, rel=1e-9)   # corner of side sqrt(3) h
    np.testing.assert_allclose(r["normal"], [0, 0, 1], atol=1e-12)
    side = np.sqrt(6) * h                                          # an equilateral triangle
    assert r["area"] == pytest.approx(np.sqrt(3) / 4 * side ** 2, rel=1e-9)
    assert np.all(r["footprint"] <= side * (1 + 1e-9)) and np.all(r["footprint"] >= side * np.sqrt(3) / 2 * (1 - 1e-9))
    # edge-edge: A's top edge along x, B's bottom edge along y, h deep
    qa = wxyz(Rotation.from_euler("x", 45, degrees=True))
    qb = wxyz(Rotation.from_euler("y", 45, degrees=True))
    r = pair_overlap(v, t, [0, 0, 0], qa, v, t, [0, 0, 2 * np.sqrt(0.5) - h], qb)
    assert r["volume"] == pytest.approx(2 * h ** 3 / 3, rel=1e-9)
    np.testing.assert_allclose(r["normal"], [0, 0, 1], atol=1e-12)
    assert r["area"] == pytest.approx(2 * h * h, rel=1e-9)              # the diamond |x| + |y| <= h
    assert np.all(r["footprint"] <= 2 * h * (1 + 1e-9)) and np.all(r["footprint"] >= np.sqrt(2) * h * (1 - 1e-9))


@pytest.mark.parametrize("tilt", [1e-9, 1e-6, 1e-3])
def test_near_parallel_faces(tilt):
    """B's bottom face tilted by `tilt` about y, h = 1e-3 deep at its centre:
    volume and centroid against the reference. The normal: S_A is A's top
    face (area about 1) plus, on each side where A's side face bounds the
    overlap rather than B's (nearly coplanar) one, a strip of area at most h:
    n is within atan(sqrt(2) h) + tilt of z. (That is the exact -grad V: a
    nearly coplanar side makes V's gradient jump by up to h across a
    translation of order tilt h.)"""
    v, t = cube()
    h = 1e-3
    q = wxyz(Rotation.from_euler("y", tilt))
    r = pair_overlap(v, t, [0, 0, 0], Q0, v, t, [0, 0, 1 - h], q)
    # B's bottom centre sits h deep; its face is tilted, its sides too (by tilt)
    H = np.vstack([halfspaces(v, t, np.eye(3), np.zeros(3)),
                   halfspaces(v, t, Rotation.from_euler("y", tilt).as_matrix(), [0, 0, 1 - h])])
    V, C, _ = reference(H, r["centroid"])
    assert r["volume"] == pytest.approx(V, rel=1e-9)
    assert np.linalg.norm(r["centroid"] - C) < 1e-12
    assert np.arccos(min(1.0, r["normal"][2])) < np.arctan(np.sqrt(2) * h) + tilt


def test_invariances(library):
    table, a, b, Ra, Rb, xb = place_pairs(library, 100, seed=6)
    n = len(a)
    za = np.zeros((n, 3))
    r = batch_overlap(table, a, za, wxyz(Ra), b, xb, wxyz(Rb))
    # swapping A and B: same overlap, opposite normal
    s = batch_overlap(table, b, xb, wxyz(Rb), a, za, wxyz(Ra))
    np.testing.assert_allclose(s["volume"], r["volume"], rtol=1e-12)
    np.testing.assert_allclose(s["centroid"], r["centroid"], atol=1e-14)
    np.testing.assert_allclose(s["normal"], -r["normal"], atol=1e-10)
    # a common rigid motion
    rng = np.random.default_rng(7)
    Q = Rotation.random(random_state=rng)
    shift = rng.uniform(-10, 10, size=3)
    m = batch_overlap(table, a, za + shift, wxyz(Q * Ra), b, Q.apply(xb) + shift, wxyz(Q * Rb))
    np.testing.assert_allclose(m["volume"], r["volume"], rtol=1e-10)
    np.testing.assert_allclose(m["centroid"], Q.apply(r["centroid"]) + shift, atol=1e-12)
    np.testing.assert_allclose(m["normal"], Q.apply(r["normal"]), atol=1e-9)
    np.testing.assert_allclose(m["footprint"], r["footprint"], atol=1e-9)
    # scaling by 1e-6 and 1e6
    for c in (1e-6, 1e6):
        ts = ShapeTable([(v * c, t) for v, t, _ in library])
        g = batch_overlap(ts, a, za, wxyz(Ra), b, xb * c, wxyz(Rb))
        np.testing.assert_allclose(g["volume"], r["volume"] * c ** 3, rtol=1e-10)
        np.testing.assert_allclose(g["centroid"], r["centroid"] * c, atol=1e-12 * c)
        np.testing.assert_allclose(g["normal"], r["normal"], atol=1e-9)
        np.testing.assert_allclose(g["footprint"], r["footprint"] * c, atol=1e-9 * c)
        np.testing.assert_allclose(g["area"], r["area"] * c * c, rtol=1e-9)
    # threads: bit for bit
    one = batch_overlap(table, a, za, wxyz(Ra), b, xb, wxyz(Rb), threads=1)
    two = batch_overlap(table, a, za, wxyz(Ra), b, xb, wxyz(Rb), threads=2)
    for key in one:
        np.testing.assert_array_equal(one[key], two[key])


def test_hard_cases_are_finite(library):
    v, t = cube()
    # coplanar touching faces, and a vertex exactly touching a face: no volume
    assert pair_overlap(v, t, [0, 0, 0], Q0, v, t, [0, 0, 1.0], Q0)["volume"] == 0
    assert pair_overlap(v, t, [0, 0, 0], Q0, v, t, [1.0, 1.0, 1.0], Q0)["volume"] == 0
    # identical poses: the whole grain, S_A = 0, normal from the fallback
    vl, tl, vol = library[0]
    r = pair_overlap(vl, tl, [0, 0, 0], Q0, vl, tl, [0, 0, 0], Q0)
    assert r["volume"] == pytest.approx(vol, rel=1e-12) and r["status"] == 1
    assert np.linalg.norm(r["normal"]) == pytest.approx(1) and np.all(np.isfinite(r["centroid"]))
    # one grain deep inside another (centres 0.6 d apart along x, B small)
    r = pair_overlap(v, t, [0, 0, 0], Q0, vl * 0.2, tl, [0.2, 0.1, 0], Q0)
    assert r["volume"] == pytest.approx(vol * 0.008, rel=1e-12) and r["status"] == 1
    np.testing.assert_allclose(r["normal"], np.array([0.2, 0.1, 0]) / np.hypot(0.2, 0.1), atol=1e-14)
    # deep but not inside: more than 50 % of d
    r = pair_overlap(v, t, [0, 0, 0], Q0, v, t, [0.3, 0.1, 0.4], Q0)
    assert r["volume"] == pytest.approx(0.7 * 0.9 * 0.6, rel=1e-12)
    assert np.all(np.isfinite(r["normal"])) and r["status"] == 0


def test_bad_input_gives_one_line_errors():
    v, t = cube()
    with pytest.raises(OverlapError, match="not finite"):
        pair_overlap(v, t, [0, np.nan, 0], Q0, v, t, [0, 0, 1], Q0)
    with pytest.raises(OverlapError, match="zero norm"):
        pair_overlap(v, t, [0, 0, 0], [0, 0, 0, 0], v, t, [0, 0, 1], Q0)
    with pytest.raises(OverlapError, match="triangle index out of range"):
        pair_overlap(v, t + 1, [0, 0, 0], Q0, v, t, [0, 0, 1], Q0)
    with pytest.raises(OverlapError, match="vertices must be"):
        pair_overlap(v[:, :2], t, [0, 0, 0], Q0, v, t, [0, 0, 1], Q0)
    table = ShapeTable([(v, t)])
    with pytest.raises(OverlapError, match="shape index out of range"):
        batch_overlap(table, [0], [[0, 0, 0]], [Q0], [1], [[0, 0, 1]], [Q0])
    with pytest.raises(OverlapError, match="wall planes"):
        wall_overlap(v, t, [0, 0, 0], Q0, [0, 0, 0], [0, 0, 0])
