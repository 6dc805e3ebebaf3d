#!/usr/bin/python3
"""What the Python module costs over fluid_sim (docs/python.md, docs/performance.md).

  bench/python_overhead.py [BUILD_DIR] [RUNS] [END_TIME]   defaults: build/release 5 1.2

The default 2D scene (scenes/dam_break_hot_cold_2d.json, the one scripts/run.sh runs) to
END_TIME, with 2 threads and its outputs, as whole processes timed from start to exit:
`fluid_sim` and `python3 -c "numerics.Simulation(...).run()"` (interpreter start, imports and
the progress bar included), run alternately (A B A B ...) so that a change of machine load hits
both. Prints each pair, the median ratio Python / fluid_sim of wall time and of CPU time (user
+ system of the process and its threads: steadier than wall time on a loaded machine) and their
ranges; the target is a cost under 2 %. The machine and its load average are printed with the
figures.
"""
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

from machine import machine

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(SOURCE, "scenes", "dam_break_hot_cold_2d.json")
PYTHON_RUN = """
import numerics
sim = numerics.Simulation({scene!r}, threads=2, out={out!r}, quiet=True, end_time={end})
raise SystemExit(sim.run())
"""


def cpu_of_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(command, env=None):
    """Wall and CPU seconds of the command."""
    cpu = cpu_of_children()
    start = time.perf_counter()
    done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"{command[0]} failed (exit code {done.returncode}):\n{done.stderr}")
    return elapsed, cpu_of_children() - cpu


def main():
    build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/release")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    end = float(sys.argv[3]) if len(sys.argv) > 3 else 1.2
    app = os.path.join(build, "apps", "fluid_sim", "fluid_sim")
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    print(f"{machine()}, load average {os.getloadavg()[0]:.2f} before")
    wall, cpu = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(runs):
            a = timed([app, SCENE, "--threads", "2", "--end-time", str(end), "--out",
                       os.path.join(tmp, "app"), "-q"])
            code = PYTHON_RUN.format(scene=SCENE, out=os.path.join(tmp, "py"), end=end)
            b = timed(["/usr/bin/python3", "-c", code], env)
            wall.append(b[0] / a[0])
            cpu.append(b[1] / a[1])
            print(f"run {k + 1}: fluid_sim {a[0]:.2f} s ({a[1]:.2f} s CPU), Python {b[0]:.2f} s "
                  f"({b[1]:.2f} s CPU), ratios {wall[-1]:.4f} wall, {cpu[-1]:.4f} CPU", flush=True)
    print(f"load average {os.getloadavg()[0]:.2f} after")
    for name, ratios in (("wall", wall), ("CPU", cpu)):
        median = statistics.median(ratios)
        print(f"to t = {end:g} s, {name} time: Python / fluid_sim median {median:.4f} (range "
              f"{min(ratios):.4f} to {max(ratios):.4f}): Python costs "
              f"{100 * (median - 1):+.2f} % (target: under 2 %)")


if __name__ == "__main__":
    main()
