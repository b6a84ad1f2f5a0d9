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


#: the files whose YADE fixtures take longest, started first: `make test`
#: runs the suite on two pytest-xdist workers, one file per worker at a time
#: (--dist loadfile, so that a file's fixtures run once), and a long file
#: started last would leave one core idle at the end
FIRST = ("test_yade_scenes.py", "test_study_smoke.py", "test_slurm_cluster.py", "test_front.py", "test_slurm.py",
         "test_checkpoint.py")


def pytest_collection_modifyitems(config, items):
    """Put the files of :data:`FIRST` first, in that order (the others keep
    pytest's order)."""
    rank = {name: k for k, name in enumerate(FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(FIRST)))
