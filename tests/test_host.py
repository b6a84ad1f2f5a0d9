"""The host facts a run records (yade_scripts/runs/host.py): hand-built
/proc/cpuinfo texts with known answers, and a host whose facts cannot be read."""
import platform

from yade_scripts.runs.host import SIMD_FLAGS, cpu_from_cpuinfo, host_info

CPUINFO = """processor\t: 0
vendor_id\t: AuthenticAMD
cpu family\t: 25
model\t\t: 17
model name\t: AMD EPYC 9454 48-Core Processor
stepping\t: 1
flags\t\t: fpu sse4_2 avx avx2 fma avx512f avx512dq avx512bw avx512vl avx512_bf16

processor\t: 1
model name\t: another CPU
flags\t\t: fpu sse4_2
"""


def test_first_processor_block_gives_model_and_simd_flags():
    model, flags = cpu_from_cpuinfo(CPUINFO)
    assert model == "AMD EPYC 9454 48-Core Processor (family 25, model 17, stepping 1)"
    # avx512_bf16 is not one of SIMD_FLAGS; fpu is not a vector flag
    assert flags == ["avx", "avx2", "avx512bw", "avx512dq", "avx512f", "avx512vl", "fma", "sse4_2"]


def test_a_virtual_cpu_without_ids_or_flags():
    assert cpu_from_cpuinfo("processor\t: 0\nmodel name\t: QEMU Virtual CPU\n") == ("QEMU Virtual CPU", [])
    assert cpu_from_cpuinfo("") == ("", [])


def test_unreadable_cpuinfo_leaves_the_cpu_empty(tmp_path):
    info = host_info(str(tmp_path / "no-such-file"))
    assert (info["cpu"], info["cpu_flags"]) == ("", [])
    assert info["python"] == platform.python_version() and info["machine"] == platform.machine()
    assert set(host_info()["cpu_flags"]) <= set(SIMD_FLAGS)


def test_the_report_names_each_distinct_host_with_its_runs():
    """Two runs on one host and one on another give two lines, each naming
    its runs; runs that recorded no host (older dumps) give none."""
    from postproc.study.report import host_lines

    a = {"cpu": "AMD EPYC (family 25, model 1, stepping 1)", "cpu_flags": ["avx", "avx2", "fma"],
         "libc": "glibc 2.36", "numpy": "1.24.2"}
    b = dict(a, cpu_flags=["avx", "avx2", "avx512f", "fma"])
    infos = [("polyhedra", "seed 1", {"host": a}), ("spheres", "seed 1", {"host": a}),
             ("polyhedra", "seed 2", {"host": b}), ("spheres", "seed 2", {})]
    assert host_lines(infos) == [
        "Host: AMD EPYC (family 25, model 1, stepping 1), avx/avx2/fma, glibc 2.36, numpy 1.24.2 in YADE's "
        "Python (S1 polyhedra seed 1, S2 spheres seed 1).",
        "Host: AMD EPYC (family 25, model 1, stepping 1), avx/avx2/avx512f/fma, glibc 2.36, numpy 1.24.2 in "
        "YADE's Python (S1 polyhedra seed 2)."]
    assert host_lines([("spheres", "seed 1", {})]) == []
