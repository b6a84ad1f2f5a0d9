"""Flat contact tables: the layouts read as pandas reads them, and the
malformed ones refused in one line that names the line and column."""
import csv

import numpy as np
import pandas as pd
import pytest

from postproc.cli import main
from postproc.errors import InputError
from postproc.synthetic import harmonic_contacts
from postproc.tables import read_contact_table

FIELDS = ("id1", "id2", "positions", "body_ids", "point", "force", "volume", "step")


def _table(n=40, seed=3):
    s = harmonic_contacts(n, seed=seed)
    return pd.DataFrame({
        "id1": s.id1, "id2": s.id2,
        "x1": s.x1[:, 0], "y1": s.x1[:, 1], "z1": s.x1[:, 2],
        "x2": s.x2[:, 0], "y2": s.x2[:, 1], "z2": s.x2[:, 2],
        "cx": s.point[:, 0], "cy": s.point[:, 1], "cz": s.point[:, 2],
        "fx": s.force[:, 0], "fy": s.force[:, 1], "fz": s.force[:, 2]})


def _lines(df):
    """The CSV text of ``df`` as lines, floats written to the bit (repr)."""
    cols = [[str(int(v)) for v in df[c]] if df[c].dtype.kind == "i" else [repr(float(v)) for v in df[c]]
            for c in df.columns]
    return [",".join(df.columns)] + [",".join(r) for r in zip(*cols)]


def _same(a, b):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        for f in FIELDS:
            np.testing.assert_array_equal(getattr(x, f), getattr(y, f), err_msg=f)


@pytest.fixture
def plain(tmp_path):
    df = _table()
    path = tmp_path / "plain.csv"
    path.write_text("\n".join(_lines(df)) + "\n")
    return df, read_contact_table(str(path), volume=1.0)


def test_the_plain_table_is_read_to_the_bit(plain):
    df, (snap,) = plain
    np.testing.assert_array_equal(snap.id1, df["id1"].to_numpy())
    np.testing.assert_array_equal(snap.force, df[["fx", "fy", "fz"]].to_numpy())
    np.testing.assert_array_equal(snap.point, df[["cx", "cy", "cz"]].to_numpy())


def test_layouts_pandas_reads_give_the_same_snapshots(tmp_path, plain):
    df, ref = plain
    lines = _lines(df)
    variants = {
        # a trailing delimiter on some rows only (and on the header)
        "trailing": [lines[0] + ","] + [x + ("," if k % 3 == 0 else "") for k, x in enumerate(lines[1:])],
        # row names, as R's write.table writes them: one field more on every row
        "rownames": [lines[0]] + [f'"{k + 1}",{x}' for k, x in enumerate(lines[1:])],
        # blank lines, Windows line ends, spaces around fields
        "spacing": ["", lines[0]] + [x.replace(",", " , ") for x in lines[1:5]] + [""] + lines[5:],
        # whole ids as floats and in exponent form, quoted numbers
        "wholes": [lines[0]] + [x.split(",", 1)[0] + ".0," + x.split(",", 1)[1] for x in lines[1:]],
    }
    for name, rows in variants.items():
        path = tmp_path / f"{name}.csv"
        path.write_text(("\r\n" if name == "spacing" else "\n").join(rows) + "\n")
        _same(read_contact_table(str(path), volume=1.0), ref)
    quoted = tmp_path / "quoted.csv"
    df.to_csv(quoted, index=False, quoting=csv.QUOTE_ALL, float_format="%.17g")
    _same(read_contact_table(str(quoted), volume=1.0), ref)


def test_numbers_stored_as_text_in_parquet_are_read(tmp_path, plain):
    pytest.importorskip("pyarrow")
    df, ref = plain
    as_text = df.astype({c: str for c in df.columns if c not in ("id1", "id2")})
    as_text["fx"] = [repr(v) for v in df["fx"]]
    path = tmp_path / "t.parquet"
    as_text.to_parquet(path)
    _same(read_contact_table(str(path), volume=1.0), ref)
    as_text.loc[6, "fy"] = "seven"
    as_text.to_parquet(path)
    with pytest.raises(InputError, match=r"row 7, column fy: 'seven' is not a number"):
        read_contact_table(str(path), volume=1.0)


@pytest.mark.parametrize("edit, message", [
    (lambda L: L.__setitem__(3, L[3] + ",7"), r"line 4 has 15 fields where the header has 14"),
    (lambda L: L.__setitem__(3, L[3].rsplit(",", 1)[0]), r"line 4 has 13 fields where the header has 14"),
    (lambda L: L.__setitem__(5, L[5].replace(",", ",abc,", 1).rsplit(",", 1)[0]),
     r"line 6, column id2: 'abc' is not a number"),
    (lambda L: L.__setitem__(2, L[2].rsplit(",", 1)[0] + ",1e3x"), r"line 3, column fz: '1e3x' is not a number"),
    (lambda L: L.__setitem__(4, "2.5" + L[4][L[4].index(","):]), r"line 5, column id1: '2.5', not a whole number"),
    (lambda L: L.__setitem__(4, "," + L[4].split(",", 1)[1]), r"line 5, column id1: missing"),
    (lambda L: L.__setitem__(7, L[7].replace(",", ',"', 1)), r"line 8: not a readable CSV table"),
    (lambda L: L.__setitem__(0, L[0].replace("fx", "cx")), r"columns named twice in the header: cx"),
    (lambda L: L.insert(0, ""), None),
])
def test_malformed_tables_are_refused_by_line(tmp_path, capsys, plain, edit, message):
    df, ref = plain
    lines = _lines(df)
    edit(lines)
    path = tmp_path / "bad.csv"
    path.write_text("\n".join(lines) + "\n")
    if message is None:  # a blank line first: read as before
        _same(read_contact_table(str(path), volume=1.0), ref)
        return
    with pytest.raises(InputError, match=message):
        read_contact_table(str(path), volume=1.0)
    out = tmp_path / "o"
    assert main(["analyze", str(path), "--volume", "1", "--out", str(out), "--no-figures"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "Traceback" not in err[0], err


def test_line_numbers_count_blank_lines(tmp_path, plain):
    df, _ = plain
    lines = _lines(df)
    lines.insert(2, "")
    cells = lines[6].split(",")
    cells[11] = "x"
    lines[6] = ",".join(cells)
    path = tmp_path / "b.csv"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match=r"line 7, column fx"):
        read_contact_table(str(path), volume=1.0)


def test_files_that_are_not_tables(tmp_path):
    path = tmp_path / "x.csv"
    path.write_bytes(b"id1,id2\n\xff\xfe,1\n")
    with pytest.raises(InputError, match="not a text table"):
        read_contact_table(str(path), volume=1.0)
    path.write_text("\n\n")
    with pytest.raises(InputError, match="an empty table"):
        read_contact_table(str(path), volume=1.0)
    head = ",".join(_table(2).columns)
    path.write_text(head + "\n\n" + '1,"' + "9" * (csv.field_size_limit() + 1) + '"' + ",0" * 12 + "\n")
    with pytest.raises(InputError, match="line 3: not a readable CSV table"):
        read_contact_table(str(path), volume=1.0)


def test_a_fractional_step_is_refused(tmp_path, plain):
    df, _ = plain
    df = df.assign(step=np.where(np.arange(len(df)) < 20, 10, 20))
    path = tmp_path / "s.csv"
    df.to_csv(path, index=False, float_format="%.17g")
    snaps = read_contact_table(str(path), volume=1.0)
    assert [s.step for s in snaps] == [10, 20] and [len(s.id1) for s in snaps] == [20, 20]
    df = df.astype({"step": float})
    df.loc[30, "step"] = 20.5
    df.to_csv(path, index=False, float_format="%.17g")
    with pytest.raises(InputError, match=r"line 32, column step: '20.5', not a whole number"):
        read_contact_table(str(path), volume=1.0)


@pytest.mark.parametrize("quoted", [False, True])
def test_rows_are_named_by_their_line_on_both_reading_paths(tmp_path, plain, quoted):
    """A plain table is read by pandas' C parser, one with a quote by the
    strict csv reader: a row's line is the same on both."""
    df, _ = plain
    lines = _lines(df)
    lines[1:1] = ["", "  "]
    cells = lines[7].split(",")
    cells[0] = "-3"
    lines[7] = ",".join(cells)
    if quoted:
        lines[0] = lines[0].replace("fz", '"fz"')
    path = tmp_path / "n.csv"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match=r"line 8 has a negative id1"):
        read_contact_table(str(path), volume=1.0)


def test_spreadsheet_exports_read_as_pandas_read_them(tmp_path, plain):
    """A UTF-8 byte-order mark (Excel's "CSV UTF-8"), blank columns at the
    end of every row, unused columns named twice, and NaN written in capitals
    (C's %G) are read; each file gives the plain table's snapshots."""
    df, ref = plain
    lines = _lines(df)
    variants = {
        "bom": ("\ufeff" + lines[0], lines[1:]),
        "blank columns": (lines[0] + ",,,", [x + ",,," for x in lines[1:]]),
        "blank header only": (lines[0] + ",,,", lines[1:]),
        "unused twice": (lines[0] + ",note,note", [x + ",a,b" for x in lines[1:]]),
    }
    for name, (head, rows) in variants.items():
        path = tmp_path / f"{name}.csv"
        path.write_bytes(("\n".join([head] + rows) + "\n").encode("utf-8"))
        _same(read_contact_table(str(path), volume=1.0), ref)
    walls = df.copy()
    walls.loc[0, "id2"] = -1
    path = tmp_path / "nan.csv"
    text = "\n".join(_lines(walls)) + "\n"
    cells = text.split("\n")[1].split(",")
    cells[5:8] = ["NAN", "-NAN", "NaN"]                    # the wall's x2, y2, z2
    path.write_text(text.replace(text.split("\n")[1], ",".join(cells)))
    snap, = read_contact_table(str(path), volume=1.0)
    assert snap.id2[0] == -1 and len(snap.id1) == len(df)


def test_ids_are_read_exactly_past_float64(tmp_path, plain):
    """64-bit ids are read as integers, not through float64 (2^53 + 1 and
    2^53 stay two bodies), from CSV on both paths and from Parquet; an id
    that does not fit, or a float past 2^53, is refused by its line."""
    df, _ = plain
    big = df.copy()
    big["id1"] = big["id1"].astype(np.int64) + 2 ** 53
    big["id2"] = big["id2"].astype(np.int64) + 2 ** 53
    for quoted in (False, True):
        path = tmp_path / f"big{quoted}.csv"
        lines = _lines(big)
        if quoted:
            lines[0] = lines[0].replace("fz", '"fz"')
        path.write_text("\n".join(lines) + "\n")
        snap, = read_contact_table(str(path), volume=1.0)
        np.testing.assert_array_equal(snap.id1, big["id1"].to_numpy())
        np.testing.assert_array_equal(snap.id2, big["id2"].to_numpy())
    pytest.importorskip("pyarrow")
    path = tmp_path / "big.parquet"
    big.to_parquet(path)
    snap, = read_contact_table(str(path), volume=1.0)
    np.testing.assert_array_equal(snap.id1, big["id1"].to_numpy())
    lines = _lines(df)
    cells = lines[3].split(",")
    for bad, why in ((str(2 ** 63), "out of range for a 64-bit id"), ("9.1e15", "out of range for a whole number"),
                     ("inf", "'inf' is not finite")):
        cells[0] = bad
        path = tmp_path / "bad.csv"
        path.write_text("\n".join(lines[:3] + [",".join(cells)] + lines[4:]) + "\n")
        with pytest.raises(InputError, match=rf"line 4, column id1: .*{why}"):
            read_contact_table(str(path), volume=1.0)


def test_a_plain_table_takes_the_fast_path_and_a_quoted_one_the_strict(tmp_path, plain, monkeypatch):
    """The plain file is read by pandas' C parser without the csv module;
    the same content with a quote goes through the strict reader."""
    import postproc.tables as T

    df, ref = plain
    path = tmp_path / "p.csv"
    path.write_text("\n".join(_lines(df)) + "\n")
    calls = []
    strict = T._read_csv
    monkeypatch.setattr(T, "_read_csv", lambda p: calls.append(p) or strict(p))
    _same(read_contact_table(str(path), volume=1.0), ref)
    assert calls == []
    lines = _lines(df)
    lines[0] = lines[0].replace("fz", '"fz"')
    path.write_text("\n".join(lines) + "\n")
    _same(read_contact_table(str(path), volume=1.0), ref)
    assert calls == [str(path)]
