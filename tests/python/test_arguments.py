"""Every argument of the module's functions is checked (type, finite, range): a bad one raises
numerics.RunError or SceneError, exit code 2, naming the parameter."""
import math
import pathlib
import threading

import numpy as np
import pytest

import numerics


def refused(kind, name, action):
    with pytest.raises(kind) as e:
        action()
    assert e.value.exit_code == 2, str(e.value)
    assert str(e.value).startswith(name + ":"), str(e.value)
    return str(e.value)


@pytest.mark.parametrize("kwargs", [
    {"threads": 0}, {"threads": True}, {"threads": 2.0}, {"threads": "2"}, {"threads": 10**6},
    {"end_time": "1"}, {"end_time": math.nan}, {"end_time": math.inf}, {"end_time": -1},
    {"end_time": 0}, {"end_time": True}, {"end_time": [1]},
    {"quiet": "no"}, {"quiet": None}, {"out": 42}, {"out": ""}, {"out": b"/tmp"},
    {"backend": 5}, {"backend": "gpu"}])
def test_bad_simulation_options(tiny2d, tmp_path, kwargs):
    (name,) = kwargs
    options = {"out": tmp_path / "o", "quiet": True, **kwargs}
    refused(numerics.RunError, name, lambda: numerics.Simulation(tiny2d, **options))
    assert not (tmp_path / "o").exists()  # refused before the run was set up


def test_scene_of_no_kind(tmp_path):
    text = refused(numerics.RunError, "scene", lambda: numerics.Simulation(42, out=tmp_path))
    assert "found 42" in text
    refused(numerics.SceneError, "scene", lambda: numerics.Scene(42))
    refused(numerics.SceneError, "path", lambda: numerics.Scene.load(42))
    refused(numerics.SceneError, "path", lambda: numerics.Scene.load(""))


def test_bad_set(tiny2d):
    refused(numerics.SceneError, "path", lambda: tiny2d.set(3, 1))
    refused(numerics.SceneError, "value", lambda: tiny2d.set("particles.spacing", math.nan))
    refused(numerics.SceneError, "value", lambda: tiny2d.set("particles.spacing", object()))
    assert tiny2d.to_dict()["particles"]["spacing"] == 0.02


@pytest.mark.parametrize("kwargs,name", [
    ({"until": math.nan}, "until"), ({"until": math.inf}, "until"), ({"until": -1}, "until"),
    ({"until": 0}, "until"), ({"until": "0.01"}, "until"), ({"until": None, "every": 1e-300},
                                                           "every"),
    ({"every": math.nan}, "every"), ({"every": -0.1}, "every"), ({"every": "0.1"}, "every"),
    ({"every": 1e-12}, "every"), ({"callback": 3}, "callback"), ({"progress": "yes"},
                                                                 "progress")])
def test_bad_run_arguments(sim2d, kwargs, name):
    kwargs.setdefault("progress", False)
    text = refused(numerics.RunError, name, lambda: sim2d.run(**kwargs))
    assert sim2d.steps == 0 and not sim2d.finished, text


def test_every_refused_says_how_many_calls(sim2d):
    text = refused(numerics.RunError, "every", lambda: sim2d.run(every=1e-300, progress=False))
    assert "times" in text and "at most" in text


def test_until_before_now(sim2d):
    sim2d.run(until=0.01, progress=False)
    steps = sim2d.steps
    text = refused(numerics.RunError, "until", lambda: sim2d.run(until=0.005, progress=False))
    assert "does not go back" in text and sim2d.steps == steps
    # The time now is no error: nothing to do.
    assert sim2d.run(until=sim2d.time, progress=False) == 0 and sim2d.steps == steps


def test_good_arguments_of_other_types(tiny2d, tmp_path):
    sim = numerics.Simulation(str(tiny2d.file), threads=np.int64(1), out=pathlib.Path(tmp_path),
                              quiet=np.bool_(True), end_time=np.float64(0.004))
    assert sim.run(until=np.float32(0.002), every=0.001, progress=False) == 0
    assert sim.time == pytest.approx(0.002)


def test_particle_field_name(sim2d):
    with pytest.raises(TypeError, match="name"):
        sim2d.particles.field(3)


def test_run_from_a_second_thread_is_told_so(sim2d):
    seen = {}
    inside = threading.Event()
    release = threading.Event()

    def callback(s):
        if not inside.is_set():
            inside.set()
            release.wait(60)

    def other():
        inside.wait(60)
        for name, action in [("step", sim2d.step), ("run", lambda: sim2d.run(progress=False)),
                             ("particles", lambda: sim2d.particles.density)]:
            try:
                action()
            except numerics.RunError as e:
                seen[name] = str(e)
        release.set()

    t = threading.Thread(target=other)
    t.start()
    sim2d.run(until=0.002, callback=callback, progress=False)
    t.join()
    assert set(seen) == {"step", "run", "particles"}, seen
    assert all("another thread" in m and "callback" not in m for m in seen.values()), seen
