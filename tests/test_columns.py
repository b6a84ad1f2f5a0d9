"""The summary's declared columns (postproc.columns): the analysis writes
exactly what they declare, in their order; the docs' tables are the
generated ones; the study's figures and tables take their labels from them."""
import os

import numpy as np
import pandas as pd
import pytest

from postproc import columns
from postproc.columns import COLUMNS, LEAD
from postproc.pipeline import AnalysisOptions, analyze_path
from postproc.synthetic import write_synthetic_dump
from test_footprint_types import kernel_sets_dump
from test_schema_points import lattice_points

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


@pytest.fixture(scope="module")
def summaries(tmp_path_factory):
    """{name: summary columns} of a polyhedra dump of kernel contact sets
    analysed by the point count and by LMGC90's, of the same sets as a CD
    dump (contact points), and of a synthetic spheres dump."""
    tmp = tmp_path_factory.mktemp("columns")
    path = kernel_sets_dump(str(tmp / "run.h5"), 3, np.full((6, 3), 0.5))
    out = {}
    for types in ("points", "lmgc90"):
        folder = str(tmp / types)
        analyze_path(path, folder, AnalysisOptions(types=types, figures=False), progress=False)
        out[types] = list(pd.read_csv(os.path.join(folder, "summary.csv")).columns)
    cd = kernel_sets_dump(str(tmp / "cd.h5"), 3, np.full((6, 3), 0.5), points=lattice_points)
    analyze_path(cd, str(tmp / "cd"), AnalysisOptions(figures=False), progress=False)
    out["cd"] = list(pd.read_csv(os.path.join(tmp / "cd", "summary.csv")).columns)
    spheres = str(tmp / "spheres.h5")
    write_synthetic_dump(spheres, 2000, 3, (0.3, 0.1, 0.5, 0.2), seed=1)
    analyze_path(spheres, str(tmp / "s"), AnalysisOptions(figures=False), progress=False)
    out["spheres"] = list(pd.read_csv(os.path.join(tmp / "s", "summary.csv")).columns)
    return out


def test_the_analysis_writes_only_declared_columns_in_their_order(summaries):
    for name, cols in summaries.items():
        assert cols[:len(LEAD)] == list(LEAD), name
        undeclared = [c for c in cols if c not in COLUMNS]
        assert not undeclared, f"{name}: columns the schema does not declare: {undeclared}"
        rest = [c for c in cols if c not in LEAD]
        assert rest == [c for c in COLUMNS if c in cols and c not in LEAD], name
    assert "ct_alert_m" in summaries["lmgc90"] and "ct_fp_missing" in summaries["points"]
    assert "cd_force_frac_triple" in summaries["cd"] and "cd_force_frac_triple" not in summaries["points"]


def test_every_declared_column_is_written_by_some_analysis(summaries):
    """No stale declaration: each column shows in one of the summaries (the
    wall form needs the walls' forces, given here; ct_qp_wall needs wall
    contacts, which the kernel sets have not: the study's dumps have them)."""
    seen = set().union(*summaries.values())
    assert [c for c in COLUMNS if c not in seen] == ["ct_qp_wall"]


def test_every_column_has_a_unit_a_meaning_and_a_label():
    units = {"Pa", "m", "N", "m^3", "s", "deg", "1", ""}
    for name, c in COLUMNS.items():
        assert c.name == name and c.unit in units and c.meaning and c.label, name
        assert c.equation == "" or c.equation.startswith("Eq. "), name
        assert "|" not in c.meaning and "<" not in c.meaning, name          # Markdown-safe
    assert COLUMNS["p"].unit == "Pa" and COLUMNS["l0"].unit == "m" and COLUMNS["f0"].unit == "N"
    assert COLUMNS["sff"].equation == "Eq. 10" and COLUMNS["s_xx"].equation == "Eq. 2"
    assert COLUMNS["eps_q"].equation == "Eq. 3" and COLUMNS["a_t"].equation == "Eq. 9"


@pytest.mark.parametrize("page, names", columns.DOC_TABLES)
def test_the_docs_tables_are_the_generated_ones(page, names):
    with open(os.path.join(ROOT, page)) as fh:
        text = fh.read()
    assert columns.docs_block(names) in text, f"{page}'s table is stale: run python -m postproc.columns"


def test_write_docs_rewrites_a_stale_table(tmp_path):
    for page, names in columns.DOC_TABLES:
        (tmp_path / page).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / page).write_text(f"# x\n\n{columns.BEGIN}\n| stale |\n{columns.END}\n\nafter\n")
    assert columns.write_docs(str(tmp_path)) == [p for p, _ in columns.DOC_TABLES]
    text = (tmp_path / "docs/postproc.md").read_text()
    assert "| stale |" not in text and text.endswith(f"{columns.END}\n\nafter\n") and "`q_over_p`" in text
    assert columns.write_docs(str(tmp_path)) == []
    (tmp_path / "docs/postproc.md").write_text("no markers\n")
    with pytest.raises(ValueError, match="no generated table"):
        columns.write_docs(str(tmp_path))


def test_the_studys_lists_name_declared_columns_with_the_declared_labels():
    from postproc import plots
    from postproc.study import front, sizefront, sizestrain

    derived = {"sff_rel_residual", "phi_iso"}                  # computed from the summary, not in it
    for name, title in plots.SIZE_PANELS + plots.SHAPE_PANELS:
        assert name in derived or title.startswith(COLUMNS[name].label), name
    for key, (column, title) in sizefront.QUANTITIES.items():
        assert column is None or title.startswith(COLUMNS[column].label), key
    for name in tuple(sizefront.COUNT_QUANTITIES) + front.QUANTITIES + sizestrain.QUANTITIES:
        assert name in COLUMNS, name
