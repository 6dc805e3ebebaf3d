"""Shared set-up of the Python module's tests: the tiny scenes of the apps' tests (a few hundred
particles, a few dozen steps) and the source tree's paths."""
import os

import pytest

import numerics

SOURCE_DIR = os.environ.get("NUMERICS_SOURCE_DIR",
                            os.path.join(os.path.dirname(__file__), "..", ".."))
TINY_2D = os.path.join(SOURCE_DIR, "tests", "apps", "scenes", "tiny_2d.json")
TINY_3D = os.path.join(SOURCE_DIR, "tests", "apps", "scenes", "tiny_3d.json")


@pytest.fixture
def tiny2d():
    return numerics.Scene.load(TINY_2D)


@pytest.fixture
def tiny3d():
    return numerics.Scene.load(TINY_3D)


@pytest.fixture
def sim2d(tiny2d, tmp_path):
    return numerics.Simulation(tiny2d, threads=2, out=tmp_path / "out", quiet=True)
