"""numerics.Simulation: a scene's run, as fluid_sim and fluid_sim_3d run it."""
import csv
import json
import math
import os
import sys

import numpy as np

from . import _numerics
from .errors import RunError
from .particles import Particles
from .scene import Scene

_BACKENDS = ("seq", "omp", "threads", "cpu", "cuda")


# Seconds between redraws of the progress bar where stderr is not a terminal (a log file, a
# pipe, CI): each redraw there is a new line, so at most two a second; tqdm's 0.1 s on a terminal.
NON_TERMINAL_BAR_INTERVAL = 0.5


def _bar_interval(stream):
    """tqdm's mininterval for a bar drawn on `stream` (tqdm's default file is sys.stderr)."""
    try:
        terminal = stream.isatty()
    except (AttributeError, ValueError):
        terminal = False
    return 0.1 if terminal else NON_TERMINAL_BAR_INTERVAL


def _usage(message):
    return RunError(message, 2)


def _checked_options(threads, end_time, backend):
    if threads is not None and (not isinstance(threads, int) or not 1 <= threads <= 1024):
        raise _usage(f"threads: expected a whole number from 1 to 1024, found {threads!r}")
    if end_time is not None and not (math.isfinite(end_time) and end_time > 0):
        raise _usage(f"end_time: expected a finite number > 0, found {end_time!r}")
    if backend is not None and backend not in _BACKENDS:
        raise _usage(f"backend: expected one of {', '.join(_BACKENDS)}, found {backend!r}")


class Simulation:
    """A run of `scene` (a Scene, a dict or a scene file's path).

    threads: of the CPU backends (default: all cores); out: the output directory (default: the
    scene's output.directory); end_time: replaces time.end; backend: seq, omp, threads, cpu or
    cuda (default: the scene's numerics.backend); quiet: print nothing but errors.
    The run is set up and its first output written here (SceneError, RunError).
    """

    def __init__(self, scene, threads=None, out=None, quiet=False, end_time=None, backend=None):
        if not isinstance(scene, Scene):
            scene = Scene(scene) if isinstance(scene, dict) else Scene.load(scene)
        _checked_options(threads, end_time, backend)
        kind = _numerics.Simulation3 if scene.dimension == 3 else _numerics.Simulation2
        self.scene = scene
        self.dimension = scene.dimension
        self._driver = kind(scene._doc, threads or 0, None if out is None else os.fspath(out),
                            bool(quiet), end_time, backend)

    @property
    def time(self):
        """The simulated time [s]."""
        return self._driver.time

    @property
    def steps(self):
        """The steps taken (from the start of the run)."""
        return self._driver.steps

    @property
    def end_time(self):
        return self._driver.end_time

    @property
    def output_directory(self):
        return self._driver.output_directory

    @property
    def finished(self):
        """Whether the run has ended (summary.json written)."""
        return self._driver.finished

    def step(self):
        """One step towards the end time; returns its dt [s]."""
        return self._driver.step()

    def run(self, until=None, every=None, callback=None, progress=True):
        """Steps to `until` (default: the end time). Reaching the end time ends the run as the
        apps do (last output, probes plot, summary.json) and returns the exit code, 0; before
        it, returns 0 and a later run() continues.

        callback(sim) is called every `every` seconds of simulated time (the steps land on those
        times), or after every step when `every` is None. progress: a tqdm bar (terminal or
        Jupyter). Ctrl-C stops the run cleanly (its end written as interrupted), then raises
        KeyboardInterrupt.
        """
        target = self.end_time if until is None else min(float(until), self.end_time)
        if every is not None and not (math.isfinite(every) and every > 0):
            raise _usage(f"every: expected a finite number > 0, found {every!r}")
        call = None if callback is None else (lambda: callback(self))
        bar = self._progress_bar(target) if progress and not self.finished else None
        update = None if bar is None else (lambda: self._advance_bar(bar))
        try:
            return self._driver.advance(target, every or 0.0, call, update)
        finally:
            if bar is not None:
                self._advance_bar(bar)
                bar.close()

    def _progress_bar(self, target):
        from tqdm.auto import tqdm

        total = max(target - self.time, 0.0)
        bar = tqdm(total=round(total, 9), unit="s", unit_scale=False, desc="simulated",
                   bar_format="{l_bar}{bar}| {n:.4g}/{total:.4g} s [{elapsed}<{remaining}]",
                   mininterval=_bar_interval(sys.stderr))
        bar.start_time_of_run = self.time
        return bar

    def _advance_bar(self, bar):
        done = min(self.time - bar.start_time_of_run, bar.total)
        bar.update(done - bar.n)

    @property
    def particles(self):
        """The particles now, read-only NumPy views (numerics.Particles)."""
        return Particles(self._driver, writable=False)

    def particles_writable(self):
        """The particles now, as writable NumPy views: what is written before the next step
        changes the run."""
        return Particles(self._driver, writable=True)

    @property
    def probes(self):
        """{probe: {"time": array, field: array, ...}}: what probes.csv holds so far."""
        path = os.path.join(self.output_directory, "probes.csv")
        if not os.path.exists(path):
            return {}
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
        if not rows:
            return {}
        columns = np.array(rows[1:], dtype=float).reshape(len(rows) - 1, len(rows[0])).T
        out = {}
        for name, values in zip(rows[0][1:], columns[1:]):
            probe, _, field = name.rpartition(".")
            out.setdefault(probe, {"time": columns[0]})[field] = values
        return out

    @property
    def summary(self):
        """summary.json as a dict once the run has ended; None before (and after a failure
        that wrote none)."""
        path = os.path.join(self.output_directory, "summary.json")
        if not self.finished or not os.path.exists(path):
            return None
        with open(path) as f:
            return json.load(f)

    def __repr__(self):
        return (f"numerics.Simulation({self.scene.file!r}, t = {self.time:g} s of "
                f"{self.end_time:g} s, {self.steps} steps)")
