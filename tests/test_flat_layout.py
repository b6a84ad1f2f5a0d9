"""Run folders made by the code before ``yade_scripts`` had its rooms
(tests/data/flat-layout/flat-layout.tar.gz, made by make_flat_layout.sh
from commit a9d5786: a tiny S2 folder whose ``pkg/`` holds that code, its
scene importing ``yade_scripts.attempt``, ``yade_scripts.loading`` ...; each
line in its array task's folder: seed 1 stopped by SIGTERM with a
checkpoint, seed 2 not started, seed 3 complete). Today's launchers resume
such a folder with its own scene and its own copy of the packages, a
``slurm.sh`` written for it today runs the folder's own task module, never
this checkout's, and today's scene writes the old scene's dump bit for bit."""
import os
import re
import shutil
import subprocess
import tarfile

import pytest

from yade_scripts.launch.batch import read_table
from yade_scripts.launch.slurm import task_module, write_slurm
from yade_scripts.runs.runstate import state_of

HERE = os.path.dirname(os.path.abspath(__file__))
TARBALL = os.path.join(HERE, "data", "flat-layout", "flat-layout.tar.gz")
YADE = shutil.which("yade")


@pytest.fixture
def old(tmp_path):
    with tarfile.open(TARBALL) as tar:
        tar.extractall(tmp_path)
    return tmp_path / "spheres"


def test_the_fixture_is_the_flat_layout_and_is_recognised(old):
    pkg = old / "pkg" / "yade_scripts"
    assert (pkg / "task.py").exists() and (pkg / "attempt.py").exists() and not (pkg / "launch").exists()
    assert "from yade_scripts.attempt import" in (old / "triaxial.py").read_text()    # the folder's own scene
    assert [r["description"] for _, r in read_table(str(old))] == ["spheres-seed1", "spheres-seed2", "spheres-seed3"]
    st = state_of(str(old / "spheres-seed1" / "spheres-seed1.h5"))
    assert st.state == "resumable" and st.step > 0
    assert state_of(str(old / "spheres-seed2" / "spheres-seed2.h5")).state == "not started"
    assert state_of(str(old / "spheres-seed3" / "spheres-seed3.h5")).state == "complete"
    assert task_module(str(old)) == "yade_scripts.task"


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")
def test_today_s_pool_resumes_the_old_run_with_the_folder_s_own_scene(old):
    from postproc.schema import DumpReader
    from yade_scripts.launch.pool import Job, run_pool

    own = old / "spheres-seed1"
    dump = own / "spheres-seed1.h5"
    step = state_of(str(dump)).step
    job = Job(str(own), 2, "spheres-seed1", str(dump), tag="flat", log=str(own / "triaxial.log"),
              table=str(old / "table.txt"))
    assert run_pool([job], 1, echo=lambda m: None) == {"spheres-seed1": 0}
    log = (own / "triaxial.log").read_text()
    assert "stopped on SIGTERM" in log                       # the first attempt's lines are kept
    assert re.search(rf"resumes from its checkpoint at step {step}\b", log) and "resumed from spheres-seed1.ckpt" in log
    with DumpReader(str(dump)) as r:
        assert r.complete and [s.stage for s in r][0] == "isotropic"
    assert state_of(str(dump)).state == "complete"


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")
def test_a_slurm_script_written_today_runs_the_folder_s_own_task(old):
    """slurm.sh written by today's code for the old folder ends by running
    the folder's own ``yade_scripts.task`` on YADE's Python with the
    folder's ``pkg/`` first: that command runs the unstarted line to the end
    (the plugin's build before it, which a spheres run does not use, is
    left out here)."""
    script = open(write_slurm(str(old), cpus=1, time="1:00:00")).read()
    assert "-m yade_scripts.task " in script and "launch.task" not in script
    line = [x for x in script.splitlines() if x.startswith('exec "$PY" -m ')][0]
    py = next(p for p in ("/usr/bin/python3", shutil.which("python3")) if p and os.path.exists(p))
    env = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    env.update(SLURM_ARRAY_TASK_ID="2", PYTHONPATH=str(old / "pkg"), OMP_WAIT_POLICY="PASSIVE",
               HERE=str(old), PY=py)
    r = subprocess.run(["bash", "-c", line[len("exec "):]], cwd=str(old), env=env, capture_output=True, text=True,
                       timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "task: FINAL done: spheres-seed2.h5 complete" in r.stdout
    assert state_of(str(old / "spheres-seed2" / "spheres-seed2.h5")).state == "complete"


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")
def test_today_s_scene_writes_the_old_scene_s_dump_bit_for_bit(old, tmp_path):
    """The same table line (tiny S2, seed 3) run by today's scene, in its
    rooms, gives the flat layout's dump: every dataset equal (dtype, shape
    and bytes). Skipped on a host whose CPU flags, libc or machine differ
    from the fixture's (a run repeats bit for bit only where glibc picks
    the same code)."""
    import json

    import h5py
    import numpy as np

    from yade_scripts.campaign.generate import generate
    from yade_scripts.launch.pool import Job, run_pool
    from yade_scripts.runs.host import host_info

    made = json.loads((old / "spheres-seed3" / "spheres-seed3.info.json").read_text())["host"]
    here = host_info()
    if any(made[k] != here[k] for k in ("cpu_flags", "libc", "machine")):
        pytest.skip(f"the fixture was made on another host ({made['cpu']}, {made['libc']})")
    new = tmp_path / "new"
    generate(str(new), "tiny", "spheres", seeds=[1, 2, 3])
    job = Job(str(new), 4, "spheres-seed3", str(new / "spheres-seed3.h5"), tag="spheres")
    assert run_pool([job], 1, echo=lambda m: None) == {"spheres-seed3": 0}
    with h5py.File(old / "spheres-seed3" / "spheres-seed3.h5", "r") as a, h5py.File(new / "spheres-seed3.h5", "r") as b:
        names = []
        a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        others = []
        b.visititems(lambda n, o: others.append(n) if isinstance(o, h5py.Dataset) else None)
        assert len(names) > 10 and sorted(names) == sorted(others)
        for n in names:
            x, y = np.asarray(a[n][()]), np.asarray(b[n][()])
            assert x.dtype == y.dtype and x.shape == y.shape and x.tobytes() == y.tobytes(), n
        assert json.loads(a.attrs["parameters"]) == json.loads(b.attrs["parameters"])
