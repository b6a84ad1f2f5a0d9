"""The summary's columns, declared once: name, unit, meaning, the paper's
equation and a short label.

``summary.csv`` (:func:`postproc.pipeline.analyze_path`, one row per
snapshot) has the columns :data:`COLUMNS` declares: the leading ones
(:data:`LEAD`, in that order) and then, in the order the analysis makes
them, the three forms of the stress, the anisotropies and their fits, the
coordination, the contact types and the strong and weak networks. Families
of columns (the stress components of each form, the statistics of each
contact class) are declared from one template each. The analysis
(:mod:`postproc.analysis`) writes no column this module does not declare
(tests/test_columns.py) and takes its stress components and contact
groups from here; the pipeline orders the summary by :data:`LEAD`; the
size and shape fronts' tables and figures take their labels from
:func:`label`; the tables of docs/postproc.md and docs/summary-columns.md
are :func:`markdown_table` (``python -m postproc.columns`` writes them).

Equations are those of Azéma, Radjaï and Saussine 2009 ("Eq. 2" ...), with
compression positive: Eq. 1 the internal moment M^i, Eq. 2 the stress
tensor, Eq. 3 the cumulative strains, Eq. 5 the angular averages, Eqs. 6,
7 and 9 the harmonic forms that define a, a_l, a_n and a_t, Eq. 10 the
stress-force-fabric relation. A unit "1" is dimensionless; "" a text.
"""
from __future__ import annotations

from dataclasses import dataclass

from .contacttypes import PAIR_TYPES

#: the paper's groups of contacts (by their number of points), after the pair types
GROUPS = ("simple", "double", "triple")
#: the components of a stress tensor, as the summary names them
COMPONENTS = ("xx", "yy", "zz", "yz", "xz", "xy")
#: the stress forms: column prefix -> what the sum runs over
FORMS = {"s": "the internal moments of every contact, walls included (the primary form)",
         "b": "the branch vectors of the particle-particle contacts",
         "w": "the wall forces over the wall areas"}
#: the networks of the force-bearing particle-particle contacts
NETWORKS = {"strong": "the strong network (f_n above its mean)", "weak": "the weak network (f_n below its mean)"}


@dataclass(frozen=True)
class Column:
    """One column of ``summary.csv``.

    Attributes
    ----------
    name : str
        The column's name in summary.csv.
    unit : str
        Its unit: "Pa", "m", "N", "m^3", "s", "deg"; "1" for a
        dimensionless number, a count or a share; "" for a text.
    meaning : str
        What it is, one sentence fragment (compression positive).
    equation : str
        The paper's equation it follows ("Eq. 2"), or "" when none.
    label : str
        A short label for tables and figures ("q/p").
    """

    name: str
    unit: str
    meaning: str
    equation: str = ""
    label: str = ""


def _declare():
    cols = []

    def add(name, unit, meaning, equation="", label=None):
        cols.append(Column(name, unit, meaning, equation, name if label is None else label))

    # the leading columns (LEAD), in their order
    add("step", "1", "the simulation step of the snapshot")
    add("eps_1", "1", "cumulative axial strain ln(H0/H), from the isotropic reference snapshot", "Eq. 3", "ε1")
    add("eps_q", "1", "cumulative shear strain eps_1 - eps_3", "Eq. 3", "εq")
    add("eps_v", "1", "cumulative volumetric strain eps_1 + eps_2 + eps_3", "Eq. 3", "εv")
    add("p", "Pa", "mean stress (sigma_1 + sigma_2 + sigma_3)/3 of the primary form", "Eq. 2")
    add("q", "Pa", "stress deviator (sigma_1 - sigma_3)/3 of the primary form", "Eq. 2")
    add("q_over_p", "1", "normalised shear stress q/p", "Eq. 2", "q/p")
    add("a", "1", "branch-direction (fabric) anisotropy, from the fabric tensor", "Eq. 6")
    add("a_l", "1", "branch-length anisotropy, from the length-weighted tensor", "Eq. 7")
    add("a_n", "1", "radial (normal) force anisotropy a_n'", "Eq. 9")
    add("a_t", "1", "orthoradial (tangential) force anisotropy a_t'", "Eq. 9")
    add("sff", "1", "the stress-force-fabric prediction (2/5)(a + a_l + a_n + a_t) of q/p", "Eq. 10", "(2/5)Σa")
    add("sff_residual", "1", "q_axial/p - sff: how far the prediction is from the signed shear stress", "Eq. 10")
    add("z", "1", "coordination number 2 N_c / N_p of the non-rattlers (a pair counts once)", "", "z")
    add("n_contacts", "1", "contacts of the snapshot, walls included")
    # identification
    add("snapshot", "", "the snapshot's name in the dump")
    add("time", "s", "the simulated time of the snapshot")
    add("stage", "", "the loading stage (isotropic, shear ...)")
    add("volume", "m^3", "the packing's volume V")
    # the three forms of the stress
    for f, over in FORMS.items():
        for c in COMPONENTS:
            add(f"{f}_{c}", "Pa", f"stress component {c}, sum over {over}", "Eq. 2")
        for k in (1, 2, 3):
            add(f"{f}_sigma_{k}", "Pa", f"principal stress sigma_{k} (decreasing), sum over {over}", "Eq. 2")
        for k in (1, 3):
            for x in "xyz":
                add(f"{f}_dir{k}_{x}", "1", f"{x} component of the unit direction of sigma_{k}, sum over {over} "
                                            "(sign: largest component positive)", "Eq. 2")
        if f == "s":
            add("q_axial_over_p", "1", "(sigma_axis - mean lateral stress)/3 over p: q/p signed along the "
                                       "compression axis", "Eq. 2")
            add("angle_sigma1_axis", "deg", "angle between the major principal direction and the compression axis")
            add("antisymmetry", "1", "the norm of skew(sigma) over the norm of sigma (Frobenius norms)")
            add("sin_phi", "1", "sin of the friction angle, 3q/(2p + q)")
        else:
            name = {"b": "branch", "w": "wall"}[f]
            add(f"p_{name}", "Pa", f"mean stress, sum over {over}", "Eq. 2")
            add(f"q_{name}", "Pa", f"stress deviator, sum over {over}", "Eq. 2")
            add(f"q_over_p_{name}", "1", f"q/p, sum over {over}", "Eq. 2", f"q/p ({name})")
            add(f"reldiff_{name}", "1", f"the norm of sigma_{f} - sigma_s over that of sigma_s: this form against the primary one")
    # anisotropies: errors, scales, fits
    for k in ("a", "a_l", "a_n", "a_t"):
        add(f"{k}_se", "1", f"standard error of {k}")
    add("l0", "m", "mean branch length l_0", "Eq. 7", "ℓ0")
    add("f0", "N", "mean radial force f_0", "Eq. 9", "f0")
    add("sff_residual_branch", "1", "q_axial/p of the branch form - sff", "Eq. 10")
    eq = {"a": "Eq. 6", "a_l": "Eq. 7", "a_n": "Eq. 9", "a_t": "Eq. 9"}
    for k in ("a", "a_l", "a_n", "a_t"):
        add(f"{k}_fit", "1", f"{k} from the harmonic fit of the binned angular function", eq[k])
        add(f"{k}_fit_se", "1", f"standard error of {k}_fit (the fit's)")
        if k == "a_l":
            add("l0_fit", "m", "l_0 from the harmonic fit of ⟨ℓ⟩(θ)", "Eq. 7")
        if k == "a_n":
            add("f0_fit", "N", "f_0 from the harmonic fit of ⟨f_n'⟩(θ)", "Eq. 9")
    add("sff_fit", "1", "(2/5)(a + a_l + a_n + a_t) of the fits", "Eq. 10")
    # coordination and forces
    add("z_all", "1", "coordination number of every particle and contact")
    add("n_rattlers", "1", "rattlers: particles with fewer than 2 force-bearing contacts, removed iteratively; left out of z")
    add("n_bearing", "1", "force-bearing particle-particle contacts")
    add("frac_below_mean", "1", "share of the force-bearing contacts whose f_n is below the mean",
        label="forces below the mean")
    # contact types: the criterion
    add("ct_method", "", "the contact-type criterion (postproc.classify.CRITERIA)")
    add("ct_threshold", "1", "the criterion's parameter (alpha, t, theta, tau or the alert distance, in the "
                             "criterion's unit)")
    add("ct_theta_deg", "deg", "the angular tolerance theta of the vertex/edge/face labels")
    add("ct_fp_recomputed", "1", "1 when the overlaps or footprints were recomputed from the shapes, else 0")
    add("ct_fp_missing", "1", "polyhedra contacts without an overlap, left with their angular class")
    add("ct_relabelled", "1", "share of the polyhedra contacts whose class differs from the angular one")
    add("ct_pts_h_median", "m", "median mean overlap thickness V/area (the point count)")
    add("ct_alert_m", "m", "the LMGC90 count's alert distance")
    add("ct_cp_empty", "1", "share of the polyhedra pairs with no contact point (common-plane and LMGC90 counts)")
    # contact types: per class
    for k in PAIR_TYPES + GROUPS:
        add(f"ct_frac_{k}", "1", f"proportion of {k} contacts among the force-bearing particle pairs",
            label=f"{k} contacts")
        add(f"ct_fratio_{k}", "1", f"mean f_n of the {k} contacts over the mean f_n", label=f"{k} f/⟨f⟩")
        add(f"ct_fshare_{k}", "1", f"share of the summed f_n carried by the {k} contacts")
        add(f"ct_fabric_{k}", "1", f"signed branch fabric of the {k} contacts: positive towards the axis, "
                                   "negative lateral (their leaning)", "Eq. 6", f"{k} leaning")
        add(f"ct_fabric_{k}_se", "1", f"standard error of ct_fabric_{k}")
    for k in PAIR_TYPES + GROUPS + ("wall",):
        add(f"ct_qp_{k}", "1", f"share of q_axial/p carried by the {k} contacts (partial stress)", "Eq. 2")
    add("ct_partial_sum_reldiff", "1", "relative difference between the summed partial stresses and the total")
    for tag, factor in (("lo", "halved"), ("hi", "doubled")):
        for k in PAIR_TYPES + GROUPS:
            add(f"ct_frac_{k}_{tag}", "1", f"ct_frac_{k} with the criterion's parameter {factor}")
        for k in PAIR_TYPES:
            add(f"ct_fratio_{k}_{tag}", "1", f"ct_fratio_{k} with the criterion's parameter {factor}")
            add(f"ct_fabric_{k}_{tag}", "1", f"ct_fabric_{k} with the criterion's parameter {factor}", "Eq. 6")
        for n in NETWORKS:
            add(f"{n}_frac_FF_{tag}", "1", f"{n}_frac_FF with the criterion's parameter {factor}")
    add("ct_l1_median", "1", "median largest footprint extent L1/d of the polyhedra pairs")
    add("ct_l2_median", "1", "median smallest footprint extent L2/d of the polyhedra pairs")
    add("ct_points_per_contact", "1", "mean contact points per contact (1 simple, 2 double, 3 triple)")
    add("z_points", "1", "z counting a contact as 1, 2 or 3 points (simple, double, triple)")
    # contact types read off the contact points of a CD dump (postproc.cdpoints; schema version 3)
    add("cd_pairs", "1", "CD: force-bearing particle pairs (at least one point carrying a force)")
    add("cd_points", "1", "CD: contact points of the snapshot (every LMGC90 interaction)")
    add("cd_points_carrying", "1", "CD: contact points carrying a normal force above the round-off floor")
    add("cd_force_floor", "N", "CD: the floor P eps max f_n below which a point carries no force")
    add("cd_pairs_all", "1", "CD: particle pairs with at least one point within the alert distance")
    for g in GROUPS:
        add(f"cd_alert_frac_{g}_all", "1", f"CD: proportion of {g} pairs among every pair with a point, "
                                           "counting every point within the alert distance")
    for count, how in (("alert", "every point within the alert distance"), ("force", "the force-carrying points")):
        for g in GROUPS:
            add(f"cd_{count}_frac_{g}", "1", f"CD: proportion of {g} pairs among the force-bearing pairs, "
                                             f"counting {how}", label=f"CD {g} contacts ({count})")
            add(f"cd_{count}_fratio_{g}", "1", f"CD: mean f_n of the {g} pairs over the mean f_n ({how})")
            add(f"cd_{count}_fshare_{g}", "1", f"CD: share of the summed f_n carried by the {g} pairs ({how})")
            add(f"cd_{count}_fabric_{g}", "1", f"CD: signed branch fabric of the {g} pairs, positive towards "
                                               f"the axis ({how})", "Eq. 6")
            add(f"cd_{count}_fabric_{g}_se", "1", f"standard error of cd_{count}_fabric_{g}")
        for g in GROUPS:
            add(f"cd_{count}_qp_{g}", "1", f"CD: share of q_axial/p carried by the {g} pairs ({how})", "Eq. 2")
        for n in NETWORKS:
            add(f"cd_{count}_{n}_frac_triple", "1", f"CD: proportion of triple pairs in the {n} network ({how})")
    add("cd_points_per_pair", "1", "CD: mean force-carrying points of a force-bearing pair")
    # the strong and weak networks
    for n, what in NETWORKS.items():
        add(f"{n}_fraction", "1", f"share of the force-bearing contacts in {what}")
        add(f"{n}_force_share", "1", f"share of the summed f_n carried by {what}")
        for k in ("a", "a_l", "a_n", "a_t"):
            add(f"{n}_{k}", "1", f"{k} of {what}", eq[k])
        for k in PAIR_TYPES + GROUPS:
            add(f"{n}_frac_{k}", "1", f"proportion of {k} contacts in {what}", label=f"{k} share of {n}")
        add(f"{n}_qp", "1", f"share of q_axial/p carried by {what} (partial stress)", "Eq. 2")
    add("wall_qp", "1", "share of q_axial/p carried by the wall contacts (partial stress)", "Eq. 2")
    add("n_particles", "1", "particles of the snapshot")
    add("n_contacts_pp", "1", "particle-particle contacts")
    add("n_contacts_wall", "1", "wall contacts")
    add("eps_2", "1", "cumulative lateral strain ln(L0/L)", "Eq. 3", "ε2")
    add("eps_3", "1", "cumulative lateral strain ln(l0/l)", "Eq. 3", "ε3")
    return {c.name: c for c in cols}


#: every column of summary.csv, by name, in the summary's order
COLUMNS = _declare()
#: the leading columns of summary.csv, in their order
LEAD = ("step", "eps_1", "eps_q", "eps_v", "p", "q", "q_over_p", "a", "a_l", "a_n", "a_t", "sff", "sff_residual",
        "z", "n_contacts")


def label(name):
    """The short label of a summary column (for a table or a figure).

    Parameters
    ----------
    name : str
        A column of :data:`COLUMNS` ("q_over_p").

    Returns
    -------
    str
        Its label ("q/p").

    Raises
    ------
    KeyError
        An undeclared column.

    Examples
    --------
    >>> label("q_over_p"), label("ct_fabric_EE")
    ('q/p', 'EE leaning')
    """
    return COLUMNS[name].label


def markdown_table(names=LEAD):
    """The Markdown table of some columns: name, unit, meaning, equation
    (docs/postproc.md holds it for :data:`LEAD`).

    Parameters
    ----------
    names : sequence of str, optional
        Columns of :data:`COLUMNS` (default :data:`LEAD`).

    Returns
    -------
    str
        The table, one line per column after the header, no final newline.

    Examples
    --------
    >>> print(markdown_table(["q_over_p"]))
    | column | unit | meaning | paper |
    |---|---|---|---|
    | `q_over_p` | 1 | normalised shear stress q/p | Eq. 2 |
    """
    lines = ["| column | unit | meaning | paper |", "|---|---|---|---|"]
    for n in names:
        c = COLUMNS[n]
        lines.append(f"| `{c.name}` | {c.unit or '–'} | {c.meaning} | {c.equation or '–'} |")
    return "\n".join(lines)


#: the markers of the generated tables in the docs (:func:`write_docs`)
BEGIN = "<!-- generated from postproc/columns.py by python -m postproc.columns; do not edit -->"
END = "<!-- end of the generated table -->"
#: the pages holding a generated table, and the columns each lists
DOC_TABLES = (("docs/postproc.md", LEAD), ("docs/summary-columns.md", tuple(COLUMNS)))


def docs_block(names):
    """A generated table of the docs, its markers included.

    Parameters
    ----------
    names : sequence of str
        The columns it lists.

    Returns
    -------
    str
        :data:`BEGIN`, :func:`markdown_table` of ``names`` and :data:`END`,
        one per line.
    """
    return "\n".join([BEGIN, markdown_table(names), END])


def write_docs(root):
    """Rewrite the generated tables of :data:`DOC_TABLES` under ``root``
    (the repository): the text between the markers of each page.

    Parameters
    ----------
    root : str
        The repository's folder.

    Returns
    -------
    list of str
        The pages whose table changed.

    Raises
    ------
    ValueError
        A page without the two markers.
    """
    import os

    changed = []
    for page, names in DOC_TABLES:
        path = os.path.join(root, page)
        with open(path) as fh:
            text = fh.read()
        if text.count(BEGIN) != 1 or text.count(END) != 1:
            raise ValueError(f"{page}: no generated table (the markers {BEGIN!r} ... {END!r})")
        head, rest = text.split(BEGIN)
        new = head + docs_block(names) + rest.split(END, 1)[1]
        if new != text:
            with open(path, "w") as fh:
                fh.write(new)
            changed.append(page)
    return changed


if __name__ == "__main__":
    import os
    import sys

    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    got = write_docs(here)
    print("rewritten: " + ", ".join(got) if got else "the docs' tables are current", file=sys.stderr)
