"""The contact engine (shapes/engine.py on the compiled kernel), without YADE.

The engine takes a different path from the one-pair geometry of
``shapes.overlap``: a Verlet list, cached separating axes, and for pairs that
touched at the last step no separation tests and another clipping order. So
its contacts are checked against ``batch_overlap`` / ``batch_wall`` on the
same poses; the two agree to round-off (tolerances: 1e-9 relative, about
1e6 x the 1e-15 of the clipping in double precision, since the two paths clip
in different orders). The laws are checked against exact values, and the
forces against Newton's third law.
"""
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from shapes.engine import ContactEngine, EngineError
from shapes.generate import generate_library
from shapes.overlap import ShapeTable, batch_overlap, batch_wall

K_V, KT_COEF, MU = 1.0e7, 2.0e5, 0.5


@pytest.fixture(scope="module")
def grains():
    shapes, _ = generate_library(16, seed=11)
    return [s.vertices for s in shapes], [s.triangles for s in shapes]


def packing(grains, m, seed, spacing=0.55):
    """m^3 grains of d = 1 (some scaled to 0.7) on a jittered lattice of the
    given spacing, in random orientations: neighbours overlap by a few
    percent of their volume or not at all."""
    rng = np.random.default_rng(seed)
    n = m ** 3
    idx = np.stack(np.meshgrid(*[np.arange(m)] * 3, indexing="ij"), -1).reshape(-1, 3)
    pos = spacing * idx + rng.uniform(-0.04, 0.04, size=(n, 3))
    quat = np.roll(Rotation.random(n, random_state=rng).as_quat(), 1, axis=1)     # (w, x, y, z)
    shape = rng.integers(len(grains[0]), size=n)
    scale = np.where(rng.random(n) < 0.3, 0.7, 1.0)
    verts = [grains[0][s] * c for s, c in zip(shape, scale)]
    tris = [grains[1][s] for s in shape]
    sizes = np.array([2 * np.linalg.norm(v, axis=1).max() for v in verts])
    return verts, tris, pos, quat, sizes


def engine_for(verts, tris, sizes, walls, threads=1, skin=0.05):
    return ContactEngine(verts, tris, np.arange(len(verts)), sizes, K_V, KT_COEF, MU, 0.0, skin,
                         walls=walls, threads=threads)


def reference_pairs(verts, tris, pos, quat):
    """Every touching pair i < j by the one-pair geometry."""
    n = len(verts)
    i, j = np.triu_indices(n, 1)
    table = ShapeTable(list(zip(verts, tris)))
    r = batch_overlap(table, i, pos[i], quat[i], j, pos[j], quat[j], threads=1)
    keep = r["volume"] > 0
    return i[keep], j[keep], {k: v[keep] for k, v in r.items()}


def check_pairs(c, verts, tris, pos, quat, sizes):
    pp = c["i"] >= 0
    i, j, ref = reference_pairs(verts, tris, pos, quat)
    got = sorted(zip(c["i"][pp].tolist(), c["j"][pp].tolist()))
    assert got == sorted(zip(i.tolist(), j.tolist()))
    order = np.lexsort((c["j"][pp], c["i"][pp]))
    ref_order = np.lexsort((j, i))
    d = sizes.max()
    vol = c["volume"][pp][order]
    np.testing.assert_allclose(vol, ref["volume"][ref_order], rtol=1e-9, atol=0)
    np.testing.assert_allclose(c["point"][pp][order], ref["centroid"][ref_order], rtol=0, atol=1e-9 * d)
    np.testing.assert_allclose(c["normal"][pp][order], ref["normal"][ref_order], rtol=0, atol=1e-9)
    np.testing.assert_allclose(c["footprint"][pp][order], ref["footprint"][ref_order], rtol=0, atol=1e-9 * d)
    np.testing.assert_allclose(c["area"][pp][order], ref["area"][ref_order], rtol=1e-9, atol=1e-12 * d * d)
    # the volumetric normal law, exactly: F_n = k_V V n on j
    np.testing.assert_allclose(c["force_normal"][pp], K_V * c["volume"][pp, None] * c["normal"][pp],
                               rtol=1e-15, atol=0)
    return len(i)


def test_engine_contacts_match_the_pair_geometry(grains):
    verts, tris, pos, quat, sizes = packing(grains, 3, seed=1)
    eng = engine_for(verts, tris, sizes, walls=False)
    eng.step(pos, quat)
    n = check_pairs(eng.contacts(), verts, tris, pos, quat, sizes)
    assert n > 20                      # the packing has contacts to check
    # a second step with small rigid motions: the pairs that touched take the
    # engine's other path (no separation tests, planes facing A first)
    rng = np.random.default_rng(2)
    pos2 = pos + rng.normal(scale=2e-3, size=pos.shape)
    rot = Rotation.from_rotvec(rng.normal(scale=5e-3, size=(len(pos), 3)))
    q2 = np.roll((rot * Rotation.from_quat(np.roll(quat, -1, axis=1))).as_quat(), 1, axis=1)
    eng.step(pos2, q2)
    check_pairs(eng.contacts(), verts, tris, pos2, q2, sizes)


def test_wall_contacts_match_the_half_space_cut(grains):
    verts, tris, pos, quat, sizes = packing(grains, 3, seed=3)
    lo, hi = pos.min(axis=0) - 0.1, pos.max(axis=0) + 0.1          # walls cut the outer grains
    wall_pos = np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])
    eng = engine_for(verts, tris, sizes, walls=True)
    eng.step(pos, quat, wall_pos)
    c = eng.contacts()
    w = c["i"] < 0
    assert w.sum() > 10
    table = ShapeTable(list(zip(verts, tris)))
    n = len(verts)
    for k in range(6):
        axis, sign = k // 2, (1.0, -1.0)[k % 2]
        m = np.zeros(3)
        m[axis] = sign
        point = np.zeros(3)
        point[axis] = wall_pos[k]
        ref = batch_wall(table, np.arange(n), pos, quat, np.tile(point, (n, 1)), np.tile(m, (n, 1)), threads=1)
        mine = c["i"] == -1 - k
        touching = np.flatnonzero(ref["volume"] > 0)
        assert sorted(c["j"][mine].tolist()) == touching.tolist()
        rows = np.flatnonzero(mine)[np.argsort(c["j"][mine])]
        np.testing.assert_allclose(c["volume"][rows], ref["volume"][touching], rtol=1e-12)
        np.testing.assert_allclose(c["point"][rows], ref["centroid"][touching], atol=1e-12)
        np.testing.assert_array_equal(c["normal"][rows], np.tile(m, (len(rows), 1)))
        np.testing.assert_allclose(c["footprint"][rows], ref["footprint"][touching], atol=1e-12)
        # frictionless walls: no tangential force
        assert np.all(c["force_tangential"][rows] == 0)


def test_facet_rows_pair_with_no_facet_and_touch_no_wall(grains):
    """set_facets(m): body rows m .. n - 1 are facets (a user scene's come
    after its polyhedra). The pairs of two of them, listed before, are
    dropped at once and never listed again, and no wall touches them; every
    other contact is exactly that of the engine without the setting, and
    the walls' forces are the sums over the first rows' wall contacts."""
    verts, tris, pos, quat, sizes = packing(grains, 3, seed=3)
    lo, hi = pos.min(axis=0) - 0.1, pos.max(axis=0) + 0.1
    wall_pos = np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])
    every = engine_for(verts, tris, sizes, walls=True)
    some = engine_for(verts, tris, sizes, walls=True)
    m = len(verts) // 2
    for eng in (every, some):                          # the pairs of two facets listed (then dropped from some)
        eng.step(pos, quat, wall_pos)
    facet_pair = lambda i, j: (i >= m) & (j >= m)      # noqa: E731
    assert np.sum(facet_pair(*some.state()["pair_ids"].T)) > 0
    some.set_facets(m)
    assert np.sum(facet_pair(*some.state()["pair_ids"].T)) == 0
    for eng in (every, some):
        eng.step(pos, quat, wall_pos)
    assert np.sum(facet_pair(*some.state()["pair_ids"].T)) == 0
    a, b = every.contacts(), some.contacts()
    wall = lambda c: c["i"] < 0                        # noqa: E731
    # in the engine without the setting: facets touch walls, and facets touch each other
    assert np.sum(wall(a) & (a["j"] >= m)) > 0 and np.sum(wall(a) & (a["j"] < m)) > 0
    assert np.sum(~wall(a) & facet_pair(a["i"], a["j"])) > 0
    keep = ~((wall(a) & (a["j"] >= m)) | (~wall(a) & facet_pair(a["i"], a["j"])))
    order = lambda c, w: np.flatnonzero(w)[np.lexsort((c["j"][w], c["i"][w]))]   # noqa: E731
    ka, kb = order(a, keep), order(b, np.ones(len(b["i"]), bool))
    np.testing.assert_array_equal(np.c_[a["i"][ka], a["j"][ka]], np.c_[b["i"][kb], b["j"][kb]])
    for key in ("volume", "force_normal", "force_tangential", "point", "normal"):
        np.testing.assert_array_equal(a[key][ka], b[key][kb])
    wall_force = np.zeros((6, 3))
    for i, f in zip(a["i"][keep & wall(a)], a["force_normal"][keep & wall(a)]):
        wall_force[-1 - i] -= f
    np.testing.assert_allclose(some.step(pos, quat, wall_pos)[2], wall_force, rtol=1e-12,
                               atol=1e-12 * np.abs(wall_force).max())
    with pytest.raises(ValueError, match="^set_facets: the first facet row must be within 0 .. "):
        some.set_facets(len(verts) + 1)


def test_forces_obey_newtons_third_law(grains):
    """Pairs only: total force and total moment (torques + x cross F) vanish;
    with walls the forces on the walls balance those on the particles."""
    verts, tris, pos, quat, sizes = packing(grains, 3, seed=4)
    eng = engine_for(verts, tris, sizes, walls=False)
    rng = np.random.default_rng(5)
    for step in range(3):                              # tangential forces build up
        pos = pos + rng.normal(scale=1e-3, size=pos.shape)
        F, T, _ = eng.step(pos, quat)
    scale = np.abs(F).sum()
    assert scale > 0 and np.linalg.norm(eng.contacts()["force_tangential"]) > 0
    assert np.linalg.norm(F.sum(axis=0)) < 1e-13 * scale
    moment = T.sum(axis=0) + np.cross(pos, F).sum(axis=0)
    assert np.linalg.norm(moment) < 1e-12 * scale * np.abs(pos).max()
    lo, hi = pos.min(axis=0) - 0.1, pos.max(axis=0) + 0.1
    eng2 = engine_for(verts, tris, sizes, walls=True)
    F, T, W = eng2.step(pos, quat, np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]]))
    assert np.abs(W).sum() > 0
    assert np.linalg.norm(F.sum(axis=0) + W.sum(axis=0)) < 1e-13 * np.abs(F).sum()


def cube():
    v = np.array([[x, y, z] for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)])
    t = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return v, t


def test_tangential_law_elastic_then_coulomb():
    """Two unit cubes face to face, overlap depth h: V = h, F_n = k_V h along
    z exactly. The top cube slides along x by s per step: |f_t| grows by
    k_t s' per step (s' the tangential part of the step, the normal tilting
    as the overlap's x-extent shrinks) until it reaches mu F_n; then it stays
    there, opposite the sliding. k_t = KT_COEF d^2 with d = sqrt(3)."""
    v, t = cube()
    d = np.sqrt(3.0)
    eng = ContactEngine([v], [t], [0, 0], [d, d], K_V, KT_COEF, MU, 0.0, 0.1, walls=False, threads=1)
    h, s = 1e-4, 1e-4
    q = np.tile([1.0, 0, 0, 0], (2, 1))
    kt = KT_COEF * d * d
    fn = K_V * h                                       # the face overlap: 1 x 1 x h
    cap = MU * fn
    slid = 0.0
    for k in range(40):
        eng.step(np.array([[0, 0, 0], [slid, 0, 1 - h]]), q)
        c = eng.contacts()
        ft = c["force_tangential"][0]
        n = c["normal"][0]
        vol = c["volume"][0]
        assert vol == pytest.approx(h * (1 - slid), rel=1e-12)
        # once sliding, the normal tilts by atan(h / (1 - slid)) towards +x:
        # S_A has A's +x face strip (h x 1) besides the top face
        # ((1 - slid) x 1); aligned, both x faces lie on A and B and cancel
        tilt = np.array([h, 0, 1 - slid]) if slid > 0 else np.array([0, 0, 1.0])
        assert n == pytest.approx(tilt / np.linalg.norm(tilt), abs=1e-12)
        expected = min(kt * s * k, MU * K_V * vol)        # up to the tilt factor (1e-6 here)
        assert np.linalg.norm(ft) == pytest.approx(expected, rel=2e-6)
        assert ft[0] <= 0 and abs(ft @ n) < 1e-12 * (np.linalg.norm(ft) + 1e-30)
        slid += s
    assert kt * s * 39 > cap                           # the run did reach the cap


@pytest.mark.parametrize("mu_new", [0.4, 0.6])
def test_a_friction_change_caps_the_shear_history_at_the_next_step(mu_new):
    """The scene compacts at one friction and shears at another
    (``set_friction`` before shear). Two unit cubes face to face, the top one
    slid until |f_t| = MU F_n; then the friction is set to mu_new and the
    pose kept. Lowered (0.4), the history is cut to mu_new F_n at that very
    step; raised (0.6), the elastic history is kept as it was (no motion, no
    increment)."""
    v, t = cube()
    d = np.sqrt(3.0)
    eng = ContactEngine([v], [t], [0, 0], [d, d], K_V, KT_COEF, MU, 0.0, 0.1, walls=False, threads=1)
    h, s = 1e-4, 1e-3
    q = np.tile([1.0, 0, 0, 0], (2, 1))
    for k in range(6):
        pos = np.array([[0, 0, 0], [s * k, 0, 1 - h]])
        eng.step(pos, q)
    c = eng.contacts()
    fn, ft = np.linalg.norm(c["force_normal"][0]), np.linalg.norm(c["force_tangential"][0])
    assert ft == pytest.approx(MU * fn, rel=1e-12)      # sliding at the old cap
    eng.set_friction(mu_new, 0.0)
    assert eng.friction == (mu_new, 0.0)
    eng.step(pos, q)
    c = eng.contacts()
    fn2, ft2 = np.linalg.norm(c["force_normal"][0]), np.linalg.norm(c["force_tangential"][0])
    assert fn2 == pytest.approx(fn, rel=1e-12)
    assert ft2 == pytest.approx(min(mu_new, MU) * fn, rel=1e-12)


def test_threads_give_identical_forces_and_history_survives_rebuilds(grains):
    verts, tris, pos, quat, sizes = packing(grains, 6, seed=6)      # 216 grains: the parallel path
    lo, hi = pos.min(axis=0) - 0.1, pos.max(axis=0) + 0.1
    walls = np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])
    engines = [engine_for(verts, tris, sizes, walls=True, threads=th) for th in (1, 2)]
    rng = np.random.default_rng(7)
    p = pos
    for step in range(4):
        p = p + rng.normal(scale=1e-3, size=p.shape)
        out = [tuple(a.copy() for a in e.step(p, quat, walls)) for e in engines]
        for a, b in zip(*out):
            np.testing.assert_array_equal(a, b)
    e = engines[0]
    c = e.contacts()
    k = int(np.flatnonzero(c["i"] >= 0)[0])
    i, j = int(c["i"][k]), int(c["j"][k])
    before = e.n_rebuilds
    # move a body far from (i, j) by more than the skin: the list is rebuilt;
    # (i, j) did not move, so its shear force is only turned into the new
    # tangent plane (which is the old one): unchanged
    far = int(np.argmax(np.linalg.norm(p - p[i], axis=1)))
    assert far not in (i, j)
    p2 = p.copy()
    p2[far] += [0.2, 0, 0]
    e.step(p2, quat, walls)
    assert e.n_rebuilds == before + 1
    c2 = e.contacts()
    k2 = int(np.flatnonzero((c2["i"] == i) & (c2["j"] == j))[0])
    np.testing.assert_allclose(c2["force_tangential"][k2], c["force_tangential"][k], rtol=1e-12, atol=0)
    e.set_history(i, j, [0.0, 0.0, 0.0])
    with pytest.raises(KeyError):
        e.set_history(far, far, [0.0, 0.0, 0.0])


def test_bad_input_is_refused_clearly(grains):
    verts, tris, pos, quat, sizes = packing(grains, 2, seed=8)
    eng = engine_for(verts, tris, sizes, walls=False)
    bad = pos.copy()
    bad[3, 1] = np.nan
    with pytest.raises(EngineError, match="not finite"):
        eng.step(bad, quat)
    with pytest.raises(ValueError, match="positions must be"):
        eng.step(pos[:-1], quat)
    with pytest.raises(ValueError, match="shape index out of range"):
        ContactEngine(verts, tris, np.arange(len(verts)) + 1, sizes, K_V, KT_COEF, MU, 0, 0.05)
    # an orientation the kernel would have taken as the identity (zero, NaN)
    # or lost to round-off (squared norm under 1e-200 or over 1e200): refused,
    # naming the body; the C function says so too, past the Python step
    for q in ([0, 0, 0, 0], [np.nan, 0, 0, 1], [1e-101, 0, 0, 0], [1e101, 0, 0, 0], [np.inf, 0, 0, 0]):
        badq = quat.copy()
        badq[5] = q
        with pytest.raises(EngineError, match=r"body 5: orientation quaternion .* is zero, not finite or out of range"):
            eng.step(pos, badq)
        from shapes import ckernel
        err = eng.lib.pc_engine_step(eng._live(), ckernel.dptr(ckernel.f64(pos)), ckernel.dptr(ckernel.f64(badq)),
                                     ckernel.dptr(eng._no_walls), ckernel.dptr(eng.force), ckernel.dptr(eng.torque),
                                     ckernel.dptr(eng.wall_force), ckernel.dptr(eng.stat))
        assert err == -5
        with pytest.raises(EngineError, match="an orientation quaternion is zero"):
            eng.raise_for(err)
    tiny = quat * 2.0 ** -300                           # tiny but in range: the same rotations, to the bit
    F, T, _ = eng.step(pos, tiny)                      # a refused step leaves the engine usable
    ref = engine_for(verts, tris, sizes, walls=False)
    F2, T2, _ = ref.step(pos, quat)
    np.testing.assert_array_equal(F, F2)
    np.testing.assert_array_equal(T, T2)


def test_a_restored_state_continues_bit_for_bit(grains):
    """state() at step 4, set_state() on a fresh engine: steps 5-9 give the
    same forces, torques, wall forces and contacts, bit for bit, including a
    neighbour-list rebuild on the way; a state of another engine is refused."""
    verts, tris, pos, quat, sizes = packing(grains, 3, seed=9)
    lo, hi = pos.min(axis=0) - 0.1, pos.max(axis=0) + 0.1
    walls = np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])
    rng = np.random.default_rng(10)
    poses = []
    p = pos
    for k in range(10):
        p = p + rng.normal(scale=2e-3, size=p.shape) + (0.06 * (k == 7)) * np.eye(3)[0]   # step 7 rebuilds
        poses.append(p)
    a = engine_for(verts, tris, sizes, walls=True)
    for k in range(5):
        a.step(poses[k], quat, walls)
    saved = {k: v.copy() for k, v in a.state().items()}
    assert len(saved["pair_ids"]) > 0 and np.any(saved["pair_records"][:, :3] != 0)   # shear history in it
    b = engine_for(verts, tris, sizes, walls=True)
    b.set_state(saved)
    for key, val in b.contacts().items():
        np.testing.assert_array_equal(val, a.contacts()[key])
    rebuilds = a.n_rebuilds
    for k in range(5, 10):
        fa = [x.copy() for x in a.step(poses[k], quat, walls)]
        fb = [x.copy() for x in b.step(poses[k], quat, walls)]
        for x, y in zip(fa, fb):
            np.testing.assert_array_equal(x, y)
        ca, cb = a.contacts(), b.contacts()
        for key in ca:
            np.testing.assert_array_equal(ca[key], cb[key])
    assert a.n_rebuilds > rebuilds and a.n_rebuilds == b.n_rebuilds
    other = engine_for(verts[:5], tris[:5], sizes[:5], walls=True)
    with pytest.raises(ValueError, match="engine state: x has shape"):
        other.set_state(saved)
    bad = dict(saved, pair_ids=saved["pair_ids"][:, ::-1].copy())
    with pytest.raises(ValueError, match="pair ids"):
        b.set_state(bad)


# ---------------------------------------------------------------- the fast path against the plain one
# The fast path (proofs of separation, shared-vertex cuts) and the plain one
# (face tests and polygon clipping for every listed pair) compute the same
# overlap vertices bit for bit; only the order in which the cap polygons are
# summed differs, so volumes, centroids and normals differ by a few ulps of
# the overlap's own size, and so do forces and (through the tangential
# history) the forces of later steps. REL: 1e-12 of the largest force, about
# 5000 ulps, covers that after tens of steps; contact sets must be equal.
REL = 1e-12


def contact_rows(eng):
    c = eng.contacts()
    key = c["i"] * (eng.n + 1) + c["j"]
    o = np.argsort(key)
    return key[o], {k: v[o] for k, v in c.items()}


def step_both(fast, plain, pos, quat, walls=None, rel=REL):
    """One step of both engines; asserts they agree (forces and volumes to
    ``rel``); returns the fast one's contacts."""
    out_f = [x.copy() for x in fast.step(pos, quat, walls)]
    out_p = [x.copy() for x in plain.step(pos, quat, walls)]
    kf, cf = contact_rows(fast)
    kp, cp = contact_rows(plain)
    np.testing.assert_array_equal(kf, kp)              # no contact missed, none added
    scale = max(np.abs(out_p[0]).max(), 1e-300)
    for a, b in zip(out_f, out_p):
        assert a.size == 0 or np.abs(a - b).max() <= rel * scale
    if len(kf):
        vmax = cp["volume"].max()
        assert np.abs(cf["volume"] - cp["volume"]).max() <= rel * vmax
        np.testing.assert_allclose(cf["normal"], cp["normal"], rtol=0, atol=1e-9)
        np.testing.assert_allclose(cf["area"], cp["area"], rtol=1e-9, atol=1e-12 * np.nanmax(cp["area"]))
    return cf


def pair_engines(verts, tris, sizes, skin=0.05):
    mk = lambda fast: ContactEngine(verts, tris, np.arange(len(verts)), sizes, K_V, KT_COEF, MU, 0.0, skin,
                                    walls=False, threads=1, fast=fast)
    return mk(True), mk(False)


def test_fast_path_equals_plain_path_on_a_moving_packing(grains):
    """64 grains jostled for 40 steps (contacts form, slide and break, the
    list is rebuilt): at every step the fast and plain engines find the same
    contacts, and the same forces and torques to REL; both also match the
    one-pair geometry (batch_overlap) of the step's poses; the separation
    proofs do most of the work."""
    verts, tris, pos, quat, sizes = packing(grains, 4, seed=21)
    fast, plain = pair_engines(verts, tris, sizes)
    rng = np.random.default_rng(22)
    proved = clipped = kept = 0
    q = quat.copy()
    for k in range(40):
        pos = pos + rng.normal(scale=4e-3, size=pos.shape)
        dq = np.roll(Rotation.from_rotvec(rng.normal(scale=2e-2, size=(len(pos), 3))).as_quat(), 1, axis=1)
        q = np.roll((Rotation.from_quat(np.roll(dq, -1, axis=1)) * Rotation.from_quat(np.roll(q, -1, axis=1)))
                    .as_quat(), 1, axis=1)
        c = step_both(fast, plain, pos, q)
        st = fast.stats
        proved += st["apart_by_motion_bound"] + st["apart_by_cached_axis"] + st["apart_by_axis_search"]
        clipped += st["clipped_pairs"]
        kept += st["structure_kept"]
        assert st["clip_fallbacks"] == 0 and plain.stats["apart_by_motion_bound"] == 0
        assert plain.stats["structure_kept"] == 0
        if k % 10 == 9:
            i, j, ref = reference_pairs(verts, tris, pos, q)
            np.testing.assert_array_equal(c["i"], i)
            np.testing.assert_array_equal(c["j"], j)
            np.testing.assert_allclose(c["volume"], ref["volume"], rtol=1e-9)
    assert proved > clipped > 0
    assert kept > 0                                           # touching pairs reused their structure


@pytest.mark.parametrize("depth", [1e-9, 1e-6, 1e-3, 0.1])
def test_hard_cases_exact_volumes_on_both_paths(depth):
    """Unit cubes (d = sqrt 3) at depths 1e-9 d to 0.1 d, each pose stepped
    twice (a new contact, then a hot one): face on face V = h, parallel edges
    on edges (both turned 45 deg about y) V = h^2/2, a vertex on a face
    V = sqrt(3) h^3 / 2; fast and plain agree, and the volumes are exact to
    the round-off of unit coordinates (1e-15 absolute per unit area). The
    fast path cuts the cube's faces as squares, the plain one as two
    triangles each, so their normals (sums of the faces' area vectors) differ
    by round-off of the overlap's area, about 1e-12 of a thin wedge's: the
    forces are compared to 1e-11 of the largest here."""
    v, t = cube()
    d = np.sqrt(3.0)
    h = depth * d
    up = Rotation.align_vectors([[0, 0, 1]], [[1, 1, 1]])[0]           # a vertex along z
    turn = Rotation.from_euler("y", 45, degrees=True)
    cases = [(Rotation.identity(), Rotation.identity(), 1.0 - h, h),
             (turn, turn, np.sqrt(2.0) - h, h * h / 2),
             (up, Rotation.identity(), np.sqrt(3.0) / 2 + 0.5 - h, np.sqrt(3.0) * h ** 3 / 2)]
    for ra, rb, z, exact in cases:
        fast, plain = pair_engines([v, v], [t, t], np.array([d, d]))
        pos = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, z]])
        quat = np.roll(np.stack([ra.as_quat(), rb.as_quat()]), 1, axis=1)
        for _ in range(2):
            c = step_both(fast, plain, pos, quat, rel=1e-11)
            if exact < 1e-300:
                continue
            assert len(c["volume"]) == 1
            assert abs(c["volume"][0] - exact) <= 4e-15 * max(1.0, exact ** (2 / 3)) + 1e-12 * exact


def test_a_grain_almost_inside_another(grains):
    """A grain scaled by 0.3 inside a full one, pushed until one vertex pokes
    out of it: both paths agree and give the one-pair geometry's volume."""
    v, t = grains[0][0], grains[1][0]
    small = v * 0.3
    sizes = np.array([2 * np.linalg.norm(v, axis=1).max(), 2 * np.linalg.norm(small, axis=1).max()])
    fast, plain = pair_engines([v, small], [t, t], sizes)
    quat = np.array([[1.0, 0, 0, 0], [0.9, 0.1, 0.3, 0.2]])
    quat[1] /= np.linalg.norm(quat[1])
    for x in np.linspace(0.0, 0.4, 9):
        pos = np.array([[0.0, 0.0, 0.0], [x, 0.0, 0.0]])
        for _ in range(2):
            c = step_both(fast, plain, pos, quat)
        i, j, ref = reference_pairs([v, small], [t, t], pos, quat)
        np.testing.assert_allclose(c["volume"], ref["volume"], rtol=1e-9)


def test_separate_touch_again_and_turn_fast_the_cache_never_hides_a_contact(grains):
    """Two grains that touch, separate for a few steps (the fast path keeps a
    separating axis and its gap), touch again, and then one turns by up to
    90 degrees in a single step while still apart by less than that turn
    sweeps: at every step both paths give the same contacts as the one-pair
    geometry, so no proof ever claimed a false separation."""
    v, t = grains[0][3], grains[1][3]
    d = 2 * np.linalg.norm(v, axis=1).max()
    fast, plain = pair_engines([v, v], [t, t], np.array([d, d]), skin=0.5 * d)
    quat = np.array([[1.0, 0, 0, 0], [1.0, 0, 0, 0]])
    touching = []
    xs = list(np.linspace(0.6 * d, 1.05 * d, 10)) + list(np.linspace(1.05 * d, 0.6 * d, 10))
    for x in xs:
        pos = np.array([[0.0, 0.0, 0.0], [x, 0.0, 0.0]])
        c = step_both(fast, plain, pos, quat)
        i, j, ref = reference_pairs([v, v], [t, t], pos, quat)
        assert len(c["i"]) == len(i)
        touching.append(len(i))
    assert 0 in touching and max(touching) == 1                # it did separate and touch again
    # B's long axis (x) across the line of centres, apart by a small gap;
    # then B turns its long axis towards A by large angles in single steps
    across = lambda angle: np.array([[1.0, 0, 0, 0], np.roll(Rotation.from_euler("z", angle, degrees=True)
                                                                 .as_quat(), 1)])
    x_apart = None
    for x in np.linspace(0.4 * d, 1.1 * d, 300):
        pos = np.array([[0.0, 0.0, 0.0], [x, 0.0, 0.0]])
        if len(reference_pairs([v, v], [t, t], pos, across(90))[0]) == 0:
            x_apart = x
            break
    assert x_apart is not None
    pos = np.array([[0.0, 0.0, 0.0], [x_apart, 0.0, 0.0]])
    hits = broken = 0
    for angle in (90, 90, 85, 60, 60, 0, 0, 90, 45):
        q = across(angle)
        c = step_both(fast, plain, pos, q)
        ref = reference_pairs([v, v], [t, t], pos, q)[0]
        assert len(c["i"]) == len(ref)
        hits += len(ref)
        broken += fast.stats["structure_broken"]
    assert hits > 0                                           # some turn brought them into contact
    assert broken > 0                                         # a turn broke a kept structure, which was cut again


@pytest.mark.parametrize("fast", [True, False])
def test_a_workspace_overflow_stops_the_step_with_a_message(grains, fast):
    verts, tris, pos, quat, sizes = packing(grains, 2, seed=8)
    eng = ContactEngine(verts, tris, np.arange(len(verts)), sizes, K_V, KT_COEF, MU, 0.0, 0.05, walls=False,
                        threads=1, fast=fast)
    F, _, _ = eng.step(pos, quat)
    assert eng.n_pair_contacts > 0
    eng.set_workspace_points(16)
    with pytest.raises(EngineError, match=r"\d+ contacts overflowed the clipping workspace"):
        eng.step(pos, quat)
    assert eng.stats["workspace_overflows"] >= 1
    with pytest.raises(ValueError, match="workspace points"):
        eng.set_workspace_points(10)


def test_the_c_side_names_its_counters_and_sizes_its_records(grains):
    from shapes.engine import layout
    L = layout()
    assert L["stat_names"][:3] == ("touching_pairs", "wall_contacts", "listed_pairs")
    assert len(set(L["stat_names"])) == len(L["stat_names"])
    verts, tris, pos, quat, sizes = packing(grains, 2, seed=8)
    eng = engine_for(verts, tris, sizes, walls=False)
    eng.step(pos, quat)
    assert set(eng.stats) == set(L["stat_names"])
    st = eng.state()
    assert st["pair_records"].shape[1] == L["pair_doubles"] and st["scalars"].shape == (L["scalars"],)
    old = dict(st, pair_records=st["pair_records"][:, :20].copy())   # an older kernel's 20-double records
    with pytest.raises(ValueError, match="pair_records has shape"):
        eng.set_state(old)
    with pytest.raises(ValueError, match="lacks"):
        eng.set_state({k: v for k, v in st.items() if k != "motion"})


def test_wall_positions_and_triangles_are_validated(grains):
    verts, tris, pos, quat, sizes = packing(grains, 2, seed=8)
    eng = engine_for(verts, tris, sizes, walls=True)
    lo, hi = pos.min(axis=0) - 0.1, pos.max(axis=0) + 0.1
    good = np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])
    with pytest.raises(ValueError, match="give their positions"):
        eng.step(pos, quat)
    with pytest.raises(ValueError, match="6 finite numbers"):
        eng.step(pos, quat, good[:5])
    with pytest.raises(ValueError, match="6 finite numbers"):
        eng.step(pos, quat, np.where(np.arange(6) == 2, np.nan, good))
    with pytest.raises(ValueError, match="below its high wall"):
        eng.step(pos, quat, good[[1, 0, 2, 3, 4, 5]])
    eng.step(pos, quat, good)
    bad = [t.copy() for t in tris]
    bad[1][4, 2] = len(verts[1])
    with pytest.raises(ValueError, match="shape 1: triangle index"):
        engine_for(verts, bad, sizes, walls=False)


def pushed_pair(verts, tris, rng, steps, amp_range, turn_range, drift=0.0):
    """Two shapes pushed together along a random trajectory by the fast engine,
    checked at every step against the one-pair geometry (a contact exactly
    when it finds one, its volume to 1e-9): steps of 10**U(amp_range) and
    turns of 10**U(turn_range), drawn from ``rng``, plus ``drift`` along the
    line of centres. Returns (steps in contact, structures kept, broken)."""
    sizes = np.array([2 * np.linalg.norm(v, axis=1).max() for v in verts])
    eng = ContactEngine(verts, tris, np.arange(2), sizes, K_V, KT_COEF, MU, 0.0, 0.5, walls=False, threads=1)
    table = ShapeTable(list(zip(verts, tris)))
    u = rng.normal(size=3)
    u /= np.linalg.norm(u)
    x = 0.55 * u * rng.uniform(0.8, 1.0)
    q = np.roll(Rotation.random(2, random_state=rng).as_quat(), 1, axis=1)
    amp, turn = 10 ** rng.uniform(*amp_range), 10 ** rng.uniform(*turn_range)
    contacts = kept = broken = 0
    for k in range(steps):
        x = x + rng.normal(scale=amp, size=3) - 0.3 * amp * u - drift * u
        q[1] = np.roll((Rotation.from_rotvec(rng.normal(scale=turn, size=3))
                        * Rotation.from_quat(np.roll(q[1], -1))).as_quat(), 1)
        pos = np.array([[0.0, 0.0, 0.0], x])
        eng.step(pos, q)
        c = eng.contacts()
        ref = batch_overlap(table, np.array([0]), pos[:1], q[:1], np.array([1]), pos[1:], q[1:], threads=1)
        assert len(c["i"]) == int(ref["volume"][0] > 0)
        if len(c["i"]):
            contacts += 1
            np.testing.assert_allclose(c["volume"], ref["volume"], rtol=1e-9)
        kept += eng.stats["structure_kept"]
        broken += eng.stats["structure_broken"]
    return contacts, kept, broken


def test_kept_structures_never_outlive_their_validity():
    """120 random pairs of library grains pushed together along random
    trajectories (steps of 1e-6 to 3e-2 d, turns of 1e-6 to 0.3 rad): at
    every step the fast engine (which reuses the last step's face structure
    while its checks hold) finds the contact exactly when the one-pair
    geometry does, with its volume to 1e-9 (the tolerance of two clipping
    orders, as above); structures are both reused and broken on the way."""
    shapes, _ = generate_library(12, seed=5)
    V, T = [s.vertices for s in shapes], [s.triangles for s in shapes]
    rng = np.random.default_rng(1)
    kept = broken = contacts = 0
    for trial in range(120):
        a, b = rng.integers(len(V), size=2)
        verts, tris = [V[a], V[b]], [T[a], T[b]]
        n, k, b = pushed_pair(verts, tris, rng, 30, (-6, -1.5), (-6, -0.5))
        contacts, kept, broken = contacts + n, kept + k, broken + b
    assert contacts > 1000 and kept > 500 and broken > 100


def prism(n, radius, height):
    """A right prism on a regular n-gon: its two n-gon faces fanned into
    n - 2 triangles each and its sides split in two, so that every face is
    several coplanar triangles (as YADE's polyhedra, whose polygonal faces
    come triangulated)."""
    a = 2 * np.pi * np.arange(n) / n
    ring = np.stack([radius * np.cos(a), radius * np.sin(a)], 1)
    v = np.vstack([np.c_[ring, np.full(n, -height / 2)], np.c_[ring, np.full(n, height / 2)]])
    t = [[0, k + 1, k] for k in range(1, n - 1)] + [[n, n + k, n + k + 1] for k in range(1, n - 1)]
    for k in range(n):
        m = (k + 1) % n
        t += [[k, m, n + m], [k, n + m, n + k]]
    return v, np.array(t)


def test_kept_structures_of_shapes_with_coplanar_triangles():
    """Pairs of prisms (five-, six- and eight-sided) and cubes, whose faces
    are each two triangles or more, pushed together as above: the fast engine reuses
    their face structure too (the cuts take a plane once, the structure
    looks its vertices and edges up on the planes' whole faces), and its
    contacts and volumes are the one-pair geometry's at every step."""
    cv, ct = cube()
    split = [prism(5, 0.5, 0.7), prism(6, 0.45, 0.9), prism(8, 0.5, 0.6), (0.8 * cv, ct)]
    rng = np.random.default_rng(3)
    kept = contacts = 0
    for trial in range(40):
        a, b = rng.integers(len(split), size=2)
        verts, tris = [split[a][0], split[b][0]], [split[a][1], split[b][1]]
        n, k, _ = pushed_pair(verts, tris, rng, 25, (-6, -2.5), (-6, -2), drift=2e-3)
        contacts, kept = contacts + n, kept + k
    assert contacts > 300 and kept > 0.5 * contacts


def test_a_closed_engine_refuses_every_call_in_one_line():
    """After close() (or a second close(), which does nothing) each method
    raises EngineError instead of handing the C side a freed engine."""
    v, t = cube()
    d = 2 * np.linalg.norm(v, axis=1).max()
    eng = ContactEngine([v], [t], [0, 0], [d, d], K_V, KT_COEF, MU, 0.0, 0.1, walls=False, threads=1)
    eng.close()
    eng.close()
    pos = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.9 * d]])
    quat = np.tile([1.0, 0.0, 0.0, 0.0], (2, 1))
    for call in (lambda: eng.step(pos, quat), eng.contacts, eng.state, eng.memory_bytes, lambda: eng.friction,
                 lambda: eng.set_friction(0.3, 0.0), lambda: eng.set_groups([0, 0]), lambda: eng.set_facets(1)):
        with pytest.raises(EngineError, match="^the contact engine is closed$"):
            call()


def cut_polytope(rng, planes=15):
    """A random convex polytope as YADE's ``polyhedra_utils.polyhedra`` makes
    them: a few random planes about the origin (distances 0.35 to 0.5), its
    vertices each on three planes, its polygonal faces triangulated (qhull),
    so most faces are several coplanar triangles. Returns vertices (V, 3)
    about the centroid and outward triangles (T, 3)."""
    from scipy.spatial import ConvexHull, HalfspaceIntersection
    u = rng.normal(size=(planes, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    box = np.vstack([np.eye(3), -np.eye(3)])
    n = np.vstack([u, box])
    h = np.r_[rng.uniform(0.35, 0.5, planes), np.full(6, 0.5)]
    v = HalfspaceIntersection(np.c_[n, -h], np.zeros(3)).intersections
    hull = ConvexHull(v)
    v = v[hull.vertices]
    hull = ConvexHull(v)
    v = v - v.mean(axis=0)
    t = hull.simplices.copy()
    for k, (a, b, c) in enumerate(t):
        if np.dot(np.cross(v[b] - v[a], v[c] - v[a]), v[a] + v[b] + v[c]) < 0:
            t[k] = [a, c, b]
    return v, t


def hull_overlap_volume(va, vb):
    """m^3, the volume of the intersection of the convex hulls of the point
    sets va and vb (scipy: HalfspaceIntersection of their facets' planes), or
    0 when no interior point is found."""
    from scipy.optimize import linprog
    from scipy.spatial import ConvexHull, HalfspaceIntersection
    hs = np.vstack([ConvexHull(va).equations, ConvexHull(vb).equations])
    norm = np.linalg.norm(hs[:, :3], axis=1)
    res = linprog(np.r_[0, 0, 0, -1], A_ub=np.c_[hs[:, :3], norm], b_ub=-hs[:, 3], bounds=[(None, None)] * 3 + [(0, 1)])
    if not res.success or res.x[3] < 1e-9:
        return 0.0
    return ConvexHull(HalfspaceIntersection(hs, res.x[:3]).intersections).volume


def test_polygonal_faces_of_coplanar_triangles_exact_against_scipy():
    """YADE-like random polytopes (polygonal faces, triangulated) pushed
    together in the fast engine, which cuts them face by face (the coplanar
    triangles merged into polygons once per shape): at every step its volume
    equals scipy's HalfspaceIntersection of the two hulls to 1e-9 relative
    (scipy's own round-off is about 1e-12 here), a step without a contact
    is one where scipy finds none (below 1e-12 of a unit grain's volume), and
    the kept structure is reused."""
    rng = np.random.default_rng(7)
    shapes = [cut_polytope(rng) for _ in range(4)]
    from scipy.spatial import ConvexHull
    planes = [len(np.unique(np.round(ConvexHull(v).equations, 9), axis=0)) for v, t in shapes]
    assert all(p < 0.6 * len(t) for p, (v, t) in zip(planes, shapes))          # faces of several triangles
    kept = contacts = 0
    for trial in range(6):
        a, b = rng.integers(len(shapes), size=2)
        verts, tris = [shapes[a][0], shapes[b][0]], [shapes[a][1], shapes[b][1]]
        sizes = np.array([2 * np.linalg.norm(v, axis=1).max() for v in verts])
        eng = ContactEngine(verts, tris, np.arange(2), sizes, K_V, KT_COEF, MU, 0.0, 0.5, walls=False, threads=1)
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        x = 0.64 * u
        q = np.roll(Rotation.random(2, random_state=rng).as_quat(), 1, axis=1)
        for k in range(16):
            x = x - 4e-3 * u + rng.normal(scale=1e-4, size=3)
            pos = np.array([[0.0, 0.0, 0.0], x])
            eng.step(pos, q)
            c = eng.contacts()
            R = [Rotation.from_quat(np.roll(qq, -1)).as_matrix() for qq in q]
            ref = hull_overlap_volume(verts[0] @ R[0].T, verts[1] @ R[1].T + x)
            if len(c["i"]):
                contacts += 1
                np.testing.assert_allclose(c["volume"][0], ref, rtol=1e-9)
            else:
                assert ref < 1e-12
            kept += eng.stats["structure_kept"]
    assert contacts > 60 and kept > 0.25 * contacts


def test_bodies_of_one_group_are_never_a_pair(grains):
    """Groups (a YADE clump's members): the contacts of an engine with
    groups are those of the engine without them, value for value, less the
    pairs of one group >= 0, which are not even listed; the bodies' forces
    are the sums of the remaining contacts'. Set on a running engine, the
    groups drop the listed pairs at once, and a state restored afterwards
    is cut the same way; one group per body or a one-line error."""
    verts, tris, pos, quat, sizes = packing(grains, 3, seed=1)
    n = len(verts)
    groups = np.full(n, -1)
    groups[:9] = np.arange(9) // 3          # three groups of three bodies, the others in none
    plain, grouped = engine_for(verts, tris, sizes, walls=False), engine_for(verts, tris, sizes, walls=False)
    grouped.set_groups(groups)
    plain.step(pos, quat)
    f_grouped, _, _ = grouped.step(pos, quat)
    same = lambda i, j: (groups[i] >= 0) & (groups[i] == groups[j])
    c, g = plain.contacts(), grouped.contacts()
    keep = ~same(c["i"], c["j"])
    assert (~keep).sum() > 0 and keep.sum() > 20       # the packing has contacts of both kinds
    for k in ("i", "j", "volume", "normal", "point", "force_normal", "force_tangential"):
        np.testing.assert_array_equal(g[k], c[k][keep])
    ij = grouped.state()["pair_ids"]
    assert len(ij) and not same(ij[:, 0], ij[:, 1]).any()
    f = np.zeros((n, 3))
    np.add.at(f, g["j"], g["force_normal"] + g["force_tangential"])
    np.add.at(f, g["i"], -(g["force_normal"] + g["force_tangential"]))
    np.testing.assert_allclose(f_grouped, f, rtol=0, atol=1e-12 * np.abs(f).max())
    # on a running engine: the listed pairs of one group go at once, a restored state is cut too
    st = plain.state()
    plain.set_groups(groups)
    assert not same(*plain.state()["pair_ids"].T).any()
    plain.set_state(st)
    np.testing.assert_array_equal(plain.state()["pair_ids"], ij)
    plain.step(pos, quat)
    grouped.step(pos, quat)                  # the second step of both, on the same poses
    for k in ("i", "j", "volume", "force_normal", "force_tangential"):
        np.testing.assert_array_equal(plain.contacts()[k], grouped.contacts()[k])
    plain.set_groups(None)                   # no groups: the next rebuild lists every pair again
    with pytest.raises(ValueError, match="^set_groups: one group per body"):
        plain.set_groups(groups[:-1])
