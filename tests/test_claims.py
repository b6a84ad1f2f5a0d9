"""Plateau estimates, confidence intervals and the claim verdicts on
summaries built with known answers."""
import numpy as np
import pandas as pd
import pytest

from postproc.study.claims import evaluate
from postproc.statistics import Estimate, difference, plateau_estimate, steady_indices


def test_steady_indices():
    eq = np.array([0, 0, 0.1, 0.2, 0.3, 0.4])
    st = np.array(["compaction", "isotropic", "shear", "shear", "shear", "shear"])
    assert steady_indices(eq, st).tolist() == [3, 4, 5]
    assert steady_indices(np.full(3, np.nan), ["a", "b", "c"]).tolist() == [2]


def test_interval_over_seeds_covers_the_truth_at_95_percent():
    """Seeds drawn from N(0.4, 0.05): the t interval over 3 seeds covers 0.4
    in 95 % of 2000 repetitions, within 3 binomial standard errors."""
    rng = np.random.default_rng(0)
    hits = 0
    n = 2000
    for _ in range(n):
        e = plateau_estimate([rng.normal(0.4, 0.05, size=10).mean() + np.zeros(5) for _ in range(3)])
        lo, hi = e.ci()
        hits += lo < 0.4 < hi
    assert e.method == "seeds" and e.dof == 2
    assert abs(hits / n - 0.95) < 3 * np.sqrt(0.95 * 0.05 / n)


def test_batch_means_for_one_seed_and_degenerate_inputs():
    e = plateau_estimate([np.arange(8.0)])
    assert e.method.startswith("batch means") and e.n == 4 and e.mean == 3.5
    # batch means 0.5, 2.5, 4.5, 6.5: sd 2.582, se 1.291
    assert e.se == pytest.approx(np.std([0.5, 2.5, 4.5, 6.5], ddof=1) / 2)
    assert np.isnan(plateau_estimate([np.array([1.0])]).ci()[0])
    assert plateau_estimate([]).method == "no values"
    d = difference(Estimate(1.0, 0.1, 3, 4, "seeds"), Estimate(0.5, 0.1, 3, 4, "seeds"))
    assert d.mean == 0.5 and d.se == pytest.approx(np.sqrt(0.02)) and d.dof == pytest.approx(6)


def _frames(values, n_seeds=3, spread=0.005, seed=0):
    """Summaries of n_seeds runs: 10 shear snapshots at the given constant
    plateau values plus small noise; q_axial_over_p = q_over_p."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n_seeds):
        n = 10
        df = pd.DataFrame({"eps_q": np.linspace(0, 0.3, n), "stage": ["isotropic"] + ["shear"] * (n - 1)})
        for k, v in values.items():
            df[k] = v + rng.normal(0, spread, n)
        df["q_axial_over_p"] = df["q_over_p"]
        out.append(df)
    return out


PAPER_LIKE = {
    "polyhedra": dict(q_over_p=0.46, a=0.08, a_l=0.12, a_n=0.50, a_t=0.38, sff=0.43,
                      ct_fratio_FF=1.7, ct_fabric_FF=0.3, ct_fratio_VF=0.7, ct_fratio_EE=0.75,
                      ct_fabric_VF=-0.2, ct_fabric_EE=-0.25, strong_frac_FF=0.3,
                      weak_frac_FF=0.1, ct_theta_deg=5.0),
    "spheres": dict(q_over_p=0.23, a=0.24, a_l=0.0, a_n=0.21, a_t=0.05, sff=0.20),
}


def test_claims_reproduced_on_paper_like_data():
    s = {k: _frames(v) for k, v in PAPER_LIKE.items()}
    verdicts = [c["verdict"] for c in evaluate(s)]
    assert verdicts == ["reproduced"] * 6


def test_claims_not_reproduced_when_contradicted():
    flipped = {"polyhedra": dict(PAPER_LIKE["spheres"], ct_fratio_FF=0.5, ct_fabric_FF=-0.3,
                                 ct_fratio_VF=1.3, ct_fratio_EE=1.2, ct_fabric_VF=0.2,
                                 ct_fabric_EE=0.3, strong_frac_FF=0.1, weak_frac_FF=0.3,
                                 ct_theta_deg=5.0, sff=0.6),
               "spheres": dict(PAPER_LIKE["polyhedra"], a_l=0.2)}
    s = {k: _frames(v) for k, v in flipped.items()}
    verdicts = [c["verdict"] for c in evaluate(s)]
    assert verdicts == ["not reproduced"] * 6


def test_claims_inconclusive_with_noise_or_missing_runs():
    s = {k: _frames(v, spread=2.0) for k, v in PAPER_LIKE.items()}
    assert [c["verdict"] for c in evaluate(s)] == ["inconclusive"] * 6
    s = {"polyhedra": _frames(PAPER_LIKE["polyhedra"]), "spheres": []}
    out = evaluate(s)
    assert [c["verdict"] for c in out[:5]] == ["inconclusive"] * 5
    assert out[5]["verdict"] == "reproduced"


def test_claim6_names_the_criterion_it_was_read_with():
    for method, words in (("points", "contact-point count, tolerance 0.1 V/area"),
                          ("commonplane", "LMGC90's common-plane count, band 0.1 x the radius"),
                          ("footprint", "footprint criterion, threshold 0.1 d")):
        s = {k: _frames(v) for k, v in PAPER_LIKE.items()}
        for df in s["polyhedra"]:
            df["ct_method"], df["ct_threshold"] = method, 0.1
        c6 = evaluate(s)[5]
        assert c6["verdict"] == "reproduced" and words in c6["numbers"], c6["numbers"]
