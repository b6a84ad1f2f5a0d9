"""Why is the branch-length anisotropy a_l about 0 for our polyhedra?

    postproc investigate al-investigation DUMP [DUMP ...] [--axis z] [--pairs 20000]

(:func:`investigate`; one dump at a time: :func:`analyse`.)

For each dump (postproc.schema), over its steady snapshots (stage shear,
eps_q >= half its final value, postproc.statistics.steady_indices), pooling
their particle-particle contacts, prints:

1. overall: a, a_l from the tensor (postproc.fabric, with its delta-method
   se on the pooled contacts, which are correlated between snapshots, so
   optimistic) and the batch-means interval of the per-snapshot values;
   a_l of l / d_pair (d_pair = (d1 + d2)/2, the size distribution taken
   out); a_l from a direct least-squares fit of seed eq. a2 to the
   contacts (l = l0 [1 + a_l P2(cos theta)], an estimator independent of
   the tensor inversion); the mean and spread of l / d_pair;
2. <l / d_pair>(theta) in 15 degree bins;
3. (polyhedra) a_l by the pair's mean elongation I/L and flatness S/I
   (quartiles of the contacts), I/L and S/I from each body's own vertices
   (principal_extents: extents along the principal axes of inertia);
4. (polyhedra) a_l per contact group, angular criterion (theta = 5 deg) and
   footprint criterion (t = 0.1);
5. (polyhedra) grain orientation: the order parameter <P2> of the long axes
   against the compression axis, and a_l predicted from geometry alone,
   l_model = rho_1(n) + rho_2(n) (centre-to-surface distances along the
   branch direction n): on the real contacts, and for isotropic branch
   directions with random, the real, all-axial and all-lateral long axes.

A synthetic check of the estimator (postproc.synthetic, known a = 0.08,
a_l = 0.12) is printed first. Everything goes to standard output, as
markdown tables.
"""
from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

from ..axes import axis_vector, quaternion_matrices, rotation_z_to
from .branchlength import solid_moments, length_profile, principal_extents, radial_distance, subset_anisotropy
from ..classify import Classifier
from ..contactset import resolve
from ..schema import DumpReader
from ..statistics import plateau_estimate, steady_indices
from ..strain import box_strains
from ..synthetic import harmonic_contacts

GROUP = {"VV": "simple", "VE": "simple", "VF": "simple", "EE": "simple", "EF": "double",
         "FF": "triple"}


def fit_eq_a2(branch, length, e):
    """a_l from ordinary least squares of length = l0 + l0 a_l P2 over the
    contacts (P2 = 3 cos^2 theta - 1): the regression of the conditional
    mean, valid whatever the density of directions.

    Parameters
    ----------
    branch : ndarray, shape (C, 3)
        Branch vectors (any length unit).
    length : ndarray, shape (C,)
        The per-contact length fitted (l in m, or l / d_pair).
    e : ndarray, shape (3,)
        Unit compression axis.

    Returns
    -------
    float
        a_l (dimensionless).
    """
    c = np.abs(branch @ e) / np.linalg.norm(branch, axis=1)
    X = np.column_stack([np.ones(len(c)), 3 * c * c - 1])
    coef, *_ = np.linalg.lstsq(X, length, rcond=None)
    return coef[1] / coef[0]


def _fmt(r):
    """'a_l ± se' of a :func:`subset_anisotropy` result."""
    return f"{r['a_l']:+.3f} ± {r['a_l_se']:.3f}"


def model_lengths(geo, bodies1, bodies2, R1, R2, n):
    """The branch lengths of a geometric model: rho_1(n) + rho_2(n), each
    grain's centre-to-surface distance along the branch direction.

    Parameters
    ----------
    geo : list of (ndarray, ndarray, ndarray)
        Per shape: vertices (V, 3), triangles (T, 3) and centre of mass (3,),
        in the shape's local frame (m).
    bodies1, bodies2 : ndarray of int, shape (K,)
        Rows into ``geo`` of each pair's two grains.
    R1, R2 : ndarray, shape (K, 3, 3)
        Their local -> global rotations.
    n : ndarray, shape (K, 3)
        Unit branch directions, from grain 1 to grain 2.

    Returns
    -------
    ndarray, shape (K,)
        rho_1(n) + rho_2(-n) (m).
    """
    out = np.zeros(len(n))
    for side, (b, R, sgn) in enumerate(((bodies1, R1, 1.0), (bodies2, R2, -1.0))):
        u = np.einsum("kji,kj->ki", R, sgn * n)          # R^T n, local frame
        for j in np.unique(b):
            sel = b == j
            v, t, cen = geo[j]
            out[sel] += radial_distance(v, t, u[sel], centre=cen)
    return out


def analyse(path, axis, n_pairs, rng):
    """Sections 1 to 5 of the module docstring on one dump, printed.

    Parameters
    ----------
    path : str
        A RUN.h5 dump (polyhedra: every section; spheres: 1 and 2).
    axis : str or array_like
        The compression axis ("x", "y", "z" or a vector).
    n_pairs : int
        Random pairs of the isotropic geometric model (section 5).
    rng : numpy.random.Generator
        Draws the random pairs, directions and spins.

    Returns
    -------
    dict
        ``path``, ``n`` (grains), ``a``, ``a_l`` and ``a_l_norm`` (the
        pooled steady contacts' :func:`subset_anisotropy` results, of l and
        of l / d_pair) and ``el`` (the batch-means estimate of the
        per-snapshot a_l).
    """
    e = axis_vector(axis)
    ax = int(np.argmax(np.abs(e)))
    with DumpReader(path) as r:
        snaps = [r.read(i) for i in range(len(r))]
        shapes = r.shapes()
    stage = np.array([s.stage for s in snaps])
    lengths = np.array([s.box_lengths for s in snaps])
    iso = np.flatnonzero(stage == "isotropic")
    ref = lengths[iso[-1]] if len(iso) else lengths[np.flatnonzero(stage == "shear")[0]]
    eps_q = box_strains(lengths, ref, ax)["eps_q"]
    steady = steady_indices(eps_q, stage)
    last = snaps[steady[-1]]
    nb = len(last.body_ids)
    phi = np.sum(last.volumes) / last.volume if last.volumes is not None else np.nan
    poly = shapes is not None and len(shapes[0]) > 0
    print(f"\n## {path}: {r.sample_kind}, {nb} grains, solid fraction {phi:.3f} (last steady), "
          f"{len(steady)} steady snapshots, eps_q {eps_q[steady[0]]:.3f}..{eps_q[steady[-1]]:.3f}")

    geo, dims, long_local = None, None, None
    if poly:
        verts, tris, _ = shapes
        geo, dims, long_local = [], [], []
        for v, t in zip(verts, tris):
            d, axes = principal_extents(v, t)
            geo.append((v, t, solid_moments(v, t)[1]))
            dims.append(d)
            long_local.append(axes[:, 0])
        dims, long_local = np.array(dims), np.array(long_local)
        classifiers = {}
        classifiers["angular 5°"] = Classifier(shapes, "angular", theta_deg=5.0)
        classifiers["footprint t=0.1"] = Classifier(shapes, "footprint", threshold=0.1)

    # pool the steady contacts
    rows = {k: [] for k in ("branch", "dm", "snap", "il", "si", "b1", "b2", "R1", "R2")}
    groups = {k: [] for k in (classifiers if poly else {})}
    per_snap = {"a": [], "a_l": [], "a_l_norm": []}
    order_p2 = []
    for k in steady:
        s = snaps[k]
        cs = resolve(s)
        pp = cs.pp
        br = cs.arm[pp]
        i1, i2 = cs.i1[pp], cs.i2[pp]
        d1, d2 = s.sizes[i1], s.sizes[i2]
        dm = 0.5 * (d1 + d2)
        rows["branch"].append(br)
        rows["dm"].append(dm)
        rows["snap"].append(np.full(len(br), k))
        ra = subset_anisotropy(br, axis=e)
        rn = subset_anisotropy(br, axis=e, length=np.linalg.norm(br, axis=1) / dm)
        per_snap["a"].append(ra["a"])
        per_snap["a_l"].append(ra["a_l"])
        per_snap["a_l_norm"].append(rn["a_l"])
        if poly:
            sh1, sh2 = s.shape_index[i1], s.shape_index[i2]
            R = quaternion_matrices(s.orientations)
            rows["il"].append(0.5 * (dims[sh1, 1] / dims[sh1, 0] + dims[sh2, 1] / dims[sh2, 0]))
            rows["si"].append(0.5 * (dims[sh1, 2] / dims[sh1, 1] + dims[sh2, 2] / dims[sh2, 1]))
            rows["b1"].append(sh1)
            rows["b2"].append(sh2)
            rows["R1"].append(R[i1])
            rows["R2"].append(R[i2])
            for name, cl in classifiers.items():
                lab = cl.classify(s, variants=False).labels
                groups[name].append(np.array([GROUP.get(x, "other") for x in lab[pp]]))
            glong = np.einsum("bij,bj->bi", R, long_local[s.shape_index])
            c = glong @ e
            order_p2.append((1.5 * c * c - 0.5, dims[s.shape_index, 1] / dims[s.shape_index, 0]))
    br = np.concatenate(rows["branch"])
    dm = np.concatenate(rows["dm"])
    ell = np.linalg.norm(br, axis=1)
    lam = ell / dm

    # 1. overall
    ra = subset_anisotropy(br, axis=e)
    rn = subset_anisotropy(br, axis=e, length=lam)
    ea, el, en = (plateau_estimate([per_snap[k]]) for k in ("a", "a_l", "a_l_norm"))
    print(f"\n1. overall ({len(br)} contacts pooled)")
    print("| quantity | value |\n|---|---|")
    print(f"| a (tensor) | {ra['a']:+.3f} ± {ra['a_se']:.3f}; snapshots {ea.text(3)} |")
    print(f"| a_l of l (tensor, postproc.fabric) | {_fmt(ra)}; snapshots {el.text(3)} |")
    print(f"| a_l of l / d_pair (tensor) | {_fmt(rn)}; snapshots {en.text(3)} |")
    print(f"| a_l of l, direct fit of eq. a2 | {fit_eq_a2(br, ell, e):+.3f} |")
    G = np.einsum("ki,kj->ij", br, br / ell[:, None]) / len(br)
    plain = 2.5 * (e @ G @ e - 0.5 * (np.trace(G) - e @ G @ e)) / np.trace(G)
    print(f"| plain ratio (5/2)(G_3 - G_1)/tr G, G = <l n (x) n>: a + a_l + O(a a_l), "
          f"not a_l | {plain:+.3f} |")
    print(f"| a_l of l / d_pair, direct fit | {fit_eq_a2(br, lam, e):+.3f} |")
    q = np.percentile(lam, [10, 50, 90])
    print(f"| l / d_pair: mean, sd, 10/50/90 % | {lam.mean():.3f}, {lam.std():.3f}, "
          f"{q[0]:.3f} / {q[1]:.3f} / {q[2]:.3f} |")
    print(f"| d_pair / mean d_pair: sd | {(dm / dm.mean()).std():.3f} |")

    # 2. profile
    p = length_profile(br, lam, axis=e)
    pl = length_profile(br, ell / ell.mean(), axis=e)
    print("\n2. <l / d_pair>(theta), theta from the compression axis")
    print("| theta (deg) | contacts | <l/d_pair> ± se | <l>/<l>_all | <d_pair> / mean |\n|---|---|---|---|---|")
    c = np.abs(br @ e) / ell
    th = np.degrees(np.arccos(np.clip(c, 0, 1)))
    for j in range(len(p["lo"])):
        sel = (th >= p["lo"][j]) & (th < p["hi"][j] if j < len(p["lo"]) - 1 else th <= 90)
        print(f"| {p['lo'][j]:.0f}–{p['hi'][j]:.0f} | {p['frac'][j]:.3f} | {p['mean'][j]:.4f} ± "
              f"{p['se'][j]:.4f} | {pl['mean'][j]:.4f} | {dm[sel].mean() / dm.mean():.4f} |")
    if not poly:
        return {"path": path, "n": nb, "a": ra, "a_l": ra, "a_l_norm": rn, "el": el}

    il = np.concatenate(rows["il"])
    si = np.concatenate(rows["si"])
    # 3. elongation
    print("\n3. a_l by the pair's mean elongation I/L and flatness S/I (quartiles of the contacts)")
    print("| split | range | contacts | a | a_l of l | a_l of l/d_pair | <l/d_pair> |\n|---|---|---|---|---|---|---|")
    for name, x in (("I/L", il), ("S/I", si)):
        qs = np.percentile(x, [0, 25, 50, 75, 100])
        for j in range(4):
            m = (x >= qs[j]) & ((x < qs[j + 1]) if j < 3 else (x <= qs[j + 1]))
            r1 = subset_anisotropy(br, m, axis=e)
            r2 = subset_anisotropy(br, m, axis=e, length=lam)
            print(f"| {name} Q{j + 1} | {qs[j]:.2f}–{qs[j + 1]:.2f} | {m.sum()} | {r1['a']:+.3f} | "
                  f"{_fmt(r1)} | {_fmt(r2)} | {lam[m].mean():.3f} |")
    bil = dims[:, 1] / dims[:, 0]
    el_grain = bil < np.percentile(bil, 25)
    both = el_grain[np.concatenate(rows["b1"])] & el_grain[np.concatenate(rows["b2"])]
    r1 = subset_anisotropy(br, both, axis=e)
    r2 = subset_anisotropy(br, both, axis=e, length=lam)
    print(f"| both grains in the most elongated quarter of grains | I/L < "
          f"{np.percentile(bil, 25):.2f} | {both.sum()} | {r1['a']:+.3f} | {_fmt(r1)} | {_fmt(r2)} | "
          f"{lam[both].mean():.3f} |")

    # 4. contact types
    print("\n4. a_l per contact group")
    print("| criterion | group | share | a | a_l of l | a_l of l/d_pair | <l/d_pair> |\n|---|---|---|---|---|---|---|")
    for name in groups:
        g = np.concatenate(groups[name])
        for grp in ("simple", "double", "triple"):
            m = g == grp
            r1 = subset_anisotropy(br, m, axis=e)
            r2 = subset_anisotropy(br, m, axis=e, length=lam)
            print(f"| {name} | {grp} | {m.mean():.2f} | {r1['a']:+.3f} | {_fmt(r1)} | {_fmt(r2)} | "
                  f"{lam[m].mean():.3f} |")

    # 5. orientation and geometric model
    p2 = np.concatenate([o[0] for o in order_p2])
    gil = np.concatenate([o[1] for o in order_p2])
    b1, b2 = np.concatenate(rows["b1"]), np.concatenate(rows["b2"])
    R1, R2 = np.concatenate(rows["R1"]), np.concatenate(rows["R2"])
    n = br / ell[:, None]
    lm = model_lengths(geo, b1, b2, R1, R2, n)
    print("\n5. grain orientation and a_l predicted from the grains' geometry")
    print(f"order parameter <P2(cos angle(long axis, compression axis))>: all grains "
          f"{p2.mean():+.3f}, I/L < 0.65: {p2[gil < 0.65].mean():+.3f} "
          f"({(gil < 0.65).mean():.2f} of the grains); 0 = random, 1 = all axial, -0.5 = all lateral")
    print(f"l_model = rho_1(n) + rho_2(n) on the real contacts: <l / l_model> = {np.mean(ell / lm):.3f}, "
          f"sd {np.std(ell / lm):.3f}; corr(l, l_model) = {np.corrcoef(ell, lm)[0, 1]:.3f}")
    rm = subset_anisotropy(br, axis=e, length=lm)
    print("| branch directions | long axes | a_l of l_model | a_l of l_model / d_pair |\n|---|---|---|---|")
    print(f"| real contacts | real | {_fmt(rm)} | "
          f"{_fmt(subset_anisotropy(br, axis=e, length=lm / dm))} |")
    # isotropic directions, random pairs of the sample's grains
    K = n_pairs
    nz = rng.normal(size=(K, 3))
    nz /= np.linalg.norm(nz, axis=1)[:, None]
    j1, j2 = rng.integers(0, len(geo), K), rng.integers(0, len(geo), K)
    sizes = np.array([2 * np.max(np.linalg.norm(g[0] - g[2], axis=1)) for g in geo])
    dmk = 0.5 * (sizes[j1] + sizes[j2])
    Rlast = quaternion_matrices(last.orientations)
    row_of_shape = np.empty(len(geo), int)
    row_of_shape[last.shape_index] = np.arange(nb)

    to_z = np.array([Rotation.align_vectors([[0.0, 0.0, 1.0]], [a])[0].as_matrix()
                     for a in long_local])

    def aligned(j, lateral):
        # the local long axis onto z (or, for lateral, onto a random
        # direction of the lateral plane), with a random spin about it
        out = Rotation.from_rotvec(rng.uniform(0, 2 * np.pi, (len(j), 1)) * [0, 0, 1.0]).as_matrix() @ to_z[j]
        if lateral:
            tilt = Rotation.from_rotvec(np.pi / 2 * np.array([1.0, 0, 0])).as_matrix()
            turn = Rotation.from_rotvec(rng.uniform(0, 2 * np.pi, (len(j), 1)) * [0, 0, 1.0]).as_matrix()
            out = turn @ (tilt @ out)
        return rotation_z_to(e) @ out

    cases = (("random", Rotation.random(K, random_state=1).as_matrix(),
              Rotation.random(K, random_state=2).as_matrix()),
             ("real (last steady snapshot)", Rlast[row_of_shape[j1]], Rlast[row_of_shape[j2]]),
             ("all along the compression axis", aligned(j1, False), aligned(j2, False)),
             ("all in the lateral plane", aligned(j1, True), aligned(j2, True)))
    for name, RA, RB in cases:
        lk = model_lengths(geo, j1, j2, RA, RB, nz)
        r1 = subset_anisotropy(nz, axis=e, length=lk)
        r2 = subset_anisotropy(nz, axis=e, length=lk / dmk)
        print(f"| isotropic, random pairs ({K}) | {name} | {_fmt(r1)} | {_fmt(r2)} |")
    return {"path": path, "n": nb, "a": ra, "a_l": ra, "a_l_norm": rn, "el": el}


def investigate(dumps, axis="z", n_pairs=20000):
    """The whole investigation, printed: the synthetic check, then
    :func:`analyse` of each dump (a dump that fails is said and skipped),
    then a_l against sample size.

    Parameters
    ----------
    dumps : list of str
        RUN.h5 dumps.
    axis : str
        The compression axis.
    n_pairs : int
        Random pairs of the isotropic geometric model.

    Returns
    -------
    list of dict
        :func:`analyse`'s result for each dump analysed.
    """
    rng = np.random.default_rng(0)
    s = harmonic_contacts(200_000, a=0.08, a_l=0.12, seed=1)
    r = subset_anisotropy(s.branch, axis=2)
    print(f"synthetic check (200000 contacts, a = 0.08, a_l = 0.12 drawn from eqs. a1-a2): "
          f"a = {r['a']:.3f} ± {r['a_se']:.3f}, a_l = {_fmt(r)}, direct fit of eq. a2 "
          f"{fit_eq_a2(s.branch, np.linalg.norm(s.branch, axis=1), np.array([0, 0, 1.0])):+.3f}")
    out = []
    for path in dumps:
        try:
            out.append(analyse(path, axis, n_pairs, rng))
        except Exception as exc:  # one bad dump must not lose the others
            print(f"\n## {path}: skipped: {exc.__class__.__name__}: {exc}")
    print("\nsummary: a_l against sample size")
    print("| dump | grains | a | a_l of l | a_l of l/d_pair | a_l snapshots (batch means) |\n|---|---|---|---|---|---|")
    for o in out:
        print(f"| {o['path']} | {o['n']} | {o['a']['a']:+.3f} | {_fmt(o['a_l'])} | {_fmt(o['a_l_norm'])} | "
              f"{o['el'].text(3)} |")
    return out
