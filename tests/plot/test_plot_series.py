"""scripts/plot_series.py: probes.csv (a line per probe), bodies.csv (a line per body), PNG and
SVG, and its one-line errors (exit 2: bad input, 3: no matplotlib)."""
import importlib.util
import os
import subprocess
import sys

import pytest

SCRIPT = os.environ["NUMERICS_PLOT_SCRIPT"]
PROBES = ("time,wall.pressure,floor.temperature,floor.vx,floor.vy,hot.temperature,drag.force_x\n"
          "0,0,10,0,0,nan,0\n0.001,120.5,10.2,0.1,-0.2,80,1.5\n0.002,9511,10.5,0.3,-0.1,81,2\n")
BODIES = "time,body,x,y,angle\n0,0,1,0.5,0\n0,1,2,0.5,0\n0.1,0,1.1,0.45,0.1\n0.1,1,2,0.4,0.2\n"


def plot_series():
    spec = importlib.util.spec_from_file_location("plot_series", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def written(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def run(*args, env=None):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True,
                          env=env)


def labels(panel):
    return [label for label, _, _ in panel]


def test_probes_a_panel_per_quantity_a_line_per_probe(tmp_path):
    m = plot_series()
    panels = m.panels_of(*m.read_csv(written(tmp_path, "probes.csv", PROBES)))
    assert list(panels) == ["pressure", "temperature", "velocity", "force"]
    assert labels(panels["temperature"]) == ["floor", "hot"]
    assert labels(panels["velocity"]) == ["floor vx", "floor vy"]
    _, times, values = panels["pressure"][0]
    assert times == [0, 0.001, 0.002] and values == [0, 120.5, 9511]
    assert m.axis_label("pressure") == "pressure [Pa]"
    assert m.axis_label("temperature") == "temperature [°C]"


def test_bodies_a_line_per_body(tmp_path):
    m = plot_series()
    panels = m.panels_of(*m.read_csv(written(tmp_path, "bodies.csv", BODIES)))
    assert list(panels) == ["position", "angle"]
    assert labels(panels["position"]) == ["body 0 x", "body 0 y", "body 1 x", "body 1 y"]
    _, times, values = panels["angle"][1]
    assert times == [0, 0.1] and values == [0, 0.2]


def test_png_and_svg(tmp_path):
    csv = written(tmp_path, "probes.csv", PROBES)
    png, svg = tmp_path / "probes.png", tmp_path / "probes.svg"
    r = run(csv, "-o", str(png), "-o", str(svg), "--title", "probes: test")
    assert r.returncode == 0, r.stderr
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "<svg" in svg.read_text()


@pytest.mark.parametrize("text, args, message", [
    ("x,y\n1,2\n", ["-o", "p.png"], "first column is \"time\""),
    ("time,a.b\n0,1,2\n", ["-o", "p.png"], "row 2 has 3 values, the header 2"),
    (PROBES, ["-o", "p.jpg"], "p.jpg: expected a picture ending in .png, .svg or .pdf"),
])
def test_bad_input_is_one_line_and_exit_2(tmp_path, text, args, message):
    r = run(written(tmp_path, "in.csv", text), *[str(tmp_path / a) if a.startswith("p.") else a
                                                  for a in args])
    assert r.returncode == 2 and message in r.stderr and r.stderr.count("\n") == 1, r.stderr


def test_no_matplotlib_is_one_line_and_exit_3(tmp_path):
    fake = tmp_path / "fake" / "matplotlib"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("raise ImportError('no matplotlib here')\n")
    env = dict(os.environ, PYTHONPATH=str(tmp_path / "fake"))
    r = run(written(tmp_path, "probes.csv", PROBES), "-o", str(tmp_path / "p.png"), env=env)
    assert r.returncode == 3 and "matplotlib is not installed" in r.stderr, r.stderr
    assert r.stderr.count("\n") == 1 and not (tmp_path / "p.png").exists()
