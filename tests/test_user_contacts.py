"""PolyhedraContactEngine in hand-built user scenes (Debian's yade, the
plugin loaded by the script itself): overlap and force against analytic and
scipy values, O.interactions against the kernel, getStress() against
postproc's stress, bodies added and erased mid-run, refused scenes."""
import json
import os
import shutil
import subprocess

import numpy as np
import pytest
from scipy.spatial import ConvexHull, HalfspaceIntersection

from postproc.stress import contact_stress

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
YADE = shutil.which("yade")
pytestmark = [pytest.mark.yade, pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")]
A, KN = 0.02, 1e8          # cube side (m); k_n = E E / (E + E) with E = 2e8


@pytest.fixture(scope="module")
def res(tmp_path_factory):
    from yade_scripts import yadeplugin

    if not yadeplugin.build()["ok"]:
        pytest.skip("the YADE plugin is not built here")
    env = {k: v for k, v in os.environ.items() if k != "YADE_PREFIX"}
    env["OMP_WAIT_POLICY"] = "PASSIVE"
    out = subprocess.run([YADE, "-j1", "-n", "-x", os.path.join(ROOT, "tests", "yade_cases", "user_contacts.py"), ROOT,
                          str(tmp_path_factory.mktemp("vtk"))],
                         cwd=ROOT, capture_output=True, text=True, timeout=600, env=env, stdin=subprocess.DEVNULL)
    lines = [x for x in out.stdout.splitlines() if x.startswith("RESULT ")]
    assert lines, out.stdout[-3000:] + out.stderr[-3000:]
    return json.loads(lines[-1][len("RESULT "):])


def hull_overlap(a, b):
    """Volume (m^3) and centroid of the intersection of the convex hulls of
    the vertex arrays ``a`` and ``b`` (V, 3), by scipy's
    HalfspaceIntersection (an interior point found by linear programming)."""
    from scipy.optimize import linprog

    planes = np.vstack([ConvexHull(a).equations, ConvexHull(b).equations])      # n.x + c <= 0, |n| = 1
    # the point deepest inside both: max t with n.x + c + t <= 0
    lp = linprog(np.r_[0, 0, 0, -1.0], A_ub=np.c_[planes[:, :3], np.ones(len(planes))], b_ub=-planes[:, 3],
                 bounds=[(None, None)] * 3 + [(0, None)], method="highs")
    assert lp.status == 0 and lp.x[3] > 0
    hull = ConvexHull(HalfspaceIntersection(planes, lp.x[:3]).intersections)
    return hull.volume


def cut_volume(vertices, normal, point):
    """Volume of the convex hull of ``vertices`` beyond the plane through
    ``point`` (the side against ``normal``)."""
    n = np.asarray(normal) / np.linalg.norm(normal)
    u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    w = np.cross(n, u)
    big = [np.asarray(point) + s1 * u + s2 * w - s3 * n for s1 in (-1, 1) for s2 in (-1, 1) for s3 in (0, 1)]
    return hull_overlap(np.asarray(vertices), np.array(big))


def test_cube_on_a_facet(res):
    """A 2 cm cube 0.1 mm into a facet: V = a^2 h = 4e-8 m^3, F = k_n V = 4 N
    along +z on the cube (the facet is id2: its force is -F); after
    O.interactions.clear() the next step's fill writes the one real
    interaction again, its geometry and forces those of the kernel."""
    r = res["facet"]
    assert r["error"] == 0 and r["count"] == 1
    (i,) = r["inter"]
    assert i["volume"] == pytest.approx(A * A * 1e-4, rel=1e-12, abs=0)
    assert r["force"][2] == pytest.approx(KN * A * A * 1e-4, rel=1e-12, abs=0)
    # lateral: the shear of the second step, k_s times the round-off of YADE's quaternion renormalisation
    assert abs(r["force"][0]) < 1e-9 and abs(r["force"][1]) < 1e-9
    assert np.allclose(r["facet_force"], -np.array(r["force"]), rtol=0, atol=1e-12)
    assert np.allclose(i["normal"], [0, 0, -1], atol=1e-15)           # cube (id1) -> facet (id2)
    assert np.allclose(i["point"], [0.001, 0.002, -5e-5], atol=1e-15)  # the overlap's centroid
    assert np.allclose(np.add(i["fn"], i["ft"]), -np.array(r["force"]), rtol=0, atol=1e-15)   # on id2: the facet
    assert (i["kn"], i["ks"]) == (KN, pytest.approx(0.5 * KN)) and i["mu"] == pytest.approx(np.tan(0.5))
    k = r["kernel"]
    assert k["id1"] == [i["id1"]] and k["id2"] == [i["id2"]]
    assert k["volume"][0] == i["volume"] and k["normal"][0] == list(i["normal"])


def test_a_moving_facet(res):
    """A facet rising at 1 m/s (1 um a step) under a held cube 0.1 mm above
    it: no contact for the first 100 steps, then the overlap a^2 (z_f - 0.1 mm)
    with z_f the facet's height the step read (the position before that
    step's move)."""
    r = res["moving"]
    v = np.array(r["volumes"])
    z = 1.0 * r["dt"] * np.arange(len(v))            # the facet's height read at each step
    expected = A * A * np.maximum(z - 1e-4, 0)
    np.testing.assert_allclose(v, expected, rtol=1e-9, atol=1e-12 * A ** 3)
    assert v[150] > 0 and v[:100].max() == 0


def test_cube_on_a_tilted_plane_against_halfspace_intersection(res):
    """A rotated cube into a plane tilted about two axes (a fixed slab,
    contacts.plane_body): the overlap volume equals scipy's
    HalfspaceIntersection of the cube with the slab, and with the plane's
    half-space; the force is k_n V along the plane's normal."""
    r = res["tilted"]
    expected = hull_overlap(np.array(r["cube"]), np.array(r["slab"]))
    (i,) = r["inter"]
    assert expected > 1e-8
    assert cut_volume(np.array(r["cube"]), r["plane_normal"], r["plane_point"]) == pytest.approx(expected, rel=1e-9)
    assert i["volume"] == pytest.approx(expected, rel=1e-9, abs=0)
    n = np.array(i["normal"])                                        # cube (id2) pushed along the slab's normal
    assert abs(np.dot(n, r["plane_normal"])) == pytest.approx(1, abs=1e-6)
    assert np.allclose(r["force"], KN * i["volume"] * np.sign(np.dot(n, r["plane_normal"])) * n, rtol=0,
                       atol=1e-12 * KN * expected)


def test_cube_on_a_wall_of_axis_y(res):
    """A rotated cube into a Wall (axis y, sense -1, at y = 0.1): the overlap
    is the part of the cube beyond y = 0.1, F = -k_n V e_y on the cube and
    the opposite on the wall."""
    r = res["wall"]
    expected = cut_volume(np.array(r["cube"]), [0, -1, 0], [0, r["wall"], 0])
    (i,) = r["inter"]
    assert i["volume"] == pytest.approx(expected, rel=1e-9, abs=0)
    assert r["force"][1] == pytest.approx(-KN * expected, rel=1e-9, abs=0)
    assert np.allclose(r["wall_force"], -np.array(r["force"]), atol=1e-12)


def test_a_wall_across_a_facet_pushes_the_cube_only(res):
    """A Wall (axis x, at x = 0.05) crosses the prism behind a large facet;
    a cube (side a) sits 0.1 mm into both. The wall and the facet each push
    the cube with k_n a^2 h (h = 0.1 mm) and nothing else: no wall-facet
    contact (YADE has no such functor either), so the wall's force is the
    cube's reaction only."""
    r = res["wallfacet"]
    pairs = sorted(tuple(sorted((i["id1"], i["id2"]))) for i in r["inter"])
    assert pairs == sorted([tuple(sorted((r["wall"], r["cube"]))), tuple(sorted((r["facet"], r["cube"])))])
    f = KN * A * A * 1e-4
    np.testing.assert_allclose(r["force"], [-f, 0, f], rtol=1e-9, atol=1e-9 * f)
    np.testing.assert_allclose(r["wall_force"], [f, 0, 0], rtol=1e-9, atol=1e-9 * f)
    np.testing.assert_allclose(r["facet_force"], [0, 0, -f], rtol=1e-9, atol=1e-9 * f)


def test_get_stress_equals_postproc_stress(res):
    """YADE's getStress(V) on O.interactions, filled by the engine, equals
    postproc's contact stress of the kernel's own contacts with the branch
    vectors x2 - x1 (YADE's sign: tension positive, so the negative)."""
    r = res["stress"]
    k = r["kernel"]
    assert r["count"] == len(k["id1"]) > 10
    pos = {int(a): np.array(b) for a, b in r["pos"].items()}
    branch = np.array([pos[j] - pos[i] for i, j in zip(k["id1"], k["id2"])])
    force = np.array(k["force_normal"]) + np.array(k["force_tangential"])
    ours = contact_stress(force, branch, r["volume"])
    theirs = np.array(r["getStress"])
    assert np.abs(ours).max() > 0
    np.testing.assert_allclose(-theirs, ours, rtol=0, atol=1e-12 * np.abs(ours).max())


def test_two_facets_are_never_a_pair(res):
    """A facetBox's facets meet along edges (each side's two triangles along
    a diagonal), so their bounding spheres overlap and, as any two bodies,
    they would be listed; they are not (YADE has no facet-facet functor),
    while the grains are listed against the facets."""
    r = res["stress"]
    ng, rows = r["n_grains"], r["rows"]
    facets = {int(k): np.array(v) for k, v in r["facets"].items()}
    assert len(facets) == 10 and sorted(rows[ng:]) == sorted(facets)
    # facets that share a vertex (to round-off): the pairs a sphere test would list
    ids = sorted(facets)
    sharing = [(a, b) for k, a in enumerate(ids) for b in ids[k + 1:]
               if np.min(np.linalg.norm(facets[a][:, None] - facets[b][None], axis=2)) < 1e-12]
    assert len(sharing) >= 20
    kinds = [(i >= ng) + (j >= ng) for i, j in r["pairs"]]
    assert kinds.count(2) == 0
    assert kinds.count(1) > 0 and kinds.count(0) > 0


def test_vtk_exporter_writes_the_interactions(res):
    """export.VTKExporter.exportInteractions on O.interactions filled by the
    engine: one line cell per contact, with the normal force and volume the
    kernel computed."""
    r = res["stress"]
    (path,) = r["vtk"]
    text = open(path).read()
    n = len(r["kernel"]["id1"])
    assert f"LINES {n} {3 * n}" in text
    fn = np.array(text.split("SCALARS forceN double 1\nLOOKUP_TABLE default\n")[1].split()[:n], float)
    ours = np.linalg.norm(np.array(r["kernel"]["force_normal"]), axis=1)
    np.testing.assert_allclose(np.sort(fn), np.sort(ours), rtol=1e-5)      # VTK writes %g


def test_bodies_added_and_erased_mid_run(res):
    """A cube added at step 10 is picked up (a second scan) and gets its
    contact with the facet; the two sliding cubes' forces, shear history
    included, are those of the run without the addition, bit for bit; an
    erased body leaves the kernel and O.interactions."""
    w, wo = res["added"]["with"], res["added"]["without"]
    assert w["forces"] == wo["forces"]
    assert abs(w["forces"][-1][0][0]) > 0                      # the shear force built by sliding
    assert w["scans"] == 2
    (i,) = w["new_inter"]
    assert i["volume"] == pytest.approx(A * A * 5e-5, rel=1e-9, abs=0)
    assert w["new_force"][2] == pytest.approx(0.5e8 * A * A * 5e-5, rel=1e-9, abs=0)   # E = 1e8 there
    assert w["n_inter"] == 3 and wo["n_inter"] == 2
    gone = res["added"]["after_erase"]
    assert gone["n_inter"] == 1 and 2 not in gone["ids"]


def test_refused_scenes_say_why_in_one_line(res):
    """A periodic cell, a Sphere, a YADE whose PolyhedraGeom is laid out
    otherwise (no field where the plugin would write it), and a plugin built
    from other sources: each refused with a one-line reason."""
    r = res["refused"]
    assert r["periodic"] is not None and "periodic cells are not supported" in r["periodic"]
    assert r["sphere"] is not None and "is a Sphere" in r["sphere"]
    assert r["layout"] is not None and "PolyhedraGeom.normal is not where this plugin can write it" in r["layout"]
    assert r["sources"] is not None and "built from other sources" in r["sources"]
    assert all("\n" not in r[k] for k in ("periodic", "sphere", "layout", "sources"))
