#!/bin/bash
# Makes flat-layout.tar.gz: a run folder as the code of COMMIT (default a9d5786,
# the last one whose yade_scripts/ was one flat folder of modules) made it, its
# pkg/ holding that code (yade_scripts.task, yade_scripts.pool, ... and the scene
# triaxial.py importing yade_scripts.attempt, yade_scripts.loading ...):
#
#   spheres/   generate --preset tiny --sample spheres --seeds 1 2 3 --slurm:
#              seed 1 stopped by SIGTERM with a checkpoint, seed 2 not started,
#              seed 3 complete (each line in its array task's folder <description>/)
#
# tests/test_flat_layout.py checks that today's launchers resume it. Run from
# the repository with its venv: bash tests/data/flat-layout/make_flat_layout.sh [COMMIT]
set -euo pipefail
COMMIT=${1:-a9d5786}
ROOT=$(git rev-parse --show-toplevel)
PY=$ROOT/.venv/bin/python
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
mkdir -p "$T/code" "$T/old"
git -C "$ROOT" archive "$COMMIT" yade_scripts shapes postproc | tar -x -C "$T/code"
cd "$T/code"
F=$T/old/spheres
$PY -m yade_scripts.generate --preset tiny --sample spheres --out "$F" --seeds 1 2 3 --slurm
# seed 1 in its array task's folder (as slurm.sh's task lays it out), stopped by
# SIGTERM once its log.csv exists (the handler is installed before): the scene
# writes a checkpoint and exits 75
mkdir -p "$F/spheres-seed1"
for f in triaxial.py pkg; do ln -s "../$f" "$F/spheres-seed1/$f"; done
cd "$F/spheres-seed1"
YADE_BATCH=../table.txt:2 yade -j 1 -n -x triaxial.py > triaxial.log 2>&1 &
pid=$!
for _ in $(seq 600); do [ -f spheres-seed1.log.csv ] && break; sleep 0.02; done
sleep 0.3
kill -TERM $pid
rc=0; wait $pid || rc=$?
echo "spheres-seed1 exit $rc"
test "$rc" = 75 && test -f spheres-seed1.ckpt
mkdir -p "$F/spheres-seed3"
for f in triaxial.py pkg; do ln -s "../$f" "$F/spheres-seed3/$f"; done
(cd "$F/spheres-seed3" && YADE_BATCH=../table.txt:4 yade -j 1 -n -x triaxial.py > triaxial.log 2>&1)
cd "$T/code"
find "$T/old" -name _build -prune -exec rm -rf {} + -o -name __pycache__ -prune -exec rm -rf {} +
rm -f "$F/slurm.sh"            # it names the folder's absolute path: the test writes it again
tar -C "$T/old" --owner=0 --group=0 --sort=name -czf "$ROOT/tests/data/flat-layout/flat-layout.tar.gz" spheres
echo "wrote tests/data/flat-layout/flat-layout.tar.gz ($(du -h "$ROOT/tests/data/flat-layout/flat-layout.tar.gz" | cut -f1))"
