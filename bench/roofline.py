#!/usr/bin/env python3
"""A roofline line per pair loop: flops and bytes per pair, and the rate achieved against the
core's peak (one thread).

    bench/roofline.py [BUILD_DIR] [REPEATS]      (default build/release, 3)

Runs bench_core_peak (the core's peak with the engine's flags: multiplies and adds as separate
instructions) and bench_pair_loops (one evaluation of each pair loop on the 2D and 3D dam break,
1 thread), REPEATS times each, and prints the loops' medians against the best peak as a markdown table.

Per pair, counted from the formulas (sph/formulas/, the Wendland C2 kernel; every +, -, *, /,
sqrt, min and max is one flop):
  geometry   dx and r^2 (the list's collect), r, the gradient factor, grad W, the Laplacian
             factor and 1/(r^2 + eta^2), plus W where a loop needs kernel values
  density    continuity (formulas::continuityRate) and delta-SPH (deltaSphFlux)
  forces     pressure gradient (pressureGradientForce) and artificial viscosity (Pi_ij)
  heat       conduction (heatExchange, heatRate)
  all        the apps' whole evaluation: the above, laminar viscosity, the free-surface kernel
             sums and particle shifting's sums (W needed)
Bytes per pair: the neighbour's values the formulas read (8 B per double, 4 B per int or
index); the particle's own values and the pair geometry stay in registers or L1. Pairs per
evaluation: those the gather visits (bench_pair_loops' `pairs`: the particles it evaluates
times their mean number of neighbours).
"""
import json
import statistics
import subprocess
import sys

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build/release"
REPEATS = int(sys.argv[2]) if len(sys.argv) > 2 else 3


def geometry(dim, with_w):
    collect = dim + (2 * dim - 1)  # dx, r^2
    factor = 11  # q = min(r / h, 2), Wendland C2 df(q), scale / max(r, tiny)
    laplacian = (2 * dim - 1) + 3  # dx . grad / (r r + eta^2)
    w = 9 if with_w else 0
    return collect + 1 + factor + dim + laplacian + 3 + w


def parts(dim):
    d = dim
    return {
        "continuity": d + (2 * d - 1) + 3,
        "delta": 1 + (2 * d - 1) + 1 + 1 + (2 * d - 1) + 4,
        "pressure": 1 + 3 * d,
        "artificial": d + (2 * d - 1) + 6 + 3 * d,
        "laminar": 4 + 3 * d,
        "conduction": 13,
        "kernel_sum": 3,
        "shifting": 9 + 3 * d + d + 2 + 2 * d + 2 * d + d * (1 + 2 * d),
    }


def neighbour_bytes(dim):
    vec = 8 * dim
    return {"x": vec, "v": vec, "volume": 8, "kind": 4, "rho": 8, "p_over_rho2": 8, "mass": 8,
            "mu": 8, "active": 1, "condition": 4, "material": 4, "T": 8, "T_wall": 8,
            "at_surface": 1, "inverse_w": 8}


LOOPS = {  # loop: (parts, neighbour values read, kernel values)
    "DENSITY": (["continuity", "delta"], ["x", "v", "volume", "kind", "rho"], False),
    "FORCES": (["pressure", "artificial"], ["x", "p_over_rho2", "mass", "v", "rho"], False),
    "HEAT": (["conduction"], ["x", "condition", "material", "T", "T_wall", "mass", "rho"], False),
    "ALL": (list(parts(2).keys()), list(neighbour_bytes(2).keys()), True),
}


def run_json(args):
    out = subprocess.run(args + ["--benchmark_format=json"], check=True, capture_output=True,
                         text=True).stdout
    return json.loads(out)["benchmarks"]


def peaks():
    rates = {}
    for _ in range(REPEATS):
        for b in run_json([f"{BUILD}/bench/bench_core_peak", "--benchmark_min_time=0.3"]):
            rates.setdefault(b["name"], []).append(b["flops_per_second"])
    return {k: max(v) for k, v in rates.items()}  # the peak: the best run


def loops():
    times, pairs = {}, {}
    for _ in range(REPEATS):
        for b in run_json([f"{BUILD}/bench/bench_pair_loops", "--benchmark_min_time=0.5",
                           "--benchmark_filter=/1/real_time"]):
            name = b["name"].split("/")[0]
            times.setdefault(name, []).append(b["real_time"] * 1e-3)  # ms -> s
            if "pairs" in b:
                pairs[name] = b["pairs"]
    return {k: statistics.median(v) for k, v in times.items()}, pairs


def main():
    peak = peaks()
    times, pairs = loops()
    load = open("/proc/loadavg").read().split()[:3]
    print(f"Core peak, 1 thread (flop/s): scalar {peak['scalar'] / 1e9:.1f} G, "
          f"2-wide {peak['vector2'] / 1e9:.1f} G, 4-wide {peak['vector4'] / 1e9:.1f} G; "
          f"load {' '.join(load)}\n")
    print("| loop | dim | flops/pair | bytes/pair | ns/pair | Gflop/s | of scalar peak "
          "| of 4-wide peak | GB/s |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for dim in (2, 3):
        for loop, (names, values, with_w) in LOOPS.items():
            key = f"loop<{dim}, Loop::{loop}>"
            flops = geometry(dim, with_w) + sum(parts(dim)[p] for p in names)
            nbytes = sum(neighbour_bytes(dim)[v] for v in values)
            seconds_per_pair = times[key] / pairs[key]
            rate = flops / seconds_per_pair
            print(f"| {loop.lower()} | {dim}D | {flops} | {nbytes} | {seconds_per_pair * 1e9:.2f} "
                  f"| {rate / 1e9:.2f} | {100 * rate / peak['scalar']:.0f} % "
                  f"| {100 * rate / peak['vector4']:.0f} % | {nbytes / seconds_per_pair / 1e9:.1f} |")


if __name__ == "__main__":
    main()
