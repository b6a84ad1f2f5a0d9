"""LMGC90's build helper (lmgc90/build.py): a missing or broken build is
refused in one line naming the problem; the cached build, when there,
imports pylmgc90's chipy and pre."""
import os
import subprocess
import sys

import pytest

from lmgc90 import build as lb

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _refusal(directory):
    """Run import_pylmgc90 on ``directory`` in a fresh Python; its stderr and exit code."""
    code = ("import sys\nfrom lmgc90.build import import_pylmgc90, LMGC90BuildError\n"
            "try:\n    import_pylmgc90(sys.argv[1])\n"
            "except LMGC90BuildError as e:\n    print(e, file=sys.stderr); sys.exit(3)\n")
    res = subprocess.run([sys.executable, "-c", code, str(directory)], cwd=ROOT,
                         capture_output=True, text=True, timeout=120)
    return res.returncode, res.stderr.strip()


def test_an_empty_folder_is_refused_as_not_built(tmp_path):
    rc, err = _refusal(tmp_path)
    assert rc == 3 and len(err.splitlines()) == 1
    assert "not built" in err and str(tmp_path) in err


def test_a_package_without_its_compiled_module_is_refused(tmp_path):
    (tmp_path / "pylmgc90" / "chipy").mkdir(parents=True)
    rc, err = _refusal(tmp_path)
    assert rc == 3 and len(err.splitlines()) == 1 and "no compiled chipy module" in err


def test_a_corrupt_shared_library_is_refused_in_one_line(tmp_path):
    chipy = tmp_path / "pylmgc90" / "chipy"
    chipy.mkdir(parents=True)
    (tmp_path / "pylmgc90" / "__init__.py").write_text("")
    (chipy / "__init__.py").write_text("from ._lmgc90 import *\n")
    (chipy / "_lmgc90.so").write_bytes(b"\x7fELF not really a library" * 10)
    rc, err = _refusal(tmp_path)
    assert rc == 3 and len(err.splitlines()) == 1
    assert "cannot be loaded" in err


def test_the_build_hash_names_the_source_and_the_python():
    assert lb.source_hash(sys.executable) == lb.source_hash(sys.executable)
    assert lb.source_hash(sys.executable) != lb.source_hash("/usr/bin/false")


def test_the_cached_build_imports_chipy_and_pre():
    try:
        lb.pylmgc90_path()
    except lb.LMGC90BuildError as exc:
        pytest.skip(f"LMGC90 is not built ({exc})")
    code = ("from lmgc90.build import import_pylmgc90\nchipy, pre = import_pylmgc90()\n"
            "print('ok', hasattr(chipy, 'RBDY3_TriaxialLoading'), hasattr(chipy, 'ReadDatbox'), hasattr(pre, 'rigidPolyhedron'))")
    res = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr
    # pylmgc90 prints a warning about the optional vtk package first
    assert res.stdout.splitlines()[-1].split() == ["ok", "True", "True", "True"]


def test_the_real_build_with_its_library_overwritten_is_refused(tmp_path):
    try:
        built = lb.pylmgc90_path()
    except lb.LMGC90BuildError as exc:
        pytest.skip(f"LMGC90 is not built ({exc})")
    import shutil
    shutil.copytree(os.path.join(built, "pylmgc90"), tmp_path / "pylmgc90")
    (tmp_path / "pylmgc90" / "chipy" / "_lmgc90.so").write_bytes(os.urandom(4096))
    rc, err = _refusal(tmp_path)
    assert rc == 3 and len(err.splitlines()) == 1
    assert "cannot be loaded" in err and "_lmgc90.so" in err
