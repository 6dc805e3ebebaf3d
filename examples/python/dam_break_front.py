#!/usr/bin/python3
"""A 2D dam break whose surge front is tracked from the particles as the run goes, against
Martin & Moyce's (1952) experiment, in their units: Z = z / a against T = t sqrt(2 g / a), a the
width of the water column.

    python3 dam_break_front.py --out out/dam_break_front [--quick]

Writes dam_break_front.png in --out and prints the front against the experiment; exits 1 if it is
further from it than the bound stated in SETTINGS (--quick: the CI run, coarser and shorter).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import numerics

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "validation", "data", "martin_moyce1952.csv")

# Particles across the column, end time [s] and bound on |Z - Z_exp| / Z_exp at the tabulated
# times the run reaches. The model releases the column at once; the front leads the experiment
# early on by 12 to 16 % at every spacing from a / 20 to a / 80 (validation/cases.py), while a
# coarse surge lags late. Measured with these settings (2026-12-05): at a / 30 to T = 9.3, at
# most 0.19 (-0.19 at T = 9.2, +0.14 at T = 1.2); at a / 10 to T = 4.6, at most 0.08 (+0.08 at
# T = 1.2). The bounds are those plus 50 %; a front that stays put or runs off misses them by far.
SETTINGS = {
    "full": {"per_width": 30, "end": 0.5, "bound": 0.28},
    "quick": {"per_width": 10, "end": 0.25, "bound": 0.12},
}


def martin_moyce():
    """The experiment's front: T and Z (validation/data/martin_moyce1952.csv)."""
    with open(DATA) as f:
        rows = [line for line in f if line.strip() and not line.startswith("#")]
    table = np.loadtxt(rows[1:], delimiter=",")
    return table[:, 0], table[:, 1]


def surge_front(x, support, spacing):
    """The front of the fluid particles at x (the column stands at x = 0): the farthest particle
    still joined to the bulk, each closer than the kernel support to the next along x (spray
    ahead is not the front), plus half a spacing (a particle stands for the water around it)."""
    x = np.sort(x)
    gaps = np.nonzero(np.diff(x) > support)[0]
    return (x[gaps[0]] if len(gaps) else x[-1]) + spacing / 2


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default="out/dam_break_front", help="directory of the plot and the run")
    ap.add_argument("--quick", action="store_true", help="coarse and short: the CI run")
    ap.add_argument("--threads", type=int, default=2, help="threads of the run (default: 2)")
    args = ap.parse_args()
    settings = SETTINGS["quick" if args.quick else "full"]

    scene = numerics.Scene.load(numerics.scenes()["dam_break_martin_moyce"])
    d = scene.to_dict()
    a, g = d["fluids"][0]["max"][0], -d["gravity"][1]
    spacing = a / settings["per_width"]
    scene.set("particles.spacing", spacing)
    support = 2 * d["particles"].get("h_over_spacing", 1.5) * spacing  # 2 h (Wendland C2)
    sim = numerics.Simulation(scene, threads=args.threads, out=args.out, quiet=True, end_time=settings["end"])

    # The front at the start, then every 0.01 s, read from the particles while the run goes.
    times, fronts = [], []

    def track(sim):
        p = sim.particles
        times.append(sim.time)
        fronts.append(surge_front(p.position[p.kind == 0, 0], support, spacing))

    track(sim)
    sim.run(until=settings["end"], every=0.01, callback=track, progress=False)

    T, Z = np.array(times) * np.sqrt(2 * g / a), np.array(fronts) / a
    T_exp, Z_exp = martin_moyce()
    reached = T_exp <= T[-1]
    Z_run = np.interp(T_exp[reached], T, Z)
    error = np.abs(Z_run - Z_exp[reached]) / Z_exp[reached]
    for t, z, z_exp in zip(T_exp[reached], Z_run, Z_exp[reached]):
        print(f"T = {t:5.3f}: Z = {z:6.3f}, experiment {z_exp:6.3f} ({(z - z_exp) / z_exp:+.3f})")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(T, Z, "-", label=f"numerics, a / {settings['per_width']}")
    ax.plot(T_exp, Z_exp, "o", label="Martin & Moyce (1952)")
    ax.set(xlabel="T = t sqrt(2 g / a)", ylabel="Z = z / a", title="Dam break: surge front")
    ax.legend()
    figure = os.path.join(args.out, "dam_break_front.png")
    fig.savefig(figure, dpi=120, bbox_inches="tight")
    print(f"figure: {figure}")
    if error.max() > settings["bound"]:
        print(f"front {error.max():.3g} from the experiment, above the bound {settings['bound']:g}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
