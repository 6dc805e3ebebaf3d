"""numerics.Simulation: a scene's run, as fluid_sim and fluid_sim_3d run it."""
import csv
import json
import os
import sys

import numpy as np

from . import _arguments, _numerics
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


def _checked_options(threads, out, quiet, end_time, backend):
    """The options of Simulation(), each checked by name (RunError, exit code 2)."""
    if threads is not None:
        threads = _arguments.whole("threads", threads, 1, 1024)
    if out is not None:
        out = _arguments.path("out", out)
    quiet = _arguments.flag("quiet", quiet)
    if end_time is not None:
        end_time = _arguments.number("end_time", end_time, positive=True)
    if backend is not None and (not isinstance(backend, str) or backend not in _BACKENDS):
        _arguments.refuse("backend", f"one of {', '.join(_BACKENDS)}", backend)
    return threads, out, quiet, end_time, backend


def _scene_of(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        return Scene(scene)
    if isinstance(scene, (str, os.PathLike)):
        return Scene.load(scene)
    _arguments.refuse("scene", "a numerics.Scene, a dict or a scene file's path", scene)


class Simulation:
    """A run of `scene` (a Scene, a dict or a scene file's path).

    threads: of the CPU backends (default: all cores); out: the output directory (default: the
    scene's output.directory); end_time: replaces time.end; backend: seq, omp, threads, cpu or
    cuda (default: the scene's numerics.backend); quiet: print nothing but errors.
    The run is set up and its first output written here (SceneError, RunError).
    """

    def __init__(self, scene, threads=None, out=None, quiet=False, end_time=None, backend=None):
        threads, out, quiet, end_time, backend = _checked_options(threads, out, quiet, end_time,
                                                                  backend)
        scene = _scene_of(scene)
        kind = _numerics.Simulation3 if scene.dimension == 3 else _numerics.Simulation2
        self.scene = scene
        self.dimension = scene.dimension
        self._driver = kind(scene._doc, threads or 0, out, quiet, end_time, backend)

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
        target, every = self._checked_run(until, every, callback, progress)
        call = None if callback is None else (lambda: callback(self))
        bar = self._progress_bar(target) if progress and not self.finished else None
        update = None if bar is None else (lambda: self._advance_bar(bar))
        try:
            return self._driver.advance(target, every or 0.0, call, update)
        finally:
            if bar is not None:
                self._advance_bar(bar)
                bar.close()

    def _checked_run(self, until, every, callback, progress):
        """run()'s arguments, each checked by name (RunError, exit code 2): the time to run to
        and the interval of the callback (None: after every step)."""
        now, end = self.time, self.end_time
        target = end
        if until is not None:
            until = _arguments.number("until", until, positive=True)
            if until < now - 1e-9 * max(abs(now), 1e-300):
                _arguments.refuse("until", f"a time from the run's time now, {now:g} s, on",
                                  until, extra=": a run does not go back")
            target = min(until, end)
        if every is not None:
            every = _arguments.number("every", every, positive=True)
            calls = (target - now) / every
            if every < 1e-9 * end or calls > _arguments.MAX_CALLBACKS:
                least = max(1e-9 * end, (target - now) / _arguments.MAX_CALLBACKS)
                _arguments.refuse(
                    "every", f"an interval of at least {least:g} s", every,
                    extra=f": it would call back {calls:.3g} times from {now:g} s to {target:g} "
                    f"s (at most {_arguments.MAX_CALLBACKS:g}, each a step landing on its time)")
        _arguments.callable_or_none("callback", callback)
        _arguments.flag("progress", progress)
        return target, every

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
    def bodies(self):
        """The moving bodies now (bodies[i].motion free or prescribed), as bodies.csv names them:
        {"name": [...], "position": (n, dim), "velocity": (n, dim), "angle": (n, 1) in 2D or
        "quaternion": (n, 4) in 3D, "angular_velocity": (n, 1 or 3), "force": (n, dim),
        "torque": (n, 1 or 3)}, the force and torque those of the water [N, N m; per metre of
        depth in 2D]."""
        return self._driver.bodies()

    def set_body_velocity(self, body, velocity, angular_velocity=None):
        """Holds the prescribed body named `body` at this velocity [m/s] and angular velocity
        [rad/s] (zero when not given) from the next step on, replacing its expressions: a
        paddle under control, e.g. from a callback of run()."""
        if angular_velocity is None:
            angular_velocity = [0.0] * (1 if self.dimension == 2 else 3)
        elif self.dimension == 2 and not hasattr(angular_velocity, "__len__"):
            angular_velocity = [angular_velocity]
        self._driver.set_body_velocity(str(body), [float(v) for v in velocity],
                                       [float(w) for w in angular_velocity])

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
