"""python -m shapes pins OpenBLAS's kernels so that a recipe and a seed give the
same library on every CPU of a kind (shapes/blaspin.py); the committed archive's
library itself is rebuilt to its fingerprint by tests/test_committed_archive.py."""
import os
import subprocess
import sys

from shapes.blaspin import ENV, KEEP, cpu_flags, pin, reproducible_coretype

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
AVX512 = {"avx2", "fma", "avx512f", "avx512dq", "avx512bw", "avx512vl"}


def test_the_kernel_set_follows_the_cpu_flags():
    assert reproducible_coretype(AVX512) == "SkylakeX"
    assert reproducible_coretype(AVX512 - {"avx512vl"}) == "Haswell"
    assert reproducible_coretype({"avx2"}) is None
    assert reproducible_coretype(set()) is None


def test_pin_sets_the_variable_and_reexecutes_once():
    calls, env = [], {}
    assert pin(["build", "--n", "3"], env, lambda exe, args: calls.append((exe, args)), AVX512) == "SkylakeX"
    assert env[ENV] == "SkylakeX"
    assert calls == [(sys.executable, [sys.executable, "-m", "shapes", "build", "--n", "3"])]
    # the re-executed process finds the variable set and does not execute again
    assert pin(["build"], env, lambda *a: calls.append(a), AVX512) == "SkylakeX" and len(calls) == 1


def test_another_value_is_replaced_with_a_note_unless_kept(capsys):
    calls = []
    env = {ENV: "Haswell"}
    assert pin(["build"], env, lambda *a: calls.append(a), AVX512) == "SkylakeX" and env[ENV] == "SkylakeX"
    assert len(calls) == 1 and "OPENBLAS_CORETYPE=Haswell replaced by SkylakeX" in capsys.readouterr().err
    env = {ENV: "Haswell", KEEP: "1"}
    assert pin(["build"], env, lambda *a: calls.append(a), AVX512) == "Haswell" and env[ENV] == "Haswell"
    env = {}
    assert pin(["build"], env, lambda *a: calls.append(a), {"sse4_2"}) is None and ENV not in env
    assert len(calls) == 1


def test_cpu_flags_reads_the_first_processor(tmp_path):
    info = tmp_path / "cpuinfo"
    info.write_text("processor\t: 0\nflags\t\t: fpu avx2 fma\n\nprocessor\t: 1\nflags\t\t: fpu\n")
    assert cpu_flags(str(info)) == {"fpu", "avx2", "fma"}
    assert cpu_flags(str(tmp_path / "missing")) == set()


def test_python_m_shapes_builds_with_the_pinned_kernels(tmp_path):
    """The command itself, in an environment that asks for other kernels: its OpenBLAS runs
    the pinned set (where no pinned set runs on this CPU, the one it was given)."""
    env = {k: v for k, v in os.environ.items() if k != KEEP}
    env[ENV] = "Haswell" if reproducible_coretype(cpu_flags()) != "Haswell" else "SkylakeX"
    out = subprocess.run([sys.executable, "-m", "shapes", "build", "--n", "2", "--seed", "0",
                          "--out", str(tmp_path / "lib.h5")], env=env, cwd=ROOT, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    want = reproducible_coretype(cpu_flags())
    if want is None:
        assert "OpenBLAS kernels" in out.stderr
    else:
        assert f"OpenBLAS kernels {want}" in out.stderr, out.stderr
