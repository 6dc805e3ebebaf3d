"""Ctrl-C during sim.run(): the run stops cleanly (its end written as interrupted, as the apps
do it), then KeyboardInterrupt is raised; the interpreter lives on."""
import signal
import threading

import pytest

import numerics


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
