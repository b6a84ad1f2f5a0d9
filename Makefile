# Two entry points on a fresh Debian 12 machine (see README.md):
#   make test    install what is missing, run the test suite
#   make study   install what is missing, run the main job
# Both are idempotent: installed pieces are detected and skipped.
SHELL := /bin/bash
PYTHON ?= python3
VENV ?= .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
STUDY ?= runs/study
PRESET ?= default
ENSEMBLE ?= 3
JOBS ?= 2
JOB_THREADS ?= 1
SHAPES_LIB ?= runs/shapes/library.h5
# SHAPES=LIB.h5: S1 of make study on this library (e.g. from python -m shapes import)
SHAPES ?=
# COUNTS="lmgc90 lmgc90-2009": the contact counts claim 6 is read by besides ours
# (default lmgc90); on a finished study make study makes only the missing analyses
COUNTS ?=
# ARCHIVE=DEST: an archive of analysed runs (make archive; yade_scripts/campaign/archive.py):
# make study runs only the seeds it does not hold, reads those it does, and adds
# each run it completes as soon as it is analysed
ARCHIVE ?=
# DRY_RUN=1: make study says what it would take from ARCHIVE and run, and runs nothing
DRY_RUN ?=
# SET_ASIDE=1: a run folder of STUDY made with other parameters is renamed
# FOLDER.old-K and started afresh (without it the study refuses and renames nothing)
SET_ASIDE ?=
# OpenMP threads sleep when idle (the polyhedra kernel; see yade_scripts/launch/pool.py)
export OMP_WAIT_POLICY ?= PASSIVE

.PHONY: test test-fast docs study cd-study archive collect-archive results compare test-slurm system venv bench clean-venv shapes front kernel size-front lmgc90 lmgc90-system

# Debian's YADE (runs the scenes on /usr/bin/python3), h5py for that Python,
# gcc for the compiled contact kernel (shapes/polycontact.c, OpenMP), and
# g++ with the headers the kernel's YADE plugin compiles against (Eigen,
# Boost.Python, CGAL, MPI and Python: yade_scripts/yadeplugin).
PLUGIN_DEBS := g++ libeigen3-dev libboost-python-dev libboost-serialization-dev libboost-log-dev \
	libcgal-dev libopenmpi-dev python3-dev
system:
	@if ! command -v yade >/dev/null 2>&1 || ! /usr/bin/python3 -c 'import h5py' >/dev/null 2>&1 \
	    || ! command -v gcc >/dev/null 2>&1 || ! command -v g++ >/dev/null 2>&1 \
	    || ! dpkg -s $(PLUGIN_DEBS) >/dev/null 2>&1; then \
	  echo "make: installing Debian packages yade python3-h5py gcc $(PLUGIN_DEBS)"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq yade python3-h5py gcc libgomp1 $(PLUGIN_DEBS); \
	fi

$(STAMP): pyproject.toml
	@$(PYTHON) -m venv $(VENV) 2>/dev/null || { \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq python3-venv && $(PYTHON) -m venv $(VENV); }
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -e '.[test]'
	@touch $(STAMP)

venv: $(STAMP)

# The compiled contact kernel: shapes/_build/polycontact-<hash>.so (gcc,
# OpenMP), loaded with ctypes by YADE's Python and the venv alike; and its
# YADE plugin, which steps it inside YADE's C++ loop: built against the
# installed YADE, checked and probed in YADE (about a minute, once), in
# yade_scripts/yadeplugin/_build/<hash>. Both are rebuilt only when their
# sources change (or YADE does). A plugin that cannot be built here says why
# and leaves the scenes on the PyRunner path; make does not stop.
kernel: system venv
	$(PY) -c "from shapes import ckernel; ckernel.build(quiet=False)"
	$(PY) -m yade_scripts.yadeplugin build

# LMGC90 (the Contact Dynamics code of the paper), its Python API pylmgc90
# built from the vendored source lmgc90/vendor (lmgc90/ORIGIN.md) with
# gfortran, swig, LAPACK and BLAS, once, into lmgc90/_build/<hash of the
# source> (about 4 minutes on 2 cores; docs/lmgc90.md). Rebuilt only when
# the vendored source changes.
LMGC90_DEBS := gfortran swig cmake liblapack-dev libblas-dev
lmgc90-system:
	@if ! dpkg -s $(LMGC90_DEBS) >/dev/null 2>&1; then \
	  echo "make: installing Debian packages $(LMGC90_DEBS)"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $(LMGC90_DEBS); \
	fi

lmgc90: lmgc90-system venv
	$(PY) -m lmgc90.build

# The suite on TEST_WORKERS pytest-xdist workers, a file to a worker at a time
# (its fixtures run once). tests/conftest.py starts the longest files first;
# --no-loadscope-reorder keeps that order (xdist would otherwise sort the files
# by their number of tests and start the long YADE files, which have few, last)
TEST_WORKERS ?= 2
XDIST = -n $(TEST_WORKERS) --dist loadfile --no-loadscope-reorder
test: system venv kernel lmgc90
	$(PY) -m pytest -q $(XDIST) --durations=25

# The documentation: docs/*.md and the API reference from the docstrings
# (Sphinx, MyST), warnings as errors, into runs/docs/html.
docs: venv
	$(PY) -m sphinx -E -W -q -b html docs runs/docs/html
	@echo "docs: runs/docs/html/index.html"

# The cluster test: installs Debian's slurm-wlm, munge and MariaDB (.ci/slurm-node, root),
# brings up a single-node SLURM and runs arrays of tiny scenes through it
# (tests/test_slurm_cluster.py; the full suite runs it too where the packages are there).
test-slurm: system venv kernel
	$(SUDO) .ci/slurm-node install
	$(PY) -m pytest -q -m slurm -s

# The fast subset (no YADE, nothing slow), for the edit-test loop.
test-fast: venv kernel
	$(PY) -m pytest -q $(XDIST) -m "not yade and not slow"

# The polyhedra library (1000 ballast-like grains, seed 0) and its report.
$(SHAPES_LIB): | venv
	@mkdir -p $(dir $(SHAPES_LIB))
	$(PY) -m shapes build --n 1000 --seed 0 --out $(SHAPES_LIB) --report $(dir $(SHAPES_LIB))library-report

shapes: $(SHAPES_LIB)

# The main job: S1 and S2 on the default preset, side by side (2 cores),
# then the analysis of every dump and the report (STUDY/report/report.md).
# ENSEMBLE=n runs n seeds per sample in one schedule on JOBS cores
# (yade_scripts/launch/pool.py: longest first, no core idle at the end; a polyhedra
# job starts on JOB_THREADS threads). Finished runs are not run again.
# One 16-core node: make study PRESET=intermediate ENSEMBLE=16 JOBS=16
study: system venv kernel $(if $(SHAPES),,$(SHAPES_LIB))
	$(PY) -m yade_scripts.campaign.study --preset $(PRESET) --out $(STUDY) --ensemble $(ENSEMBLE) \
	    --jobs $(JOBS) --job-threads $(JOB_THREADS) $(if $(SHAPES),--library $(SHAPES)) \
	    $(if $(COUNTS),--counts $(COUNTS)) $(if $(ARCHIVE),--archive $(ARCHIVE)) \
	    $(if $(SET_ASIDE),--set-aside) $(if $(DRY_RUN),--dry-run)
	@if [ "$(PRESET)" = default ] && [ "$(ENSEMBLE)" = 3 ] && [ -z "$(SHAPES)" ] && [ -z "$(DRY_RUN)" ]; then \
	  $(PY) -m postproc.cli compare-results $(STUDY) || true; fi

# The CD study (docs/lmgc90.md, "A CD study"): each seed of the YADE study FROM
# (found by its manifest.json: make study PRESET=small STUDY=runs/small; this
# target never runs YADE and says so in one line when FROM is not a finished
# study) taken through Contact Dynamics by LMGC90 into CD_STUDY/<sample>-seed<K>/,
# JOBS runs at once (python -m lmgc90.study). Finished runs are adopted, not run
# again; unfinished ones resume from their checkpoint; a run another process
# writes is left alone. Then CD_STUDY/manifest.json and CD_STUDY/report/.
# CD_SET="NAME=VALUE ...": the scene's parameters; CD_ARCHIVE=DEST keeps the
# finished runs' numbers there; CD_SLURM=1 writes CD_STUDY/slurm.sh (a job array)
# instead of running; DRY_RUN=1 and SET_ASIDE=1 as for make study.
CD_STUDY ?= runs/cd-small
FROM ?= runs/small
CD_SET ?=
CD_ARCHIVE ?=
CD_SLURM ?=
cd-study: lmgc90
	$(PY) -m lmgc90.study --from $(FROM) --out $(CD_STUDY) --jobs $(JOBS) $(foreach s,$(CD_SET),--set $(s)) \
	    $(if $(CD_ARCHIVE),--archive $(CD_ARCHIVE)) $(if $(CD_SLURM),--slurm) \
	    $(if $(SET_ASIDE),--set-aside) $(if $(DRY_RUN),--dry-run)

# Keep STUDY's analysed runs (numbers only, no dumps) in ARCHIVE, to carry a
# long study to another host: make study ... ARCHIVE=DEST runs only the rest.
archive: venv
	@test -n "$(ARCHIVE)" || { echo "make archive: give ARCHIVE=DEST (e.g. reference_data/<study name>)"; exit 2; }
	$(PY) -m yade_scripts.campaign.archive $(STUDY) $(ARCHIVE)

# An archive's study collected on a host that has none of its run folders
# (STUDY, a new folder; today's code): make collect-archive
# ARCHIVE=reference_data/claim6-5000 STUDY=runs/claim6, then postproc results
# STUDY --out reference_data/claim6-5000.json gives back the committed file.
# An archive of another analysis version: python -m yade_scripts.campaign.archive
# collect-at-commit ARCHIVE OUT (its commit's code, docs/study.md).
collect-archive: venv $(SHAPES_LIB)
	@test -n "$(ARCHIVE)" || { echo "make collect-archive: give ARCHIVE=DIR"; exit 2; }
	$(PY) -m yade_scripts.campaign.archive collect $(ARCHIVE) $(STUDY) --library $(SHAPES_LIB)

# After make study: its results against the committed ones, which the README's
# claims table shows ("same as the README", or each difference; exit 1 then).
# make study prints the same when it ran the default (3 seeds, generated grains).
compare: venv
	$(PY) -m postproc.cli compare-results $(STUDY)

# The committed results of the default study, from STUDY's report (after
# make study): reference_data/default-study.json, the README's claims table
# (generated from that file; tests/test_results.py holds the two together)
# and the README's figure.
results: venv
	$(PY) -m postproc.cli results $(STUDY) --out reference_data/default-study.json \
	    --readme README.md --figure docs/figures/study-qp.png

# Speed against error: a sweep over kappa and I (yade_scripts.launch.batch) around the
# default preset, 3 seeds per point, S1 200 grains and S2 1000 spheres
# (FRONT_PLAN=default, 1.9 core-hours by the cost model; FRONT_PLAN=kernel is the sweep
# around the soft preset, FRONT_PLAN=quick the older 24-grain, one-seed one),
# then the analysis estimators on synthetic sets. Finished runs are not run again.
FRONT ?= runs/front
FRONT_PLAN ?= default
front: system venv kernel $(SHAPES_LIB)
	$(PY) -m yade_scripts.campaign.sweeps --plan $(FRONT_PLAN) --out $(FRONT)
	$(PY) -m postproc.cli investigate analysis-front --out $(FRONT)-analysis

# The size front: the default study at 200, 1000 and 5000 grains per sample
# (presets small, default, intermediate; 3 + 3 seeds each, about 4.7
# core-hours by the model, most of it the 5000-grain S1), then the table and
# figure of every claim's quantity against N (runs/size-front/size.md), and
# how the claim-6 leanings' scatter scales with N, from blocks of each
# packing (runs/size-front/blocks/blocks.md). Finished runs are not run again.
SIZE_FRONT ?= runs/size-front
size-front: system venv kernel $(SHAPES_LIB)
	$(MAKE) study PRESET=small STUDY=runs/small
	$(MAKE) study PRESET=default STUDY=runs/study
	$(MAKE) study PRESET=intermediate STUDY=runs/intermediate
	$(PY) -m postproc.cli investigate size-front runs/small runs/study runs/intermediate --out $(SIZE_FRONT)
	$(PY) -m postproc.cli investigate leaning-blocks runs/small runs/study runs/intermediate --out $(SIZE_FRONT)/blocks

bench: venv
	$(PY) benchmarks/bench_analysis.py

clean-venv:
	rm -rf $(VENV)
