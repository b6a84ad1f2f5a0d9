"""The face-pair tilt (postproc.facetilt) on hand-built pairs with exact
answers, against a brute-force computation from the raw triangles, and its
invariances."""
import numpy as np
import pytest

from postproc.contacttypes import shape_tables
from postproc.errors import InputError
from postproc.facetilt import face_pair_tilt
from shapes.overlap import rotation_matrices
from shapes.polyhedron import geometric_faces, hull
from test_contact_types import CORNER_DOWN, CUBE_PTS, PRISM_PTS, quat_from_matrix, rot

I3 = np.eye(3)
# float32 tables: a unit normal's components carry a relative error of 2**-24,
# so an angle between two of them is off by at most a few 1e-8 rad
ANGLE_TOL = 1e-6


def _shape(points):
    v, t = hull(points)
    return v, t, geometric_faces(v, t)


@pytest.fixture(scope="module")
def cube_tables():
    return shape_tables(*zip(*[_shape(CUBE_PTS), _shape(PRISM_PTS)]))


def _run(tables, cases, normal=(0.0, 0.0, 1.0)):
    s1 = np.array([c[0] for c in cases])
    s2 = np.array([c[2] for c in cases])
    q1 = np.array([quat_from_matrix(c[1]) for c in cases])
    q2 = np.array([quat_from_matrix(c[3]) for c in cases])
    n = np.tile(normal, (len(cases), 1))
    return face_pair_tilt(tables, s1, q1, s2, q2, n)


@pytest.mark.parametrize("beta", [0.0, 1e-4, 1e-2, 0.3, 10.0, 30.0])
def test_cube_face_tilted_about_an_edge_direction(cube_tables, beta):
    """B's bottom face turned by beta about x: phi = beta, tilt1 = 0,
    tilt2 = beta, both faces the unit square (diameter sqrt 2), rise
    sqrt(2) sin beta."""
    r = _run(cube_tables, [(0, I3, 0, rot([1, 0, 0], beta))])
    b = np.radians(beta)
    assert r.tilt[0] == pytest.approx(b, abs=ANGLE_TOL)
    assert r.tilt1[0] == pytest.approx(0.0, abs=ANGLE_TOL)
    assert r.tilt2[0] == pytest.approx(b, abs=ANGLE_TOL)
    assert r.size1[0] == pytest.approx(np.sqrt(2), rel=1e-6)
    assert r.size2[0] == pytest.approx(np.sqrt(2), rel=1e-6)
    assert r.rise[0] == pytest.approx(np.sqrt(2) * np.sin(b), abs=np.sqrt(2) * ANGLE_TOL)


def test_edge_and_vertex_on_a_face(cube_tables):
    """An edge of B down (45 deg about x): phi = 45 deg; a corner down: the
    three faces at it are all arccos(1/sqrt 3) = 54.7356 deg off -n; the
    prism's ridge on a cube face: its sloped faces' normals stand
    atan(0.7 / 0.5) = 54.46 deg off -z."""
    cases = [(0, I3, 0, rot([1, 0, 0], 45)), (0, I3, 0, CORNER_DOWN), (0, I3, 1, rot([1, 0, 0], 180))]
    r = _run(cube_tables, cases)
    # the prism's sloped faces join (-.5, -.3)-(0, .4) and (.5, -.3)-(0, .4)
    # in (y, z): normal (0.7, 0.5)/|.|, at atan(0.5/0.7) from the horizontal
    prism = np.pi / 2 - np.arctan2(0.5, 0.7)
    assert r.tilt == pytest.approx([np.pi / 4, np.arccos(1 / np.sqrt(3)), prism], abs=ANGLE_TOL)
    assert r.tilt1 == pytest.approx([0.0, 0.0, 0.0], abs=ANGLE_TOL)
    # the prism's sloped face: a 1 x |(0.5, 0.7)| rectangle
    assert r.size2[2] == pytest.approx(np.hypot(1.0, np.hypot(0.5, 0.7)), rel=1e-6)


def _brute(vertices, triangles, faces, R1, R2, s1, s2, n):
    """Contact faces from the raw triangles, in float64, one contact at a time."""
    out = []
    for a, b, Ra, Rb, u in zip(s1, s2, R1, R2, n):
        ms, ls = [], []
        for s, R, d in ((a, Ra, u), (b, Rb, -u)):
            v, t, f = vertices[s], triangles[s], faces[s]
            x = v @ R.T
            top = int(np.argmax(x @ d))
            best, bm, bl = -np.inf, None, None
            for k in np.unique(f[(t == top).any(axis=1)]):
                tri = t[f == k]
                m = np.cross(x[tri[:, 1]] - x[tri[:, 0]], x[tri[:, 2]] - x[tri[:, 0]]).sum(axis=0)
                m /= np.linalg.norm(m)
                if m @ d > best:
                    pv = x[np.unique(tri)]
                    best, bm = m @ d, m
                    bl = max(np.linalg.norm(p - q) for p in pv for q in pv)
            ms.append(bm)
            ls.append(bl)
        out.append((np.arccos(np.clip(-ms[0] @ ms[1], -1, 1)), ls[0], ls[1]))
    return np.array(out)


def _library(n, seed):
    """(vertices, triangles, faces) lists of n generated ballast grains."""
    from shapes.generate import generate_library

    shapes, _ = generate_library(n, seed=seed)
    return ([np.asarray(s.vertices, float) for s in shapes], [np.asarray(s.triangles, np.int64) for s in shapes],
            [np.asarray(s.triangle_face, np.int64) for s in shapes])


def _random_contacts(n_shapes, C, seed):
    """Shape rows, orientations (uniform) and unit normals (uniform) of C
    random contacts."""
    rng = np.random.default_rng(seed)
    n = rng.normal(size=(C, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    return (rng.integers(0, n_shapes, C), rng.normal(size=(C, 4)), rng.integers(0, n_shapes, C),
            rng.normal(size=(C, 4)), n)


def test_library_grains_against_brute_force():
    """Random orientations and normals on generated ballast grains: the
    tilt and both face diameters equal the brute-force ones. arccos there
    loses precision near 0 (float64: ~1e-8 rad), far below the tolerance."""
    vertices, triangles, faces = _library(8, seed=3)
    tables = shape_tables(vertices, triangles, faces)
    s1, q1, s2, q2, n = _random_contacts(8, 300, seed=11)
    r = face_pair_tilt(tables, s1, q1, s2, q2, n)
    ref = _brute(vertices, triangles, faces, rotation_matrices(q1), rotation_matrices(q2), s1, s2, n)
    assert np.max(np.abs(r.tilt - ref[:, 0])) < ANGLE_TOL
    assert np.allclose(r.size1, ref[:, 1], rtol=1e-6)
    assert np.allclose(r.size2, ref[:, 2], rtol=1e-6)
    assert np.all((r.tilt1 >= 0) & (r.tilt1 <= np.pi / 2 + ANGLE_TOL))


def test_rotation_and_swap_invariance():
    """A common rotation of both bodies and the normal changes nothing;
    swapping the sides (n -> -n) swaps tilt1/tilt2 and size1/size2."""
    tables = shape_tables(*_library(6, seed=4))
    s1, q1, s2, q2, n = _random_contacts(6, 200, seed=2)
    r = face_pair_tilt(tables, s1, q1, s2, q2, n)
    G = rot([0.3, -1.0, 0.7], 71.0)
    qg = quat_from_matrix(G)

    def compose(q):      # G R(q) as a quaternion
        w0, x0, y0, z0 = qg
        w, x, y, z = q.T
        return np.stack([w0 * w - x0 * x - y0 * y - z0 * z, w0 * x + x0 * w + y0 * z - z0 * y,
                         w0 * y - x0 * z + y0 * w + z0 * x, w0 * z + x0 * y - y0 * x + z0 * w], axis=1)

    g = face_pair_tilt(tables, s1, compose(q1), s2, compose(q2), n @ G.T)
    sw = face_pair_tilt(tables, s2, q2, s1, q1, -n)
    # the rotated normals carry float64 round-off (1e-16) but the tables are
    # float32: a support vertex or face can only change on an exact tie
    for k in ("tilt", "tilt1", "tilt2", "size1", "size2", "rise"):
        assert np.allclose(getattr(g, k), getattr(r, k), atol=ANGLE_TOL), k
    assert np.allclose(sw.tilt, r.tilt, atol=1e-12)
    assert np.array_equal(sw.tilt1, r.tilt2) and np.array_equal(sw.size1, r.size2)


def test_bad_input_is_one_line(cube_tables):
    q = np.array([[1.0, 0, 0, 0]])
    n = np.array([[0.0, 0, 1]])
    with pytest.raises(InputError, match="shape row 5"):
        face_pair_tilt(cube_tables, [5], q, [0], q, n)
    with pytest.raises(InputError, match="orientation"):
        face_pair_tilt(cube_tables, [0], np.zeros((1, 4)), [0], q, n)
    with pytest.raises(InputError, match="not a unit vector"):
        face_pair_tilt(cube_tables, [0], q, [0], q, np.array([[0.0, 0, np.nan]]))
    with pytest.raises(InputError, match="same 1 contacts"):
        face_pair_tilt(cube_tables, [0], q, [0, 0], q, n)


def test_tolerance_moves_log_uniform_and_gap():
    """Tilts log-uniform on [a, b] (n points at exact quantiles): F(theta) =
    log(theta / a) / log(b / a), so the move is log 2 / log(b / a) for theta
    in [2a, b/2], to the 1/n of the empirical distribution. With a gap (half
    the tilts at 1e-6, half in [10, 20] deg) a tolerance of 0.1 deg is
    exactly stable (share 0.5, move 0)."""
    from postproc.facetilt import tolerance_moves

    a, b, n = 0.1, 100.0, 100_000
    phi = a * (b / a) ** ((np.arange(n) + 0.5) / n)
    theta = np.array([0.2, 1.0, 7.0, 50.0])
    F, move = tolerance_moves(phi, theta)
    assert F == pytest.approx(np.log(theta / a) / np.log(b / a), abs=1.0 / n)
    assert move == pytest.approx(np.log(2) / np.log(b / a), abs=2.0 / n)
    gap = np.concatenate([np.full(500, 1e-6), np.linspace(10, 20, 500)])
    F, move = tolerance_moves(gap, [0.1])
    assert F[0] == 0.5 and move[0] == 0.0
    with pytest.raises(InputError, match="non-empty"):
        tolerance_moves([], [1.0])
    with pytest.raises(InputError, match="finite"):
        tolerance_moves([1.0, np.nan], [1.0])
