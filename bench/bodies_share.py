#!/usr/bin/python3
"""The cost of many moving bodies: a 2D flume 4 m long with debris (1,000 small free boxes, 4
particles each, in the water's top 0.4 m; some 10 % of the particles) against the same scene with the boxes fixed, runs alternating; the bodies' share of
a step is 1 - (time per step, fixed) / (time per step, free): the coupling's loads and motion,
the contacts, the moved particles and the containment that follows them.

    bench/bodies_share.py [--bodies 1000] [--repeats 3] [--end-time 0.05] [--threads 2] [--bin DIR]

Prints the medians with the machine's load. A step's time is the difference of two runs, to T
and to 2 T, over their difference in steps (the apps' summary.json: wall time with the set-up,
steps), so the set-up of the bodies is left out. Benchmarks only: no test reads a time.
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def debris_scene(bodies, free):
    """Boxes 0.02 m square (2 x 2 particles) on a grid 0.08 by 0.04 m, half of them under water."""
    columns = 50
    rows = -(-bodies // columns)
    boxes = []
    for k in range(bodies):
        i, j = k % columns, k // columns
        x0, y0 = 0.04 + 0.08 * i, 0.6 + 0.04 * (j - rows // 2)
        body = {"shape": "box", "min": [x0, y0], "max": [x0 + 0.02, y0 + 0.02]}
        if free:
            body["motion"] = {"type": "free", "density": 600}
        boxes.append(body)
    return {
        "dimension": 2, "name": f"debris, {bodies} {'free' if free else 'fixed'} bodies",
        "domain": {"min": [0, 0], "max": [4.04, 1.4]},
        "boundaries": {"x_min": {"type": "wall"}, "x_max": {"type": "wall"},
                       "y_min": {"type": "wall"}, "y_max": {"type": "open"}},
        "particles": {"spacing": 0.01}, "time": {"end": 1.0}, "gravity": [0, -9.81],
        "materials": {"water": {"density": 1000, "viscosity": 1e-6}},
        "physics": {"heat": False, "max_speed": 2},
        "fluids": [{"material": "water", "shape": "box", "min": [0, 0], "max": [4.04, 0.6],
                    "pressure": "1000*9.81*(0.6-y)"}],
        "bodies": boxes,
        "output": {"directory": "out/debris", "every": 10, "formats": [], "images": False},
    }


def run_once(app, scene_path, out, end_time, threads):
    """wall seconds (set-up included) and steps of a run to end_time."""
    subprocess.run([app, scene_path, "--quiet", "--out", out, "--end-time", str(end_time),
                    "--threads", str(threads)], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return s["wall_seconds"], s["steps"], s["particles"]


def step_time(app, scene_path, out, end_time, threads):
    """Seconds per step without the set-up: runs to end_time and to twice that, differenced."""
    w1, n1, particles = run_once(app, scene_path, out + "a", end_time, threads)
    w2, n2, _ = run_once(app, scene_path, out + "b", 2 * end_time, threads)
    return (w2 - w1) / max(1, n2 - n1), particles


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bodies", type=int, default=1000)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--end-time", type=float, default=0.05)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "release", "apps"))
    a = ap.parse_args()
    app = os.path.join(a.bin, "fluid_sim", "fluid_sim")
    work = tempfile.mkdtemp(prefix="bodies_share_")
    paths = {}
    for free in (True, False):
        paths[free] = os.path.join(work, f"{'free' if free else 'fixed'}.json")
        with open(paths[free], "w") as f:
            json.dump(debris_scene(a.bodies, free), f)
    times = {True: [], False: []}
    particles = 0
    for r in range(a.repeats):
        for free in (False, True):  # alternating
            t, particles = step_time(app, paths[free], os.path.join(work, f"out{r}{free}"),
                                     a.end_time, a.threads)
            times[free].append(t)
    free_t, fixed_t = statistics.median(times[True]), statistics.median(times[False])
    with open("/proc/loadavg") as f:
        load = " ".join(f.read().split()[:3])
    print(f"{a.bodies} bodies, {particles} particles, {a.threads} threads, to t = {a.end_time} s, "
          f"median of {a.repeats} alternating runs, load {load}")
    print(f"time per step (set-up excluded): free {free_t * 1e3:.3f} ms, fixed {fixed_t * 1e3:.3f} ms; "
          f"the bodies' share of a step: {1 - fixed_t / free_t:.1%}")


if __name__ == "__main__":
    main()
