"""A whole sim.run() writes the files fluid_sim writes on the same scene, byte for byte."""
import os
import subprocess

import pytest

import numerics
from conftest import TINY_2D, TINY_3D

COMPARED = (".vtu", ".csv", ".pvd")


def app(dimension):
    path = os.environ["NUMERICS_FLUID_SIM"]
    return path if dimension == 2 else os.path.join(os.path.dirname(os.path.dirname(path)),
                                                    "fluid_sim_3d", "fluid_sim_3d")


def compared_files(folder):
    return sorted(f for f in os.listdir(folder) if f.endswith(COMPARED))


@pytest.mark.parametrize("scene_file", [TINY_2D, TINY_3D])
def test_python_run_writes_what_the_app_writes(scene_file, tmp_path):
    scene = numerics.Scene.load(scene_file)
    scene.set("time.end", 0.015)
    subprocess.run([app(scene.dimension), scene_file, "--set", "time.end=0.015", "--out",
                    str(tmp_path / "app"), "--threads", "2", "-q"], check=True)
    sim = numerics.Simulation(scene, threads=2, out=tmp_path / "py", quiet=True)
    assert sim.run(progress=False) == 0
    files = compared_files(tmp_path / "app")
    assert "probes.csv" in files and sum(f.endswith(".vtu") for f in files) >= 2
    assert compared_files(tmp_path / "py") == files
    for f in files:
        a, b = (tmp_path / "app" / f).read_bytes(), (tmp_path / "py" / f).read_bytes()
        assert a == b, f
