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
