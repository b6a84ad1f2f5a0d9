"""Clumps of polyhedra on PolyhedraContactEngine (Debian's yade, the plugin
loaded by the script itself, tests/yade_cases/user_clumps.py): no contact
between members of one clump, the members' contact forces moving the clump
(NewtonIntegrator sums them into it), against exact values: the overlap and
force of a member pressed into a wall, the weight of a clump at rest and the
damped oscillation that brings it there, clumps appended, made of bodies
already there, and a body released from its clump mid-run."""
import json
import math
import os
import shutil
import subprocess

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
YADE = shutil.which("yade")
pytestmark = [pytest.mark.yade, pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")]
A, KN, RHO, G = 0.02, 1e8, 2000.0, 9.81     # cube side (m), k_n = E E / (E + E) with E = 2e8, density, gravity
DAMPING = 0.5


@pytest.fixture(scope="module")
def res():
    from yade_scripts import yadeplugin

    if not yadeplugin.build()["ok"]:
        pytest.skip("the YADE plugin is not built here")
    env = {k: v for k, v in os.environ.items() if k != "YADE_PREFIX"}
    env["OMP_WAIT_POLICY"] = "PASSIVE"
    out = subprocess.run([YADE, "-j1", "-n", "-x", os.path.join(ROOT, "tests", "yade_cases", "user_clumps.py"), ROOT],
                         cwd=ROOT, capture_output=True, text=True, timeout=600, env=env, stdin=subprocess.DEVNULL)
    lines = [x for x in out.stdout.splitlines() if x.startswith("RESULT ")]
    assert lines, out.stdout[-3000:] + out.stderr[-3000:]
    return json.loads(lines[-1][len("RESULT "):])


def pairs(inter):
    return sorted(tuple(sorted(i[:2])) for i in inter)


def qmul(p, q):
    """Hamilton product of quaternions (w, x, y, z)."""
    a, b, c, d = p
    e, f, g, h = q
    return np.array([a * e - b * f - c * g - d * h, a * f + b * e + c * h - d * g,
                     a * g - b * h + c * e + d * f, a * h + b * g - c * f + d * e])


def rotate_back(q, v):
    """The vector v (3,) in the frame of the unit quaternion q (w, x, y, z)."""
    qc = np.array([q[0], -q[1], -q[2], -q[3]])
    return qmul(qmul(qc, np.r_[0.0, v]), q)[1:]


def test_clump_at_rest_on_a_facet(res):
    """A clump of two cubes overlapping by half a side, let go at rest with
    its bottom on a facet. YADE's clump mass is the members' sum, M = 2 rho
    a^3 (their overlap counted twice, as YADE does for non-spheres); the
    contact stiffness of the two bottom faces is K = 2 k_n a^2, so the clump
    oscillates about h_eq = M g / K below the contact with omega = sqrt(K /
    M) and YADE's local damping d = 0.5: a quarter cycle towards rest has
    stiffness (1 - d) K, one away (1 + d) K, so each half cycle lasts
    (pi / 2 omega) (1/sqrt(1 - d) + 1/sqrt(1 + d)) and shrinks the amplitude
    by r = sqrt((1 - d)/(1 + d)). Checked: the extremes' times and
    amplitudes (to a step and the leapfrog's (omega dt)^2 a half cycle), the
    total contact force M g to the r^n left after n half cycles, the
    members' relative pose in the clump's frame (to round-off) and no
    interaction between the members (their overlap would push each with
    k_n a^3 / 2 = 400 N along x)."""
    r = res["rest"]
    cid, a, b = r["ids"]
    assert r["error"] == 0
    M = r["mass"]
    assert M == pytest.approx(2 * RHO * A ** 3, rel=1e-12) and M == pytest.approx(2 * r["member_mass"], rel=1e-15)
    assert pairs(r["inter"]) == [(0, a), (0, b)]                        # member-facet only
    assert sorted(zip(r["kernel"]["id1"], r["kernel"]["id2"])) == [(a, 0), (b, 0)]
    assert [a, b] not in r["kernel"]["listed"]
    K = 2 * KN * A * A
    h_eq, omega, dt = M * G / K, math.sqrt(K / M), r["dt"]
    ratio = math.sqrt((1 - DAMPING) / (1 + DAMPING))
    t_half = math.pi / (2 * omega) * (1 / math.sqrt(1 - DAMPING) + 1 / math.sqrt(1 + DAMPING))
    x = np.array(r["z"]) - (A / 2 - h_eq)                             # from the equilibrium, m
    turn = np.where(np.sign(np.diff(x))[1:] != np.sign(np.diff(x))[:-1])[0] + 1
    k = np.arange(1, 13)
    # times: the extreme's sample (a step), and YADE switches the damping's sign at a step, not at the
    # instant the force or the velocity turns (up to a step a half cycle); amplitudes: the leapfrog's (omega dt)^2
    assert np.all(np.abs((turn[:12] + 1) * dt - k * t_half) <= (k + 1) * dt)    # z[s] is after step s + 1
    assert np.all(np.abs(np.abs(x[turn[:12]]) / (h_eq * ratio ** k) - 1) <= k * (omega * dt) ** 2)
    # at the end: at rest to the amplitude left
    left = ratio ** math.floor(len(x) * dt / t_half)
    fz = r["force_a"][2] + r["force_b"][2]
    assert abs(fz - M * G) <= M * G * left
    assert abs(x[-1]) <= h_eq * left
    assert r["force_a"][2] == r["force_b"][2]                           # the two bottom faces alike
    assert max(abs(r["force_a"][0]), abs(r["force_b"][0])) < 1e-6      # not the 400 N of a members' pair
    # NewtonIntegrator added the members' forces to the clump (its own force is zero)
    assert r["force_clump"] == [fa + fb for fa, fb in zip(r["force_a"], r["force_b"])]
    for when in ("start", "end"):
        p = r[when]
        q = np.array(p["clump"]["ori"])
        rel = rotate_back(q, np.subtract(p["b"]["pos"], p["a"]["pos"]))
        np.testing.assert_allclose(rel, [A / 2, 0, 0], rtol=0, atol=1e-15)
        for m in ("a", "b"):
            np.testing.assert_allclose(qmul(q * [1, -1, -1, -1], p[m]["ori"]), [1, 0, 0, 0], rtol=0, atol=1e-15)
            off = rotate_back(q, np.subtract(p[m]["pos"], p["clump"]["pos"]))
            np.testing.assert_allclose(off, [-A / 4 if m == "a" else A / 4, 0, 0], rtol=0, atol=1e-15)


def test_clump_member_pressed_into_a_wall(res):
    """A held clump, member A 0.1 mm into a Wall (axis z), member B above
    it, overlapping A by a quarter of a cube and clear of the wall: one
    interaction (wall, A) with V = a^2 h and F = k_n V e_z on A, as for a
    single body; nothing on B; the clump's force the members' sum and its
    torque t_A + (x_A - X) x F_A about its centre X (NewtonIntegrator's
    sum)."""
    r = res["pressed"]
    w, cid, a, b = r["ids"]
    (i,) = r["inter"]
    assert i[:2] == [w, a]
    V = A * A * 1e-4
    assert i[2] == pytest.approx(V, rel=1e-12, abs=0)
    assert r["f"]["a"][2] == pytest.approx(KN * V, rel=1e-12, abs=0)
    assert r["f"]["a"][:2] == [0, 0] and r["f"]["b"] == [0, 0, 0] and r["t"]["b"] == [0, 0, 0]
    assert r["kernel"]["id1"] == [w] and r["kernel"]["id2"] == [a] and r["kernel"]["listed"] == []
    assert r["f"]["clump"] == [fa + fb for fa, fb in zip(r["f"]["a"], r["f"]["b"])]
    X = np.array(r["pos"]["clump"])
    torque = (np.array(r["t"]["a"]) + np.cross(np.array(r["pos"]["a"]) - X, r["f"]["a"])
              + np.cross(np.array(r["pos"]["b"]) - X, r["f"]["b"]))
    assert abs(torque[1]) == pytest.approx(KN * V * A / 4, rel=1e-12)     # lever a/4 along x
    np.testing.assert_allclose(r["t"]["clump"], torque, rtol=0, atol=1e-12 * KN * V * A)


def test_clump_appended_mid_run(res):
    """A held clump appended at step 10 (appendClumped) is picked up by a
    new scan: member A, 0.05 mm into the facet, gets F = k_n a^2 h; B and
    the members' pair are not a contact (not even listed); the cube that
    was there keeps its k_n a^2 (0.1 mm)."""
    r = res["added"]
    f, c0, cid, a, b = r["ids"]
    assert r["before"]["scans"] == 1 and pairs(r["before"]["inter"]) == [(f, c0)]
    assert r["scans"] == 2
    assert pairs(r["inter"]) == [(f, c0), (f, a)]
    assert sorted([a, b]) not in [sorted(p) for p in r["kernel"]["listed"]]
    assert r["f"]["a"][2] == pytest.approx(KN * A * A * 5e-5, rel=1e-12, abs=0)
    assert r["f"]["c0"][2] == pytest.approx(KN * A * A * 1e-4, rel=1e-12, abs=0)
    assert r["f"]["b"] == [0, 0, 0]


def test_bodies_clumped_and_released_mid_run(res):
    """Three held cubes overlapping in a row (V = a^3 / 2, F = k_n V between
    neighbours); clumped (O.bodies.clump) they have no contact and no listed
    pair; the third released from the clump (its clumpId changed: a new
    scan) gets its contact with the second back, the same V and F."""
    r = res["clumped"]
    c1, c2, c3, cl = r["ids"]
    V = A ** 3 / 2
    assert pairs(r["free"]) == [(c1, c2), (c2, c3)]
    for i in r["free"] + r["released"]:
        assert i[2] == pytest.approx(V, rel=1e-12) and np.linalg.norm(i[3]) == pytest.approx(KN * V, rel=1e-12)
    assert r["clumped"] == [] and r["clumped_listed"] == []
    assert r["clump_ids"] == [cl, cl, -1] and r["scans"] == 3
    assert pairs(r["released"]) == [(c2, c3)]
    assert [c1, c2] not in r["released_listed"] and [c2, c3] in r["released_listed"]
    assert r["forces"][0] == [0, 0, 0]
    assert r["forces"][1][0] == pytest.approx(-KN * V, rel=1e-12) and r["forces"][2][0] == pytest.approx(KN * V, rel=1e-12)


def test_a_clumped_wall_is_refused_in_one_line(res):
    """A Wall made a clump's member (YADE allows it): the scan refuses it
    rather than compute its contacts with the clump's other members."""
    msg = res["wall_clump"]
    assert msg is not None and "wall 0 is a member of clump 2" in msg and "\n" not in msg


def test_a_facet_clumped_with_a_cube(res):
    """A facet clumped with the cube 0.1 mm into it (a polyhedron and its
    base moving as one): no contact between them; another cube, not in the
    clump, 0.05 mm into the facet, has its F = k_n a^2 h, the facet the
    opposite, which goes to the clump."""
    r = res["facet_clump"]
    fc, c1, c2, cl = r["ids"]
    (i,) = r["inter"]
    assert sorted(i[:2]) == sorted([fc, c2])
    assert i[2] == pytest.approx(A * A * 5e-5, rel=1e-12, abs=0)
    assert sorted([fc, c1]) not in [sorted(p) for p in r["kernel"]["listed"]]
    assert r["f"]["c1"] == [0, 0, 0]
    assert r["f"]["c2"][2] == pytest.approx(KN * A * A * 5e-5, rel=1e-12, abs=0)
    assert r["f"]["facet"] == [-f for f in r["f"]["c2"]] and r["f"]["clump"] == r["f"]["facet"]
