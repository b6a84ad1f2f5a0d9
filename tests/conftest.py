"""Fixtures shared by the YADE tests."""
import pytest


@pytest.fixture(scope="session")
def shape_library(tmp_path_factory):
    """A small library of 60 grains (seed 5) for the tiny scenes."""
    from shapes.generate import Recipe, generate_library
    from shapes.library import write_library

    path = tmp_path_factory.mktemp("shapes") / "lib.h5"
    shapes, _ = generate_library(60, seed=5)
    write_library(str(path), shapes, 5, Recipe().as_dict(), {})
    return str(path)


#: the files that take longest, longest first (their durations on 2 cores,
#: docs/measurements.md "The test suite"): `make test` runs the suite on two
#: pytest-xdist workers, one file per worker at a time (--dist loadfile, so
#: that a file's fixtures run once), and a long file started last would leave
#: one core idle at the end. xdist gives a worker its next file while it still
#: has two tests to run, so a file of two tests (the SLURM cluster's) comes
#: with the next one: the list alternates files of many tests and of few.
FIRST = ("test_yade_scenes.py", "test_slurm_cluster.py", "test_checkpoint.py", "test_study_smoke.py",
         "test_slurm.py", "test_old_layout.py", "test_front.py", "test_docs.py", "test_shapes.py")


def pytest_configure(config):
    """Warn when xdist would reorder the files (``--dist loadfile`` without
    ``--no-loadscope-reorder``): it sorts them by their number of tests and
    would start the long YADE files, which have few, last."""
    if getattr(config.option, "dist", "no") == "loadfile" and getattr(config.option, "loadscopereorder", False):
        config.issue_config_time_warning(pytest.PytestConfigWarning(
            "--dist loadfile without --no-loadscope-reorder: xdist starts the long files last "
            "(make test passes it)"), stacklevel=2)


def pytest_collection_modifyitems(config, items):
    """Put the files of :data:`FIRST` first, in that order (the others keep
    pytest's order)."""
    rank = {name: k for k, name in enumerate(FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(FIRST)))
