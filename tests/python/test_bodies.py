"""numerics.Simulation.bodies and set_body_velocity: the moving bodies as NumPy arrays, and a
prescribed body steered from a callback."""
import os

import numpy as np
import pytest

import numerics
from conftest import SOURCE_DIR

BODIES_2D = os.path.join(SOURCE_DIR, "tests", "apps", "scenes", "moving_bodies_2d.json")
BODIES_3D = os.path.join(SOURCE_DIR, "tests", "apps", "scenes", "moving_bodies_3d.json")


def test_bodies_as_arrays(tmp_path):
    sim = numerics.Simulation(numerics.Scene.load(BODIES_2D), threads=2, out=tmp_path / "o",
                              quiet=True, end_time=0.02)
    b = sim.bodies
    assert b["name"] == ["float", "paddle"]  # the fixed circle is not listed
    assert b["position"].shape == (2, 2) and b["angle"].shape == (2, 1)
    assert b["position"][1] == pytest.approx([0.08, 0.17])
    sim.run(progress=False)
    b = sim.bodies
    assert b["position"][1][0] == pytest.approx(0.08 + 0.25 * 0.02, abs=1e-12)
    assert np.all(np.isfinite(b["force"])) and b["torque"].shape == (2, 1)


def test_three_dimensional_bodies_have_quaternions(tmp_path):
    sim = numerics.Simulation(numerics.Scene.load(BODIES_3D), out=tmp_path / "o", quiet=True,
                              end_time=0.01)
    sim.run(progress=False)
    b = sim.bodies
    assert b["quaternion"].shape == (1, 4) and b["angular_velocity"].shape == (1, 3)
    assert np.linalg.norm(b["quaternion"][0]) == pytest.approx(1, abs=1e-12)


def test_a_callback_steers_a_prescribed_body(tmp_path):
    sim = numerics.Simulation(numerics.Scene.load(BODIES_2D), out=tmp_path / "o", quiet=True,
                              end_time=0.04)
    sim.run(until=0.02, progress=False)
    x = sim.bodies["position"][1][0]
    sim.set_body_velocity("paddle", [-0.5, 0], 0)
    sim.run(progress=False)
    assert sim.bodies["position"][1][0] == pytest.approx(x - 0.5 * 0.02, abs=1e-9)
    assert sim.bodies["velocity"][1] == pytest.approx([-0.5, 0])


def test_only_a_prescribed_body_is_steered(tmp_path):
    sim = numerics.Simulation(numerics.Scene.load(BODIES_2D), out=tmp_path / "o", quiet=True)
    with pytest.raises(numerics.RunError, match="float"):
        sim.set_body_velocity("float", [0, 0])
    with pytest.raises(numerics.RunError, match="velocity"):
        sim.set_body_velocity("paddle", [0, 0, 0])


def test_no_moving_body_gives_empty_arrays(sim2d):
    b = sim2d.bodies
    assert b["name"] == [] and b["position"].shape == (0, 2)
