"""Plateau estimates, confidence intervals and the claim verdicts on
summaries built with known answers."""
import numpy as np
from scipy.stats import t
import pandas as pd
import pytest

from postproc.study.claims import evaluate
from postproc.statistics import (Estimate, block_components, difference, plateau_estimate, seed_scatter, seeds_needed,
                                 seeds_to_decide,
                                 steady_indices)


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


def test_seeds_needed_against_the_t_table():
    """mean = sd: t_5 / sqrt(6) = 2.5706 / 2.4495 = 1.049 >= 1, t_6 / sqrt(7)
    = 2.4469 / 2.6458 = 0.925 < 1, so 7 seeds; the answer depends on
    mean / sd only and keeps the interval off 0 exactly from there."""
    from scipy.stats import t
    assert seeds_needed(1.0, 1.0) == 7
    assert seeds_needed(-0.3, 0.3) == 7 and seeds_needed(1e-3, 1e-3) == 7
    for m, sd in ((0.04, 0.085), (0.02, 0.035), (0.5, 0.1)):
        n = seeds_needed(m, sd)
        assert t.ppf(0.975, n - 1) * sd / np.sqrt(n) < m
        assert n == 2 or t.ppf(0.975, n - 2) * sd / np.sqrt(n - 1) >= m
    assert seeds_needed(0.0, 0.1) is None and seeds_needed(1e-6, 1.0, n_max=1000) is None
    with pytest.raises(ValueError, match="finite"):
        seeds_needed(np.nan, 1.0)


def test_block_components_split_local_packing_and_position_parts():
    """Hand-built: a packing part plus a position part has no local part;
    a local part alone has no packing part. Monte Carlo, S = 2000 packings
    of B = 8 blocks, local sd 0.1, packing sd 0.05 and fixed position
    effects of sd 0.08: local^2 has (S-1)(B-1) = 13 993 degrees of freedom,
    a relative standard error of sqrt(2 / 13 993) = 0.012; packing^2 =
    (MS_seed - MS_res) / B has a standard error of about sqrt(2 / 1999) x
    (0.05^2 + 0.1^2 / 8) = 1.2e-4; the tolerances are 4 of them. The 95 %
    interval of local covers the truth in 95 % of 2000 small replications
    (S = 3, B = 8) to within 4 binomial standard errors."""
    pack = np.array([[0.0], [1.0], [2.0]])
    pos = np.array([[0.0, 0.5, 0.25, 0.75]])
    c = block_components(pack + pos)
    assert c.local == pytest.approx(0, abs=1e-12) and c.packing == pytest.approx(1.0)
    assert c.position == pytest.approx(np.std(pos, ddof=1)) and (c.seeds, c.blocks) == (3, 4)
    v = np.array([[1.0, -1.0], [-1.0, 1.0]])               # residuals only: rows and columns cancel
    c = block_components(v)
    assert c.local == pytest.approx(2.0) and c.packing == 0 and c.position == 0 and c.local_dof == 1
    assert block_components(np.array([[1.0, np.nan, 2.0], [3.0, 4.0, 5.0]])).blocks == 2
    assert np.isnan(block_components(np.ones((1, 5))).local)
    with pytest.raises(ValueError, match="packings, blocks"):
        block_components(np.ones(5))
    rng = np.random.default_rng(2)
    S, B = 2000, 8
    beta = rng.normal(0, 0.08, B)
    v = rng.normal(0, 0.05, (S, 1)) + beta[None, :] + rng.normal(0, 0.1, (S, B))
    c = block_components(v)
    assert abs(c.local ** 2 / 0.01 - 1) < 4 * np.sqrt(2 / ((S - 1) * (B - 1)))
    assert abs(c.packing ** 2 - 0.0025) < 4 * np.sqrt(2 / (S - 1)) * (0.0025 + 0.01 / B)
    assert c.whole == pytest.approx(np.sqrt(c.packing ** 2 + c.local ** 2 / B))
    assert c.position_p < 1e-6
    n, hits = 2000, 0
    for _ in range(n):
        lo, hi = block_components(rng.normal(0, 0.1, (3, B)) + beta[None, :]).local_ci
        hits += lo <= 0.1 <= hi
    assert abs(hits / n - 0.95) < 4 * np.sqrt(0.95 * 0.05 / n)


def test_seed_scatter_splits_persistent_from_window_noise():
    """Constant series: all scatter is persistent. Equal series: none.
    Monte Carlo, persistent sd 0.08 and white noise 0.08 per value over 16
    values (a plateau-mean error of 0.02): over 4000 seeds the estimate of
    persistent² = 0.0064 has a standard error of about sqrt(2 / 3999) x
    0.0068 = 1.5e-4, and the rms error one of 0.02 x sqrt(2/3) / (2 sqrt(4000))
    = 1.3e-4 (each seed's squared error has 3 degrees of freedom); the
    tolerances are 4 of them."""
    c = seed_scatter([np.full(5, v) for v in (0.125, 0.25, 0.75)])
    assert c.within == 0 and c.persistent == pytest.approx(np.std([0.125, 0.25, 0.75], ddof=1)) and c.n == 3
    same = np.array([0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0])    # batch means 0, 1, 2, 3
    e = seed_scatter([same, same, same])
    assert e.between == 0 and e.persistent == 0
    assert e.within == pytest.approx(np.std([0.0, 1.0, 2.0, 3.0], ddof=1) / 2)
    assert np.isnan(seed_scatter([same]).between) and np.isnan(seed_scatter([same, same[:3]]).within)
    rng = np.random.default_rng(1)
    n = 4000
    series = [rng.normal(0.08 * z, 0.08, size=16) for z in rng.standard_normal(n)]
    s = seed_scatter(series)
    assert s.n == n
    assert abs(s.persistent ** 2 - 0.0064) < 4 * np.sqrt(2 / (n - 1)) * 0.0068
    assert abs(s.within - 0.02) < 4 * 0.02 * np.sqrt(2 / 3) / (2 * np.sqrt(n))


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


def test_claim6_says_how_many_seeds_would_decide_a_straddling_leaning():
    """EE leanings constant per seed at -0.1, +0.1, -0.2 (mean -0.0667, sd
    0.1528, t_2 interval straddles 0): seeds_needed gives 23 (t_21 x 0.1528 /
    sqrt(22) = 0.0678 > 0.0667 > t_22 x 0.1528 / sqrt(23) = 0.0661) and the
    text names it; a decided condition gets no such words."""
    s = {k: _frames(v) for k, v in PAPER_LIKE.items()}
    for df, v in zip(s["polyhedra"], (-0.1, 0.1, -0.2)):
        df["ct_fabric_EE"] = v
    from scipy.stats import t
    sd = np.std([-0.1, 0.1, -0.2], ddof=1)
    n = seeds_needed(-0.2 / 3, sd)
    assert n == 23
    assert t.ppf(0.975, n - 1) * sd / np.sqrt(n) < 0.2 / 3 <= t.ppf(0.975, n - 2) * sd / np.sqrt(n - 1)
    c6 = evaluate(s)[5]
    assert c6["verdict"] == "inconclusive"
    assert f"EE signed branch anisotropy -0.07 [-0.45, 0.31] (< 0, about {n} seeds would decide it (lateral); " \
           "leaning undecided, none inside ±0.03)" \
        in c6["numbers"], c6["numbers"]
    assert c6["numbers"].count("seeds would decide") == 1 and "seeds would tell" not in c6["numbers"]


@pytest.mark.parametrize("mean", [-0.08, -0.031, -0.02, -0.005, 0.0, 0.006, 0.015, 0.029, 0.03, 0.045])
@pytest.mark.parametrize("sd", [0.005, 0.015, 0.04])
def test_seeds_to_decide_is_the_first_n_the_rule_decides(mean, sd):
    """Against the rule itself: the leaning of n seeds with this mean and sd
    (se = sd / sqrt(n), n - 1 dof) is undecided for every n below the
    figure and decided, with the figure's word, at it."""
    from postproc.study.claims import leaning_decision

    def word(n):
        return leaning_decision(Estimate(mean, sd / np.sqrt(n), n - 1, n, "seeds"))

    got = seeds_to_decide(mean, sd, 0.03, n_max=400)
    first = next((n for n in range(2, 401) if word(n) != "undecided"), None)
    if first is None:
        assert got is None
    else:
        assert got == (first, word(first))


def test_claim6_names_the_criterion_it_was_read_with():
    for method, words in (("points", "contact-point count, tolerance 0.1 V/area"),
                          ("commonplane", "the earlier band count on a common plane, band 0.1 x the radius"),
                          ("lmgc90", "LMGC90's own count (today's point stage), alert distance 0.1 x the smallest "
                                     "grain radius"),
                          ("footprint", "footprint criterion, threshold 0.1 d")):
        s = {k: _frames(v) for k, v in PAPER_LIKE.items()}
        for df in s["polyhedra"]:
            df["ct_method"], df["ct_threshold"] = method, 0.1
        c6 = evaluate(s)[5]
        assert c6["verdict"] == "reproduced" and words in c6["numbers"], c6["numbers"]


def _rule_rates(mu, sigma, n, reps, rng):
    """Monte Carlo of claim 6's leaning rule: ``reps`` ensembles of ``n``
    seeds drawn from N(mu, sigma^2); returns the share of each decision and
    the coverage of the 95 % interval."""
    from postproc.study.claims import leaning_decision

    x = rng.normal(mu, sigma, size=(reps, n))
    m, se = x.mean(axis=1), x.std(axis=1, ddof=1) / np.sqrt(n)
    counts = {"lateral": 0, "axial": 0, "none": 0, "undecided": 0}
    covered = 0
    for a, b in zip(m, se):
        e = Estimate(a, b, n - 1, n, "seeds")
        counts[leaning_decision(e)] += 1
        lo, hi = e.ci()
        covered += lo <= mu <= hi
    return {k: v / reps for k, v in counts.items()}, covered / reps


def _rule_exact(mu, sigma, n, margin):
    """The rule's decision probabilities for normal seeds, exactly: the mean
    ~ N(mu, sigma^2/n) and (n-1) s^2 / sigma^2 ~ chi^2(n-1), independent;
    with h = t_{0.975, n-1} s / sqrt(n), "lateral" is mean + h < 0, "none"
    is |mean| + h < margin (it comes first), integrated over s."""
    from scipy import integrate
    from scipy.stats import chi2, norm

    k = t.ppf(0.975, n - 1) / np.sqrt(n)
    sm = sigma / np.sqrt(n)

    def over_s(f):
        return integrate.quad(lambda c: f(sigma * np.sqrt(c / (n - 1))) * chi2.pdf(c, n - 1), 0, np.inf,
                              limit=200)[0]

    def band(a, b):                                  # P(a < mean < b)
        return max(0.0, norm.cdf((b - mu) / sm) - norm.cdf((a - mu) / sm))

    none = over_s(lambda s: band(-margin + k * s, margin - k * s))
    # "lateral": the interval below 0 and not inside the margin
    lateral = over_s(lambda s: norm.cdf((-k * s - mu) / sm) - band(-margin + k * s, -k * s))
    return {"lateral": lateral, "none": none}


@pytest.mark.parametrize("mu, sigma, n", [(0.0, 0.02, 6), (0.03, 0.02, 6), (-0.03, 0.01, 3), (-0.05, 0.03, 6),
                                          (0.01, 0.015, 10)])
def test_the_leaning_rule_decides_at_its_stated_rates(mu, sigma, n):
    """Claim 6's leaning rule on synthetic ensembles of known mean: the share
    of "lateral" and of "none" decisions equals its exact probability, the
    95 % interval covers the true mean 95 % of the time, and a leaning of
    the margin's size (|mu| = 0.03) is called "none" at most 2.5 % of the
    time (the equivalence test's level). Tolerances: 4 binomial standard
    errors of the 4000 replications."""
    from postproc.study.claims import NO_LEANING

    reps = 4000
    rates, coverage = _rule_rates(mu, sigma, n, reps, np.random.default_rng(abs(hash((mu, sigma, n))) % 2**32))
    exact = _rule_exact(mu, sigma, n, NO_LEANING)
    tol = lambda p: 4 * np.sqrt(max(p * (1 - p), 1 / reps) / reps)
    assert sum(rates.values()) == pytest.approx(1.0)
    for k in ("lateral", "none"):
        assert abs(rates[k] - exact[k]) <= tol(exact[k]), (k, rates[k], exact[k])
    assert abs(coverage - 0.95) <= tol(0.95)
    if abs(mu) >= NO_LEANING:
        assert exact["none"] <= 0.025 and rates["none"] <= 0.025 + tol(0.025)


def test_a_leaning_called_none_or_axial_contradicts_claim_6():
    """The rule inside claim 6: VF and EE leanings both "none" (intervals
    inside +-0.03) make the claim not reproduced; both lateral, with FF
    strong and axial, reproduced; one undecided, inconclusive."""
    from postproc.study.claims import claim6

    def seeds(vf, ee, spread):
        out = []
        for k in range(5):
            eps = np.linspace(0, 0.3, 40)
            d = {"eps_q": eps, "stage": ["shear"] * 40, "ct_fratio_FF": 1.7, "ct_fabric_FF": 0.3,
                 "ct_fratio_VF": 0.7, "ct_fratio_EE": 0.75, "strong_frac_FF": 0.3 + 0.002 * k,
                 "weak_frac_FF": 0.1 + 0.002 * k,
                 "ct_fabric_VF": vf + spread * (k - 2), "ct_fabric_EE": ee + spread * (k - 2)}
            out.append(pd.DataFrame(d))
        return out

    assert claim6(seeds(0.0, 0.001, 0.003))["verdict"] == "not reproduced"
    assert "leaning none, none inside ±0.03" in claim6(seeds(0.0, 0.001, 0.003))["numbers"]
    assert claim6(seeds(-0.1, -0.08, 0.003))["verdict"] == "reproduced"
    assert claim6(seeds(-0.1, 0.0, 0.03))["verdict"] == "inconclusive"


def _decide(x):
    """The leaning rule on one study's seeds ``x`` (shape (n,)): Estimate
    and leaning_decision, as the report decides."""
    from postproc.study.claims import leaning_decision

    return leaning_decision(Estimate(x.mean(), x.std(ddof=1) / np.sqrt(len(x)), len(x) - 1, len(x), "seeds"))


def _two_stage_by_hand(mu, sigma, n1, n_cap, reps, rng):
    """The two-stage design written out study by study with the rule itself
    (Estimate and leaning_decision), for comparison with the vectorised
    :func:`postproc.statistics.two_stage_rates`."""
    from postproc.study.claims import NO_LEANING
    from postproc.statistics import seeds_to_decide

    counts = dict.fromkeys(("none", "lateral", "axial", "undecided"), 0)
    for _ in range(reps):
        x = rng.normal(mu, sigma, n1)
        word = _decide(x)
        if word == "undecided":
            plan = seeds_to_decide(x.mean(), x.std(ddof=1), NO_LEANING, n_max=n_cap)
            if plan is not None:
                word = _decide(np.concatenate([x, rng.normal(mu, sigma, plan[0] - n1)]))
        counts[word] += 1
    return {k: v / reps for k, v in counts.items()}


def test_two_stage_rates_without_extension_are_the_rule_s_exact_rates():
    """With no room to extend (n_cap = n1) the two-stage design is the
    fixed one: its shares equal the rule's exact probabilities (4 binomial
    standard errors of the replications), nothing is extended, and the
    vectorised rule gives leaning_decision's word on every study."""
    from postproc.study.claims import NO_LEANING, leaning_decision
    from postproc.statistics import leaning_words, two_stage_rates

    reps = 4000
    tol = lambda p: 4 * np.sqrt(max(p * (1 - p), 1 / reps) / reps)
    for mu, sigma in ((0.0, 0.02), (0.03, 0.02), (-0.02, 0.03)):
        r = two_stage_rates(mu, sigma, 6, 6, NO_LEANING, reps=reps, rng=7)
        exact = _rule_exact(mu, sigma, 6, NO_LEANING)
        assert r["extended"] == 0.0 and r["mean_seeds"] == 6.0
        assert sum(r[k] for k in ("none", "lateral", "axial", "undecided")) == pytest.approx(1.0)
        for k in ("lateral", "none"):
            assert abs(r[k] - exact[k]) <= tol(exact[k]), (mu, sigma, k, r[k], exact[k])
    rng = np.random.default_rng(3)
    m, s = rng.normal(0, 0.03, 2000), rng.uniform(0.001, 0.05, 2000)
    h = t.ppf(0.975, 5) * s / np.sqrt(6)
    m[:3], h[:3] = (np.nan, np.inf, 0.01), (0.01, 0.01, np.inf)      # intervals that are not finite
    words = leaning_words(m - h, m + h, NO_LEANING)
    assert list(words) == [leaning_decision(Estimate(a, b / np.sqrt(6), 5, 6, "seeds"))
                           for a, b in zip(m, s * np.where(np.isinf(h), np.inf, 1.0))]
    assert list(words[:3]) == ["undecided"] * 3


@pytest.mark.parametrize("mu, sigma", [(0.0, 0.032), (0.03, 0.032), (0.015, 0.018)])
def test_two_stage_rates_agree_with_the_design_written_out(mu, sigma):
    """Extended to at most 16 seeds from 6, the vectorised Monte Carlo and
    the design written out study by study with the rule's own functions give
    the same shares, within 4 standard errors of the difference of two
    independent binomial shares of the replications."""
    from postproc.study.claims import NO_LEANING
    from postproc.statistics import two_stage_rates

    reps = 1500
    r = two_stage_rates(mu, sigma, 6, 16, NO_LEANING, reps=reps, rng=11)
    by_hand = _two_stage_by_hand(mu, sigma, 6, 16, reps, np.random.default_rng(12))
    assert 0 < r["extended"] < 1 and 6 < r["mean_seeds"] <= 16
    for k, p in by_hand.items():
        q = max((p + r[k]) / 2, 1 / reps)
        assert abs(r[k] - p) <= 4 * np.sqrt(2 * q * (1 - q) / reps), (k, r[k], p)


def test_two_stage_rates_scale_with_the_leaning_and_refuse_bad_input():
    """Scaling mu, sigma and the margin by a power of two changes no
    decision (the same draws, scaled exactly); bad input: one line."""
    from postproc.statistics import two_stage_rates

    a = two_stage_rates(0.01, 0.03, 5, 12, 0.03, reps=500, rng=5)
    b = two_stage_rates(0.04, 0.12, 5, 12, 0.12, reps=500, rng=5)
    assert a == b
    for args in ((np.nan, 0.03, 6, 16, 0.03), (0.0, 0.0, 6, 16, 0.03), (0.0, 0.03, 1, 16, 0.03),
                 (0.0, 0.03, 6, 5, 0.03), (0.0, 0.03, 6, 16, -1.0)):
        with pytest.raises(ValueError, match="two_stage_rates"):
            two_stage_rates(*args, reps=10)


def test_two_stage_rates_decide_each_study_as_the_rule_does_on_the_same_draws():
    """The same draws as two_stage_rates (stage one's (reps, n1) block, then
    each extension size's block in increasing size), each study decided with
    Estimate and leaning_decision and extended by seeds_to_decide on its own
    first-stage seeds: the shares are equal exactly, so the extension reuses
    stage one's seeds and extends to the planned size."""
    from postproc.study.claims import NO_LEANING
    from postproc.statistics import seeds_to_decide, two_stage_rates

    mu, sigma, n1, cap, reps = 0.01, 0.03, 6, 16, 800
    rng = np.random.default_rng(21)
    x = rng.normal(mu, sigma, size=(reps, n1))
    words = [_decide(row) for row in x]
    plan = {}
    for i, w in enumerate(words):
        if w == "undecided":
            p = seeds_to_decide(x[i].mean(), x[i].std(ddof=1), NO_LEANING, n_max=cap)
            if p is not None:
                plan.setdefault(p[0], []).append(i)
    for size in sorted(plan):
        more = rng.normal(mu, sigma, size=(len(plan[size]), size - n1))
        for i, extra in zip(plan[size], more):
            words[i] = _decide(np.concatenate([x[i], extra]))
    r = two_stage_rates(mu, sigma, n1, cap, NO_LEANING, reps=reps, rng=21)
    assert {k: r[k] for k in ("none", "lateral", "axial", "undecided")} == \
        {k: words.count(k) / reps for k in ("none", "lateral", "axial", "undecided")}
    assert r["extended"] == sum(map(len, plan.values())) / reps > 0
