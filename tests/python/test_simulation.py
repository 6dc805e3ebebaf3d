"""numerics.Simulation: steps, partial and whole runs, callbacks, progress, probes, summary."""
import io
import sys
import math

import pytest

import numerics


def test_state_and_single_steps(sim2d):
    assert sim2d.dimension == 2 and sim2d.time == 0 and sim2d.steps == 0
    assert sim2d.end_time == pytest.approx(0.02)
    dt = sim2d.step()
    assert dt > 0 and sim2d.time == pytest.approx(dt) and sim2d.steps == 1
    assert sim2d.summary is None and not sim2d.finished


def test_options(tiny2d, tmp_path):
    sim = numerics.Simulation(tiny2d, threads=1, out=tmp_path / "o", quiet=True, end_time=0.005,
                              backend="seq")
    assert sim.end_time == 0.005 and sim.output_directory == str(tmp_path / "o")
    assert sim.run(progress=False) == 0
    assert sim.summary["status"] == "completed" and sim.summary["threads"] == 1
    # A path and a dict are scenes too.
    assert numerics.Simulation(tiny2d.to_dict(), out=tmp_path / "d", quiet=True).time == 0


def test_bad_options(tiny2d, tmp_path):
    for kwargs, text in [({"threads": 0}, "threads"), ({"end_time": -1}, "end_time"),
                         ({"end_time": math.nan}, "end_time"), ({"backend": "gpu"}, "backend")]:
        with pytest.raises(numerics.RunError) as e:
            numerics.Simulation(tiny2d, out=tmp_path, quiet=True, **kwargs)
        assert e.value.exit_code == 2 and text in str(e.value)


def test_run_until_then_run_continues(sim2d):
    assert sim2d.run(until=0.01, progress=False) == 0
    assert sim2d.time == pytest.approx(0.01) and not sim2d.finished
    assert sim2d.summary is None
    assert sim2d.run(progress=False) == 0
    assert sim2d.time == pytest.approx(0.02) and sim2d.finished
    summary = sim2d.summary
    assert summary["status"] == "completed" and summary["steps"] == sim2d.steps
    with pytest.raises(numerics.RunError, match="has ended") as e:
        sim2d.step()
    assert e.value.exit_code == 2
    with pytest.raises(numerics.RunError, match="has ended"):
        sim2d.run()


def test_callback_at_its_times(sim2d):
    seen = []
    sim2d.run(until=0.0125, every=0.0025, callback=lambda s: seen.append((s.time, len(
        s.particles))), progress=False)
    assert [t for t, _ in seen] == pytest.approx([0.0025, 0.005, 0.0075, 0.01, 0.0125])
    assert all(n > 0 for _, n in seen)


def test_callback_every_step_and_its_errors(sim2d):
    steps = []
    sim2d.run(until=0.003, callback=lambda s: steps.append(s.steps), progress=False)
    assert steps == list(range(1, sim2d.steps + 1))

    def fail(s):
        raise ValueError("stop here")

    with pytest.raises(ValueError, match="stop here"):
        sim2d.run(callback=fail, progress=False)
    assert sim2d.steps == steps[-1] + 1 and not sim2d.finished  # one step, then the error
    assert sim2d.run(progress=False) == 0  # and the run goes on


def test_progress_bar(sim2d, monkeypatch):
    import tqdm.auto
    bars = []
    real = tqdm.auto.tqdm

    def recording(*args, **kwargs):
        kwargs["file"] = io.StringIO()
        bars.append(real(*args, **kwargs))
        return bars[-1]

    monkeypatch.setattr(tqdm.auto, "tqdm", recording)
    sim2d.run(until=0.01)
    assert len(bars) == 1 and bars[0].n == pytest.approx(0.01) and bars[0].total == 0.01


class _Stream(io.StringIO):
    def __init__(self, terminal):
        super().__init__()
        self.terminal = terminal

    def isatty(self):
        return self.terminal


@pytest.mark.parametrize("terminal, interval", [(True, 0.1), (False, 0.5)])
def test_progress_bar_redraws_seldom_off_a_terminal(sim2d, monkeypatch, terminal, interval):
    # Off a terminal (a log, a pipe) every redraw is a new line: at most two a second.
    import tqdm.auto
    bars = []
    real = tqdm.auto.tqdm
    monkeypatch.setattr(sys, "stderr", _Stream(terminal))
    monkeypatch.setattr(tqdm.auto, "tqdm", lambda *a, **k: bars.append(real(*a, **k)) or bars[-1])
    sim2d.run(until=0.005)
    assert len(bars) == 1 and bars[0].mininterval == interval


def test_probes_and_summary(sim2d):
    assert set(sim2d.probes) == {"p1"}
    sim2d.run(progress=False)
    p1 = sim2d.probes["p1"]
    assert set(p1) == {"time", "pressure", "vx", "vy"}
    # Sampled every 1 ms (output.probes_every's default; outputs every 10 ms): one row in each
    # millisecond from t = 0, the first step to reach it (the steps are shorter than 1 ms),
    # the last at the end.
    slots = [math.floor(t / 1e-3 + 1e-9) for t in p1["time"]]
    assert slots == list(range(21)) and p1["time"][-1] == pytest.approx(0.02)
    assert all(len(v) == 21 for v in p1.values())
    assert sim2d.summary["status"] == "completed"


def test_3d(tiny3d, tmp_path):
    sim = numerics.Simulation(tiny3d, threads=2, out=tmp_path, quiet=True)
    assert sim.dimension == 3 and sim.particles.position.shape[1] == 3
    assert sim.run(progress=False) == 0
    assert sim.summary["status"] == "completed" and sim.steps == sim.summary["steps"]


def test_steps_to_the_end_then_run_writes_the_end(tiny2d, tmp_path):
    sim = numerics.Simulation(tiny2d, out=tmp_path, quiet=True, end_time=0.002)
    while sim.time < sim.end_time * (1 - 1e-9):
        sim.step()
    with pytest.raises(numerics.RunError, match="at its end time") as e:
        sim.step()
    assert e.value.exit_code == 2 and not sim.finished
    assert sim.run(progress=False) == 0 and sim.summary["status"] == "completed"


def test_no_steps_from_inside_a_callback(sim2d):
    def nested(s):
        s.step()

    with pytest.raises(numerics.RunError, match="from a callback") as e:
        sim2d.run(until=0.005, callback=nested, progress=False)
    assert e.value.exit_code == 2 and sim2d.steps == 1
