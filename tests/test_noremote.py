"""Runs listen on nothing: YADE started without its remote servers (the
project's launchers), the scene closing them when started by hand, a pause
from outside told from a crash, files under the user's umask, and the docs
that say so."""
import glob
import os
import re
import shutil
import socket
import stat
import subprocess
import sys
import time

import pytest

from yade_scripts.runs import checkpoint, noremote
from yade_scripts import yadeplugin
from yade_scripts.campaign.generate import generate
from yade_scripts.runs.runlock import RunLock
from yade_scripts.runs.runstate import EXIT_TERM, judge
from yade_scripts.launch.slurm import write_slurm

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
YADE = shutil.which("yade")


def needs_yade(test):
    """Runs YADE: marked ``yade`` and skipped without Debian's yade."""
    return pytest.mark.yade(pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")(test))


# ------------------------------------------------------------ listening sockets of a process tree
def _tree(pid):
    """pid and all its descendants (from /proc/PID/task/*/children)."""
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        out.append(p)
        for f in glob.glob(f"/proc/{p}/task/*/children"):
            try:
                with open(f) as fh:
                    todo.extend(int(c) for c in fh.read().split())
            except OSError:
                pass
    return out


def listening_ports(pid):
    """TCP ports on which the process ``pid`` or one of its children
    listens: the socket inodes of their open files against the LISTEN (0A)
    rows of /proc/net/tcp and tcp6."""
    inodes = set()
    for p in _tree(pid):
        for fd in glob.glob(f"/proc/{p}/fd/*"):
            try:
                target = os.readlink(fd)
            except OSError:
                continue
            m = re.fullmatch(r"socket:\[(\d+)\]", target)
            if m:
                inodes.add(m.group(1))
    ports = set()
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        with open(table) as fh:
            for row in fh.readlines()[1:]:
                f = row.split()
                if f[3] == "0A" and f[9] in inodes:
                    ports.add(int(f[1].rsplit(":", 1)[1], 16))
    return ports


def test_listening_ports_sees_a_listener():
    """The check can fail: a socket this process listens on is found, and gone once closed."""
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    s.listen(1)
    port = s.getsockname()[1]
    assert port in listening_ports(os.getpid())
    s.close()
    assert port not in listening_ports(os.getpid())


# ------------------------------------------------------------ the command line
def test_command_wraps_only_a_python_yade_launcher(tmp_path):
    stand_in = tmp_path / "fake"
    stand_in.write_text("#!/bin/sh\nexit 0\n")
    assert noremote.command(str(stand_in), ["-n"]) == [str(stand_in), "-n"]
    launcher = tmp_path / "yade"
    launcher.write_text("#!/usr/bin/env python3.11\nfrom yade import remote\nyade.remote.runServers()\n")
    assert noremote.command(str(launcher), ["-j", "2", "-x", "t.py"]) == \
        ["python3.11", noremote.__file__.replace(".pyc", ".py"), str(launcher), "-j", "2", "-x", "t.py"]
    plain = tmp_path / "other.py"
    plain.write_text("#!/usr/bin/python3\nprint(1)\n")               # a Python script that opens no server
    assert noremote.command(str(plain), []) == [str(plain)]


@pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")
def test_the_installed_launcher_is_wrapped():
    cmd = noremote.command(YADE, ["-n"])
    assert cmd[1:] == [os.path.abspath(noremote.__file__), YADE, "-n"] and os.path.basename(cmd[0]).startswith("python")


def test_every_launch_in_the_code_goes_through_noremote():
    """Each ``"-x"`` command line the project's code builds (launchers and
    benchmarks; the tests that start the scene by hand excepted) is passed
    through :func:`noremote.command`."""
    lines = []
    for path in sorted(glob.glob(os.path.join(ROOT, "yade_scripts", "**", "*.py"), recursive=True) +
                       glob.glob(os.path.join(ROOT, "benchmarks", "*.py"))):
        with open(path) as fh:
            text = fh.read().splitlines()
        for i, line in enumerate(text):
            if '"-x"' in line and not line.lstrip().startswith("#"):
                if "noremote.command" not in text[i] + (text[i - 1] if i else "") and not path.endswith("noremote.py"):
                    lines.append(f"{os.path.relpath(path, ROOT)}:{i + 1}")
    assert lines == []


# ------------------------------------------------------------ real tiny runs
def _tiny(folder, library, **over):
    generate(str(folder), "tiny", "polyhedra", {"kernel_threads": 1, **over}, library=library)
    return dict(yadeplugin.environment(run_folder=str(folder)), OMP_WAIT_POLICY="PASSIVE")


def _wait_for(cond, timeout=300):
    t = time.time()
    while not cond():
        assert time.time() - t < timeout, "timed out"
        time.sleep(0.02)


def _read(path):
    with open(path) as fh:
        return fh.read()


@needs_yade
def test_a_run_started_as_the_launchers_start_it_listens_on_no_port(tmp_path, shape_library):
    d = tmp_path / "run"
    env = _tiny(d, shape_library, final_strain=0.2)
    log = d / "yade.log"
    with open(log, "w") as fh:
        p = subprocess.Popen(noremote.command(YADE, ["-j", "1", "-n", "-x", "triaxial.py"]), cwd=d, env=env,
                             stdout=fh, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    try:
        _wait_for(lambda: "polyhedra contacts" in _read(log) or p.poll() is not None)
        ports = listening_ports(p.pid)
        running = p.poll() is None
    finally:
        rc = p.wait(timeout=300)
    assert running, _read(log)[-2000:]              # checked while the scene ran
    assert ports == set()
    text = _read(log)
    assert rc == 0, text[-2000:]
    assert "cookie" not in text and "TCP python prompt" not in text and "XMLRPC" not in text
    assert "closed YADE's remote" not in text        # nothing was open to close


@needs_yade
def test_a_scene_started_by_hand_closes_the_servers_at_its_start(tmp_path, shape_library):
    d = tmp_path / "run"
    env = _tiny(d, shape_library, final_strain=0.2)
    log = d / "yade.log"
    with open(log, "w") as fh:
        p = subprocess.Popen([YADE, "-n", "-x", "triaxial.py"], cwd=d, env=env, stdout=fh,
                             stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    try:
        _wait_for(lambda: "TCP python prompt" in _read(log) or p.poll() is not None)
        opened = listening_ports(p.pid)              # the launcher's servers, before the scene runs (or already closed)
        _wait_for(lambda: "polyhedra contacts" in _read(log) or p.poll() is not None)
        ports = listening_ports(p.pid)
        running = p.poll() is None
    finally:
        rc = p.wait(timeout=300)
    text = _read(log)
    assert running and rc == 0, text[-2000:]
    m = re.search(r"closed YADE's remote prompt and XMLRPC server \(ports (\d+), (\d+)\)", text)
    assert m, text[-2000:]
    assert opened <= {int(m.group(1)), int(m.group(2))} and ports == set()


def _beside_the_scene(path, body):
    """Write a YADE script ``path`` that starts a daemon thread running
    ``body`` (the indented lines of a function of no argument; ``O``,
    ``time`` and the scene's globals in reach), then runs the folder's
    ``triaxial.py`` in its own globals."""
    path.write_text("import threading, time\n"
                    "def beside():\n" + body +
                    "threading.Thread(target=beside, daemon=True).start()\n"
                    "exec(compile(open('triaxial.py').read(), 'triaxial.py', 'exec'))\n")


@needs_yade
def test_a_pause_from_another_thread_checkpoints_exits_75_and_resumes(tmp_path, shape_library):
    """O.pause() from a second thread of the run's process, at step 3000
    (compaction): the scene names it "paused from outside", not a crash,
    checkpoints at that step, exits 75 (which the launchers resume); run
    again, it resumes from there and completes."""
    d = tmp_path / "run"
    env = _tiny(d, shape_library, final_strain=0.02)
    _beside_the_scene(d / "pause.py",
                      "    while O.iter < 3000:\n"
                      "        time.sleep(0.001)\n"
                      "    O.pause()\n")
    cmd = noremote.command(YADE, ["-j", "1", "-n", "-x"])
    r = subprocess.run(cmd + ["pause.py"], cwd=d, env=env, capture_output=True, text=True, timeout=300)
    assert r.returncode == EXIT_TERM, (r.stdout + r.stderr)[-2000:]
    m = re.search(r"paused from outside at step (\d+) \(a stop the scene did not ask for\)", r.stdout)
    assert m and "an exception" not in r.stdout and "STOPPED" not in r.stdout, r.stdout[-2000:]
    meta = checkpoint.read(str(d / "run.ckpt"))[0]
    assert meta["why"] == "paused from outside" and meta["step"] == int(m.group(1)) >= 3000
    assert judge(r.returncode, str(d / "run.h5")).action == "resume"
    again = subprocess.run(cmd + ["triaxial.py"], cwd=d, env=env, capture_output=True, text=True, timeout=300)
    assert again.returncode == 0, (again.stdout + again.stderr)[-2000:]
    assert f"resumed from run.ckpt at step {meta['step']} " in again.stdout, again.stdout[-2000:]


@needs_yade
def test_an_exception_in_the_scenes_own_engine_is_a_failure_not_a_pause(tmp_path, shape_library):
    """The scene's controller (a PyRunner) raises at step 3000: exit 3,
    named an exception in its own engines, never "paused from outside"."""
    d = tmp_path / "run"
    env = _tiny(d, shape_library, final_strain=0.02)
    _beside_the_scene(d / "boom.py",
                      "    while 'control' not in globals() or O.iter < 3000:\n"
                      "        time.sleep(0.001)\n"
                      "    def control():\n"
                      "        raise ValueError('injected')\n"
                      "    globals()['control'] = control\n")
    r = subprocess.run(noremote.command(YADE, ["-j", "1", "-n", "-x", "boom.py"]), cwd=d, env=env,
                       capture_output=True, text=True, timeout=300)
    out = r.stdout + r.stderr
    assert r.returncode == 3, out[-2000:]
    assert "an exception in the scene's own engines stopped the simulation" in out and "ValueError: injected" in out
    assert "paused from outside" not in out


# ------------------------------------------------------------ files under the umask
def test_folders_lock_and_slurm_script_follow_the_umask(tmp_path, shape_library):
    old = os.umask(0o027)
    try:
        d = tmp_path / "run"
        generate(str(d), "tiny", "spheres", {}, library=shape_library)
        write_slurm(str(d))
        with RunLock(str(d / "run.lock"), "scene"):
            lock_mode = stat.S_IMODE(os.stat(d / "run.lock").st_mode)
    finally:
        os.umask(old)
    assert stat.S_IMODE(os.stat(d).st_mode) == 0o750
    assert stat.S_IMODE(os.stat(d / "triaxial.py").st_mode) == 0o640
    assert lock_mode == 0o640
    assert stat.S_IMODE(os.stat(d / "slurm.sh").st_mode) == 0o750


# ------------------------------------------------------------ the docs
def test_scenes_doc_says_what_a_run_opens_writes_and_trusts():
    text = _read(os.path.join(ROOT, "docs", "scenes.md"))
    m = re.search(r"^## What a run opens, writes and trusts\n(.*?)(?=^## )", text, re.S | re.M)
    assert m, "docs/scenes.md lacks the section"
    sec = " ".join(m.group(1).split())
    for claim in ("**Opens: nothing.**", "**Writes: its folder.**", "**Trusts: its own files.**",
                  "yade_scripts/runs/noremote.py", "umask", "paused from outside", "exits 75",
                  "closed YADE's remote prompt and XMLRPC server"):
        assert claim in sec, claim
    assert "closes both servers at its start" in sec      # the hand-started scene closes, not refuses
    assert "| 75 | SIGTERM, or paused from outside" in text
