#!/usr/bin/python3
"""A heated cavity (natural convection at Ra = 1e3) whose mean Nusselt number is read from the
particles as the run goes, against de Vahl Davis's (1983) benchmark value.

    python3 heated_cavity_nusselt.py --out out/heated_cavity_nusselt [--quick]

Writes heated_cavity_nusselt.png in --out and prints the Nusselt number averaged over the end of
the run, once the flow is steady; exits 1 if it is further from the benchmark than the bound
stated below (--quick: the CI run, coarser and shorter).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import numerics

# de Vahl Davis (1983), Ra = 1e3: the mean Nusselt number (as validation/cases.py states it).
NU_REFERENCE = 1.118
# |Nu - NU_REFERENCE| / NU_REFERENCE must stay under the validation's gate, 3 %
# (validation/cases.py), at both resolutions; measured with these settings (2026-12-05): 0.6 % at
# 40 x 40 (mean over t = 10 to 15 s), 0.2 % at 20 x 20 (t = 5 to 8 s). Heat carried by conduction
# alone (no flow) gives Nu = 1, 10.6 % low. The flow is steady from t = 5 s on.
SETTINGS = {
    "full": {"spacing": 0.025, "end": 15.0, "mean_from": 10.0},
    "quick": {"spacing": 0.05, "end": 8.0, "mean_from": 5.0},
}
BOUND = 0.03


def nusselt(p, spacing, width, dT, alpha):
    """Mean Nusselt number: the heat flux q_x = rho c (u T - alpha dT/dx) averaged over the fluid
    between its first and last column of particles (the conduction part from their mean
    temperatures), over alpha rho c dT / L."""
    fluid = p.kind == 0
    x, u, T = p.position[fluid, 0], p.velocity[fluid, 0], p.temperature[fluid]
    column = np.clip(np.floor(x / spacing).astype(int), 0, int(round(width / spacing)) - 1)
    first, last = column == column.min(), column == column.max()
    conduction = (T[first].mean() - T[last].mean()) / (x[last].mean() - x[first].mean()) * width / dT
    band = (x >= x[first].mean()) & (x <= x[last].mean())
    convection = np.mean(u[band] * (T[band] - T[band].mean())) * width / (alpha * dT)
    return conduction + convection


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default="out/heated_cavity_nusselt", help="directory of the plot and the run")
    ap.add_argument("--quick", action="store_true", help="coarse and short: the CI run")
    ap.add_argument("--threads", type=int, default=2, help="threads of the run (default: 2)")
    args = ap.parse_args()
    settings = SETTINGS["quick" if args.quick else "full"]

    scene = numerics.Scene.load(numerics.scenes()["natural_convection_ra1e3"])
    scene.set("particles.spacing", settings["spacing"])
    d = scene.to_dict()
    fluid = d["materials"]["fluid"]
    alpha = fluid["conductivity"] / (fluid["density"] * fluid["heat_capacity"])
    hot, cold = (d["boundaries"][side]["thermal"]["temperature"] for side in ("x_min", "x_max"))
    width = d["domain"]["max"][0]
    sim = numerics.Simulation(scene, threads=args.threads, out=args.out, quiet=True, end_time=settings["end"])

    # The Nusselt number every 0.25 s, read from the particles while the run goes.
    times, values = [], []

    def record(sim):
        times.append(sim.time)
        values.append(nusselt(sim.particles, settings["spacing"], width, hot - cold, alpha))

    sim.run(until=settings["end"], every=0.25, callback=record, progress=False)

    times, values = np.array(times), np.array(values)
    steady = times >= settings["mean_from"] - 1e-9
    mean = values[steady].mean()
    error = abs(mean - NU_REFERENCE) / NU_REFERENCE
    print(f"Nu = {mean:.4f} (mean over t = {settings['mean_from']:g} to {times[-1]:g} s); "
          f"de Vahl Davis {NU_REFERENCE}: {error:.1%} apart")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(times, values, "-", label=f"numerics, {round(width / settings['spacing'])}² particles")
    ax.axhline(NU_REFERENCE, color="k", ls="--", label="de Vahl Davis (1983)")
    ax.set(xlabel="t [s]", ylabel="mean Nusselt number", title="Heated cavity, Ra = 1e3")
    ax.legend()
    figure = os.path.join(args.out, "heated_cavity_nusselt.png")
    fig.savefig(figure, dpi=120, bbox_inches="tight")
    print(f"figure: {figure}")
    if not mean > 0 or error > BOUND:
        print(f"Nu {mean:.4g} is {error:.1%} from {NU_REFERENCE}, above the bound {BOUND:.0%}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
