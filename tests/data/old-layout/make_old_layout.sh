#!/bin/bash
# Makes old-layout.tar.gz: run folders as the code of COMMIT (default d2d56fd,
# the last one before run folders got the packages under their own names)
# made them, with its renamed module copies in lib/ and its own triaxial.py:
#
#   study/polyhedra-ensemble/  make study --preset tiny --ensemble 2: seeds 1 and 2 complete
#   study/spheres-ensemble/    seed 1 complete, seed 2 stopped by SIGTERM with a checkpoint
#   array/                     generate --slurm, spheres seeds 1-2: task 1 run by hand, task 2 not started
#
# tests/test_old_layout.py checks that today's code recognises them. Run from
# the repository with its venv: bash tests/data/old-layout/make_old_layout.sh [COMMIT]
set -euo pipefail
COMMIT=${1:-d2d56fd}
ROOT=$(git rev-parse --show-toplevel)
PY=$ROOT/.venv/bin/python
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
mkdir -p "$T/code" "$T/old"
git -C "$ROOT" archive "$COMMIT" yade_scripts shapes postproc | tar -x -C "$T/code"
cd "$T/code"
# the tests' shape library: 60 grains, seed 5
$PY -c "
from shapes.generate import Recipe, generate_library
from shapes.library import write_library
s, _ = generate_library(60, seed=5)
write_library('$T/lib.h5', s, 5, Recipe().as_dict(), {})"
S=$T/old/study
for sample in polyhedra spheres; do
    $PY -m yade_scripts.generate --preset tiny --sample $sample --out "$S/$sample-ensemble" --seeds 1 2 \
        --library "$T/lib.h5"
done
run_line() {  # folder line description: as the old pool ran a line
    (cd "$1" && YADE_BATCH=table.txt:$2 OMP_WAIT_POLICY=PASSIVE yade -j 1 -n -x triaxial.py \
        >> "triaxial.py.$3.log" 2>&1)
}
run_line "$S/polyhedra-ensemble" 2 polyhedra-seed1
run_line "$S/polyhedra-ensemble" 3 polyhedra-seed2
run_line "$S/spheres-ensemble" 2 spheres-seed1
# spheres seed 2: SIGTERM once its log.csv exists (the SIGTERM handler is
# installed before); the scene writes a checkpoint and exits 75
cd "$S/spheres-ensemble"
YADE_BATCH=table.txt:3 yade -j 1 -n -x triaxial.py > triaxial.py.spheres-seed2.log 2>&1 &
pid=$!
for _ in $(seq 600); do [ -f spheres-seed2.log.csv ] && break; sleep 0.02; done
sleep 0.3
kill -TERM $pid
rc=0; wait $pid || rc=$?
echo "spheres-seed2 exit $rc"
cd "$T/code"
test -f "$S/spheres-ensemble/spheres-seed2.ckpt"
A=$T/old/array
$PY -m yade_scripts.generate --preset tiny --sample spheres --out "$A" --seeds 1 2 --slurm
(cd "$A" && SLURM_ARRAY_TASK_ID=1 bash slurm.sh > slurm-manual_1.out 2>&1)
find "$T/old" -name _build -prune -exec rm -rf {} + -o -name __pycache__ -prune -exec rm -rf {} +
tar -C "$T/old" --owner=0 --group=0 --sort=name -czf "$ROOT/tests/data/old-layout/old-layout.tar.gz" study array
echo "wrote tests/data/old-layout/old-layout.tar.gz ($(du -h "$ROOT/tests/data/old-layout/old-layout.tar.gz" | cut -f1))"
