"""Contact classes of a snapshot under one chosen criterion.

Seven criteria, one interface (:class:`Classifier`), one registry
(:data:`CRITERIA`: each criterion's name, description, parameter, default,
its name in the study's tables and its implementation), which the command
line (``--types``), the analysis options, the study's counts and its
results all read, so that a new criterion is one entry there and its
implementation:

* ``"points"`` (the default): our count of contact points from the
  overlap (:mod:`postproc.contactpoints`): the vertices of each side within the
  overlap slab (along the normal, or the partner's face plane closest to
  it), plus a tolerance alpha times the overlap's mean thickness V/area
  (``--tolerance``, default 0.1), give the touching
  features (1 vertex, 2 edge, 3+ face), the pair type VV .. FF and the
  group simple (1 point), double (EF, 2), triple (FF, 3+). V/area from the
  dump (kernel runs) or recomputed with :mod:`shapes.overlap`.
* ``"footprint"``: the group (simple, double, triple) from the
  overlap's footprint (:mod:`postproc.footprint`, threshold t in units of
  the pair size), dumped by kernel runs or recomputed from the shapes and
  poses for older or stock-YADE dumps. The vertex/edge/face features of the
  two sides come from the support features along the normal
  (:mod:`postproc.contacttypes` at its default 5 deg) and are made to agree
  with the group, which the footprint decides: triple -> FF (two convex
  bodies touch over an area only face to face), double -> EF (a line: an
  edge on a face; the rare parallel edges are counted here too), simple ->
  VF when either side is a face (a tilted edge or face dips in by one
  corner), else VV, VE or EE from the two sides.
* ``"angular"`` (``--types angular``): the angular criterion alone, with
  tolerance theta (:mod:`postproc.contacttypes`).
* ``"commonplane"`` (``--types commonplane``): our earlier band count
  on LMGC90's kind of detection (:mod:`postproc.commonplane`): Cundall's common plane from the contact
  normal, the vertices within tau * ref of it (``--tolerance`` tau, default
  0.1; ref the centre-to-extreme-vertex distance), the vertices of the
  intersection of their projected hulls as the contact points; no overlap
  needed. Our band count, kept for the study's earlier numbers: it is not
  LMGC90's count (docs/lmgc90-contacts.md).
* ``"lmgc90"`` (``--types lmgc90``): LMGC90's own count, its CpCundall
  detection with today's default point stage (:func:`postproc.lmgc90count.lmgc90_points`),
  with the alert distance as ``--tolerance`` in units of the smallest grain
  radius (default 0.1, what LMGC90's granular examples set);
  ``"lmgc90-planplan"``: the same detection with LMGC90's older point stage
  (planplan: 3 or 4 points, or none); ``"lmgc90-2009"``: planplan with the
  length-tolerant intersection it used before Clipper2
  (:func:`postproc.polygons.tolerant_intersection`: a point or a segment
  gives 1 or 2 points too), presumably the paper's route.

:meth:`Classifier.classify` returns the class of every contact of a
snapshot ("VV".."FF", "sphere", "wall") at the chosen parameter and, for
the stability columns, at half and twice it.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from . import commonplane as cpl
from . import contactpoints as cpm
from . import footprint as fpm
from . import lmgc90count as lmgc
from . import lmgc90shape as lshape
from .contactset import lookup
from .contacttypes import DEFAULT_THETA_DEG, FACE, PAIR_TYPES, classify_snapshot, shape_tables
from .errors import InputError

DEFAULT_METHOD = "points"
_TYPE = {k: i for i, k in enumerate(PAIR_TYPES)}
_FF, _EF, _VF = _TYPE["FF"], _TYPE["EF"], _TYPE["VF"]


def reconcile(pair, f1, f2, group):
    """(C,) int index into PAIR_TYPES: the angular pair types ``pair`` made
    to agree with the footprint groups ``group`` (SIMPLE, DOUBLE, TRIPLE):
    triple -> FF, double -> EF, simple -> VF when a side is a FACE, else
    the angular type (VV, VE or EE). f1, f2 (C,) the sides' features.

    Parameters
    ----------
    pair : array_like of int, shape (C,)
        The angular pair types, indices into PAIR_TYPES
        (:func:`postproc.contacttypes.classify_contacts`).
    f1, f2 : array_like of int, shape (C,)
        The two sides' angular features (VERTEX 0, EDGE 1, FACE 2).
    group : array_like of int, shape (C,)
        The footprint groups, SIMPLE 0, DOUBLE 1, TRIPLE 2
        (:func:`postproc.footprint.footprint_groups`).

    Returns
    -------
    ndarray of int8, shape (C,)
        The index into PAIR_TYPES of each contact's reconciled type.
    """
    out = np.asarray(pair, np.int8).copy()
    g = np.asarray(group)
    face = (np.asarray(f1) == FACE) | (np.asarray(f2) == FACE)
    out[g == fpm.TRIPLE] = _FF
    out[g == fpm.DOUBLE] = _EF
    out[(g == fpm.SIMPLE) & face] = _VF
    return out


@dataclass
class Classes:
    """The classes of one snapshot's contacts.

    labels (C,) str: "VV".."FF" for polyhedra pairs, "sphere", "wall";
    variants {"lo": labels, "hi": labels} at half and twice the parameter;
    poly (C,) bool the polyhedra pairs; rel (P, 2) their footprint extents
    over the pair size (footprint method; NaN where the footprint is
    missing); columns: scalars for summary.csv (criterion, parameter,
    footprint source, fallbacks).

    Attributes
    ----------
    labels : ndarray of str, shape (C,)
        The class of each contact at the criterion's parameter: "VV".."FF"
        (PAIR_TYPES) for a polyhedra pair, "sphere" for a particle pair
        with a sphere, "wall" for a wall contact.
    variants : dict
        {"lo": labels, "hi": labels}, each (C,) str, at half and twice the
        parameter (for the ``ct_*_lo`` / ``_hi`` columns); empty when the
        variants were not asked for.
    poly : ndarray of bool, shape (C,)
        True for the P polyhedra pairs.
    rel : ndarray of float, shape (P, 2), or None
        Dimensionless footprint extents L1/d >= L2/d of the polyhedra pairs
        (:func:`postproc.footprint.relative_extents`), NaN for a pair
        without overlap: from the "footprint" method ((0, 2) without
        polyhedra pairs) and from "points" when footprints and finite
        sizes are at hand; None otherwise.
    columns : dict
        Scalars for summary.csv: ``ct_method``, ``ct_threshold`` (the
        parameter), ``ct_theta_deg`` and the method's own
        (``ct_fp_recomputed``, ``ct_fp_missing``, ``ct_relabelled``,
        ``ct_pts_h_median`` (m), ``ct_cp_empty``, ``ct_alert_m`` (m)).
    """

    labels: np.ndarray
    variants: dict
    poly: np.ndarray
    rel: np.ndarray = None
    columns: dict = field(default_factory=dict)


@dataclass
class _Pairs:
    """What the geometric criteria share about one snapshot: ``where`` (for
    messages), the angular labels ``base`` (C,), the polyhedra pairs ``poly``
    (C,) bool, the two sides' features ``f1``, ``f2`` and pair types
    ``pair`` (P,) at theta, the summary columns, and, when P > 0, the rows
    ``i1``, ``i2`` (P,) of the two bodies and their ``poses`` (shape index,
    position (P, 3) m, orientation quaternion (P, 4)) of side 1 then side 2."""

    where: str
    base: np.ndarray
    poly: np.ndarray
    f1: np.ndarray
    f2: np.ndarray
    pair: np.ndarray
    cols: dict
    i1: np.ndarray = None
    i2: np.ndarray = None
    poses: tuple = None


class Classifier:
    """Contact classes of polyhedra snapshots under one criterion.

    shapes : (vertices, triangles, triangle_faces) lists as returned by
    :meth:`postproc.schema.DumpReader.shapes`. method : "points" (the
    default), "footprint", "angular", "commonplane", "lmgc90",
    "lmgc90-planplan" or "lmgc90-2009" (``METHODS``; module docstring).
    threshold : t in units of the pair
    size (footprint; default :data:`postproc.footprint.DEFAULT_THRESHOLD`).
    theta_deg : the angular tolerance (the criterion itself for "angular";
    the feature labels of contacts without overlap otherwise; default 5).
    recompute : "auto" (use the dumped footprint or overlap area, else
    recompute), "always" (ignore dumped ones) or "never". tolerance : alpha
    of the "points" method (delta = alpha V/area; default
    :data:`postproc.contactpoints.DEFAULT_ALPHA`), tau of the
    "commonplane" method (default :data:`postproc.commonplane.DEFAULT_NEIGHBOR`),
    or the alert distance of the LMGC90 methods ("lmgc90", "lmgc90-planplan", "lmgc90-2009") in
    units of the smallest grain radius (of the shapes; default
    :data:`postproc.lmgc90count.DEFAULT_ALERT`).
    reference : how the "commonplane" method measures ref, the length its
    band is tau times: "vertex" (the default: the distance from the centre
    to the extreme vertex, LMGC90's older routine) or "normal" (that
    distance along the common plane's normal, LMGC90's current routine).

    Raises InputError (one line) for an unknown method, ``recompute`` or
    ``reference``, theta not in (0, 45) deg, t not in (0, 1), a tolerance
    not finite and > 0, or bad shapes.

    Attributes
    ----------
    method : str
        The criterion, one of ``METHODS``.
    theta_deg : float
        deg, the angular tolerance theta, 0 < theta < 45.
    threshold : float
        t, in units of the pair size d, 0 < t < 1 (the "footprint" method).
    tolerance : float
        The parameter of "points" (alpha, dimensionless), "commonplane"
        (tau, in units of ref) or the LMGC90 routes (the alert distance in
        units of the smallest grain radius), > 0.
    recompute : str
        "auto", "always" or "never".
    reference : str
        "vertex" or "normal" (the "commonplane" method).
    tables : postproc.contacttypes.ShapeTables
        The angular criterion's tables (every method labels with them first).
    parameter : float
        Property: the criterion's parameter (alpha, t, theta in deg, tau or
        the alert distance in smallest grain radii).
    point_tables, plane_tables, lmgc90_tables, geometry
        Properties, built on first use: the tables of the "points",
        "commonplane" and LMGC90 counts and the overlap kernel's shapes
        (:class:`postproc.footprint.Geometry`).
    """

    def __init__(self, shapes, method=DEFAULT_METHOD, threshold=None, theta_deg=None,
                 recompute="auto", tolerance=None, reference="vertex"):
        crit = criterion(method)
        if recompute not in ("auto", "always", "never"):
            raise InputError(f"recompute must be auto, always or never, got {recompute!r}")
        self.method = method
        self.theta_deg = DEFAULT_THETA_DEG if theta_deg is None else float(theta_deg)
        if not (np.isfinite(self.theta_deg) and 0 < self.theta_deg < 45):
            raise InputError(f"--theta must be in (0, 45) degrees, got {theta_deg}")
        self.threshold = fpm.check_threshold(fpm.DEFAULT_THRESHOLD if threshold is None else threshold)
        self.recompute = recompute
        self.reference = cpl.check_reference(reference)
        default = crit.default if crit.option == "--tolerance" else cpm.DEFAULT_ALPHA
        self.tolerance = cpm.check_alpha(default if tolerance is None else tolerance)
        vertices, triangles, faces = shapes
        self.tables = shape_tables(vertices, triangles, faces)
        self._shapes = (vertices, triangles)
        self._geometry = None
        self._points = None
        self._planes = None
        self._lmgc = None

    @property
    def parameter(self):
        """The criterion's parameter: alpha, t (units of d), theta (deg), tau,
        or the alert distance (units of the smallest grain radius)."""
        return {"--tolerance": self.tolerance, "--threshold": self.threshold,
                "--theta": self.theta_deg}[CRITERIA[self.method].option]

    @property
    def lmgc90_tables(self):
        if self._lmgc is None:
            self._lmgc = lshape.lmgc90_tables(*self._shapes)
        return self._lmgc

    @property
    def plane_tables(self):
        if self._planes is None:
            self._planes = cpl.plane_tables(*self._shapes)
        return self._planes

    @property
    def point_tables(self):
        if self._points is None:
            self._points = cpm.point_tables(*self._shapes)
        return self._points

    @property
    def geometry(self):
        if self._geometry is None:
            self._geometry = fpm.Geometry(*self._shapes)
        return self._geometry

    def classify(self, snap, variants=True):
        """:class:`Classes` of every contact of the snapshot ``snap``.
        Raises InputError (one line, naming the snapshot) for a polyhedron
        without a shape, a bad normal, a bad footprint or size.

        Parameters
        ----------
        snap : postproc.schema.Snapshot
            A dump's snapshot: normals (from id1 to id2), body kinds, shape
            indices, positions (m) and orientations; the "footprint" method
            also reads ``sizes`` (m) and the dumped footprints, "points" the
            dumped overlap volumes and areas (else recomputes them).
        variants : bool, optional
            Also classify at half and twice the parameter (default True).

        Returns
        -------
        Classes
            The labels (C,) str ("VV".."FF", "sphere", "wall"), the variants
            at half and twice the parameter, the polyhedra pairs, the
            relative footprint extents and the summary columns.

        Raises
        ------
        InputError
            As said above, or a missing overlap or footprint with
            ``recompute="never"``.
        """
        return CRITERIA[self.method].classify(self, snap, variants)

    def _angular_classes(self, snap, variants):
        lab = classify_snapshot(snap, self.tables, self.theta_deg)
        var = {}
        if variants:
            var = {"lo": classify_snapshot(snap, self.tables, self.theta_deg / 2),
                   "hi": classify_snapshot(snap, self.tables, self.theta_deg * 2)}
        poly = np.isin(lab, PAIR_TYPES)
        return Classes(lab, var, poly, None, {"ct_method": self.method, "ct_theta_deg": self.theta_deg,
                                              "ct_threshold": self.theta_deg})

    def _lmgc90_classes(self, snap, variants):
        pp = self._pairs(snap, self.tolerance)
        if not pp.poly.any():
            return self._no_pairs(pp, variants, None, {"ct_cp_empty": 0.0})
        tables = self.lmgc90_tables
        r_min = min(t.radius for t in tables)
        # LMGC90's candidate is the body with the lower number
        s1, x1, q1, s2, x2, q2 = pp.poses
        lo = pp.i1 < pp.i2
        w = lambda a, b: np.where(lo.reshape((-1,) + (1,) * (np.ndim(a) - 1)), a, b)
        args = (tables, w(s1, s2), w(x1, x2), w(q1, q2), w(s2, s1), w(x2, x1), w(q2, q1))

        # one detection for the alert distance and the band test's half and double of it
        count = lambda alerts: lmgc.lmgc90_points_alerts(*args, [a * r_min for a in alerts], route=self.method,
                                                        min_radius=r_min)
        return self._count_classes(pp, count, self.tolerance, {"ct_alert_m": self.tolerance * r_min}, variants)

    def _commonplane_classes(self, snap, variants):
        pp = self._pairs(snap, self.tolerance)
        if not pp.poly.any():
            return self._no_pairs(pp, variants, None, {"ct_cp_empty": 0.0})
        args = (self.plane_tables, *pp.poses, snap.normal[pp.poly])

        count = lambda taus: [cpl.contact_points(*args, neighbor=tau, reference=self.reference) for tau in taus]
        return self._count_classes(pp, count, self.tolerance, {}, variants)

    @staticmethod
    def _count_classes(pp, count, parameter, extra, variants):
        """The classes from a count of contact points: ``count(values)``
        returns, for each value of the parameter in ``values``, the dict of
        :func:`postproc.commonplane.contact_points` or
        :func:`postproc.lmgc90count.lmgc90_points` for the polyhedra pairs
        (one call, so that a count can share its work between the values);
        the variants at half and twice the parameter. Pairs without a point
        (LMGC90 makes no contact there) count as simple; their share is
        ``ct_cp_empty``."""
        def labels(r):
            out = pp.base.copy()
            out[pp.poly] = np.array(PAIR_TYPES)[r["pair"]]
            return out

        got = count([parameter, parameter / 2, parameter * 2] if variants else [parameter])
        r = got[0]
        lab = labels(r)
        var = {"lo": labels(got[1]), "hi": labels(got[2])} if variants else {}
        cols = {**pp.cols, **extra, "ct_cp_empty": float(np.mean(r["points"] == 0))}
        return Classes(lab, var, pp.poly, None, cols)

    def _pairs(self, snap, parameter):
        """The first steps of every geometric criterion: the orientation
        check, the angular labels and features at theta, the columns named
        after the method and its parameter, and (when polyhedron pairs
        exist) the two sides' rows and poses. Returns a :class:`_Pairs`."""
        where = f"snapshot {snap.name} (step {snap.step})"
        self._check_orientations(snap, where)
        base, poly, f1, f2, pair = classify_snapshot(snap, self.tables, self.theta_deg, features=True)
        cols = {"ct_method": self.method, "ct_threshold": parameter, "ct_theta_deg": self.theta_deg}
        i1 = i2 = poses = None
        if poly.any():
            i1, i2 = lookup(snap.id1[poly], snap.body_ids), lookup(snap.id2[poly], snap.body_ids)
            poses = (snap.shape_index[i1], snap.positions[i1], snap.orientations[i1],
                     snap.shape_index[i2], snap.positions[i2], snap.orientations[i2])
        return _Pairs(where, base, poly, f1, f2, pair, cols, i1, i2, poses)

    @staticmethod
    def _no_pairs(pp, variants, rel, extra):
        """The classes of a snapshot without polyhedron pairs: the angular
        labels at every parameter."""
        return Classes(pp.base, {"lo": pp.base, "hi": pp.base} if variants else {}, pp.poly, rel,
                       {**pp.cols, **extra})

    def _check_orientations(self, snap, where):
        if snap.orientations is not None and snap.body_kind is not None:
            q = np.asarray(snap.orientations, float)
            qn = np.linalg.norm(q, axis=1)
            bad = (snap.body_kind == 1) & ~(np.isfinite(qn) & (qn > 0))
            if bad.any():
                raise InputError(f"{where}: polyhedron {int(snap.body_ids[np.flatnonzero(bad)[0]])} "
                                 "has a zero or non-finite orientation")

    def _points_classes(self, snap, variants):
        pp = self._pairs(snap, self.tolerance)
        if not pp.poly.any():
            return self._no_pairs(pp, variants, None, {"ct_fp_recomputed": 0, "ct_fp_missing": 0})
        where, base, poly, pair, cols, i1, i2 = pp.where, pp.base, pp.poly, pp.pair, pp.cols, pp.i1, pp.i2
        use_dump = snap.footprint_area is not None and self.recompute != "always"
        if not use_dump and self.recompute == "never":
            raise InputError(f"{where}: the dump has no overlap area (contacts/footprint_area) and "
                             "recomputing it is switched off")
        if use_dump:
            area = np.asarray(snap.footprint_area, float)
            vol = np.asarray(snap.overlap, float)
            if area.shape != (len(snap.id1),) or vol.shape != (len(snap.id1),):
                raise InputError(f"{where}: contacts/footprint_area has shape {area.shape}, expected "
                                 f"({len(snap.id1)},)")
            area, vol = area[poly], vol[poly]
            ext = None if snap.footprint is None else np.asarray(snap.footprint, float)[poly]
        else:
            ext, area, vol = fpm.recompute(self.geometry, *pp.poses)
        bad = ~(np.isfinite(area) & np.isfinite(vol) & (area >= 0) & (vol >= 0))
        if bad.any():
            c = int(np.flatnonzero(poly)[np.flatnonzero(bad)[0]])
            raise InputError(f"{where}: contact {c}: overlap volume {float(vol[bad][0])!r} or area "
                             f"{float(area[bad][0])!r} is not finite and >= 0")
        # no overlap (exactly touching, or a stock-YADE contact whose exact
        # overlap is empty): no slab to count in; the angular class stays
        missing = (area == 0) | (vol == 0)
        h = np.where(missing, 0.0, vol / np.where(missing, 1.0, area))
        cols.update({"ct_fp_recomputed": int(not use_dump), "ct_fp_missing": int(missing.sum())})
        args = (self.point_tables, *pp.poses, snap.normal[poly], h)

        def labels_at(alpha):
            r = cpm.contact_points(*args, alpha=alpha)
            out = base.copy()
            out[poly] = np.array(PAIR_TYPES)[np.where(missing, pair, r["pair"])]
            return out, r

        lab, r = labels_at(self.tolerance)
        var = {"lo": labels_at(self.tolerance / 2)[0], "hi": labels_at(self.tolerance * 2)[0]} if variants else {}
        cols["ct_relabelled"] = float(np.mean(lab[poly] != np.array(PAIR_TYPES)[pair]))
        keep = ~missing
        cols["ct_pts_h_median"] = float(np.median(h[keep])) if keep.any() else np.nan
        # the footprint extents over the pair size, for the footprint figure
        rel = None
        if ext is not None and snap.sizes is not None and ext.shape == (len(h), 2):
            d = fpm.pair_size(snap.sizes[i1], snap.sizes[i2])
            if np.all(np.isfinite(d) & (d > 0)) and np.all(np.isfinite(ext)):
                rel = np.where(missing[:, None], np.nan, np.sort(ext / d[:, None], axis=1)[:, ::-1])
        return Classes(lab, var, poly, rel, cols)

    def _footprint_classes(self, snap, variants):
        pp = self._pairs(snap, self.threshold)
        if not pp.poly.any():
            return self._no_pairs(pp, variants, np.zeros((0, 2)), {"ct_fp_recomputed": 0, "ct_fp_missing": 0})
        where, base, poly, f1, f2, pair, cols = pp.where, pp.base, pp.poly, pp.f1, pp.f2, pp.pair, pp.cols
        i1, i2 = pp.i1, pp.i2
        if snap.sizes is None:
            raise InputError(f"{where}: footprint contact types need the particle sizes (bodies/size)")
        d = fpm.pair_size(snap.sizes[i1], snap.sizes[i2])
        use_dump = snap.footprint is not None and self.recompute != "always"
        if not use_dump and self.recompute == "never":
            raise InputError(f"{where}: the dump has no contact footprint (contacts/footprint) and "
                             "recomputing it is switched off")
        if use_dump:
            ext = np.asarray(snap.footprint, float)
            if ext.shape != (len(snap.id1), 2):
                raise InputError(f"{where}: contacts/footprint has shape {ext.shape}, expected "
                                 f"({len(snap.id1)}, 2)")
            ext = ext[poly]
        else:
            ext, _, _ = fpm.recompute(self.geometry, *pp.poses)
        bad = ~np.isfinite(ext).all(axis=1) | (ext < 0).any(axis=1)
        if bad.any():
            c = int(np.flatnonzero(poly)[np.flatnonzero(bad)[0]])
            raise InputError(f"{where}: contact {c}: footprint {np.asarray(ext)[bad][0].tolist()} "
                             "is not finite and >= 0")
        bad = ~(np.isfinite(d) & (d > 0))
        if bad.any():
            c = int(np.flatnonzero(poly)[np.flatnonzero(bad)[0]])
            raise InputError(f"{where}: contact {c}: a particle size is not finite and > 0")
        rel = fpm.relative_extents(ext, d)
        # a contact with no overlap (exactly touching, or a stock-YADE contact
        # whose exact overlap is empty) has no footprint: its angular class stays
        missing = rel[:, 0] == 0
        cols.update({"ct_fp_recomputed": int(not use_dump), "ct_fp_missing": int(missing.sum())})
        rel = np.where(missing[:, None], np.nan, rel)

        def labels_at(t):
            g = fpm.footprint_groups(np.nan_to_num(rel), t)
            out = base.copy()
            types = np.where(missing, pair, reconcile(pair, f1, f2, g))
            out[poly] = np.array(PAIR_TYPES)[types]
            return out

        lab = labels_at(self.threshold)
        var = {"lo": labels_at(self.threshold / 2), "hi": labels_at(self.threshold * 2)} if variants else {}
        relabel = np.mean(lab[poly] != np.array(PAIR_TYPES)[pair])
        cols["ct_relabelled"] = float(relabel)
        return Classes(lab, var, poly, rel, cols)


@dataclass(frozen=True)
class Criterion:
    """One contact-type criterion of the registry :data:`CRITERIA`.

    Attributes
    ----------
    name : str
        Its name: ``postproc analyze --types NAME``, the summary's
        ``ct_method``, a study's count (``--counts``).
    description : str
        What it is, one phrase (the command line's help).
    option : str
        The option that sets its parameter: "--tolerance", "--threshold"
        (the footprint's t) or "--theta" (the angular tolerance).
    parameter : str
        What the parameter is, with its unit (the command line's help).
    default : float
        The parameter's default, in the unit of ``parameter``.
    unit : str
        The parameter's unit, short, for a figure's axis ("(alpha x V/area)").
    reading : str
        How the claims name a summary counted so: a format string of the
        parameter's value ("contact-point count, tolerance {:g} V/area").
    label : str
        Its name in the study's results and claim-6 tables.
    classify : callable
        The implementation: ``classify(classifier, snap, variants)`` ->
        :class:`Classes` (:meth:`Classifier.classify` calls it).
    check : callable
        ``check(tolerance)``: raises InputError (one line) for a ``--tolerance``
        the criterion cannot take (:func:`check_options`).
    """

    name: str
    description: str
    option: str
    parameter: str
    default: float
    unit: str
    reading: str
    label: str
    classify: Callable
    check: Callable


def _alert_check(route):
    """The ``--tolerance`` check of an LMGC90 route (the alert distance)."""
    return lambda tol: lmgc.check_alert(
        tol, f"--tolerance ({route}: the alert distance in units of the smallest grain radius)")


_ALERT = "the alert distance in units of the smallest grain radius"

#: The contact-type criteria, by name, in the order the command line shows
#: them (the first is the default, :data:`DEFAULT_METHOD`). A new criterion
#: is one entry here and its implementation; the command line's ``--types``
#: choices and help, the analysis options, the study's counts and the
#: names in its results read this table.
CRITERIA = {c.name: c for c in (
    Criterion("points", "a count of contact points from the overlap (the default)", "--tolerance",
              "alpha, the distance tolerance in units of the overlap's mean thickness V/area", cpm.DEFAULT_ALPHA,
              "(alpha x V/area)", "contact-point count, tolerance {:g} V/area", "our contact-point count",
              Classifier._points_classes, cpm.check_alpha),
    Criterion("footprint", "the overlap's footprint", "--threshold",
              "the footprint threshold t in units of the pair size d", fpm.DEFAULT_THRESHOLD,
              "(t x d)", "footprint criterion, threshold {:g} d", "the footprint count",
              Classifier._footprint_classes, cpm.check_alpha),
    Criterion("angular", "the angular criterion alone", "--theta",
              "the angular tolerance theta in degrees", DEFAULT_THETA_DEG,
              "(deg)", "angular criterion, tolerance {:g} deg", "the angular criterion",
              Classifier._angular_classes, cpm.check_alpha),
    Criterion("commonplane", "our earlier band count on Cundall's common plane (not LMGC90's count)", "--tolerance",
              "tau, the band in units of the centre-to-extreme-vertex distance", cpl.DEFAULT_NEIGHBOR,
              "(tau x the radius)", "the earlier band count on a common plane, band {:g} x the radius",
              "the earlier band count on a common plane", Classifier._commonplane_classes,
              lambda tol: cpl.check_neighbor(tol, "--tolerance (commonplane: tau, the band in units of the radius)")),
    Criterion("lmgc90", "LMGC90's own count: its CpCundall detection with today's point stage", "--tolerance",
              _ALERT, lmgc.DEFAULT_ALERT, "(alert x the smallest radius)",
              "LMGC90's own count (today's point stage), alert distance {:g} x the smallest grain radius",
              "LMGC90's own count", Classifier._lmgc90_classes, _alert_check("lmgc90")),
    Criterion("lmgc90-planplan", "LMGC90's own count with its older planplan point stage", "--tolerance",
              _ALERT, lmgc.DEFAULT_ALERT, "(alert x the smallest radius)",
              "LMGC90's own count (its older planplan point stage), alert distance {:g} x the smallest grain "
              "radius", "LMGC90's own count, its planplan stage", Classifier._lmgc90_classes,
              _alert_check("lmgc90-planplan")),
    Criterion("lmgc90-2009", "LMGC90's planplan with the length-tolerant intersection it used before Clipper2",
              "--tolerance", _ALERT, lmgc.DEFAULT_ALERT, "(alert x the smallest radius)",
              "LMGC90's own count (planplan with its older length-tolerant intersection), alert distance {:g} x "
              "the smallest grain radius", "LMGC90's own count, planplan with its 2009 intersection",
              Classifier._lmgc90_classes, _alert_check("lmgc90-2009")),
)}
#: the criteria's names, in the registry's order (as at import; code that
#: must see criteria added later reads :data:`CRITERIA`)
METHODS = tuple(CRITERIA)


def criterion(method):
    """The registry's :class:`Criterion` of a criterion's name.

    Parameters
    ----------
    method : str
        A name of :data:`CRITERIA` ("points", "lmgc90", ...).

    Returns
    -------
    Criterion
        Its entry.

    Raises
    ------
    InputError
        One line naming the unknown criterion and the known ones.
    """
    try:
        return CRITERIA[method]
    except (KeyError, TypeError):
        raise InputError(f"--types must be one of {', '.join(CRITERIA)}, got {method!r}") from None


def check_options(method=DEFAULT_METHOD, threshold=None, theta_deg=None, tolerance=None):
    """Check the contact-type options before any file is opened; raises
    InputError (one line) for an unknown criterion or a bad parameter.

    Parameters
    ----------
    method : str, optional
        The criterion, one of ``METHODS`` (default "points").
    threshold : float or None, optional
        t in units of the pair size, checked to lie in (0, 1) whatever the
        method (None: not given).
    theta_deg : float or None, optional
        The angular tolerance, deg, in (0, 45) (None: not given).
    tolerance : float or None, optional
        The method's parameter, finite and > 0: tau for "commonplane", the
        alert distance (smallest grain radii) for the LMGC90 routes, alpha
        otherwise (None: not given).

    Returns
    -------
    None
        Nothing: it only raises.

    Raises
    ------
    InputError
        As said above (a ``theta_deg`` that is not a number raises
        ValueError instead).
    """
    crit = criterion(method)
    if threshold is not None:
        fpm.check_threshold(threshold)
    if tolerance is not None:
        crit.check(tolerance)
    if theta_deg is not None and not (np.isfinite(float(theta_deg)) and 0 < float(theta_deg) < 45):
        raise InputError(f"--theta must be in (0, 45) degrees, got {theta_deg}")


def classifier_for(shapes, method=DEFAULT_METHOD, threshold=None, theta_deg=None, tolerance=None):
    """A :class:`Classifier` for a dump's shapes, or None when there are
    none (spheres, flat tables). Bad shapes raise InputError.

    Parameters
    ----------
    shapes : tuple of three lists, or None
        (vertices, triangles, triangle_faces) as
        :meth:`postproc.schema.DumpReader.shapes` returns them; None or
        empty lists for a dump without shapes.
    method, threshold, theta_deg, tolerance
        As :class:`Classifier` (``recompute="auto"``, ``reference="vertex"``).

    Returns
    -------
    Classifier or None
        The classifier, or None when there are no shapes.

    Raises
    ------
    InputError
        Bad shapes or options (:class:`Classifier`).
    """
    if shapes is None or not len(shapes[0]):
        return None
    return Classifier(shapes, method, threshold, theta_deg, tolerance=tolerance)


class AngularTables(Classifier):
    """The angular criterion at ``theta_deg`` from prebuilt
    :class:`postproc.contacttypes.ShapeTables` (no triangles needed).

    Parameters
    ----------
    tables : postproc.contacttypes.ShapeTables
        The dump's shapes.
    theta_deg : float or None, optional
        deg, in (0, 45) (None: ``DEFAULT_THETA_DEG`` = 5); InputError
        otherwise.

    Attributes
    ----------
    method : str
        "angular".
    theta_deg : float
        deg, the angular tolerance.
    tables : postproc.contacttypes.ShapeTables
        The tables given.
    threshold, tolerance, recompute
        The defaults (``DEFAULT_THRESHOLD``, ``DEFAULT_ALPHA``, "never"),
        unused by the angular criterion.
    """

    def __init__(self, tables, theta_deg=None):
        self.method = "angular"
        self.theta_deg = DEFAULT_THETA_DEG if theta_deg is None else float(theta_deg)
        if not (np.isfinite(self.theta_deg) and 0 < self.theta_deg < 45):
            raise InputError(f"--theta must be in (0, 45) degrees, got {theta_deg}")
        self.threshold = fpm.DEFAULT_THRESHOLD
        self.tolerance = cpm.DEFAULT_ALPHA
        self.recompute = "never"
        self.tables = tables
        self._shapes = None
        self._geometry = None
        self._points = None


def snapshot_classes(snap, classifier):
    """(C,) str class of every contact of ``snap``: the classifier's labels
    when there is one (a dump with shapes), else "sphere" for particle pairs
    and "wall" for wall contacts.

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        The snapshot.
    classifier : Classifier or None
        The dump's classifier (:func:`classifier_for`), or None.

    Returns
    -------
    ndarray of str, shape (C,)
        The classifier's labels ("VV".."FF", "sphere", "wall"; no variants)
        when there is a classifier and the snapshot has a polyhedron (body
        kind 1); else "sphere" when both ids are bodies and "wall" otherwise.

    Raises
    ------
    InputError
        As :meth:`Classifier.classify`.
    """
    if classifier is not None and snap.body_kind is not None and np.any(snap.body_kind == 1):
        return classifier.classify(snap, variants=False).labels
    both = (lookup(snap.id1, snap.body_ids) >= 0) & (lookup(snap.id2, snap.body_ids) >= 0)
    return np.where(both, "sphere", "wall")
