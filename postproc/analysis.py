"""The per-snapshot analysis: one row of ``summary.csv`` per snapshot.

Pure composition of the physics modules; no file I/O here.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .angular import AngularFunctions, angular_functions, fit_harmonics
from .axes import axis_vector
from .cdpoints import cd_type_columns
from .contactset import ContactSet, resolve
from .classify import AngularTables
from .columns import COMPONENTS, GROUPS
from .contacttypes import DEFAULT_THETA_DEG, GROUP_OF, PAIR_TYPES, ShapeTables
from .coordination import coordination, force_bearing, fraction_below_mean
from .errors import InputError
from .fabric import anisotropies, stress_force_fabric
from .networks import network_statistics, strong_mask
from .pertype import class_columns, class_statistics, partial_stresses, stress_contributions
from .schema import WALL_ORDER, Snapshot
from .strain import box_strains
from .stress import contact_stress, invariants, relative_difference, wall_stress

_IDX = {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "yz": (1, 2), "xz": (0, 2), "xy": (0, 1)}


@dataclass
class SnapshotResult:
    """Everything computed for one snapshot.

    Attributes
    ----------
    row : dict
        The scalars of the snapshot's ``summary.csv`` row (stresses in Pa,
        compression positive; anisotropies; coordination; networks;
        contact types).
    angular : postproc.angular.AngularFunctions
        The binned angular functions of the force-bearing particle pairs
        (for the polar plots).
    fits : dict
        Their harmonic fits (``a_fit``, ``a_l_fit``, ``a_n_fit``,
        ``a_t_fit``, ...; :func:`postproc.angular.fit_harmonics`).
    normal_force : ndarray, shape (C',)
        N, the normal forces of the C' force-bearing particle-particle
        contacts (compression positive).
    labels : ndarray of str, shape (C',)
        Their classes: "VV".."FF" for polyhedra pairs under the chosen
        criterion, "sphere" otherwise (all "sphere" without contact types).
    extents : ndarray, shape (P, 2), or None
        Footprint extents L1/d >= L2/d (dimensionless) of the force-bearing
        polyhedra pairs, NaN for a pair without overlap, when the criterion
        gives them (:attr:`postproc.classify.Classes.rel`); else None.
    """

    row: dict                  # scalars for summary.csv
    angular: AngularFunctions  # binned functions (for the polar plots)
    fits: dict                 # harmonic fits
    normal_force: np.ndarray = None   # (C',) N, force-bearing particle-particle contacts
    labels: np.ndarray = None         # (C',) their classes ("VV".."FF", "sphere")
    extents: np.ndarray = None        # (P, 2) footprint L1 >= L2 over d of the force-bearing
                                      # polyhedra pairs (footprint criterion; NaN: no overlap)


def wall_forces_from_contacts(cs: ContactSet):
    """(6, 3) N, force on each wall slot summed from the wall contacts, or
    None when the wall slots are unknown.

    Parameters
    ----------
    cs : postproc.contactset.ContactSet
        The snapshot's resolved contacts.

    Returns
    -------
    ndarray, shape (6, 3), or None
        N, the force on each wall by the particles, walls in
        ``WALL_ORDER`` (x-, x+, y-, y+, z-, z+): the sum of ``wall_sign *
        force`` over its contacts (zero for a wall without contact); None
        when no contact has a known wall slot.
    """
    known = cs.wall_slot >= 0
    if not known.any():
        return None
    F = np.zeros((len(WALL_ORDER), 3))
    np.add.at(F, cs.wall_slot[known], cs.wall_sign[known, None] * cs.force[known])
    return F


def _stress_columns(prefix, sigma, axis):
    inv = invariants(sigma, axis)
    row = {f"{prefix}{c}": float(sigma[_IDX[c]]) for c in COMPONENTS}
    row.update({
        f"{prefix}sigma_1": inv["principal"][0], f"{prefix}sigma_2": inv["principal"][1],
        f"{prefix}sigma_3": inv["principal"][2],
    })
    # principal directions of sigma_1 and sigma_3 (unit vectors, sign fixed so
    # that the largest component is positive)
    for k, label in ((0, "1"), (2, "3")):
        d = inv["directions"][:, k]
        d = d * np.sign(d[np.argmax(np.abs(d))])
        row.update({f"{prefix}dir{label}_{c}": float(v) for c, v in zip("xyz", d)})
    return row, inv


def contact_type_columns(snap, cs, sel, classifier, p, total, axis):
    """summary.csv columns of the contact types of a polyhedra snapshot
    (seed figs. 10-12 and claim 6), and the class of each contact.

    ``classifier`` a :class:`postproc.classify.Classifier` under any of its
    seven criteria (:func:`postproc.classify.classifier_for` makes the point
    count by default). ``sel`` (C,) bool marks the
    force-bearing particle-particle contacts, over which proportions, force
    ratios, force shares and the signed branch fabric of each class are
    taken (:func:`postproc.pertype.class_statistics`). Partial stresses are
    over all contacts (walls as their own class) and sum to the total;
    ``ct_qp_<k>`` is class k's share of q_axial/p. ``ct_frac_<k>_lo`` /
    ``_hi`` are the proportions with the criterion's parameter (footprint
    threshold, angular tolerance, the point count's alpha, the common
    plane's band or LMGC90's alert distance) halved and doubled, and so are ``ct_fratio_<k>_lo``,
    ``ct_fabric_<k>_lo``, ``strong_frac_FF_lo``, ``weak_frac_FF_lo`` (and
    ``_hi``), claim 6's quantities for its band test. ``z_points`` counts
    a contact as 1, 2 or 3 points (simple, double, triple), as a multi-point
    contact code would, beside ``z`` which counts every pair once (the
    paper's convention). ``total`` is the (3, 3) stress over all contacts
    the partials must sum to. Returns (row, labels (C,), extents (P, 2) of
    the force-bearing polyhedra pairs or None).

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        The snapshot (with normals, body kinds, shapes and orientations).
    cs : postproc.contactset.ContactSet
        Its resolved contacts (C).
    sel : ndarray of bool, shape (C,)
        The force-bearing particle-particle contacts.
    classifier : postproc.classify.Classifier
        The contact-type criterion.
    p : float
        Pa, the mean stress of the total stress (compression positive).
    total : ndarray, shape (3, 3)
        Pa, the stress over all contacts (seed eq. 2).
    axis : ndarray, shape (3,)
        The unit compression axis.

    Returns
    -------
    row : dict
        The ``ct_*``, ``strong_frac_FF_*``, ``weak_frac_FF_*`` columns
        described above, the classifier's columns, ``ct_l1_median``,
        ``ct_l2_median`` (when extents are given) and
        ``ct_points_per_contact`` (mean of 1, 2, 3 over the simple, double,
        triple force-bearing contacts).
    labels : ndarray of str, shape (C,)
        The class of every contact ("VV".."FF", "sphere", "wall").
    extents : ndarray, shape (P, 2), or None
        Dimensionless L1/d >= L2/d of the force-bearing polyhedra pairs
        (NaN: no overlap), or None when the criterion gives none.
    """
    res = classifier.classify(snap, variants=True)
    labels = res.labels
    group_labels = group_labels_of(labels)
    row = dict(res.columns)
    fn, L = cs.normal_force[sel], cs.arm[sel]
    for lab, classes in ((labels[sel], PAIR_TYPES), (group_labels[sel], GROUPS)):
        row.update(class_columns(class_statistics(lab, fn, L, axis), classes, "ct_"))
    row.update({f"ct_qp_{k}": 0.0 for k in PAIR_TYPES + GROUPS})   # a class with no contact carries 0
    for lab in (labels, group_labels):
        parts = partial_stresses(lab, cs.force, cs.arm, cs.volume)
        for k, (_, qk) in stress_contributions(parts, p, axis).items():
            row[f"ct_qp_{k}"] = qk
        if lab is labels:
            row["ct_partial_sum_reldiff"] = relative_difference(sum(parts.values()), total)
    strong = strong_mask(fn) if len(fn) else np.zeros(0, bool)
    for tag, other in res.variants.items():
        other = other[sel]
        og = group_labels_of(other)
        for k in PAIR_TYPES:
            row[f"ct_frac_{k}_{tag}"] = float(np.mean(other == k))
        for k in GROUPS:
            row[f"ct_frac_{k}_{tag}"] = float(np.mean(og == k))
        # claim 6 with the parameter halved and doubled (the band test):
        # force ratio and signed fabric of each type, FF's share of each network
        st = class_statistics(other, fn, L, axis) if len(fn) else {}
        for k in PAIR_TYPES:
            d = st.get(k)
            row[f"ct_fratio_{k}_{tag}"] = d["mean_force_ratio"] if d else np.nan
            row[f"ct_fabric_{k}_{tag}"] = d["fabric_a"] if d else np.nan
        for name, net in (("strong", strong), ("weak", ~strong)):
            row[f"{name}_frac_FF_{tag}"] = float(np.mean(other[net] == "FF")) if net.any() else np.nan
    rel = None
    if res.rel is not None and len(res.rel):
        # the footprint extents of the force-bearing polyhedra pairs, over d
        rel = res.rel[sel[res.poly]]
        for j, name in ((0, "l1"), (1, "l2")):
            x = rel[:, j][np.isfinite(rel[:, j])]
            row[f"ct_{name}_median"] = float(np.median(x)) if len(x) else np.nan
    points = np.select([group_labels[sel] == g for g in GROUPS], [1, 2, 3], 1)
    row["ct_points_per_contact"] = float(points.mean())
    return row, labels, rel


def group_labels_of(labels):
    """(C,) group of each class label: "simple", "double", "triple" for
    the pair types, the label itself otherwise ("sphere", "wall").

    Parameters
    ----------
    labels : array_like of str, shape (C,)
        Contact classes ("VV".."FF", "sphere", "wall").

    Returns
    -------
    ndarray of str, shape (C,)
        The paper's group of each pair type (``GROUP_OF``: VV, VE, VF, EE
        simple, EF double, FF triple), other labels unchanged.
    """
    labels = np.asarray(labels)
    out = labels.astype(object)
    for k, g in GROUP_OF.items():
        out[labels == k] = g
    return out.astype(str)


def analyze_snapshot(snap: Snapshot, axis=2, nbins=18, errors=True, tables=None,
                     theta_deg=DEFAULT_THETA_DEG) -> SnapshotResult:
    """Stress, fabric, force anisotropies and coordination of one snapshot.

    Stress (Pa, compression positive) in three forms: ``s_*`` the internal
    moment sum over all contacts including walls (seed eq. 2, first form:
    the primary one, giving p, q, q/p); ``b_*`` the branch-vector sum over
    particle-particle contacts only (eq. 2, second form); ``w_*`` the wall
    forces over the wall areas. The branch form leaves out the moments of
    the wall contacts, so it falls below the other two by a boundary term of
    relative order d/L.

    Anisotropies from tensors (:func:`postproc.fabric.anisotropies`) over the
    force-bearing particle-particle contacts, and from harmonic fits of the
    binned functions (suffix ``_fit``). ``sff`` = (2/5)(a + a_l + a_n + a_t)
    (eq. 10) and ``sff_residual`` = q_axial/p - sff, where q_axial =
    (sigma_axis - mean lateral)/3 is the signed deviator along the
    compression axis (it equals q once sigma_1 lies along the axis).

    ``tables``: the contact-type criterion of polyhedra snapshots, a
    :class:`postproc.classify.Classifier` under any of its seven criteria
    (:func:`postproc.classify.classifier_for` makes the point count by
    default), or the angular :class:`postproc.contacttypes.ShapeTables`
    (angular criterion at ``theta_deg``); None (the default) for no contact
    types.

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        The snapshot: bodies, contacts (forces on id2 by id1, N), volume
        (m^3), box or wall forces; normals, body kinds, shapes and
        orientations for contact types.
    axis : int, str or array_like of shape (3,), optional
        The compression axis (:func:`postproc.axes.axis_vector`; default 2,
        z).
    nbins : int, optional
        The number of angle bins on [0, pi/2] of the angular functions
        (default 18, 5 deg each).
    errors : bool, optional
        Also give the anisotropies' standard errors ``a_se``, ``a_l_se``,
        ``a_n_se``, ``a_t_se`` (default True).
    tables : postproc.classify.Classifier, postproc.contacttypes.ShapeTables or None, optional
        The contact-type criterion, as said above (used only when the
        snapshot has a polyhedron).
    theta_deg : float, optional
        deg, the angular tolerance when ``tables`` is a ShapeTables
        (default 5).

    Returns
    -------
    SnapshotResult
        The ``summary.csv`` row (every column declared, with its unit and
        meaning, in :data:`postproc.columns.COLUMNS`): identification, the stress components,
        principal values (Pa) and directions of the three forms, p, q =
        (sigma_1 - sigma_3)/3, q/p, q_axial/p, sin phi = 3q/(2p + q), the
        relative differences between the forms; a, a_l, a_n, a_t (and
        ``_se``, ``_fit``), l0 (m), f0 (N), ``sff``, the residuals;
        coordination ``z``; the fraction of forces below the mean; the
        strong and weak networks and their shares of q_axial/p; contact
        types when asked for; the contact counts. With it the angular
        functions, their fits, and the normal forces, classes and
        footprint extents of the force-bearing particle pairs.

    Raises
    ------
    InputError
        A bad snapshot (:func:`postproc.contactset.resolve`), no
        force-bearing particle-particle contact, or a contact-type error.
    """
    where = f"snapshot {snap.name} (step {snap.step})"
    cs = resolve(snap)
    e = axis_vector(axis)
    bearing = force_bearing(cs.force)
    sel = cs.pp & bearing
    if not sel.any():
        raise InputError(f"{where}: no force-bearing particle-particle contacts")
    V = cs.volume
    s_m = contact_stress(cs.force, cs.arm, V)
    s_b = contact_stress(cs.force[cs.pp], cs.arm[cs.pp], V)
    row = {"snapshot": snap.name, "step": snap.step, "time": snap.time,
           "stage": snap.stage, "volume": V}
    cols, inv = _stress_columns("s_", s_m, e)
    row.update(cols)
    p = inv["p"]
    row.update({"p": p, "q": inv["q"], "q_over_p": inv["q_over_p"],
                "q_axial_over_p": inv["q_axial"] / p if p else np.nan,
                "angle_sigma1_axis": inv["angle_1"],
                "antisymmetry": inv["antisymmetry"]})
    row["sin_phi"] = 3 * inv["q"] / (2 * p + inv["q"]) if p else np.nan
    cols, inv_b = _stress_columns("b_", s_b, e)
    row.update(cols)
    row.update({"p_branch": inv_b["p"], "q_branch": inv_b["q"],
                "q_over_p_branch": inv_b["q_over_p"],
                "reldiff_branch": relative_difference(s_b, s_m)})
    wf = snap.wall_forces if snap.wall_forces is not None else wall_forces_from_contacts(cs)
    L = snap.box_lengths
    if wf is not None and np.all(np.isfinite(L)) and np.all(L > 0) and len(wf) == len(WALL_ORDER):
        s_w = wall_stress(wf, L)
        cols, inv_w = _stress_columns("w_", s_w, e)
        row.update(cols)
        row.update({"p_wall": inv_w["p"], "q_wall": inv_w["q"],
                    "q_over_p_wall": inv_w["q_over_p"],
                    "reldiff_wall": relative_difference(s_w, s_m)})
    else:
        row.update({k: np.nan for k in ("p_wall", "q_wall", "q_over_p_wall", "reldiff_wall")})

    branch, force = cs.arm[sel], cs.force[sel]
    an = anisotropies(branch, force, e, errors=errors)
    for k in ("a", "a_l", "a_n", "a_t"):
        row[k] = an[k]
        if errors:
            row[k + "_se"] = an[k + "_se"]
    row["l0"], row["f0"] = an["l0"], an["f0"]
    row["sff"] = stress_force_fabric(an["a"], an["a_l"], an["a_n"], an["a_t"])
    # The 2/5 relation is derived for sigma_axis - sigma_lateral, so the
    # residual uses the signed axial deviator (equal to q/p once sigma_1 is
    # along the axis, but without the |.| bias of q near isotropy).
    row["sff_residual"] = row["q_axial_over_p"] - row["sff"]
    row["sff_residual_branch"] = (inv_b["q_axial"] / inv_b["p"] if inv_b["p"] else np.nan) - row["sff"]
    af = angular_functions(branch, force, e, nbins=nbins)
    fits = fit_harmonics(af)
    row.update(fits)
    row["sff_fit"] = stress_force_fabric(fits["a_fit"], fits["a_l_fit"],
                                         fits["a_n_fit"], fits["a_t_fit"])
    co = coordination(cs.i1, cs.i2, cs.force, cs.n_particles)
    row.update(co)
    row["frac_below_mean"] = fraction_below_mean(cs.normal_force[sel])
    labels = np.where(cs.pp, "sphere", "wall").astype("<U6")
    extents = None
    if tables is not None and snap.body_kind is not None and np.any(snap.body_kind == 1):
        classifier = tables
        if isinstance(tables, ShapeTables):
            classifier = AngularTables(tables, theta_deg)
        cols, labels, extents = contact_type_columns(snap, cs, sel, classifier, p, s_m, e)
        row.update(cols)
        row["z_points"] = row["z"] * row["ct_points_per_contact"]
    if snap.points is not None:        # a CD dump: its types read off the contact points
        try:
            row.update(cd_type_columns(snap, e))
        except InputError:             # no pair carries a force: the CD columns stay empty
            pass
    typed = "ct_method" in row
    fn = cs.normal_force[sel]
    nets = network_statistics(fn, branch, force, e,
                              labels=labels[sel] if typed else None, classes=PAIR_TYPES)
    if typed:                  # a group's share is the sum of its types' shares
        for d in nets.values():
            for g in GROUPS:
                d[f"frac_{g}"] = sum(d[f"frac_{k}"] for k in PAIR_TYPES if GROUP_OF[k] == g)
    strong = np.zeros(len(sel), bool)
    strong[sel] = strong_mask(fn)
    parts = partial_stresses(np.where(~cs.pp, "wall", np.where(strong, "strong", "weak")),
                             cs.force, cs.arm, V)
    qp = stress_contributions(parts, p, e)
    for name, d in nets.items():
        for k, v in d.items():
            if not k.endswith("_se") and k not in ("l0", "f0"):
                row[f"{name}_{k}"] = v
        row[f"{name}_qp"] = qp.get(name, (np.nan, 0.0))[1]
    row["wall_qp"] = qp.get("wall", (np.nan, 0.0))[1]
    row["n_particles"] = cs.n_particles
    row["n_contacts"] = int(len(cs.force))
    row["n_contacts_pp"] = int(cs.pp.sum())
    row["n_contacts_wall"] = int((~cs.pp).sum())
    return SnapshotResult(row, af, fits, cs.normal_force[sel], labels[sel], extents)


def add_strains(rows, lengths, reference, axis=2):
    """Add eps_1, eps_2, eps_3, eps_q, eps_v (compression positive, seed
    eq. 3) to each row, from the box lengths (S, 3) and the reference box
    (3,). Rows whose box is unknown get NaN.

    Parameters
    ----------
    rows : list of dict, length S
        The summary rows, one per state, changed in place.
    lengths : array_like, shape (S, 3)
        m, the box lengths of each row (NaN when unknown).
    reference : array_like, shape (3,)
        m, the box at zero strain (the start of shear).
    axis : int, str or array_like of shape (3,), optional
        The compression axis (default 2); a vector counts as the
        coordinate axis of its largest component.

    Returns
    -------
    list of dict
        ``rows``, each with ``eps_1`` (axial), ``eps_2`` >= ``eps_3`` (the
        lateral strains), ``eps_q`` = eps_1 - eps_3 and ``eps_v`` = eps_1 +
        eps_2 + eps_3, dimensionless, eps = ln(L0 / L)
        (:func:`postproc.strain.box_strains`).
    """
    eps = box_strains(lengths, reference, int(np.argmax(np.abs(axis_vector(axis)))))
    for k, row in enumerate(rows):
        for name, vals in eps.items():
            row[name] = float(vals[k])
    return rows
