"""The report's figures classify contacts with the criterion its analysis
recorded in summary.csv (not the defaults)."""
import numpy as np
import pandas as pd
import pytest

from postproc.study.report import _run_classifier
from shapes.generate import generate_library


@pytest.fixture(scope="module")
def shapes():
    lib, _ = generate_library(3, seed=2)
    return ([s.vertices for s in lib], [s.triangles for s in lib], [s.triangle_face for s in lib])


@pytest.mark.parametrize("row, method, attr, value", [
    ({"ct_method": "footprint", "ct_threshold": 0.2, "ct_theta_deg": 5.0}, "footprint", "threshold", 0.2),
    ({"ct_method": "points", "ct_threshold": 0.05, "ct_theta_deg": 5.0}, "points", "tolerance", 0.05),
    ({"ct_method": "angular", "ct_threshold": 7.5, "ct_theta_deg": 7.5}, "angular", "theta_deg", 7.5),
])
def test_the_recorded_criterion_is_used(tmp_path, shapes, row, method, attr, value):
    pd.DataFrame([{"step": 0, **row}]).to_csv(tmp_path / "summary.csv", index=False)
    c = _run_classifier({"analysis": str(tmp_path)}, shapes)
    assert c.method == method and getattr(c, attr) == value


def test_without_a_record_the_defaults(tmp_path, shapes):
    from postproc.classify import DEFAULT_METHOD

    assert _run_classifier({"analysis": str(tmp_path)}, shapes).method == DEFAULT_METHOD
    pd.DataFrame([{"step": 0, "p": 1.0}]).to_csv(tmp_path / "summary.csv", index=False)
    assert _run_classifier({"analysis": str(tmp_path)}, shapes).method == DEFAULT_METHOD
    assert _run_classifier({"analysis": None}, shapes).method == DEFAULT_METHOD
    assert np.isfinite(_run_classifier({"analysis": str(tmp_path)}, shapes).tolerance)
