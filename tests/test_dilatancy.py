"""Peak q/p and the dilatancy angle at the peak, on hand-built series with
exact answers."""
import numpy as np
import pandas as pd
import pytest

from postproc.study.dilatancy import dilatancy_angle, peak_index, peak_summary
from postproc.errors import InputError


def _series(psi_deg, n=30, de=0.01):
    eq = np.r_[0.0, np.arange(1, n + 1) * de]
    stage = np.array(["isotropic"] + ["shear"] * n)
    ev = 0.002 + 0.3 * eq[:1].repeat(n + 1) - np.sin(np.radians(psi_deg)) * eq   # linear: exact slope
    qp = 0.45 - 0.3 * (eq - 0.08) ** 2                                          # peak at eps_q = 0.08
    qp[0] = 0.0
    return pd.DataFrame({"eps_q": eq, "eps_v": ev, "q_over_p": qp, "stage": stage})


@pytest.mark.parametrize("psi", [-3.0, 0.0, 2.5, 5.0, 20.0])
def test_linear_volume_change_gives_the_exact_angle(psi):
    df = _series(psi)
    peak, eq_peak, angle = peak_summary(df)
    assert eq_peak == pytest.approx(0.08, abs=1e-15)
    assert peak == pytest.approx(0.45, abs=1e-15)
    assert angle == pytest.approx(psi, abs=1e-9)     # round-off of the line fit


def test_only_shear_rows_count_and_the_window_is_local():
    df = _series(5.0)
    # a contracting start (eps_v rising) far from the peak does not enter the slope
    df.loc[1:3, "eps_v"] += 0.05
    df.loc[0, "q_over_p"] = 10.0                      # an isotropic row is never the peak
    k = peak_index(df["q_over_p"], df["stage"])
    assert df["eps_q"][k] == pytest.approx(0.08)
    assert dilatancy_angle(df["eps_q"], df["eps_v"], df["stage"], k) == pytest.approx(5.0, abs=1e-9)


def test_no_angle_cases_are_nan_and_no_shear_is_a_one_line_error():
    df = _series(5.0)
    df["eps_v"] = -2.0 * df["eps_q"]                  # |d eps_v/d eps_q| > 1: no angle
    assert np.isnan(peak_summary(df)[2])
    with pytest.raises(InputError, match="no shear snapshot"):
        peak_index([0.1, 0.2], ["isotropic", "isotropic"])
    assert np.all(np.isnan(peak_summary(df.assign(stage="isotropic"))))
    with pytest.raises(InputError, match="shape"):
        dilatancy_angle([0.0, 0.1], [0.0], ["shear", "shear"], 0)
