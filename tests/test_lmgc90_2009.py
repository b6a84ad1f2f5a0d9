"""The 2009 route of LMGC90's count (``--types lmgc90-2009``): planplan with
a length-tolerant convex intersection (postproc.polygons.convex_set_2d,
tolerant_intersection), on hand-built cases of known answer.

The 2-D intersection on its own: a segment across or inside a face, a point
in a polygon, two overlapping squares, collinear and crossing segments,
near misses just inside and just outside the tolerance, more than four
corners, rigid motions of the plane coordinates, swapped arguments, bad
input. Then whole pairs of cubes through ``lmgc90_pair`` and the block path
``lmgc90_points``: face on face (triple, as planplan), an edge on a face
(double with the edge's two ends, or its clipped end, where planplan gives
none), a vertex on a face (simple, 1 point), crossed edges (1 point),
parallel edges lying on each other (2 points).

Tolerances. Where the answer is a sum or product of binary fractions it is
exact and compared with ==. Elsewhere the answers are formed by a few
(< 20) floating-point operations on coordinates of size at most SCALE, so
they agree within FP = 64 ulp of SCALE (double precision: 64 x 2.2e-16 x
SCALE), far below any geometric length here. The thresholds of the tolerance
are probed at (1 -+ MARGIN) x tol, MARGIN = 1e-6: far above the round-off of
a distance (1e-15 relative), far below the geometry. planplan's points pass
through Clipper2's grid of 1e-8 m, so they agree with the 2009 route's
within 2e-8 m (one grid step in each coordinate, as in
tests/test_lmgc90_fixtures.py).
"""
import doctest

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from postproc import lmgc90count as lmgc
from postproc import lmgc90shape as lshape
from postproc import polygons as pg
from postproc.classify import check_options
from postproc.contactpoints import DOUBLE, SIMPLE, TRIPLE
from postproc.contacttypes import PAIR_TYPES
from postproc.errors import InputError

EPS = np.finfo(float).eps
MARGIN = 1e-6
TOL_GRID = 2e-8                  # m: Clipper2's 1e-8 grid in planplan


def fp(scale):
    """64 ulp of ``scale``: the round-off of a few operations on it."""
    return 64 * EPS * scale


def same_set(P, Q, tol):
    """The two point sets are equal within tol, in any order."""
    P, Q = np.asarray(P, float).reshape(-1, 2 if np.shape(P)[-1] == 2 else 3), np.asarray(Q, float)
    Q = Q.reshape(-1, P.shape[1])
    if len(P) != len(Q):
        return False
    if not len(P):
        return True
    D = np.linalg.norm(P[:, None] - Q[None], axis=2)
    return D.min(axis=1).max() <= tol and D.min(axis=0).max() <= tol


SQUARE = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
TOL = 1e-3


# ---------------------------------------------------------------- the 2-D intersection

def test_the_docstring_examples_run():
    for f in (pg.convex_set_2d, pg.tolerant_intersection):
        finder = doctest.DocTestFinder()
        runner = doctest.DocTestRunner()
        for t in finder.find(f, globs={f.__name__: f}):
            assert runner.run(t).failed == 0, f.__name__


def test_convex_sets_point_segment_polygon():
    assert pg.convex_set_2d([[1.0, 2.0]], TOL).tolist() == [[1.0, 2.0]]
    # within tol of each other: one point, their mean
    P = pg.convex_set_2d([[0.0, 0.0], [0.5 * TOL, 0.0], [0.0, 0.5 * TOL]], TOL)
    assert P.shape == (1, 2)
    # within tol of a line: a segment, its two ends exactly
    S = pg.convex_set_2d([[0.0, 0.0], [1.0, 0.5 * TOL], [2.0, 0.0], [0.5, -0.25 * TOL]], TOL)
    assert same_set(S, [[0.0, 0.0], [2.0, 0.0]], 0.0)
    # wider: a polygon, its corners exactly, counter-clockwise
    Q = pg.convex_set_2d([[0.0, 0.0], [1.0, 2 * TOL], [2.0, 0.0]], TOL)
    assert same_set(Q, [[0.0, 0.0], [1.0, 2 * TOL], [2.0, 0.0]], 0.0)
    assert pg._area2(Q) > 0
    # a corner within tol of its neighbours' line is dropped
    Q = pg.convex_set_2d(np.vstack([SQUARE, [[1.0, -0.5 * TOL]]]), TOL)
    assert same_set(Q, SQUARE, 0.0)


def test_a_segment_inside_a_face_gives_its_two_ends():
    seg = [[0.25, 0.5], [1.5, 1.25]]
    assert same_set(pg.tolerant_intersection(seg, SQUARE, TOL), seg, 0.0)


def test_a_segment_across_a_face_gives_its_two_clipped_ends():
    seg = np.array([[-1.0, 0.5], [3.0, 0.7]])
    I = pg.tolerant_intersection(seg, SQUARE, TOL)
    # where the line y = 0.5 + 0.05 (x + 1) meets x = 0 and x = 2
    assert same_set(I, [[0.0, 0.55], [2.0, 0.65]], fp(3.0))
    # clipped on one side only: the inner end and the crossing
    I = pg.tolerant_intersection([[1.0, 1.0], [1.0, 5.0]], SQUARE, TOL)
    assert same_set(I, [[1.0, 1.0], [1.0, 2.0]], 0.0)


def test_a_segment_touching_a_face_by_one_end_gives_one_point():
    I = pg.tolerant_intersection([[2.0, 1.0], [4.0, 1.0]], SQUARE, TOL)
    assert same_set(I, [[2.0, 1.0]], 0.0)


def test_a_point_inside_a_polygon_gives_one_point():
    I = pg.tolerant_intersection([[0.75, 1.25]], SQUARE, TOL)
    assert I.tolist() == [[0.75, 1.25]]
    assert len(pg.tolerant_intersection([[2.5, 1.25]], SQUARE, TOL)) == 0


def test_two_overlapping_squares_give_the_corners_of_their_overlap_exactly():
    I = pg.tolerant_intersection(SQUARE, SQUARE + [1.0, 0.5], TOL)
    assert same_set(I, [[1.0, 0.5], [2.0, 0.5], [2.0, 2.0], [1.0, 2.0]], 0.0)
    I = pg.tolerant_intersection(SQUARE, SQUARE * 0.25 + 0.5, TOL)           # one inside the other
    assert same_set(I, SQUARE * 0.25 + 0.5, 0.0)


def test_two_faces_side_by_side_meet_along_a_segment():
    """Faces touching along an edge (no area: planplan gives nothing): the
    two ends of the common stretch."""
    I = pg.tolerant_intersection(SQUARE, SQUARE + [2.0, 1.0], TOL)
    assert same_set(I, [[2.0, 1.0], [2.0, 2.0]], 0.0)
    # a sliver narrower than tol is a segment too
    I = pg.tolerant_intersection(SQUARE, SQUARE + [2.0 - 0.5 * TOL, 1.0], TOL)
    assert len(I) == 2


def test_collinear_segments_give_the_ends_of_their_overlap():
    I = pg.tolerant_intersection([[0.0, 0.0], [2.0, 0.0]], [[1.0, 0.0], [3.0, 0.0]], TOL)
    assert same_set(I, [[1.0, 0.0], [2.0, 0.0]], 0.0)
    # one inside the other, and within tol of one line
    I = pg.tolerant_intersection([[0.0, 0.0], [4.0, 0.0]], [[3.0, 0.5 * TOL], [1.0, -0.5 * TOL]], TOL)
    assert same_set(I, [[1.0, -0.5 * TOL], [3.0, 0.5 * TOL]], 0.0)
    # end to end: one point
    I = pg.tolerant_intersection([[0.0, 0.0], [1.0, 0.0]], [[1.0 + 0.5 * TOL, 0.0], [3.0, 0.0]], TOL)
    assert len(I) == 1
    # apart along their line by more than tol: nothing
    assert len(pg.tolerant_intersection([[0.0, 0.0], [1.0, 0.0]], [[1.0 + 2 * TOL, 0.0], [3.0, 0.0]], TOL)) == 0


def test_crossing_segments_give_the_crossing():
    I = pg.tolerant_intersection([[0.0, 0.0], [2.0, 2.0]], [[0.0, 2.0], [2.0, 0.0]], TOL)
    assert I.tolist() == [[1.0, 1.0]]
    I = pg.tolerant_intersection([[0.0, 0.25], [3.0, 0.25]], [[1.5, -1.0], [1.5, 1.0]], TOL)
    assert I.tolist() == [[1.5, 0.25]]
    # a T: one end on the other segment
    I = pg.tolerant_intersection([[0.0, 0.0], [2.0, 0.0]], [[1.0, 0.0], [1.0, 1.0]], TOL)
    assert I.tolist() == [[1.0, 0.0]]
    # parallel, apart by more than tol: nothing
    assert len(pg.tolerant_intersection([[0.0, 0.0], [2.0, 0.0]], [[0.0, 2 * TOL], [2.0, 2 * TOL]], TOL)) == 0


@pytest.mark.parametrize("factor,points", [(1 - MARGIN, 2), (1 + MARGIN, 0)])
def test_a_segment_just_outside_a_face(factor, points):
    """Parallel to an edge, outside by tol (1 -+ MARGIN): its two ends when
    within tol, nothing beyond."""
    off = factor * TOL
    seg = [[0.5, -off], [1.5, -off]]
    I = pg.tolerant_intersection(seg, SQUARE, TOL)
    assert len(I) == points
    if points:
        assert same_set(I, seg, 0.0)


@pytest.mark.parametrize("factor,points", [(1 - MARGIN, 1), (1 + MARGIN, 0)])
def test_a_point_just_outside(factor, points):
    off = factor * TOL
    assert len(pg.tolerant_intersection([[1.0, 2.0 + off]], SQUARE, TOL)) == points
    assert len(pg.tolerant_intersection([[1.0, off]], [[0.0, 0.0], [2.0, 0.0]], TOL)) == points
    assert len(pg.tolerant_intersection([[1.0, off]], [[1.0, 0.0]], TOL)) == points


def test_more_than_four_corners_keeps_the_four_sharpest():
    """A hexagon whose two extra corners barely turn (but stand 10 tol off
    their neighbours' line, so they are corners): the square's four."""
    hexagon = [[0.0, 0.0], [1.0, -10 * TOL], [2.0, 0.0], [2.0, 2.0], [1.0, 2.0 + 10 * TOL], [0.0, 2.0]]
    big = SQUARE * 10 - 9.0
    assert len(pg.convex_set_2d(hexagon, TOL)) == 6
    I = pg.tolerant_intersection(hexagon, big, TOL)       # the big square clipped by the hexagon's edges
    assert same_set(I, SQUARE, fp(11.0))
    assert len(pg.tolerant_intersection(hexagon, big, TOL, max_points=6)) == 6


CASES = {
    "segment across a face": ([[-1.0, 0.5], [3.0, 0.7]], SQUARE),
    "segment inside a face": ([[0.25, 0.5], [1.5, 1.25]], SQUARE),
    "overlapping squares": (SQUARE, SQUARE + [1.0, 0.5]),
    # an octagon, reduced to its four sharpest corners (turns of 60 deg; the others 30 deg)
    "tilted square on a square": (1.0 + 1.2 * np.array([[np.cos(a), np.sin(a)] for a in
                                                        np.radians([75, 165, 255, 345])]) * np.sqrt(2), SQUARE),
    "point in a face": ([[0.75, 1.25]], SQUARE),
    "collinear segments": ([[0.0, 0.0], [2.0, 0.0]], [[1.0, 0.0], [3.0, 0.0]]),
    "crossing segments": ([[0.0, 0.0], [2.0, 2.0]], [[0.0, 2.0], [2.0, 0.0]]),
    "faces side by side": (SQUARE, SQUARE + [2.0, 1.0]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_rigid_motions_of_the_plane_and_swapped_sides(case):
    """Rotating and translating the plane coordinates moves the points with
    them; swapping the two sides gives the same points."""
    P, Q = (np.asarray(x, float) for x in CASES[case])
    I = pg.tolerant_intersection(P, Q, TOL)
    assert len(I)
    assert same_set(pg.tolerant_intersection(Q, P, TOL), I, fp(4.0))
    rng = np.random.default_rng(7)
    for _ in range(5):
        a = rng.uniform(0, 2 * np.pi)
        R = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
        x = rng.uniform(-4, 4, 2)
        J = pg.tolerant_intersection(P @ R.T + x, Q @ R.T + x, TOL)
        assert same_set(J, I @ R.T + x, fp(10.0)), a


def test_bad_input_one_line_errors():
    for P, Q, tol in (([[0.0, 0.0, 0.0]], SQUARE, TOL), (np.zeros((0, 2)), SQUARE, TOL),
                      ([[np.nan, 0.0]], SQUARE, TOL), ([[0.0, 0.0]], SQUARE, -1.0),
                      ([[0.0, 0.0]], SQUARE, np.inf), ([[0.0, 0.0]], "abc", TOL)):
        with pytest.raises(InputError) as e:
            pg.tolerant_intersection(P, Q, tol)
        assert "\n" not in str(e.value)
    with pytest.raises(InputError):
        pg.tolerant_intersection(SQUARE, SQUARE, TOL, max_points=0)


# ---------------------------------------------------------------- whole pairs of cubes

H = 0.01                     # m, the small cube's half side
DEPTH = 1e-6                 # m, the interpenetration
S2 = H * np.sqrt(2)


def cube(h):
    """(vertices (8, 3), outward triangles (12, 3)) of a cube of half side h."""
    V = np.array([[x, y, z] for x in (-h, h) for y in (-h, h) for z in (-h, h)], float)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    T = []
    for a, b, c, d in quads:
        T += [(a, b, c), (a, c, d)]
    T = np.array(T)
    n = np.cross(V[T[:, 1]] - V[T[:, 0]], V[T[:, 2]] - V[T[:, 0]])
    assert np.all(np.einsum("ij,ij->i", n, V[T].mean(axis=1)) > 0)    # outward
    return V, T


BIG, SMALL = cube(2 * H), cube(H)
SHAPES = [lshape.lmgc90_shape(*BIG), lshape.lmgc90_shape(*SMALL)]
I3 = np.eye(3)
RX45 = Rotation.from_euler("x", 45, degrees=True).as_matrix()
RY45 = Rotation.from_euler("y", 45, degrees=True).as_matrix()
RVERTEX = Rotation.align_vectors([[0.0, 0.0, -1.0]], [np.ones(3) / np.sqrt(3)])[0].as_matrix()
R65, R25 = (Rotation.from_euler("x", a, degrees=True).as_matrix() for a in (65, 25))


def _top(shape, R):
    return float((SHAPES[shape].vertices @ R.T)[:, 2].max())


def _bottom(shape, R):
    return float(-(SHAPES[shape].vertices @ R.T)[:, 2].min())


# name: (antagonist shape, R, centre; candidate shape, R, centre xy), the
# candidate placed DEPTH into the antagonist; expected points of the 2009
# route (None: not checked here), planplan's count, the group
def _case(an_shape, R_an, cd_shape, R_cd, xy):
    z = _top(an_shape, R_an) + _bottom(cd_shape, R_cd) - DEPTH
    return (an_shape, R_an, np.zeros(3), cd_shape, R_cd, np.array([xy[0], xy[1], z]))


ZP = 2 * H - DEPTH / 2       # the common plane of a small cube on the big one's top face
PAIRS = {
    "face on face": (_case(0, I3, 1, I3, (0.003, 0.002)),
                     [[-0.007, -0.008], [0.013, -0.008], [0.013, 0.012], [-0.007, 0.012]], 4, TRIPLE, "FF"),
    "edge on face": (_case(0, I3, 1, RX45, (0.002, 0.001)), [[-0.008, 0.001], [0.012, 0.001]], 0, DOUBLE, "EF"),
    "edge over a face's edge": (_case(0, I3, 1, RX45, (0.015, 0.001)), [[0.005, 0.001], [0.02, 0.001]], 0,
                                DOUBLE, "EF"),
    "vertex on face": (_case(0, I3, 1, RVERTEX, (0.002, 0.001)), [[0.002, 0.001]], 0, SIMPLE, "VF"),
    "crossed edges": (_case(1, RY45, 1, RX45, (0.0, 0.0)), [[0.0, 0.0]], 0, SIMPLE, "EE"),
    "parallel edges": (_case(1, R25, 1, R65, (0.005, 0.0)), None, 0, DOUBLE, "EF"),
}


def _bodies(case):
    sa, Ra, xa, sc, Rc, xc = PAIRS[case][0]
    return lmgc._Body(SHAPES[sc], Rc, xc), lmgc._Body(SHAPES[sa], Ra, xa)


@pytest.mark.parametrize("case", sorted(PAIRS))
def test_hand_built_pairs(case):
    """The 2009 route's points where they are known, and its count against
    planplan's: equal for face on face (the same corners, within Clipper's
    grid), 1 or 2 where planplan gives none."""
    _, want, n_planplan, group, _ = PAIRS[case]
    cd, an = _bodies(case)
    alert = 0.1 * H
    r = lmgc.lmgc90_pair(cd, an, alert, route="lmgc90-2009")
    old = lmgc.lmgc90_pair(cd, an, alert, route="lmgc90-planplan")
    assert len(old["points"]) == n_planplan
    n = len(r["points"])
    assert n in {SIMPLE: (0, 1), DOUBLE: (2,), TRIPLE: (3, 4)}[group]
    assert np.array_equal(r["normal"], old["normal"]) and r["stage"] == old["stage"]
    assert np.allclose(r["gaps"], r["gap"], rtol=0, atol=0)
    if want is not None:
        assert np.allclose(r["normal"], [0.0, 0.0, 1.0], rtol=0, atol=fp(1.0))
        z = ZP if PAIRS[case][0][0] == 0 else S2 - DEPTH / 2
        assert same_set(r["points"], [[x, y, z] for x, y in want], fp(0.05))
    if n_planplan:
        assert same_set(r["points"], old["points"], TOL_GRID)
    # every point on the common plane, within the plane's round-off
    assert np.allclose((r["points"] - r["points"].mean(axis=0)) @ r["normal"], 0.0, rtol=0, atol=fp(0.05))


def test_parallel_edges_give_the_ends_of_their_overlap():
    """Two cubes turned about x by 25 and 65 deg, so that an edge of each
    along x meets the other's and no faces do: the two ends of the stretch
    the edges share, x from -H + 0.005 to H."""
    cd, an = _bodies("parallel edges")
    r = lmgc.lmgc90_pair(cd, an, 0.1 * H, route="lmgc90-2009")
    assert np.allclose(np.sort(r["points"][:, 0]), [-H + 0.005, H], rtol=0, atol=fp(0.05))
    assert np.ptp(r["points"][:, 1]) <= fp(0.05)


def _quat(R):
    x, y, z, w = Rotation.from_matrix(R).as_quat()
    return np.array([w, x, y, z])


def test_the_block_path_and_the_groups():
    """lmgc90_points (the analysis' path) gives the same points as
    lmgc90_pair, and the paper's group and pair labels."""
    names = sorted(PAIRS)
    rows = [PAIRS[k][0] for k in names]
    tables = lshape.LmgcTables(SHAPES)
    args = (tables, np.array([r[3] for r in rows]), np.array([r[5] for r in rows]),
            np.array([_quat(r[4]) for r in rows]), np.array([r[0] for r in rows]),
            np.array([r[2] for r in rows]), np.array([_quat(r[1]) for r in rows]))
    out = lmgc.lmgc90_points(*args, 0.1 * H, route="lmgc90-2009", min_radius=H)
    old = lmgc.lmgc90_points(*args, 0.1 * H, route="lmgc90-planplan", min_radius=H)
    assert out["group"].tolist() == [PAIRS[k][3] for k in names]
    assert [PAIR_TYPES[p] for p in out["pair"]] == [PAIRS[k][4] for k in names]
    assert old["group"].tolist() == [TRIPLE if PAIRS[k][2] else SIMPLE for k in names]
    for k, name in enumerate(names):
        cd, an = _bodies(name)
        r = lmgc.lmgc90_pair(cd, an, 0.1 * H, route="lmgc90-2009", min_radius=H)
        assert same_set(out["xyz"][k], r["points"], fp(0.05)), name


def test_the_route_is_listed_and_checked():
    assert "lmgc90-2009" in lmgc.LMGC90_ROUTES
    check_options("lmgc90-2009", tolerance=0.1)
    with pytest.raises(InputError):
        check_options("lmgc90-2009", tolerance=-1.0)
    with pytest.raises(InputError):
        lmgc.check_route("lmgc90-2008")


def test_lmgc90s_hand_built_fixture_pairs():
    """LMGC90's own hand-built cases (tests/data/lmgc90/pairs.npz: cubes face
    on face flush and tilted 1-10 deg, edge on face, vertex on face, crossed
    edges, near misses within and beyond the alert distance): the 2009
    route gives as many points as the compiled LMGC90's today's route on
    every one, and planplan's points wherever planplan gives any."""
    from test_lmgc90_fixtures import CASES as FCASES, F_PAIRS as F, _shapes

    shapes = _shapes(F)
    for ci, case in enumerate(FCASES):
        rows = np.flatnonzero(F["body_case"] == ci)
        cd, an = (lmgc._Body(shapes[F["body_shape"][k]], F["body_R"][k], F["body_x"][k]) for k in rows)
        r = lmgc.lmgc90_pair(cd, an, float(F["alert"]), route="lmgc90-2009")
        new = (F["lmgc_case"] == ci) & (F["lmgc_route"] == "new")
        old = (F["lmgc_case"] == ci) & (F["lmgc_route"] == "old")
        assert len(r["points"]) == new.sum(), case
        if old.sum():
            assert same_set(r["points"], F["lmgc_point"][old], TOL_GRID), case
