"""LIGGGHTS pair/gran/local and LAMMPS pair/local + property/local dumps:
files built here in each code's format (header, keyword order,
sign convention as pinned in postproc/lammpsdump.py), against the exact
stresses of a periodic lattice and against the flat-table path."""
import numpy as np
import pandas as pd
import pytest

from postproc.cli import main
from postproc.errors import InputError
from postproc.lammpsdump import read_text_dump, sniff

N = np.array([3, 4, 5])
D = 0.02
LO = np.array([-0.1, 0.2, 0.0])
F = (3.0, 5.0, 7.0)
T = 1.5
SIGMA = np.array([[F[0], T, 0], [T, F[1], 0], [0, 0, F[2]]]) / D ** 2
IJ = {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "yz": (1, 2), "xz": (0, 2), "xy": (0, 1)}
COMPARE = ("s_xx", "s_yy", "s_zz", "s_xy", "s_xz", "s_yz", "p", "q", "a", "a_l", "a_n", "a_t",
           "a_se", "a_fit", "a_n_fit", "z", "n_rattlers", "volume", "n_contacts")


def lattice(scale=1.0):
    """Periodic simple cubic lattice (spacing D, N cells, box from LO), each
    particle touching its + neighbour on every axis. Returns ids (1-based),
    positions, and per contact: i, j rows, our force on j by i (normal and
    tangential parts) and the unit direction. Exact stress: SIGMA * scale."""
    g = np.stack(np.meshgrid(*[np.arange(k) for k in N], indexing="ij"), -1).reshape(-1, 3)
    pos = LO + (g + 0.5) * D
    I, J, fn, ft, e = [], [], [], [], []
    for b in range(3):
        eb = np.eye(3)[b]
        t = {0: np.array([0, T, 0.0]), 1: np.array([T, 0, 0.0]), 2: np.zeros(3)}[b]
        I.append(np.ravel_multi_index(tuple(g.T), N))
        J.append(np.ravel_multi_index(tuple(((g + np.eye(3, dtype=int)[b]) % N).T), N))
        fn.append(np.tile(scale * F[b] * eb, (len(g), 1)))
        ft.append(np.tile(scale * t, (len(g), 1)))
        e.append(np.tile(eb, (len(g), 1)))
    return (np.arange(len(g)) + 1, pos, np.concatenate(I), np.concatenate(J),
            np.concatenate(fn), np.concatenate(ft), np.concatenate(e))


def header(step, n, columns, flags="pp pp pp", label="ENTRIES"):
    hi = LO + N * D
    box = "\n".join(f"{a:g} {b:g}" for a, b in zip(LO, hi))
    return (f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF {label}\n{n}\nITEM: BOX BOUNDS {flags}\n"
            f"{box}\nITEM: {label} {' '.join(columns)}\n")


def liggghts_block(step, variant=12, scale=1.0, flags="pp pp pp"):
    ids, pos, i, j, fn, ft, e = lattice(scale)
    across = (np.abs(pos[j] - pos[i]) > 1.5 * D).any(axis=1).astype(int)
    # LIGGGHTS writes the force on the FIRST particle: minus ours
    cols = [pos[i], pos[j], ids[i][:, None], ids[j][:, None], across[:, None]]
    cols += {12: [-(fn + ft)], 15: [-fn, -ft], 18: [-(fn + ft), -fn, -ft]}[variant]
    data = np.hstack(cols)
    names = [f"c_pgl[{k + 1}]" for k in range(data.shape[1])]
    rows = "\n".join(" ".join(f"{v:.17g}" for v in r) for r in data)
    return header(step, len(data), names, flags) + rows + "\n"


def lammps_files(tmp_path, branch=True, named=False, index=False, steps=(0, 1000)):
    con, atm = [], []
    for k, step in enumerate(steps):
        ids, pos, i, j, fn, ft, e = lattice(1.0 + k)
        cols = [ids[i][:, None], ids[j][:, None], -fn, -ft]      # on I = patom1
        names = ["c_cprop[1]", "c_cprop[2]"] + [f"c_cpair[{m}]" for m in range(1, 7)]
        if branch:
            cols.append(-D * e)                                  # p10..p12 = x_I - x_J
            names += [f"c_cpair[{m}]" for m in range(7, 10)]
        data = np.hstack(cols)
        if named:
            names = ["id1", "id2", "fx", "fy", "fz", "ftx", "fty", "ftz", "lx", "ly", "lz"][:len(names)]
        if index:
            data = np.hstack([np.arange(1, len(data) + 1)[:, None], data])
            names = ["index"] + names
        con.append(header(step, len(data), names) + "\n".join(
            " ".join(f"{v:.17g}" for v in r) for r in data) + "\n")
        a = np.hstack([ids[:, None], pos])
        atm.append(header(step, len(a), ["id", "x", "y", "z"], label="ATOMS") + "\n".join(
            " ".join(f"{v:.17g}" for v in r) for r in a) + "\n")
    cp, ap = tmp_path / "contacts.dump", tmp_path / "atoms.dump"
    cp.write_text("".join(con))
    ap.write_text("".join(atm))
    return cp, ap


def run(tmp_path, path, name, *opts, code=0):
    out = tmp_path / f"out_{name}"
    assert main(["analyze", str(path), "--out", str(out), "--no-progress", "--no-figures", *opts]) == code
    return pd.read_csv(out / "summary.csv")


def check_exact(row, scale=1.0):
    for c, (a, b) in IJ.items():
        assert row[f"s_{c}"] == pytest.approx(scale * SIGMA[a, b], rel=1e-12,
                                              abs=1e-12 * SIGMA.max() * scale), c
    assert row["volume"] == pytest.approx(np.prod(N * D), rel=1e-5)  # %g box bounds


@pytest.mark.parametrize("variant", [12, 15, 18])
def test_liggghts_lattice_exact_stress_and_sign(tmp_path, variant):
    path = tmp_path / "pgl.dump"
    path.write_text(liggghts_block(0, variant) + liggghts_block(500, variant, scale=2.0))
    assert sniff(str(path)) == "liggghts-local"
    df = run(tmp_path, path, f"l{variant}")
    assert list(df["step"]) == [0, 500]
    check_exact(df.iloc[0])
    check_exact(df.iloc[1], 2.0)
    assert df["p"].iloc[0] > 0          # compression positive: the sign is right
    assert (df["z"] == 6).all()


def test_liggghts_same_row_as_the_flat_table_with_cell(tmp_path):
    path = tmp_path / "pgl.dump"
    path.write_text(liggghts_block(0))
    ref = run(tmp_path, path, "dump").iloc[0]
    ids, pos, i, j, fn, ft, e = lattice()
    f = fn + ft
    table = pd.DataFrame({"id1": ids[i], "id2": ids[j], "x1": pos[i, 0], "y1": pos[i, 1],
                          "z1": pos[i, 2], "x2": pos[j, 0], "y2": pos[j, 1], "z2": pos[j, 2],
                          "cx": 0.0, "cy": 0.0, "cz": 0.0,
                          "fx": f[:, 0], "fy": f[:, 1], "fz": f[:, 2]})
    tp = tmp_path / "t.csv"
    table.to_csv(tp, index=False)
    L = LO + N * D - LO
    got = run(tmp_path, tp, "table", "--cell", *[f"{v:g}" for v in L]).iloc[0]
    for c in COMPARE:
        assert got[c] == pytest.approx(ref[c], rel=1e-9, abs=1e-9), c


@pytest.mark.parametrize("branch,named,index", [(True, False, False), (False, False, False),
                                                (True, True, True), (False, True, False)])
def test_lammps_pair_local_with_atoms(tmp_path, branch, named, index):
    cp, ap = lammps_files(tmp_path, branch, named, index)
    assert sniff(str(cp)) == "lammps-local"
    df = run(tmp_path, cp, "lmp", "--atoms", str(ap))
    check_exact(df.iloc[0])
    check_exact(df.iloc[1], 2.0)
    assert (df["n_particles"] == np.prod(N)).all()


def test_lammps_branch_columns_are_used_as_given(tmp_path):
    # positions scrambled: with p10..p12 the stress does not depend on them
    cp, ap = lammps_files(tmp_path, branch=True, steps=(0,))
    lines = ap.read_text().splitlines()
    for k in range(9, len(lines)):
        v = lines[k].split()
        lines[k] = " ".join([v[0]] + [f"{float(x) + 0.003 * (k % 7):.17g}" for x in v[1:]])
    ap.write_text("\n".join(lines) + "\n")
    check_exact(run(tmp_path, cp, "scr", "--atoms", str(ap)).iloc[0])


def _bad(tmp_path, text, match, fmt=None, **kw):
    p = tmp_path / "bad.dump"
    p.write_text(text)
    snaps = read_text_dump(str(p), fmt, **kw)
    errs = [s for s in snaps if isinstance(s, InputError)]
    assert errs and any(pytest.importorskip("re").search(match, str(e)) for e in errs), \
        [str(e) for e in errs]
    assert all("\n" not in str(e) for e in errs)
    return snaps


def test_bad_liggghts_blocks_are_named_and_the_others_kept(tmp_path, capsys):
    good = liggghts_block(0)
    # truncated last block: the first is analysed, exit code 1
    trunc = liggghts_block(100)
    trunc = "\n".join(trunc.splitlines()[:-5]) + "\n"
    path = tmp_path / "t.dump"
    path.write_text(good + trunc)
    df = run(tmp_path, path, "trunc", code=1)
    assert list(df["step"]) == [0]
    err = capsys.readouterr().err
    assert "announces 180 rows and has 175 (truncated)" in err
    # a line with a missing value, NaN, a non-integer id, a bad flag
    lines = good.splitlines()
    short = lines.copy()
    short[12] = " ".join(short[12].split()[:-1])
    _bad(tmp_path, "\n".join(short) + "\n", r"line 13: 11 values, the header names 12 columns")
    nan = lines.copy()
    v = nan[14].split()
    v[10] = "nan"
    nan[14] = " ".join(v)
    _bad(tmp_path, "\n".join(nan) + "\n", r"line 15, column 11 \(c_pgl\[11\]\): nan")
    txt = lines.copy()
    v = txt[10].split()
    v[9] = "abc"
    txt[10] = " ".join(v)
    _bad(tmp_path, "\n".join(txt) + "\n", r"line 11, column 10 .*'abc' is not a number")
    fid = lines.copy()
    v = fid[10].split()
    v[6] = "3.5"
    fid[10] = " ".join(v)
    _bad(tmp_path, "\n".join(fid) + "\n", r"line 11, column 7 .*3.5 is not an integer id")
    # wrapped contacts in a box with no periodic axis
    _bad(tmp_path, liggghts_block(0, flags="ff ff ff"),
         r"contact across a periodic boundary in a box with no periodic axis")
    # column count of no known layout
    odd = liggghts_block(0).splitlines()
    odd[8] += " c_pgl[13]"
    odd[9:] = [ln + " 0" for ln in odd[9:]]
    _bad(tmp_path, "\n".join(odd) + "\n", r"line 9: 13 columns; pair/gran/local", fmt="liggghts-local")
    with pytest.raises(InputError, match="unknown format 'xyz'"):
        read_text_dump(str(path), "xyz")
    other = tmp_path / "x.dump"
    other.write_text("hello\n")
    with pytest.raises(InputError, match="line 1: not a LAMMPS/LIGGGHTS dump"):
        read_text_dump(str(other), "liggghts-local")


def test_bad_lammps_inputs(tmp_path, capsys):
    cp, ap = lammps_files(tmp_path, steps=(0, 1000))
    with pytest.raises(InputError, match="needs the atom positions"):
        read_text_dump(str(cp), "lammps-local")
    # the atom dump lacks the second step: that block is reported, the first kept
    text = ap.read_text()
    ap.write_text(text[:text.index("ITEM: TIMESTEP\n1000")])
    df = run(tmp_path, cp, "miss", "--atoms", str(ap), code=1)
    assert list(df["step"]) == [0]
    assert "step 1000 has no block in the atom dump" in capsys.readouterr().err
    # an id the atom dump does not know
    cp2, ap2 = lammps_files(tmp_path, steps=(0,))
    lines = cp2.read_text().splitlines()
    v = lines[9].split()
    v[0] = "99999"
    lines[9] = " ".join(v)
    cp2.write_text("\n".join(lines) + "\n")
    snaps = read_text_dump(str(cp2), None, atoms=str(ap2))
    assert "line 10: patom1 99999 is not in the atom dump" in str(snaps[0])
    # wrong column count
    cp3, ap3 = lammps_files(tmp_path, steps=(0,))
    lines = cp3.read_text().splitlines()
    lines[8] += " c_extra"
    lines[9:] = [ln + " 0" for ln in lines[9:]]
    cp3.write_text("\n".join(lines) + "\n")
    snaps = read_text_dump(str(cp3), "lammps-local", atoms=str(ap3))
    assert "12 columns; a LAMMPS contact dump has 8" in str(snaps[0])
    # --volume with a dump: one line, exit 2
    assert main(["analyze", str(cp), "--out", str(tmp_path / "v"), "--no-figures", "--atoms", str(ap),
                 "--volume", "1"]) == 2
