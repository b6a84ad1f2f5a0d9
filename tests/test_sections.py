"""Plane sections of grains (shapes/sections.py) and the slab of a packing
(postproc/slab.py): exact answers for cubes and spheres, invariance under
rotation, an independent area from the derivative of scipy's cap volume,
and a hand-built lattice whose slab is known."""
import numpy as np
import pytest
from scipy.spatial import ConvexHull, HalfspaceIntersection
from scipy.spatial.transform import Rotation

from shapes.sections import plane_basis, polygon_area, polyhedron_section, sphere_section

CUBE = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])
CUBE_T = ConvexHull(CUBE).simplices


def area(v, t, point, normal):
    n = np.asarray(normal, float) / np.linalg.norm(normal)
    return polygon_area(polyhedron_section(v, t, point, n), n)


def test_cube_sections_have_their_exact_areas():
    assert area(CUBE, CUBE_T, [0, 0, 0], [0, 1, 0]) == pytest.approx(1.0, rel=1e-15)
    assert area(CUBE, CUBE_T, [0, 0.3, 0], [0, 1, 0]) == pytest.approx(1.0, rel=1e-15)
    # the diagonal plane x = y: a rectangle sqrt(2) x 1
    assert area(CUBE, CUBE_T, [0, 0, 0], [1, -1, 0]) == pytest.approx(np.sqrt(2), rel=1e-15)
    # normal (1, 1, 1) through the centre: the regular hexagon of side sqrt(2)/2
    assert area(CUBE, CUBE_T, [0, 0, 0], [1, 1, 1]) == pytest.approx(3 * np.sqrt(3) / 4, rel=1e-14)
    # near a corner: the triangle of side sqrt(2) s at distance sqrt(3)/2 - s/sqrt(3) ... from the centre
    s = 0.2
    corner = np.array([0.5, 0.5, 0.5])
    tri = area(CUBE, CUBE_T, corner - [s, 0, 0], [1, 1, 1])
    assert tri == pytest.approx(np.sqrt(3) / 4 * 2 * s ** 2, rel=1e-13)
    # the plane misses the cube: nothing
    assert len(polyhedron_section(CUBE, CUBE_T, [0, 0.6, 0], [0, 1, 0])) == 0


def test_section_is_ordered_counter_clockwise_and_lies_in_the_plane():
    n = np.array([0.3, -0.2, 0.9])
    n /= np.linalg.norm(n)
    p = np.array([0.05, -0.1, 0.02])
    sec = polyhedron_section(CUBE, CUBE_T, p, n)
    assert len(sec) >= 3
    np.testing.assert_allclose((sec - p) @ n, 0, atol=1e-15)
    assert polygon_area(sec, n) > 0
    u, v = plane_basis(n)
    np.testing.assert_allclose(np.cross(u, v), n, atol=1e-15)


def test_rotation_and_translation_invariance():
    rng = np.random.default_rng(3)
    base = area(CUBE, CUBE_T, [0.1, 0.05, -0.02], [0.2, 0.5, 0.7])
    for _ in range(20):
        R = Rotation.random(random_state=rng).as_matrix()
        x = rng.normal(size=3)
        got = area(CUBE @ R.T + x, CUBE_T, R @ [0.1, 0.05, -0.02] + x, R @ np.array([0.2, 0.5, 0.7]))
        assert got == pytest.approx(base, rel=1e-13)


def cap_volume(v, normal, h):
    """Volume of {x in hull(v): x . normal <= h} by scipy's half-space
    intersection (an independent computation)."""
    from scipy.optimize import linprog

    hull = ConvexHull(v)
    halfspaces = np.vstack([hull.equations, np.append(normal, -h)])
    # an interior point: the centre of the largest ball inside (Chebyshev)
    A, b = halfspaces[:, :3], -halfspaces[:, 3]
    res = linprog([0, 0, 0, -1], A_ub=np.hstack([A, np.linalg.norm(A, axis=1)[:, None]]), b_ub=b,
                  bounds=[(None, None)] * 3 + [(0, None)])
    pts = HalfspaceIntersection(halfspaces, res.x[:3]).intersections
    return ConvexHull(pts).volume


def test_section_area_is_the_derivative_of_the_cap_volume():
    """A(h) = dV/dh. Between two vertex heights A is a quadratic and V a
    cubic in h, so the central difference is D(e) = V' + V3 e^2 / 6 exactly
    (V3 the third derivative) and Richardson's (4 D(e / 2) - D(e)) / 3 is V'
    up to the volumes' round-off (about 1e-15 V / e: 1e-11 relative here)."""
    from shapes.generate import generate_library

    shapes, _ = generate_library(5, seed=11)
    rng = np.random.default_rng(5)
    delta = 1e-3
    checked = 0
    for sh in shapes:
        v = np.asarray(sh.vertices)
        t = ConvexHull(v).simplices
        for _ in range(4):
            n = rng.normal(size=3)
            n /= np.linalg.norm(n)
            d = v @ n
            h = rng.uniform(d.min() + 0.1 * np.ptp(d), d.max() - 0.1 * np.ptp(d))
            if np.min(np.abs(d - h)) < 2 * delta:
                continue
            def D(e):
                return (cap_volume(v, n, h + e) - cap_volume(v, n, h - e)) / (2 * e)

            dv = (4 * D(delta / 2) - D(delta)) / 3
            assert area(v, t, h * n, n) == pytest.approx(dv, rel=1e-9)
            checked += 1
    assert checked >= 15


def test_sphere_sections():
    c, r = sphere_section([1.0, 2.0, 3.0], 0.5, [0, 2.3, 0], [0, 1, 0])
    np.testing.assert_allclose(c, [1.0, 2.3, 3.0])
    assert r == pytest.approx(np.sqrt(0.25 - 0.09), rel=1e-15)
    assert sphere_section([0, 0, 0], 0.5, [0, 0.5, 0], [0, 1, 0]) is None      # tangent
    assert sphere_section([0, 0, 0], 0.5, [0, -0.7, 0], [0, 1, 0]) is None     # missed


def test_slab_of_a_lattice():
    """Spheres of radius r on a 3 x 3 x 4 lattice: the mid-plane y = 3r cuts
    the middle layer through the centres (12 discs of radius r), and a slab
    r thick holds exactly that layer's 8 x-contacts (force F_x) and 9
    z-contacts (F_z), each a segment 2r long in the (x, z) plane."""
    from builders import lattice_snapshot

    from postproc.slab import slab

    r, F = 0.01, (3.0, 5.0, 7.0)
    snap, _, _ = lattice_snapshot(nx=3, ny=3, nz=4, r=r, F=F)
    s = slab(snap, axis=1, thickness=r)
    centres, radii = s["discs"]
    assert len(radii) == 12 and np.allclose(radii, r, rtol=1e-12) and not s["polygons"]
    assert s["axes"] == (0, 2) and s["plane"] == pytest.approx(3 * r)
    fn = np.sort(s["fn"])
    np.testing.assert_allclose(fn, [F[0]] * 8 + [F[2]] * 9, rtol=1e-12)
    length = np.linalg.norm(s["segments"][:, 1] - s["segments"][:, 0], axis=1)
    np.testing.assert_allclose(length, 2 * r, rtol=1e-12)
    # the default slab (1.5 diameters) also takes the y-contacts on both sides, drawn as points
    assert len(slab(snap, axis=1)["fn"]) == 17 + 2 * 12
