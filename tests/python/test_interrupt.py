"""Ctrl-C during sim.run(): the run stops cleanly (its end written as interrupted, as the apps
do it), then KeyboardInterrupt is raised; the interpreter lives on."""
import signal
import threading

import pytest

import numerics
from numerics import _numerics


def interrupt_after_steps(sim, steps):
    """A callback that sends SIGINT to this process once `steps` steps are done."""
    def callback(s):
        if s.steps == steps:
            signal.raise_signal(signal.SIGINT)
    return callback


def test_ctrl_c_in_a_whole_run(sim2d):
    with pytest.raises(KeyboardInterrupt):
        sim2d.run(callback=interrupt_after_steps(sim2d, 3), progress=False)
    assert sim2d.finished and sim2d.steps == 3
    assert sim2d.summary["status"] == "interrupted"
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_ctrl_c_in_a_partial_run(sim2d):
    with pytest.raises(KeyboardInterrupt):
        sim2d.run(until=0.01, callback=interrupt_after_steps(sim2d, 2), progress=False)
    assert sim2d.finished and sim2d.summary["status"] == "interrupted"


def test_ctrl_c_from_another_thread(tiny2d, tmp_path):
    """The signal arrives while the steps run in C++ with the GIL released."""
    tiny2d.set("time.end", 100)
    sim = numerics.Simulation(tiny2d, threads=2, out=tmp_path, quiet=True)
    started = threading.Event()
    timer = threading.Thread(target=lambda: started.wait() and signal.raise_signal(signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        sim.run(callback=lambda s: started.set(), every=0.001, progress=False)
    timer.join()
    assert sim.finished and sim.summary["status"] == "interrupted" and sim.time < 100


def huge_set_up(scene):
    """The scene with a polygon of water on a lattice of 5e7 points (the domain's 1.8e8 are within
    the limit of 2e8): its set-up polls for Ctrl-C once per lattice row, thousands of times."""
    scene.set("particles.spacing", 1.5e-5)
    scene.set("fluids.0", {"material": "water", "shape": "polygon",
                           "points": [[0, 0], [0.1, 0], [0.1, 0.12], [0, 0.12]]})
    return scene


@pytest.mark.parametrize("what", ["Simulation", "check"])
def test_ctrl_c_during_set_up(tiny2d, tmp_path, what):
    """Ctrl-C (SIGINT, sent by the set-up itself at its 100th poll, as a terminal would send it)
    stops a long set-up; the folder and the interpreter can be used again."""
    scene = huge_set_up(tiny2d.copy())
    _numerics._sigint_at_set_up_poll(100)
    try:
        with pytest.raises(KeyboardInterrupt):
            if what == "check":
                scene.check()
            else:
                numerics.Simulation(scene, threads=2, out=tmp_path, quiet=True)
    finally:
        _numerics._sigint_at_set_up_poll(0)
    sim = numerics.Simulation(tiny2d, threads=2, out=tmp_path, quiet=True)
    sim.run(progress=False)
    assert sim.summary["status"] == "completed"
