#!/usr/bin/python3
"""Cost per particle-step against the number of particles (docs/performance.md, issue 13's
"flat within 20 % from 1e4 to 1e6 particles").

  bench/size_scaling.py [BUILD_DIR] [ROUNDS] [THREADS,...] [EVALUATION]
  defaults: build/release 5 1,2 asymmetric (the apps' default pair loop)

bench_dam_break (2D dam break, heat on) at 1e4, 1e5 and 1e6 fluid particles. The sizes run in
turn, round after round (1e4 1e5 1e6 1e4 1e5 1e6 ...), so that a drift of the machine's speed
hits every size alike; each run is itself the median of 3 timed repeats after 2 warm-up steps.
Printed per size and thread count: the median over the rounds of the wall time per fluid
particle-step and per particle-step of any kind (the small tank is a fifth walls, the large one
a fortieth), with the spread of the rounds, and the largest over the smallest size. The machine
(CPU, cores) and its load average are printed with the figures.
"""
import os
import statistics
import subprocess
import sys

from machine import machine

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else "build/release"
ROUNDS = int(sys.argv[2]) if len(sys.argv) > 2 else 5
THREADS = [int(t) for t in sys.argv[3].split(",")] if len(sys.argv) > 3 else [1, 2]
EVALUATION = sys.argv[4] if len(sys.argv) > 4 else "asymmetric"
BENCH = os.path.join(ROOT, BUILD, "bench", "bench_dam_break")
# Steps per timed repeat: about the same seconds per run at each size.
SIZES = {"1e4": 40, "1e5": 12, "1e6": 4}


def run(size, steps, threads):
    cmd = [BENCH, "--dim", "2", "--particles", size, "--heat", "1", "--threads", str(threads),
           "--steps", str(steps), "--warmup", "2", "--repeats", "3", "--evaluation", EVALUATION]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    line = next(l for l in out.splitlines() if l.startswith("result "))
    fields = dict(kv.split("=", 1) for kv in line.split()[1:])
    return float(fields["ns_per_particle_step"]), float(fields["ns_per_any_particle_step"])


def main():
    loads = [os.getloadavg()[0]]
    times = {(s, t): [] for s in SIZES for t in THREADS}
    for _ in range(ROUNDS):
        for t in THREADS:
            for size, steps in SIZES.items():
                times[(size, t)].append(run(size, steps, t))
                loads.append(os.getloadavg()[0])
    print(f"machine: {machine()}; load average {min(loads):.1f} to {max(loads):.1f}; "
          f"{ROUNDS} rounds, {EVALUATION} pair loop")
    print("| threads | fluid particles | ns per fluid particle-step (rounds' range) "
          "| ns per particle-step of any kind (range) |")
    print("| --- | --- | --- | --- |")
    for t in THREADS:
        medians = []
        for size in SIZES:
            fluid = [f for f, _ in times[(size, t)]]
            anykind = [a for _, a in times[(size, t)]]
            medians.append((statistics.median(fluid), statistics.median(anykind)))
            print(f"| {t} | {size} | {medians[-1][0]:.0f} ({min(fluid):.0f} to {max(fluid):.0f}) "
                  f"| {medians[-1][1]:.0f} ({min(anykind):.0f} to {max(anykind):.0f}) |")
        spread = [max(m[k] for m in medians) / min(m[k] for m in medians) for k in (0, 1)]
        print(f"| {t} | largest / smallest | {spread[0]:.2f} | {spread[1]:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
