"""Run folders made by the code before run folders got the packages under
their own names (tests/data/old-layout/old-layout.tar.gz, made by
make_old_layout.sh from commit d2d56fd: a scene importing renamed copies
from lib/): today's code recognises them. A complete dump is not run again,
an unfinished one with a checkpoint resumes (with the folder's own scene),
``make study`` on such a folder with the same parameters regenerates
nothing, and the analysis and report work on them."""
import json
import os
import shutil
import tarfile

import numpy as np
import pytest

from yade_scripts.launch.batch import read_table
from yade_scripts.scene.parameters import changed
from yade_scripts.campaign.presets import resolve
from yade_scripts.runs.runstate import state_of

HERE = os.path.dirname(os.path.abspath(__file__))
TARBALL = os.path.join(HERE, "data", "old-layout", "old-layout.tar.gz")
YADE = shutil.which("yade")


@pytest.fixture
def old(tmp_path):
    with tarfile.open(TARBALL) as tar:
        tar.extractall(tmp_path)
    return tmp_path


def test_old_folders_are_recognised(old):
    study = old / "study"
    for s in ("polyhedra", "spheres"):
        folder = study / f"{s}-ensemble"
        assert (folder / "lib" / "dumpschema.py").exists() and not (folder / "pkg").exists()   # the old layout
        with open(folder / "params.json") as fh:
            assert changed(json.load(fh), {"preset": "tiny", **resolve("tiny", s)}) == []    # not set aside
        assert [r["description"] for _, r in read_table(str(folder))] == [f"{s}-seed1", f"{s}-seed2"]
    for name in ("polyhedra-ensemble/polyhedra-seed1.h5", "polyhedra-ensemble/polyhedra-seed2.h5",
                 "spheres-ensemble/spheres-seed1.h5"):
        assert state_of(str(study / name)).state == "complete", name
    st = state_of(str(study / "spheres-ensemble" / "spheres-seed2.h5"))
    assert st.state == "resumable" and st.step > 0 and st.detail == f"resumable at step {st.step} (compaction)"
    assert state_of(str(old / "array" / "spheres-seed1" / "spheres-seed1.h5")).state == "complete"
    assert state_of(str(old / "array" / "spheres-seed2" / "spheres-seed2.h5")).state == "not started"


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")
def test_make_study_on_old_folders_resumes_the_unfinished_run_and_reruns_nothing(old, capsys):
    from postproc.schema import DumpReader
    from yade_scripts.campaign.study import main

    study = old / "study"
    done = {p: os.path.getmtime(study / p) for p in ("polyhedra-ensemble/polyhedra-seed1.h5",
                                                     "polyhedra-ensemble/polyhedra-seed2.h5",
                                                     "spheres-ensemble/spheres-seed1.h5")}
    assert main(["--preset", "tiny", "--out", str(study), "--ensemble", "2", "--no-figures"]) == 0
    out = capsys.readouterr().out
    for p, t in done.items():
        assert os.path.getmtime(study / p) == t, p                       # not run again
        assert f"{os.path.basename(p)[:-3]} already complete, not run again" in out
    assert "spheres-seed2: an unfinished run with a checkpoint, resuming it" in out
    log = (study / "spheres-ensemble" / "triaxial.py.spheres-seed2.log").read_text()
    assert "resumed from spheres-seed2.ckpt" in log and "==== attempt 1 of spheres-seed2" in log
    assert "stopped on SIGTERM" in log                                    # the old attempt's lines are kept
    with DumpReader(str(study / "spheres-ensemble" / "spheres-seed2.h5")) as r:
        assert r.complete and [s.stage for s in r][0] == "isotropic"
    assert not (study / "spheres-ensemble" / "pkg").exists()             # nothing regenerated
    assert not any(p.name.endswith(".old-1") for p in study.iterdir())
    manifest = json.loads((study / "manifest.json").read_text())
    assert [r["status"] for s in ("polyhedra", "spheres") for r in manifest[s]] == ["ok"] * 4
    md = (study / "report" / "report.md").read_text()                   # numbers only: no figure anywhere
    assert "Not drawn: the report was written with `--no-figures`" in md and "![" not in md
    assert not list(study.rglob("*.png"))


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")
def test_todays_scene_writes_the_old_code_s_dump_bit_for_bit(old, tmp_path):
    """The same table line (tiny S1, kernel, seed 1) run by today's scene
    gives the old code's dump: every dataset equal, bit for bit. Skipped on
    a host whose CPU flags, libc or numpy differ from the fixture's (a run
    repeats bit for bit only where glibc picks the same code)."""
    import h5py

    from yade_scripts.campaign.generate import generate
    from yade_scripts.runs.host import host_info

    folder = old / "study" / "polyhedra-ensemble"
    made = json.loads((folder / "polyhedra-seed1.info.json").read_text())["host"]
    here = host_info()
    here["numpy"] = made["numpy"] if here["numpy"] else ""            # the venv's numpy is not YADE's
    if any(made[k] != here[k] for k in ("cpu_flags", "libc", "machine")):
        pytest.skip(f"the fixture was made on another host ({made['cpu']}, {made['libc']})")
    new = tmp_path / "new"
    generate(str(new), "tiny", "polyhedra", seeds=[1, 2], library=str(folder / "shapes.h5"))
    from yade_scripts.launch.pool import Job, run_pool

    job = Job(str(new), 2, "polyhedra-seed1", str(new / "polyhedra-seed1.h5"), tag="polyhedra")
    assert run_pool([job], 1, echo=lambda m: None) == {"polyhedra-seed1": 0}
    with h5py.File(folder / "polyhedra-seed1.h5", "r") as a, h5py.File(new / "polyhedra-seed1.h5", "r") as b:
        names = []
        a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        assert len(names) > 10
        for n in names:
            x, y = np.asarray(a[n][()]), np.asarray(b[n][()])
            assert x.dtype == y.dtype and x.shape == y.shape and x.tobytes() == y.tobytes(), n
        # the same parameters, a parameter added since (at its default) counting as absent
        from yade_scripts.scene.parameters import changed
        assert changed(json.loads(a.attrs["parameters"]), json.loads(b.attrs["parameters"])) == []
        # (the compaction's gain, and the kernel's plugin, which steps the same kernel inside YADE)
        assert (set(json.loads(b.attrs["parameters"])) - set(json.loads(a.attrs["parameters"]))
                == {"compaction_gain", "kernel_plugin"})
