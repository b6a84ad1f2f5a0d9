"""The postproc CLI end to end: outputs, flat tables and bad input."""
import os

import numpy as np
import pandas as pd
import pytest
from builders import lattice_snapshot, write_snapshot

from postproc.cli import main
from postproc.schema import DumpWriter
from postproc.synthetic import harmonic_contacts, write_synthetic_dump

FIGURES = ("qp_sff.png", "anisotropies.png", "polar_last.png")
COLUMNS = ("step", "eps_1", "eps_q", "eps_v", "p", "q", "q_over_p", "a", "a_l", "a_n",
           "a_t", "sff", "sff_residual", "z", "n_contacts", "a_fit", "a_l_fit", "a_n_fit",
           "a_t_fit", "s_xx", "s_zz", "s_xz")


def test_analyze_synthetic_dump(tmp_path, monkeypatch):
    from postproc import plots

    drawn = {}
    for name in ("plot_qp_sff", "plot_anisotropies", "plot_polar"):
        def keep(*args, _f=getattr(plots, name), **kw):
            fig = _f(*args, **kw)
            png = next(a for a in args if isinstance(a, str) and a.endswith(".png"))
            drawn[os.path.basename(png)] = fig
            return fig
        monkeypatch.setattr(plots, name, keep)
    path = str(tmp_path / "run.h5")
    truths = write_synthetic_dump(path, n_contacts=20_000, n_snapshots=4, seed=1)
    out = tmp_path / "out"
    assert main(["analyze", path, "--out", str(out)]) == 0
    df = pd.read_csv(out / "summary.csv")
    for c in COLUMNS:
        assert c in df.columns, c
    assert len(df) == 4
    for k in ("a", "a_l", "a_n", "a_t"):
        truth = np.array([t[k] for t in truths])
        assert np.all(np.abs(df[k] - truth) < 5 * df[k + "_se"]), k
    # every figure written, and what it shows is the summary's numbers
    assert sorted(drawn) == sorted(FIGURES)
    for fig in FIGURES:
        with open(out / fig, "rb") as fh:
            assert fh.read(8) == b"\x89PNG\r\n\x1a\n", fig
    qp = [ln for ln in drawn["qp_sff.png"].axes[0].get_lines() if ln.get_label() == "q/p (internal moments)"][0]
    np.testing.assert_allclose(qp.get_xdata(), df["eps_q"])
    np.testing.assert_allclose(qp.get_ydata(), df["q_over_p"])
    a_t = [ln for ln in drawn["anisotropies.png"].axes[0].get_lines() if ln.get_label() == "a_t"][0]
    np.testing.assert_allclose(a_t.get_ydata(), df["a_t"])
    assert len(drawn["polar_last.png"].axes) == 4
    assert df["eps_q"].iloc[0] == 0 and df["eps_q"].iloc[-1] == pytest.approx(np.log(1 / 0.9))
    assert not (out / "errors.txt").exists()


def test_analyze_lattice_dump_matches_exact_stress(tmp_path):
    snap, sigma, _ = lattice_snapshot(4, 4, 8, F=(2.0, 2.0, 5.0), T=0.0)
    path = str(tmp_path / "lat.h5")
    with DumpWriter(path, "spheres", {}) as w:
        write_snapshot(w, snap)
    out = tmp_path / "o"
    assert main(["analyze", path, "--out", str(out), "--no-figures"]) == 0
    row = pd.read_csv(out / "summary.csv").iloc[0]
    assert row["s_zz"] == pytest.approx(sigma[2, 2], rel=1e-12)
    assert row["w_zz"] == pytest.approx(sigma[2, 2], rel=1e-12)
    assert row["q_over_p"] == pytest.approx(1 / 3, rel=1e-12)
    assert row["n_contacts_wall"] == 2 * (16 + 32 + 32)


def _table(s, walls=False):
    df = pd.DataFrame({
        "id1": s.id1, "id2": s.id2,
        "x1": s.x1[:, 0], "y1": s.x1[:, 1], "z1": s.x1[:, 2],
        "x2": s.x2[:, 0], "y2": s.x2[:, 1], "z2": s.x2[:, 2],
        "cx": s.point[:, 0], "cy": s.point[:, 1], "cz": s.point[:, 2],
        "fx": s.force[:, 0], "fy": s.force[:, 1], "fz": s.force[:, 2]})
    return df


@pytest.mark.parametrize("fmt", ["csv", "parquet"])
def test_flat_table_gives_the_same_numbers_as_the_dump(tmp_path, fmt):
    s = harmonic_contacts(5000, 0.3, 0.1, 0.4, 0.2, seed=4)
    path = tmp_path / f"c.{fmt}"
    df = _table(s)
    df.to_csv(path, index=False) if fmt == "csv" else df.to_parquet(path)
    out = tmp_path / "o"
    assert main(["analyze", str(path), "--out", str(out), "--volume", "1.0", "--no-figures"]) == 0
    row = pd.read_csv(out / "summary.csv").iloc[0]
    from postproc.fabric import anisotropies

    ref = anisotropies(s.branch, s.force)
    for k in ("a", "a_l", "a_n", "a_t"):
        assert row[k] == pytest.approx(ref[k], rel=1e-9, abs=1e-12)
    sig = s.force.T @ s.branch
    assert row["p"] == pytest.approx(np.trace(sig) / 3, rel=1e-9)


def test_flat_table_with_walls_and_box(tmp_path):
    snap, sigma, _ = lattice_snapshot(3, 3, 3, F=(1.0, 1.0, 4.0), T=0.0)
    pos = dict(zip(snap.body_ids, snap.positions))
    rows = []
    for a, b, c, f in zip(snap.id1, snap.id2, snap.point, snap.force):
        if a < 6:        # wall as id1: flip to put the wall in id2 (force sign flips)
            a, b, f = b, a, -f
        x1 = pos[a]
        x2 = pos.get(b, [np.nan] * 3)
        rows.append([a, -(b + 1) if b < 6 else b, *x1, *x2, *c, *f])
    df = pd.DataFrame(rows, columns=["id1", "id2", "x1", "y1", "z1", "x2", "y2", "z2",
                                     "cx", "cy", "cz", "fx", "fy", "fz"])
    path = tmp_path / "w.csv"
    df.to_csv(path, index=False)
    out = tmp_path / "o"
    L = snap.box_lengths
    assert main(["analyze", str(path), "--out", str(out), "--box", *map(str, L), "--no-figures"]) == 0
    row = pd.read_csv(out / "summary.csv").iloc[0]
    assert row["s_zz"] == pytest.approx(sigma[2, 2], rel=1e-12)
    assert row["w_zz"] == pytest.approx(sigma[2, 2], rel=1e-12)
    assert row["w_xx"] == pytest.approx(sigma[0, 0], rel=1e-12)


# ------------------------------------------------------------- bad input
def _dump_with(tmp_path, mutate, name="bad.h5"):
    snap, _, _ = lattice_snapshot()
    mutate(snap)
    path = str(tmp_path / name)
    with DumpWriter(path, "spheres", {}) as w:
        write_snapshot(w, snap)
    return path


def _nan(s):
    s.force[3, 1] = np.nan
    s.force_normal[3, 1] = np.nan


def _unknown(s):
    s.id2[5] = 999


def _none(s):
    for k in ("id1", "id2"):
        setattr(s, k, getattr(s, k)[:0])
    for k in ("point", "force", "force_normal", "normal"):
        setattr(s, k, getattr(s, k)[:0])
    s.overlap = s.overlap[:0]


def _flat(s):
    s.box_hi = s.box_lo.copy()


def _dup(s):
    s.body_ids[1] = s.body_ids[0]


@pytest.mark.parametrize("mutate,message", [
    (_nan, "contact forces are NaN or infinite"),
    (_unknown, "unknown body ids .*id 999"),
    (_none, "no contacts"),
    (_flat, "volume is 0.0"),
    (_dup, "duplicate body ids"),
])
def test_bad_snapshot_gives_one_line_and_writes_nothing(tmp_path, capsys, mutate, message):
    import re

    path = _dump_with(tmp_path, mutate)
    out = tmp_path / "out"
    assert main(["analyze", path, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and re.search(message, err[0]), err
    assert "Traceback" not in err[0]
    assert not out.exists()


def test_bad_files_and_options(tmp_path, capsys):
    assert main(["analyze", str(tmp_path / "nope.h5"), "--out", str(tmp_path / "o")]) == 2
    assert "no such file" in capsys.readouterr().err
    s = harmonic_contacts(100, seed=1)
    path = tmp_path / "c.csv"
    _table(s).to_csv(path, index=False)
    assert main(["analyze", str(path), "--out", str(tmp_path / "o")]) == 2
    assert "needs the volume" in capsys.readouterr().err
    assert main(["analyze", str(path), "--out", str(tmp_path / "o"), "--volume", "0"]) == 2
    assert "--volume must be finite and > 0" in capsys.readouterr().err
    assert main(["analyze", str(path), "--out", str(tmp_path / "o"), "--volume", "1", "--axis", "w"]) == 2
    assert "--axis" in capsys.readouterr().err
    _table(s).drop(columns=["fz"]).to_csv(path, index=False)
    assert main(["analyze", str(path), "--out", str(tmp_path / "o"), "--volume", "1"]) == 2
    assert "missing columns fz" in capsys.readouterr().err
    path.write_text("id1,id2\n")
    assert main(["analyze", str(path), "--out", str(tmp_path / "o"), "--volume", "1"]) == 2
    assert not (tmp_path / "o").exists()


def test_one_bad_snapshot_keeps_the_others(tmp_path, capsys):
    snap, _, _ = lattice_snapshot()
    bad, _, _ = lattice_snapshot()
    _nan(bad)
    path = str(tmp_path / "mix.h5")
    with DumpWriter(path, "spheres", {}) as w:
        write_snapshot(w, snap, step=0)
        write_snapshot(w, bad, step=1)
        write_snapshot(w, snap, step=2)
    out = tmp_path / "o"
    assert main(["analyze", path, "--out", str(out), "--no-figures"]) == 1
    df = pd.read_csv(out / "summary.csv")
    assert df["step"].tolist() == [0, 2]
    assert "step 1" in (out / "errors.txt").read_text()
    assert "NaN" in capsys.readouterr().err


def test_synthetic_subcommand(tmp_path):
    path = str(tmp_path / "s.h5")
    assert main(["synthetic", path, "--contacts", "500", "--snapshots", "2"]) == 0
    assert main(["analyze", path, "--out", str(tmp_path / "o"), "--no-figures"]) == 0


#: the subcommands of the study's own analyses (postproc.study), each with its --help
STUDY_COMMANDS = ("size-front", "leaning-blocks", "size-at-strain", "analysis-front", "claim6-criteria",
                  "lmgc90-agreement", "al-investigation",
                  "contact-types-kappa", "commonplane-reference", "facepair-tilt",
                  "timestep-front", "random-types", "shape-front", "cd-front")
#: a user's commands, in the order postproc --help lists them
USER = ("analyze", "report", "results", "compare-results", "compare-methods", "export-vtk", "import-lmgc90")


@pytest.mark.parametrize("cmd", STUDY_COMMANDS)
def test_study_subcommand_help(cmd, capsys):
    with pytest.raises(SystemExit) as exc:
        main(["investigate", cmd, "--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith(f"usage: postproc investigate {cmd}") and "--help" in out


def _listed(text, title):
    """The subcommands a help text lists under ``title`` (argparse's layout:
    a name at the start of an indented line)."""
    block = text.split(f"\n{title}:\n", 1)[1].split("\n\n", 1)[0]
    return [line.split()[0] for line in block.splitlines() if line.startswith("    ") and
            not line.startswith("     ")]


def test_the_help_lists_a_users_commands_first_and_the_investigations_in_their_group(capsys):
    from postproc import cli

    with pytest.raises(SystemExit):
        main(["--help"])
    top = _listed(capsys.readouterr().out, "commands")
    assert tuple(top[:len(USER)]) == USER and top[len(USER):] == ["synthetic", "investigate"]
    with pytest.raises(SystemExit):
        main(["investigate", "--help"])
    inner = _listed(capsys.readouterr().out, "investigations")
    assert sorted(inner) == sorted(STUDY_COMMANDS) == sorted(c.name for c in cli.INVESTIGATIONS)
    assert not set(inner) & set(top)


def test_the_old_spellings_run_with_a_note(tmp_path, capsys):
    """postproc NAME still runs an investigation, with one line on stderr
    saying its new spelling; the new spelling gives no note."""
    assert main(["timestep-front", str(tmp_path / "none")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err[0] == ("postproc: note: 'postproc timestep-front' is now 'postproc investigate timestep-front'; "
                      "the old spelling will be removed") and err[1].startswith("postproc: error: ")
    assert main(["investigate", "timestep-front", str(tmp_path / "none")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith("postproc: error: ")


def test_one_error_handler_for_every_command():
    """cli.main dispatches through the tables and turns errors into one line
    in one place."""
    import ast
    import inspect

    from postproc import cli

    src = inspect.getsource(cli)
    assert src.count('f"postproc: error: {exc}"') == 1
    tree = ast.parse(src)
    main_fn = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "main")
    assert not [n for n in ast.walk(main_fn) if isinstance(n, ast.If) and "cmd" in ast.unparse(n.test)]
    names = [c.name for c in cli.USER_COMMANDS + cli.TOOLS + cli.INVESTIGATIONS]
    assert len(names) == len(set(names)) == 22


def test_a_command_is_one_entry(monkeypatch, capsys):
    """A command added to the table is listed, parsed and run, and its bad
    input is one line with exit code 2 (the one handler)."""
    from postproc import cli
    from postproc.errors import InputError

    def run(args):
        if args.value < 0:
            raise InputError(f"--value must be >= 0, got {args.value}")
        print(f"value {args.value}")
        return 0

    extra = cli.Command("import-test", "a test's command", lambda p: p.add_argument("--value", type=int), run)
    monkeypatch.setattr(cli, "USER_COMMANDS", cli.USER_COMMANDS + (extra,))
    with pytest.raises(SystemExit):
        main(["--help"])
    assert _listed(capsys.readouterr().out, "commands")[len(USER)] == "import-test"
    assert main(["import-test", "--value", "3"]) == 0 and capsys.readouterr().out == "value 3\n"
    assert main(["import-test", "--value", "-1"]) == 2
    assert capsys.readouterr().err == "postproc: error: --value must be >= 0, got -1\n"


def test_analysis_front_subcommand(tmp_path, capsys):
    """A small front (2 sets per size, the default sizes): the CSV, the
    figure and the printed table."""
    out = tmp_path / "af"
    assert main(["investigate", "analysis-front", "--out", str(out), "--reps", "2"]) == 0
    table = pd.read_csv(out / "analysis_front.csv")
    assert set(table["estimator"]) == {"tensors", "fit-6", "fit-9", "fit-18", "fit-36"}
    assert (table["rms_max"] > 0).all() and (out / "analysis_front.png").stat().st_size > 0
    assert "rms_max" in capsys.readouterr().out
