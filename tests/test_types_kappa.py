"""postproc.study.typeskappa, postproc.study.commonplaneref and
postproc.study.facepair (``postproc contact-types-kappa``, ``postproc
commonplane-reference``, ``postproc facepair-tilt``) on a tiny kernel dump,
through the command line: the contact groups of both criteria, the common
plane's band measured two ways, the older of which is the analysis's own
common-plane count, and the face-pair tilt."""
import numpy as np
import pandas as pd
import pytest

from postproc.cli import main
from test_footprint_types import kernel_sets_dump

GROUPS = ("simple", "double", "triple")


@pytest.fixture(scope="module")
def kernel_dump(tmp_path_factory):
    """An S1-like kernel dump with its run parameters: one isotropic and two
    shear snapshots (64 grains, the box shortened along z by 1 % each), the
    overlaps' volumes and footprints dumped."""
    return kernel_sets_dump(str(tmp_path_factory.mktemp("kappa") / "polyhedra-k3000.h5"), 3, np.zeros((6, 3)),
                            parameters={"kappa": 3000.0, "inertial_number": 5e-3, "n_particles": 64, "seed": 1},
                            overlap_kind="volume", footprint=True)


@pytest.fixture(scope="module")
def kappa_table(kernel_dump, tmp_path_factory):
    """``postproc contact-types-kappa`` on the dump (both shear snapshots)."""
    out = tmp_path_factory.mktemp("ctk")
    assert main(["investigate", "contact-types-kappa", str(out), kernel_dump, "--from-eps1", "0"]) == 0
    return out


def test_contact_types_kappa_command(kappa_table):
    tab = pd.read_csv(kappa_table / "contact_types_kappa.csv")
    assert tab["criterion"].tolist() == ["commonplane", "points"]
    assert (tab["kappa"] == 3000).all() and (tab["I"] == 5e-3).all() and (tab["snapshots"] == 2).all()
    for suffix in ("", "_lo", "_hi"):
        np.testing.assert_allclose(tab[[g + suffix for g in GROUPS]].sum(axis=1), 1.0, atol=1e-12)
    assert (tab["move"] >= 0).all()
    md = (kappa_table / "contact_types_kappa.md").read_text()
    assert md.count("| 3000 | 0.005 |") == 2 and "Means over seeds" not in md      # one seed: no means
    assert (kappa_table / "polyhedra-k3000-points" / "summary.csv").exists()


def test_commonplane_reference_command(kernel_dump, kappa_table, tmp_path, capsys):
    """The band from the extreme vertex is the common-plane count the
    analysis uses: its proportions are contact-types-kappa's, exactly."""
    out = tmp_path / "cpref"
    assert main(["investigate", "commonplane-reference", str(out), kernel_dump, "--from-eps1", "0"]) == 0
    tab = pd.read_csv(out / "commonplane_reference.csv").set_index("reference")
    assert sorted(tab.index) == ["normal", "vertex"] and (tab["snapshots"] == 2).all()
    cp = pd.read_csv(kappa_table / "contact_types_kappa.csv").set_index("criterion").loc["commonplane"]
    for col in [g + s for g in GROUPS for s in ("", "_lo", "_hi")] + ["move", "contacts"]:
        assert tab.loc["vertex", col] == pytest.approx(cp[col], abs=1e-12), col
    assert "| normal | 1 |" in capsys.readouterr().out
    assert main(["investigate", "commonplane-reference", str(out), kernel_dump, "--from-eps1", "0.5"]) == 2
    assert "no shear snapshot with eps_1 >= 0.5" in capsys.readouterr().err
    assert main(["investigate", "commonplane-reference", str(out), kernel_dump, "--every", "0"]) == 2


def test_facepair_tilt_command(kernel_dump, kappa_table, tmp_path, capsys):
    """One kappa, one seed: a row per pair and snapshot, the per-run table
    whose triple shares are the two criteria's FF share (the same labels
    as contact-types-kappa's triple), the random contacts' row, the figure;
    the driver that runs the plan first answers --help."""
    from yade_scripts.campaign import facepair_sweep as facepair_tilt

    out = tmp_path / "fp"
    assert main(["investigate", "facepair-tilt", str(out), kernel_dump, "--from-eps1", "0"]) == 0
    rows = pd.read_csv(out / "facepair_tilt.csv.gz")
    tab = pd.read_csv(out / "facepair_tilt.csv")
    ctk = pd.read_csv(kappa_table / "contact_types_kappa.csv").set_index("criterion")
    assert len(tab) == 1 and tab["contacts"].iloc[0] == len(rows) == ctk.loc["points", "contacts"]
    assert rows["phi_deg"].between(0, 90).all() and (rows["h_d"] > 0).all()
    for c in ("points", "commonplane"):
        assert tab[f"triple_{c}"].iloc[0] == pytest.approx(np.mean(rows[c] == "FF"), abs=1e-12)
    assert "| random orientations | | 20000 |" in capsys.readouterr().out
    assert (out / "facepair-tilt.png").stat().st_size > 0
    with pytest.raises(SystemExit) as exc:
        facepair_tilt.main(["--help"])
    assert exc.value.code == 0 and "usage: python -m yade_scripts.campaign.facepair_sweep" in capsys.readouterr().out
