"""LMGC90's own text files read into the project's dump, so that an LMGC90 user
can analyse a run of their own with ``postproc``.

    python -m postproc.lmgc90files RUN_DIR OUT.h5

``RUN_DIR`` is the folder of an LMGC90 3D rigid run (the one holding
``DATBOX/`` and ``OUTBOX/``). Read:

* ``DATBOX/BODIES.DAT``: every ``RBDY3`` body, its reference centre
  (``$nodty NO6xx coo1..3``, the centre of mass), its bulk's behaviour and
  its one contactor: ``POLYR`` (vertices in the body's inertia frame,
  relative to its centre of mass, then the triangles ``ver1..3``),
  ``SPHER`` (``byrd``, the radius) or ``PLANx`` (half sizes ``axe1..3``:
  the plane's contact face is at ``axe3`` along its frame's third axis);
* ``DATBOX/BULK_BEHAV.DAT``: the density ``Umas`` of each behaviour;
* ``OUTBOX/DOF.OUT.n`` (``RBDY3::write_out_dof``): per body the
  displacement ``X(1..3)`` of the centre from its ``BODIES.DAT`` reference,
  the velocity ``V(1..3)`` and the inertia frame ``a``, ``b``, ``g``
  (columns alpha, beta, gamma of the rotation local -> global);
* ``OUTBOX/Vloc_Rloc.OUT.n`` (``write_out_Vloc_Rloc`` of the contact
  modules, ``PRPRx``, ``PRPLx``, ``SPSPx``, ``SPPLx``, ``SPPRx``; their rows are
  found by their labels, which differ in order and spelling between them):
  per interaction its candidate and antagonist bodies, status, the local
  reaction ``rlt/H``, ``rln/H``, ``rls/H``, the relative velocity, ``gapTT``
  (``gTT`` for spheres),
  the point ``coo1..3`` and the local frame ``t``, ``n``, ``s``.

Conventions (read from LMGC90's ``injj_PRPRx``): the reaction r = rlt t +
rln n + rls s acts on the **candidate**, -r on the antagonist, and ``n``
points from the antagonist towards the candidate. The writers divide the
reaction impulses by the time step H (the labels say ``rln/H``), so the
values read are forces in N and H is not needed. A dump's id1 is the
antagonist and id2 the candidate, so ``force on id2 by id1`` = r and the
normal is ``n``, as the schema wants.

The dump (schema version 3, :mod:`postproc.schema`): one snapshot per
``DOF.OUT.n`` with its ``Vloc_Rloc.OUT.n`` (same ``$steps``); ids are the
``RBDY3`` numbers; one ``contacts`` row per pair of bodies (the sum of its
points' forces, its normal the normalised mean of its points' normals, its
point their normal-force-weighted centroid, its overlap the deepest
interpenetration ``max(0, -gap)``, m) and every interaction in
``points/*``. The six ``PLANx`` bodies are the walls, mapped to x-, x+, y-,
y+, z-, z+ by their contact normals (the x- wall's points along +x); the
box is bounded by their contact faces. Shapes follow the project's
convention (local frame at the centre of mass along the principal axes):
LMGC90's ``POLYR`` frame is already that (``pre`` writes the vertices in the
inertia frame about the centre of mass), which is checked; a shape whose
centroid is off by more than ``FRAME_TOL`` of its size, or whose inertia
has off-diagonal terms above ``FRAME_TOL`` of its trace, is moved to its
own centre and principal axes, and the body's pose with it.

Every malformed or truncated file is refused with one line naming the file
and the line (:class:`LmgcFileError`). A ``Vloc_Rloc`` file cut exactly
between two interactions cannot be told from a complete one (LMGC90 writes
no closing line); a ``DOF`` file can (its last line is a dashed rule).
"""
from __future__ import annotations

import os
import re
import sys

import numpy as np

from shapes.polyhedron import geometric_faces

from .errors import InputError
from .schema import KIND_POLYHEDRON, KIND_SPHERE, WALL_ORDER, DumpWriter

FRAME_TOL = 1e-6     # relative: the 7-8 digits LMGC90's and pre's text formats hold
CONTACT_KINDS = {     # interaction: (candidate contactor, antagonist contactor)
    "PRPRx": ("POLYR", "POLYR"), "PRPLx": ("POLYR", "PLANx"), "SPSPx": ("SPHER", "SPHER"),
    "SPPLx": ("SPHER", "PLANx"), "SPPRx": ("SPHER", "POLYR"),
}
_NUMBER = re.compile(r"[-+ ]?(?:\d+\.\d*|\.\d+)(?:[DdEe][-+]?\d{1,3}|[-+]\d{3})?")


class LmgcFileError(InputError):
    """An LMGC90 file that cannot be read: one line naming the file and line.

    Attributes
    ----------
    args : tuple
        The message, ``"PATH:LINE: what is wrong"``.
    """


def _fail(path, line, what):
    raise LmgcFileError(f"{path}:{line}: {what}")


def _float(text):
    """A Fortran real ('0.1234567D+01', '-0.1234567-100', '1.5E-03') as float."""
    t = text.strip().replace("D", "E").replace("d", "E")
    if re.fullmatch(r"[-+]?\d*\.\d+[-+]\d{3}", t):      # D14.7 with a 3-digit exponent drops the letter
        t = t[:-4] + "E" + t[-4:]
    return float(t)


def labelled(text, path="", lineno=0):
    """The ``LABEL=value`` real fields of one line of an LMGC90 text file.

    LMGC90 writes each real as ``A5,D14.7`` (a 5-character label, then the
    number in 14 characters, e.g. ``coo1= 0.6079758D+01``, ``rlt/H-0.1D+01``)
    and ``pre`` as ``%5s=%14.7E``: the label is the 5 characters before the
    number's field.

    Parameters
    ----------
    text : str
        One line.
    path : str
        The file, for the error message.
    lineno : int
        The line number, for the error message.

    Returns
    -------
    dict
        {label (str, stripped of spaces and '='): float}.

    Raises
    ------
    LmgcFileError
        A number that does not parse.

    Examples
    --------
    >>> from postproc.lmgc90files import labelled
    >>> labelled("  rlt/H-0.1500000D+01  rln/H 0.2000000D-99  gapTT-0.3000000-100")
    {'rlt/H': -1.5, 'rln/H': 2e-100, 'gapTT': -3e-101}
    """
    out = {}
    for m in re.finditer(r"(.{5})=?\s*(" + _NUMBER.pattern + r")(?=\s|$)", text):
        label = m.group(1).replace("=", "").strip()
        try:
            out[label] = _float(m.group(2))
        except ValueError:
            _fail(path, lineno, f"{m.group(2).strip()!r} after {label!r} is not a number")
    return out


def _ints(text):
    """{label: int} of the ``label=   12`` integer fields of a line."""
    return {k: int(v) for k, v in re.findall(r"([A-Za-z_][A-Za-z0-9_]*)=\s*(-?\d+)(?![\d.])", text)}


def _lines(path):
    try:
        with open(path, encoding="ascii", errors="replace") as fh:
            return fh.read().split("\n")
    except OSError as exc:
        raise LmgcFileError(f"{path}: cannot be read ({exc.strerror or exc.__class__.__name__})") from None


# ------------------------------------------------------------------ DATBOX
def read_bodies(path):
    """Read ``BODIES.DAT``: the RBDY3 bodies with their one contactor.

    Parameters
    ----------
    path : str
        The file.

    Returns
    -------
    list of dict
        One per body, in file order: ``number`` (int, the RBDY3 number),
        ``behav`` (str, bulk behaviour), ``centre`` (3,) m (reference centre
        of mass), ``kind`` ("POLYR", "SPHER" or "PLANx"), ``color``, and for
        POLYR ``vertices`` (V, 3) m in the inertia frame about the centre,
        ``triangles`` (T, 3) int (0-based); SPHER ``radius`` m; PLANx
        ``axes`` (3,) m (half sizes); all three ``shift`` (3,) m and
        ``frame`` (3, 3) (the contactor's offset and orientation in the body
        frame; zero and identity unless ``localframe`` is given), ``line``
        (int, where the body starts).

    Raises
    ------
    LmgcFileError
        (one line, file and line) a body that is not RBDY3, a body without
        or with several contactors, a contactor kind not read here, a
        missing coordinate, a POLYR with fewer vertex or face lines than it
        announces, a face index out of range, a file ending inside a body.
    """
    lines = _lines(path)
    bodies, k, n = [], 0, len(lines)
    while k < n:
        if not lines[k].startswith("$bdyty"):
            if lines[k].strip() and not lines[k].lstrip().startswith("!"):
                _fail(path, k + 1, f"expected '$bdyty', found {lines[k].strip()[:40]!r}")
            k += 1
            continue
        start = k + 1
        try:
            end = next(j for j in range(k + 1, n) if lines[j].startswith("$$$$$$"))
        except StopIteration:
            _fail(path, start, "the body starting here has no closing '$$$$$$' line (truncated?)")
        body = _read_body(path, lines, k + 1, end)
        body["line"] = start
        bodies.append(body)
        k = end + 1
    if not bodies:
        _fail(path, 1, "no '$bdyty' body in the file")
    return bodies


def _read_body(path, lines, k, end):
    head = lines[k].split()
    if len(head) != 2 or not head[1].isdigit():
        _fail(path, k + 1, f"expected 'RBDY3  <number>', found {lines[k].strip()!r}")
    if head[0] != "RBDY3":
        _fail(path, k + 1, f"body model {head[0]!r}: only RBDY3 (3D rigid) bodies are read")
    body = {"number": int(head[1]), "shift": np.zeros(3), "frame": np.eye(3)}
    sections, cur = {}, None
    for j in range(k + 1, end):
        s = lines[j]
        if s.startswith("$"):
            cur = s[:6]
            sections[cur] = []
        elif cur is not None and s.strip():
            sections[cur].append(j)
    for sec in ("$blmty", "$nodty", "$tacty"):
        if sec not in sections:
            _fail(path, k + 1, f"body {body['number']} has no {sec} section")
    b = sections["$blmty"]
    if not b or "behav" not in lines[b[0]].split():
        _fail(path, (b[0] if b else k) + 1, f"body {body['number']}: expected a 'PLAIN ... behav NAME' bulk")
    words = lines[b[0]].split()
    body["behav"] = words[words.index("behav") + 1] if words.index("behav") + 1 < len(words) else ""
    nodes = sections["$nodty"]
    vals = {}
    for j in nodes:
        vals.update(labelled(lines[j], path, j + 1))
    if not nodes or not lines[nodes[0]].split()[0].startswith("NO6") or \
            any(f"coo{i}" not in vals for i in (1, 2, 3)):
        _fail(path, (nodes[0] if nodes else k) + 1, f"body {body['number']}: expected a NO6xx node with coo1..coo3")
    body["centre"] = np.array([vals["coo1"], vals["coo2"], vals["coo3"]])
    tact = sections["$tacty"]
    heads = [j for j in tact if lines[j][:1] == " " and lines[j][1:6].strip() and lines[j][1:6] == lines[j][1:6].lstrip()
             and re.match(r" [A-Z][A-Za-z]{4}\s+\d+\s+color", lines[j])]
    if len(heads) != 1:
        _fail(path, (tact[0] if tact else k) + 1,
              f"body {body['number']} has {len(heads)} contactors; one contactor a body is read")
    j0 = heads[0]
    words = lines[j0].split()
    body["kind"], body["color"] = words[0], words[3] if len(words) > 3 else ""
    rest = [j for j in tact if j > j0]
    if body["kind"] == "POLYR":
        counts = _ints(lines[j0])
        if "nb_vertex" not in counts or "nb_faces" not in counts:
            _fail(path, j0 + 1, "POLYR without nb_vertex= and nb_faces=")
        nv, nf = counts["nb_vertex"], counts["nb_faces"]
        if len(rest) < nv + nf:
            _fail(path, (rest[-1] if rest else j0) + 1,
                  f"POLYR of body {body['number']} announces {nv} vertices and {nf} faces, "
                  f"{len(rest)} lines follow")
        v = []
        for j in rest[:nv]:
            d = labelled(lines[j], path, j + 1)
            if any(c not in d for c in ("coo1", "coo2", "coor")) and any(c not in d for c in ("coo1", "coo2", "coo3")):
                _fail(path, j + 1, f"expected a vertex 'coo1= coo2= coo3=', found {lines[j].strip()[:60]!r}")
            v.append([d["coo1"], d["coo2"], d.get("coo3", d.get("coor"))])
        t = []
        for j in rest[nv:nv + nf]:
            d = _ints(lines[j])
            if any(c not in d for c in ("ver1", "ver2", "ver3")):
                _fail(path, j + 1, f"expected a face 'ver1= ver2= ver3=', found {lines[j].strip()[:60]!r}")
            f = [d["ver1"], d["ver2"], d["ver3"]]
            if min(f) < 1 or max(f) > nv:
                _fail(path, j + 1, f"face vertex {f} outside 1..{nv}")
            t.append([x - 1 for x in f])
        body["vertices"], body["triangles"] = np.array(v, float), outward(np.array(v, float), np.array(t, np.int64))
        extra = rest[nv + nf:]
    elif body["kind"] == "SPHER":
        d = labelled(lines[j0], path, j0 + 1)
        if "byrd" not in d or not d["byrd"] > 0:
            _fail(path, j0 + 1, "SPHER without a positive byrd= radius")
        body["radius"] = d["byrd"]
        extra = rest
    elif body["kind"] == "PLANx":
        d = labelled(lines[j0], path, j0 + 1)
        if any(c not in d for c in ("axe1", "axe2", "axe3")):
            _fail(path, j0 + 1, "PLANx without axe1= axe2= axe3=")
        body["axes"] = np.array([d["axe1"], d["axe2"], d["axe3"]])
        extra = rest
    else:
        _fail(path, j0 + 1, f"contactor {body['kind']!r} of body {body['number']}: "
                            f"only POLYR, SPHER and PLANx are read")
    _contactor_frame(path, lines, extra, body)
    return body


def _contactor_frame(path, lines, extra, body):
    """A contactor's optional 'localframe' (alp, bet, gam) and shift (coo)."""
    d = {}
    for j in extra:
        if lines[j].strip() == "localframe":
            continue
        d.update(labelled(lines[j], path, j + 1))
    if all(f"coo{i}" in d for i in (1, 2, 3)):
        body["shift"] = np.array([d["coo1"], d["coo2"], d["coo3"]])
    if all(f"{a}{i}" in d for a in ("alp", "bet", "gam") for i in (1, 2, 3)):
        body["frame"] = np.array([[d[f"{a}{i}"] for a in ("alp", "bet", "gam")] for i in (1, 2, 3)])


def read_bulk_densities(path):
    """The density of each bulk behaviour of ``BULK_BEHAV.DAT``.

    Parameters
    ----------
    path : str

    Returns
    -------
    dict
        {behaviour name: density (kg/m^3)} for every ``$behav`` block
        (its name the first word of the line after ``$behav``) with a
        ``Umas=`` field.

    Raises
    ------
    LmgcFileError
        A ``Umas=`` without a number.
    """
    lines = _lines(path)
    out, name, after = {}, None, False
    for j, s in enumerate(lines):
        if s.startswith("$"):
            name, after = None, s.startswith("$behav")
            continue
        if after and s.strip() and not s.lstrip().startswith("!"):
            name, after = s.split()[0], False
        if name is not None and "Umas" in s:
            d = labelled(s, path, j + 1)
            if "Umas" not in d:
                _fail(path, j + 1, f"behaviour {name}: 'Umas=' without a number")
            out[name] = d["Umas"]
    return out


# ------------------------------------------------------------------ OUTBOX
def _header(path, lines):
    """(step, time, first line after the header) of a DOF / Vloc_Rloc file."""
    for j, s in enumerate(lines[:20]):
        if s.startswith("$steps"):
            m = re.match(r"\$steps\s+(\d+)\s+time=\s*(\S+)", s)
            if not m:
                _fail(path, j + 1, f"expected '$steps N  time= T', found {s.strip()!r}")
            try:
                return int(m.group(1)), _float(m.group(2)), j + 1
            except ValueError:
                _fail(path, j + 1, f"time {m.group(2)!r} is not a number")
    _fail(path, 1, "no '$steps N time= T' header in the first 20 lines (not an LMGC90 output file?)")


def read_dof(path):
    """Read one ``DOF.OUT.n`` (or ``DOF.INI``).

    Parameters
    ----------
    path : str

    Returns
    -------
    dict
        ``step`` (int), ``time`` (s), ``number`` (B,) int64 RBDY3 numbers,
        ``X`` (B, 3) m displacement of the centre from ``BODIES.DAT``,
        ``V`` (B, 3) m/s, ``omega`` (B, 3) rad/s (``V(4..6)``, as LMGC90
        stores them), ``frame`` (B, 3, 3) local -> global (columns a, b, g:
        alpha, beta, gamma).

    Raises
    ------
    LmgcFileError
        (file and line) a body without X, V or frame lines, a file ending
        inside a body or without its closing dashed line (truncated).
    """
    lines = _lines(path)
    step, time, k = _header(path, lines)
    n = len(lines)
    num, X, V, W, F = [], [], [], [], []
    closed = False
    while k < n:
        s = lines[k]
        if s.startswith("$bdyty"):
            start = k + 1
            try:
                end = next(j for j in range(k + 1, n) if lines[j].startswith("$$$$$$"))
            except StopIteration:
                _fail(path, start, "the body starting here has no closing '$$$$$$' line (truncated?)")
            words = lines[k + 1].split() if k + 1 < end else []
            if len(words) != 2 or words[0] != "RBDY3" or not words[1].isdigit():
                _fail(path, k + 2, f"expected 'RBDY3  <number>', found {lines[k + 1].strip()!r}")
            d = {}
            for j in range(k + 2, end):
                d.update(labelled(lines[j], path, j + 1))
            need = [f"X({i})" for i in (1, 2, 3)] + [f"V({i})" for i in range(1, 7)] + \
                [f"{a}({i})" for a in "abg" for i in (1, 2, 3)]
            missing = [c for c in need if c not in d]
            if missing:
                _fail(path, start, f"body {words[1]} lacks {', '.join(missing[:4])}"
                                   f"{' ...' if len(missing) > 4 else ''} (truncated or not a DOF file?)")
            num.append(int(words[1]))
            X.append([d[f"X({i})"] for i in (1, 2, 3)])
            V.append([d[f"V({i})"] for i in (1, 2, 3)])
            W.append([d[f"V({i})"] for i in (4, 5, 6)])
            F.append([[d[f"{a}({i})"] for a in "abg"] for i in (1, 2, 3)])
            k = end + 1
            continue
        if s.startswith("!---") and num:
            closed = True
            break
        if s.strip() and not s.startswith("!"):
            _fail(path, k + 1, f"expected '$bdyty', found {s.strip()[:40]!r}")
        k += 1
    if not closed:
        _fail(path, n, "no closing '!-----' line after the last body (truncated?)")
    return {"step": step, "time": time, "number": np.array(num, np.int64), "X": np.array(X),
            "V": np.array(V), "omega": np.array(W), "frame": np.array(F)}


def read_vloc_rloc(path):
    """Read one ``Vloc_Rloc.OUT.n``: every interaction.

    Parameters
    ----------
    path : str

    Returns
    -------
    dict
        ``step`` (int), ``time`` (s) and, for the P interactions in file
        order: ``kind`` (P,) str ("PRPRx", ...), ``icdan`` (P,) int,
        ``cd``, ``an`` (P,) int64 RBDY3 numbers of the candidate and
        antagonist, ``status`` (P,) str, ``behav`` (P,) str, ``rl`` (P, 3) N
        (rlt/H, rln/H, rls/H), ``vl`` (P, 3) m/s (vlt, vln, vls), ``gap``
        (P,) m, ``point`` (P, 3) m, ``t``, ``n``, ``s`` (P, 3) the local
        frame, ``line`` (P,) int where each starts.

    Raises
    ------
    LmgcFileError
        (file and line) an interaction kind not read here, a body that is
        not RBDY3, a missing or unreadable row (truncated), reactions
        written as impulses (``rln =`` instead of ``rln/H``).
    """
    lines = _lines(path)
    step, time, k = _header(path, lines)
    n = len(lines)
    out = {key: [] for key in ("kind", "icdan", "cd", "an", "status", "behav", "rl", "vl", "gap", "point",
                               "t", "n", "s", "line")}
    while k < n:
        s = lines[k]
        if not s.startswith("$icdan"):
            if s.strip() and not s.startswith("!"):
                _fail(path, k + 1, f"expected '$icdan', found {s.strip()[:40]!r}")
            k += 1
            continue
        w = s.split()
        if len(w) < 3 or not w[2].isdigit():
            _fail(path, k + 1, f"expected '$icdan  KIND  number', found {s.strip()!r}")
        kind = w[1]
        if kind not in CONTACT_KINDS:
            _fail(path, k + 1, f"interaction {kind!r}: only {', '.join(CONTACT_KINDS)} are read")
        if k + 1 >= n or not lines[k + 1].strip().startswith("cdbdy"):
            _fail(path, min(k + 2, n), f"interaction {w[2]} lacks its 'cdbdy ...' column line (truncated?)")
        ids = lines[k + 2].split() if k + 2 < n else []
        j2 = next((i for i in range(1, len(ids)) if ids[i] == "RBDY3"), -1)
        if len(ids) < 9 or ids[0] != "RBDY3" or j2 < 4 or len(ids) < j2 + 5 or not ids[1].isdigit() \
                or not ids[j2 + 1].isdigit():
            _fail(path, k + 3, f"expected 'RBDY3 n {CONTACT_KINDS[kind][0]} n [ver] behav RBDY3 n "
                               f"{CONTACT_KINDS[kind][1]} n status', found {(lines[k + 2] if k + 2 < n else '').strip()!r}")
        if (ids[2], ids[j2 + 2]) != CONTACT_KINDS[kind]:
            _fail(path, k + 3, f"{kind} between {ids[2]} and {ids[j2 + 2]}: expected {CONTACT_KINDS[kind]}")
        j = k + 3
        d, where = {}, {}
        while j < n and lines[j].strip():
            got = labelled(lines[j], path, j + 1)
            d.update(got)
            where.update(dict.fromkeys(got, j))
            j += 1
        if j >= n:
            _fail(path, n, f"interaction {w[2]} ({kind}, from line {k + 1}) has no closing blank line (truncated?)")
        if any(x in d for x in ("rlt", "rln", "rls")):
            _fail(path, k + 4, "reactions written as impulses (rln without /H): divide by the time step "
                               "H, which this file does not hold; not read")
        d.setdefault("gapTT", d.get("gTT"))
        rows = {}
        for name, want in (("rl", ("rlt/H", "rln/H", "rls/H")), ("vl", ("vlt", "vln", "vls")), ("gap", ("gapTT",)),
                           ("coo", ("coo1", "coo2", "coo3")), ("t", ("t(1)", "t(2)", "t(3)")),
                           ("n", ("n(1)", "n(2)", "n(3)")), ("s", ("s(1)", "s(2)", "s(3)"))):
            missing = [x for x in want if d.get(x) is None]
            seen = [where[x] for x in want if x in where]
            if missing and seen:         # the row is there, a field of it unreadable
                _fail(path, seen[0] + 1, f"interaction {w[2]}: expected {', '.join(want)}, found "
                                         f"{lines[seen[0]].strip()[:60]!r}")
            if missing:
                _fail(path, j + 1, f"interaction {w[2]} ({kind}, from line {k + 1}) ends before its "
                                   f"{'/'.join(want)} row (truncated?)")
            rows[name] = [d[x] for x in want]
        out["kind"].append(kind)
        out["icdan"].append(int(w[2]))
        out["cd"].append(int(ids[1]))
        out["an"].append(int(ids[j2 + 1]))
        out["behav"].append(ids[j2 - 1])
        out["status"].append(ids[j2 + 4])
        out["rl"].append(rows["rl"])
        out["vl"].append(rows["vl"])
        out["gap"].append(rows["gap"][0])
        out["point"].append(rows["coo"])
        for a in "tns":
            out[a].append(rows[a])
        out["line"].append(k + 1)
        k = j + 1
    res = {"step": step, "time": time}
    for key, v in out.items():
        if key in ("kind", "status", "behav"):
            res[key] = np.array(v, dtype=str)
        elif key in ("icdan", "cd", "an", "line"):
            res[key] = np.array(v, np.int64)
        else:
            res[key] = np.array(v, float).reshape((len(v), 3) if key not in ("gap",) else (len(v),))
    return res


# ------------------------------------------------------------------ geometry
def outward(vertices, triangles):
    """The triangles of a convex polyhedron turned counter-clockwise seen from
    outside (``pre`` writes POLYR faces in either order; LMGC90's POLYR are
    convex, so the mean of the vertices is inside).

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
    triangles : ndarray of int, shape (T, 3)

    Returns
    -------
    ndarray of int, shape (T, 3)
        The same triangles, those facing inwards with two vertices swapped.

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.lmgc90files import outward
    >>> v = np.array([[0, 0, 0], [1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]])
    >>> print(outward(v, np.array([[0, 1, 2], [0, 1, 3], [0, 3, 2], [1, 2, 3]])).tolist())
    [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    """
    v = np.asarray(vertices, float)
    t = np.array(triangles, np.int64)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    inward = np.einsum("ij,ij->i", np.cross(b - a, c - a), (a + b + c) / 3 - v.mean(axis=0)) < 0
    t[inward] = t[inward][:, [0, 2, 1]]
    return t


def mesh_mass_properties(vertices, triangles):
    """Volume, centroid and inertia (unit density) of a closed triangle mesh.

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
        m.
    triangles : ndarray of int, shape (T, 3)
        Counter-clockwise seen from outside (a clockwise mesh gives a
        negative volume and is turned).

    Returns
    -------
    volume : float
        m^3 (> 0).
    centroid : ndarray, shape (3,)
        m.
    inertia : ndarray, shape (3, 3)
        m^5, the inertia tensor about the centroid (times the density:
        kg m^2).

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.lmgc90files import mesh_mass_properties
    >>> v = np.array([[x, y, z] for x in (0, 2.) for y in (0, 2.) for z in (0, 2.)])
    >>> t = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
    ...               [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    >>> vol, c, I = mesh_mass_properties(v, t)          # side 2: I = 8 (2^2 + 2^2) / 12
    >>> print(vol, c.tolist(), np.round(np.diag(I), 12).tolist())
    8.0 [1.0, 1.0, 1.0] [5.333333333333, 5.333333333333, 5.333333333333]
    """
    v = np.asarray(vertices, float)
    a, b, c = (v[np.asarray(triangles)[:, k]] for k in range(3))
    ref = v.mean(axis=0)
    a, b, c = a - ref, b - ref, c - ref
    det = np.einsum("ij,ij->i", a, np.cross(b, c))           # 6 x signed tetra volume (apex at ref)
    vol = det.sum() / 6.0
    if vol < 0:
        det, vol = -det, -vol
    cen = (det[:, None] * (a + b + c)).sum(axis=0) / (24.0 * vol)
    # second moments sum over tetrahedra (apex at ref) of det/120 (sum x x^T + (sum x)(sum x)^T)
    S = np.einsum("i,ij,ik->jk", det, a, a) + np.einsum("i,ij,ik->jk", det, b, b) + \
        np.einsum("i,ij,ik->jk", det, c, c)
    s = a + b + c
    S = (S + np.einsum("i,ij,ik->jk", det, s, s)) / 120.0        # int x x^T dV about ref
    S = S - vol * np.outer(cen, cen)                               # about the centroid
    inertia = np.trace(S) * np.eye(3) - S
    return float(vol), cen + ref, inertia


def canonical_frame(vertices, triangles, tol=FRAME_TOL):
    """Move a shape to the project's convention: origin at its centre of
    mass, axes along its principal axes of inertia (as LMGC90's POLYR
    vertices already are, to the precision of the text file).

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
        m, in the body's frame.
    triangles : ndarray of int, shape (T, 3)
    tol : float
        The centroid may be off by ``tol`` times the shape's size and the
        inertia's off-diagonal terms ``tol`` times its trace before the shape
        is moved.

    Returns
    -------
    vertices : ndarray, shape (V, 3)
        m, in the canonical frame.
    centroid : ndarray, shape (3,)
        m, the old frame's coordinates of the new origin (zeros when kept).
    rotation : ndarray, shape (3, 3)
        Columns: the new axes in the old frame (identity when kept), a
        proper rotation. A body at x with orientation F (local -> global)
        is then at x + F centroid with orientation F rotation.
    volume : float
        m^3.
    """
    v = np.asarray(vertices, float)
    vol, c, inertia = mesh_mass_properties(v, triangles)
    size = 2 * np.linalg.norm(v - c, axis=1).max()
    off = np.abs(inertia - np.diag(np.diag(inertia))).max()
    if np.linalg.norm(c) <= tol * size:
        c = np.zeros(3)
    R = np.eye(3)
    if off > tol * np.trace(inertia):
        _, R = np.linalg.eigh(inertia)
        if np.linalg.det(R) < 0:
            R[:, 2] = -R[:, 2]
    return (v - c) @ R, c, R, vol


def quaternion_of(frame):
    """The unit quaternion (w, x, y, z), w >= 0, of a rotation matrix.

    Parameters
    ----------
    frame : ndarray, shape (..., 3, 3)
        Rotations local -> global (columns: the local axes in the global
        frame).

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.lmgc90files import quaternion_of
    >>> Rz = np.array([[0, -1.0, 0], [1.0, 0, 0], [0, 0, 1.0]])      # 90 degrees about z
    >>> print(np.round(quaternion_of(Rz), 12).tolist())
    [0.707106781187, 0.0, 0.0, 0.707106781187]
    """
    R = np.asarray(frame, float)
    m = R.reshape(-1, 3, 3)
    q = np.empty((len(m), 4))
    for i, M in enumerate(m):
        # the eigenvector of the largest eigenvalue of Bar-Itzhack's symmetric 4x4 matrix
        K = np.array([
            [M[0, 0] - M[1, 1] - M[2, 2], M[1, 0] + M[0, 1], M[2, 0] + M[0, 2], M[2, 1] - M[1, 2]],
            [M[1, 0] + M[0, 1], M[1, 1] - M[0, 0] - M[2, 2], M[2, 1] + M[1, 2], M[0, 2] - M[2, 0]],
            [M[2, 0] + M[0, 2], M[2, 1] + M[1, 2], M[2, 2] - M[0, 0] - M[1, 1], M[1, 0] - M[0, 1]],
            [M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1], M[0, 0] + M[1, 1] + M[2, 2]]]) / 3.0
        w, vec = np.linalg.eigh(K)
        x, y, z, s = vec[:, -1]
        q[i] = (s, x, y, z) if s >= 0 else (-s, -x, -y, -z)
    return q.reshape(R.shape[:-2] + (4,))


# ------------------------------------------------------------------ conversion
def output_pairs(run_dir):
    """The output files of a run, paired by their number n.

    Parameters
    ----------
    run_dir : str
        The run's folder (holding ``OUTBOX/``).

    Returns
    -------
    list of tuple
        (n, path of DOF.OUT.n, path of Vloc_Rloc.OUT.n), by increasing n.

    Raises
    ------
    LmgcFileError
        No OUTBOX, no DOF.OUT.n, or a DOF.OUT.n without its Vloc_Rloc.OUT.n.
    """
    box = os.path.join(run_dir, "OUTBOX")
    if not os.path.isdir(box):
        raise LmgcFileError(f"{box}: no such folder (RUN_DIR must hold DATBOX/ and OUTBOX/)")
    names = os.listdir(box)
    dof = {int(m.group(1)): m.group(0) for m in (re.fullmatch(r"DOF\.OUT\.(\d+)", x) for x in names) if m}
    vloc = {int(m.group(1)): m.group(0) for m in (re.fullmatch(r"Vloc_Rloc\.OUT\.(\d+)", x) for x in names) if m}
    if not dof:
        raise LmgcFileError(f"{box}: no DOF.OUT.n file (did the run call WriteOut / WriteOutDof?)")
    lost = sorted(set(dof) - set(vloc))
    if lost:
        raise LmgcFileError(f"{box}: DOF.OUT.{lost[0]} has no Vloc_Rloc.OUT.{lost[0]}")
    return [(k, os.path.join(box, dof[k]), os.path.join(box, vloc[k])) for k in sorted(dof)]


def _walls(bodies, frames, centres, where):
    """The six PLANx walls in WALL_ORDER: (numbers (6,), faces (6,) position
    of each contact face along its axis)."""
    planes = [i for i, b in enumerate(bodies) if b["kind"] == "PLANx"]
    if len(planes) != 6:
        raise LmgcFileError(f"{where}: {len(planes)} PLANx bodies; a box of six PLANx walls is read")
    slots = {}
    for i in planes:
        b = bodies[i]
        F = frames[i] @ b["frame"]
        nrm = F[:, 2]
        axis = int(np.argmax(np.abs(nrm)))
        if abs(abs(nrm[axis]) - 1) > FRAME_TOL * 10:
            raise LmgcFileError(f"{where}: PLANx body {b['number']} has normal {np.round(nrm, 6).tolist()}, "
                                f"not along x, y or z; a box of six axis-aligned walls is read")
        slot = 2 * axis + (0 if nrm[axis] > 0 else 1)          # normal +x: the x- wall
        if slot in slots:
            raise LmgcFileError(f"{where}: PLANx bodies {bodies[slots[slot]]['number']} and {b['number']} are "
                                f"both the {WALL_ORDER[slot]} wall")
        slots[slot] = i
    numbers = np.array([bodies[slots[s]]["number"] for s in range(6)], np.int64)
    faces = np.empty(6)
    for s in range(6):
        i = slots[s]
        b = bodies[i]
        F = frames[i] @ b["frame"]
        face = centres[i] + frames[i] @ b["shift"] + b["axes"][2] * F[:, 2]
        faces[s] = face[s // 2]
    return numbers, faces


def convert(run_dir, out, parameters=None, progress=None):
    """Convert an LMGC90 run's text files into a project dump.

    Parameters
    ----------
    run_dir : str
        The run's folder (``DATBOX/BODIES.DAT``, ``DATBOX/BULK_BEHAV.DAT``,
        ``OUTBOX/DOF.OUT.n`` and ``OUTBOX/Vloc_Rloc.OUT.n``).
    out : str
        The dump to write (must not exist).
    parameters : dict, optional
        Stored in the dump's ``parameters`` with ``source = "lmgc90-files"``.
    progress : callable, optional
        Called with one line per snapshot written.

    Returns
    -------
    int
        The number of snapshots written.

    Raises
    ------
    LmgcFileError
        (one line, file and line) any file that cannot be read, a body
        whose behaviour has no density, a box that is not six axis-aligned
        PLANx walls, a DOF and a Vloc_Rloc file of different steps or
        bodies, an interaction naming a body BODIES.DAT lacks.
    """
    datbox = os.path.join(run_dir, "DATBOX")
    bpath = os.path.join(datbox, "BODIES.DAT")
    bodies = read_bodies(bpath)
    dens = read_bulk_densities(os.path.join(datbox, "BULK_BEHAV.DAT"))
    pairs = output_pairs(run_dir)
    index = {b["number"]: i for i, b in enumerate(bodies)}
    if len(index) != len(bodies):
        raise LmgcFileError(f"{bpath}: two bodies share an RBDY3 number")
    grains = [i for i, b in enumerate(bodies) if b["kind"] != "PLANx"]
    # shapes: one per POLYR body, in the project's frame
    shape_of, shapes_v, shapes_t, moved = {}, [], [], {}
    volume = np.empty(len(bodies))
    size = np.empty(len(bodies))
    for i in grains:
        b = bodies[i]
        if b["behav"] not in dens:
            raise LmgcFileError(f"{bpath}:{b['line']}: behaviour {b['behav']!r} of body {b['number']} has no "
                                f"density (Umas) in BULK_BEHAV.DAT")
        if b["kind"] == "POLYR":
            v = b["vertices"] @ b["frame"].T + b["shift"]          # in the body frame
            cv, c, R, vol = canonical_frame(v, b["triangles"])
            shape_of[i] = len(shapes_v)
            shapes_v.append(cv)
            shapes_t.append(b["triangles"])
            moved[i] = (c, R)
            volume[i] = vol
            size[i] = 2 * np.linalg.norm(cv, axis=1).max()
        else:
            volume[i] = 4.0 / 3.0 * np.pi * b["radius"] ** 3
            size[i] = 2 * b["radius"]
    params = {"source": "lmgc90-files", "run_dir": os.path.abspath(run_dir)}
    params.update(parameters or {})
    kind = "polyhedra" if shapes_v else "spheres"
    written = 0
    with DumpWriter(out, kind, params, overlap_kind="depth") as w:
        if shapes_v:
            w.write_shapes(shapes_v, shapes_t, [geometric_faces(v, t) for v, t in zip(shapes_v, shapes_t)])
        for n, dpath, vpath in pairs:
            dof = read_dof(dpath)
            vl = read_vloc_rloc(vpath)
            if (dof["step"], dof["time"]) != (vl["step"], vl["time"]):
                raise LmgcFileError(f"{vpath}:1: step {vl['step']} time {vl['time']!r}, but {os.path.basename(dpath)} "
                                    f"says step {dof['step']} time {dof['time']!r}")
            snap = _snapshot(bodies, index, grains, shape_of, moved, volume, size, dens, dof, vl, dpath, vpath)
            w.write_snapshot(step=dof["step"], time=dof["time"], stage="lmgc90", **snap)
            written += 1
            if progress:
                progress(f"{os.path.basename(dpath)}: step {dof['step']}, {len(vl['cd'])} interactions, "
                         f"{len(snap['contacts']['id1'])} pairs")
    return written


def _snapshot(bodies, index, grains, shape_of, moved, volume, size, dens, dof, vl, dpath, vpath):
    nb = len(bodies)
    rows = np.full(nb, -1)
    for r, num in enumerate(dof["number"]):
        if num not in index:
            raise LmgcFileError(f"{dpath}: body {num} is not in BODIES.DAT")
        rows[index[num]] = r
    if (rows < 0).any():
        raise LmgcFileError(f"{dpath}: body {bodies[int(np.flatnonzero(rows < 0)[0])]['number']} of BODIES.DAT "
                            f"is missing")
    frames = dof["frame"][rows]
    err = np.abs(np.einsum("bji,bjk->bik", frames, frames) - np.eye(3)).max(axis=(1, 2))
    if err.max() > 10 * FRAME_TOL:
        b = int(np.argmax(err))
        raise LmgcFileError(f"{dpath}: the frame of body {bodies[b]['number']} is not a rotation "
                            f"(|F^T F - I| = {err[b]:.2g})")
    centres = np.array([b["centre"] for b in bodies]) + dof["X"][rows]
    wall_ids, faces = _walls(bodies, frames, centres, dpath)
    lo, hi = faces[0::2], faces[1::2]
    g = np.array(grains)
    pos = centres[g].copy()
    orient = frames[g].copy()
    for k, i in enumerate(grains):
        if i in moved:
            c, R = moved[i]
            pos[k] = pos[k] + frames[i] @ c
            orient[k] = frames[i] @ R
    rho = np.array([dens[bodies[i]["behav"]] for i in grains])
    bodies_d = {
        "id": np.array([bodies[i]["number"] for i in grains], np.int64),
        "kind": np.array([KIND_POLYHEDRON if bodies[i]["kind"] == "POLYR" else KIND_SPHERE for i in grains], np.int8),
        "position": pos, "orientation": quaternion_of(orient) if len(g) else np.zeros((0, 4)),
        "volume": volume[g], "mass": rho * volume[g],
        "shape_index": np.array([shape_of.get(i, -1) for i in grains], np.int32),
        "size": size[g], "velocity": dof["V"][rows][g],
    }
    contacts, points, wall_force = _pairs(vl, index, wall_ids, vpath)
    return dict(box_lo=lo, box_hi=hi, wall_ids=wall_ids, wall_forces=wall_force, bodies=bodies_d,
                contacts=contacts, points=points)


def _pairs(vl, index, wall_ids, vpath):
    """contacts (one row per pair), points and the force on each wall."""
    P = len(vl["cd"])
    for key in ("cd", "an"):
        bad = [j for j in range(P) if int(vl[key][j]) not in index]
        if bad:
            raise LmgcFileError(f"{vpath}:{int(vl['line'][bad[0]])}: body {int(vl[key][bad[0]])} is not in BODIES.DAT")
    an, cd = vl["an"], vl["cd"]
    key = np.stack([np.minimum(an, cd), np.maximum(an, cd)], axis=1)
    uniq, first, inv = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inv = inv.reshape(-1)
    order = np.argsort(first, kind="stable")           # pairs in the order of their first interaction
    rank = np.empty(len(order), np.int64)
    rank[order] = np.arange(len(order))
    row = rank[inv]
    C = len(order)
    id1 = an[first[order]]
    id2 = cd[first[order]]
    sign = np.where(an == id1[row], 1.0, -1.0)[:, None]  # +1: the point's antagonist is the pair's id1
    rl = vl["rl"]
    f_on_cd = rl[:, 0:1] * vl["t"] + rl[:, 1:2] * vl["n"] + rl[:, 2:3] * vl["s"]
    normal = sign * vl["n"]
    pfn = sign * rl[:, 1:2] * vl["n"]
    pft = sign * (f_on_cd - rl[:, 1:2] * vl["n"])
    total = np.zeros((C, 3))
    np.add.at(total, row, pfn + pft)
    nsum = np.zeros((C, 3))
    np.add.at(nsum, row, normal)
    nrm = nsum / np.linalg.norm(nsum, axis=1, keepdims=True)
    fn = np.einsum("ij,ij->i", total, nrm)[:, None] * nrm
    w = np.maximum(rl[:, 1], 0.0)
    wsum = np.bincount(row, weights=w, minlength=C)
    cnt = np.bincount(row, minlength=C)
    psum = np.zeros((C, 3))
    np.add.at(psum, row, vl["point"] * np.where(wsum[row] > 0, w, 1.0)[:, None])
    point = psum / np.where(wsum > 0, wsum, cnt)[:, None]
    deepest = np.full(C, np.inf)
    np.minimum.at(deepest, row, vl["gap"])
    contacts = {"id1": id1, "id2": id2, "point": point, "normal": nrm, "force_normal": fn,
                "force_tangential": total - fn, "overlap": np.maximum(0.0, -deepest)}
    points = {"contact": row, "point": vl["point"], "normal": normal, "force_normal": pfn,
              "force_tangential": pft, "gap": vl["gap"]}
    wall_force = np.zeros((6, 3))
    for s, wid in enumerate(wall_ids):
        wall_force[s] = -total[id1 == wid].sum(axis=0) + total[id2 == wid].sum(axis=0)
    both = np.isin(id1, wall_ids) & np.isin(id2, wall_ids)
    if both.any():
        k = int(np.flatnonzero(both)[0])
        raise LmgcFileError(f"{vpath}: an interaction joins two walls ({int(id1[k])}, {int(id2[k])})")
    return contacts, points, wall_force


def main(argv=None):
    """``python -m postproc.lmgc90files RUN_DIR OUT.h5``: convert, then verify
    the dump.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit status: 0, or 2 with one line on stderr.
    """
    import argparse

    from .schema import DumpFormatError, verify_dump

    ap = argparse.ArgumentParser(prog="python -m postproc.lmgc90files",
                                 description="Convert an LMGC90 run (DATBOX/, OUTBOX/) into a contact dump.")
    ap.add_argument("run_dir", help="the run's folder, holding DATBOX/ and OUTBOX/")
    ap.add_argument("out", help="the dump to write (must not exist)")
    args = ap.parse_args(argv)
    try:
        n = convert(args.run_dir, args.out, progress=lambda s: print(s, file=sys.stderr))
        check = verify_dump(args.out)
    except (InputError, DumpFormatError) as exc:
        print(f"lmgc90files: {exc}", file=sys.stderr)
        return 2
    print(f"{args.out}: {n} snapshots from {args.run_dir} (verified: {check.n_snapshots} snapshots, "
          f"checksums {'checked' if check.checksums else 'absent'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
