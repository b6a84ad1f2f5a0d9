"""The analysis version (postproc.provenance.ANALYSIS_VERSION) changes when
an output number changes, and this test is what makes it so: the study's
analyses of two committed tiny dumps (S1 and S2; every contact count the
study offers, each with its alert distance halved and doubled) are hashed
number by number (tests/golden/analysis_digest.py) against the digest
recorded for today's version."""
import os
import sys

import pytest

from postproc import provenance

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "golden"))
import analysis_digest  # noqa: E402

#: ANALYSIS_VERSION -> the digest of analysis_digest.py under that version
GOLDEN = {
    1: "1ece3f09f91df8a3780da4a337f0f332cf7787a5b9a42ce5d4ca38596f9fe8d9",
}


def test_every_output_number_is_the_versions(tmp_path):
    got = analysis_digest.digest(str(tmp_path))
    assert len(got["files"]) == 8 and got["numbers"] > 10000      # both dumps, every count: all were hashed
    v = provenance.ANALYSIS_VERSION
    if v not in GOLDEN:
        pytest.fail(f"no golden digest for ANALYSIS_VERSION {v}: add {v}: {got['digest']!r} to GOLDEN "
                    "in tests/test_analysis_golden.py")
    if got["digest"] != GOLDEN[v]:
        pytest.fail(f"the analysis's output numbers changed (digest {got['digest'][:12]}, version {v}'s is "
                    f"{GOLDEN[v][:12]}): bump ANALYSIS_VERSION (postproc/provenance.py), add the new digest "
                    "to GOLDEN, and re-collect the committed results (docs/study.md)")


def test_the_digest_sees_a_changed_number(tmp_path):
    """One number moved by one part in 10^9 changes the digest: the test above can fail."""
    folders = analysis_digest.analyse(str(tmp_path / "a"))
    path = os.path.join(folders[0], "summary.csv")
    before = analysis_digest.file_tokens(path)
    import pandas as pd

    df = pd.read_csv(path)
    df.loc[len(df) - 1, "q_over_p"] *= 1 + 1e-9
    df.to_csv(path, index=False)
    after = analysis_digest.file_tokens(path)
    assert sum(a != b for a, b in zip(before, after)) == 1


def test_historical_code_hashes_name_known_versions():
    assert all(isinstance(v, int) and 1 <= v <= provenance.ANALYSIS_VERSION
               for v in provenance.HISTORICAL_CODE_VERSIONS.values())
    assert all(len(h) == 64 for h in provenance.HISTORICAL_CODE_VERSIONS)
    assert provenance.code_hash() not in provenance.HISTORICAL_CODE_VERSIONS or \
        provenance.HISTORICAL_CODE_VERSIONS[provenance.code_hash()] == provenance.ANALYSIS_VERSION
