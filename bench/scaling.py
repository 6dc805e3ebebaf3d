#!/usr/bin/python3
"""Processes against threads, halo traffic and load balance of the apps (docs/scaling.md).

  bench/scaling.py [BUILD_DIR] [REPEATS] [PARTS]   defaults: build/release 3 scaling,halo,balance

1. Strong scaling, whole processes timed start to exit: the 2D dam break of
   bench/pysph_dam_break_2d.json (20,000 fluid particles, to t = 0.02 s) and the 3D default
   scenes/hot_cold_exchange_3d.json (31,232 fluid particles, to t = 0.02 s) and the 3D dam
   break of scenes/dam_break_3d.json at a spacing of 2 cm (to t = 0.01 s), each as
   1 process x 1 thread, 1 process x 2 threads and 2 processes x 1 thread (mpiexec), run in
   turn (A B C A B C ...) so that a change of machine load hits all three; medians and their
   ratios to 1 x 1.
2. Halo traffic against particle count: the 2D dam break on 2 and 4 processes at spacings
   0.02, 0.01 and 0.005 (a few steps): bytes received per halo exchange, summed over the
   processes, and halo copies. A subdomain's surface grows like N^(1/2) in 2D.
3. Load balance over the 2D dam break on 4 processes: the imbalance of the last
   redistribution and the number of repartitions, at t = 0.05, 0.1 and 0.2 s.
The machine (CPU, cores) and its load average are printed with the figures.
"""
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from machine import machine

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else "build/release"
REPEATS = int(sys.argv[2]) if len(sys.argv) > 2 else 3
PARTS = sys.argv[3].split(",") if len(sys.argv) > 3 else ["scaling", "halo", "balance"]
APP2 = os.path.join(ROOT, BUILD, "apps/fluid_sim/fluid_sim")
APP3 = os.path.join(ROOT, BUILD, "apps/fluid_sim_3d/fluid_sim_3d")
MPIEXEC = shutil.which("mpiexec") or "mpiexec"
MPI_FLAGS = ["--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
QUIET = ["-q", "--set", "output.images=false", "--set", "output.video=false"]


def run(app, args, processes, threads, out):
    cmd = [app] + args + QUIET + ["--threads", str(threads), "--out", out]
    if processes > 1:
        cmd = [MPIEXEC, "-n", str(processes)] + MPI_FLAGS + cmd
    start = time.monotonic()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    seconds = time.monotonic() - start
    with open(os.path.join(out, "summary.json")) as f:
        return seconds, json.load(f)


def machine_and_load():
    return f"{machine()}, load average {os.getloadavg()[0]:.2f}"


def strong_scaling(work):
    cases = [("2D dam break, 20,000 fluid", APP2,
              [os.path.join(ROOT, "bench/pysph_dam_break_2d.json"), "--end-time", "0.02"]),
             ("3D hot/cold exchange, 31,232 fluid", APP3,
              [os.path.join(ROOT, "scenes/hot_cold_exchange_3d.json"), "--end-time", "0.02"]),
             ("3D dam break, 27,000 fluid", APP3,
              [os.path.join(ROOT, "scenes/dam_break_3d.json"), "--set", "particles.spacing=0.02",
               "--end-time", "0.01"])]
    layouts = [(1, 1), (1, 2), (2, 1)]
    print("## Strong scaling (whole process, seconds; medians of", REPEATS, "alternating runs)")
    print(f"machine: {machine_and_load()}")
    for name, app, args in cases:
        times = {layout: [] for layout in layouts}
        for _ in range(REPEATS):
            for layout in layouts:
                seconds, _ = run(app, args, *layout, os.path.join(work, "s"))
                times[layout].append(seconds)
        base = statistics.median(times[(1, 1)])
        print(f"{name}:")
        for p, t in layouts:
            m = statistics.median(times[(p, t)])
            print(f"  {p} process(es) x {t} thread(s): {m:7.2f} s  speed-up {base / m:.2f}"
                  f"  (runs: {', '.join(f'{x:.2f}' for x in times[(p, t)])})")
    print(f"load average after: {os.getloadavg()[0]:.2f}")


def halo_traffic(work):
    print("\n## Halo traffic against particle count (2D dam break, t = 0.0005 s)")
    print("processes  spacing  particles  halo copies  bytes per exchange  bytes per step")
    for processes in (2, 4):
        for spacing in ("0.02", "0.01", "0.005"):
            _, s = run(APP2, [os.path.join(ROOT, "bench/pysph_dam_break_2d.json"),
                              "--set", f"particles.spacing={spacing}", "--end-time", "0.0005"],
                       processes, 1, os.path.join(work, "h"))
            d = s["decomposition"]
            print(f"{processes:9d}  {spacing:>7}  {s['particles']:9d}  {d['halo_particles']:11d}"
                  f"  {d['halo_bytes_per_exchange']:18.0f}  {d['halo_bytes_per_step']:14.0f}")


def load_balance(work):
    print("\n## Load balance (2D dam break, 4 processes)")
    print("end time  imbalance at last redistribution  repartitions")
    for end in ("0.05", "0.1", "0.2"):
        _, s = run(APP2, [os.path.join(ROOT, "bench/pysph_dam_break_2d.json"),
                          "--set", "particles.spacing=0.02", "--end-time", end],
                   4, 1, os.path.join(work, "b"))
        d = s["decomposition"]
        print(f"{end:>8}  {100 * d['load_imbalance']:31.1f} %  {d['repartitions']:12d}")


def main():
    with tempfile.TemporaryDirectory() as work:
        if "scaling" in PARTS:
            strong_scaling(work)
        if "halo" in PARTS:
            halo_traffic(work)
        if "balance" in PARTS:
            load_balance(work)


if __name__ == "__main__":
    main()
