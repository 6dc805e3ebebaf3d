#!/usr/bin/python3
"""A viscosity sweep of 2D Poiseuille flow: the steady velocity profile read from the particles
against the analytic one, u(y) = F y (L - y) / (2 nu), for each viscosity.

    python3 poiseuille_sweep.py --out out/poiseuille_sweep [--quick]

Writes poiseuille_sweep.png in --out and prints the relative L2 error of each profile; exits 1 if
one is above the bound stated in SETTINGS (--quick: the CI run, coarser and fewer viscosities).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import numerics

# The channel is L = 1 mm wide; spacing L / 40, or L / 10 for --quick. The bound on the L2 error
# over the peak speed is the largest measured at that spacing (2026-12-05: 0.0044 at L / 40,
# 0.021 at L / 10) plus 50 %. The error comes from the
# discretisation and falls with the spacing (0.0052 at L / 25); the start-up transient left at
# the end of the run (see steady_profile) is 5e-5 of the peak.
SETTINGS = {
    "full": {"spacing": 2.5e-5, "viscosities": [0.5e-6, 1e-6, 2e-6, 4e-6], "bound": 0.0066},
    "quick": {"spacing": 1e-4, "viscosities": [1e-6, 4e-6], "bound": 0.032},
}


def channel(scene):
    """The driving force per unit mass F (the scene's gravity along x) and the width L."""
    d = scene.to_dict()
    return d["gravity"][0], d["domain"]["max"][1]


def analytic(y, force, width, nu):
    """The steady profile between no-slip plates y = 0 and y = L: u = F y (L - y) / (2 nu)."""
    return force / (2 * nu) * y * (width - y)


def steady_profile(scene, nu, spacing, threads, out):
    """Runs the channel at viscosity nu until it is steady; returns y and u of its particles."""
    force, width = channel(scene)
    scene.set("particles.spacing", spacing)
    scene.set("materials.water.viscosity", nu)
    # The peak speed sets the sound speed (the app cannot derive it from a body force).
    scene.set("physics.max_speed", analytic(width / 2, force, width, nu))
    # The start-up transient decays as exp(-pi^2 nu t / L^2): after one viscous time L^2 / nu it is
    # exp(-pi^2) = 5e-5 of the peak.
    sim = numerics.Simulation(scene, threads=threads, out=out, quiet=True, end_time=width**2 / nu)
    sim.run(progress=False)
    p = sim.particles
    fluid = p.kind == 0
    return p.position[fluid, 1].copy(), p.velocity[fluid, 0].copy()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default="out/poiseuille_sweep", help="directory of the plot and the runs")
    ap.add_argument("--quick", action="store_true", help="coarse and short: the CI run")
    ap.add_argument("--threads", type=int, default=2, help="threads of the run (default: 2)")
    args = ap.parse_args()
    settings = SETTINGS["quick" if args.quick else "full"]

    fig, ax = plt.subplots(figsize=(7, 4.5))
    worst = 0.0
    for nu in settings["viscosities"]:
        scene = numerics.Scene.load(numerics.scenes()["poiseuille_2d"])  # the shipped scene, afresh
        force, width = channel(scene)
        y, u = steady_profile(scene, nu, settings["spacing"], args.threads, os.path.join(args.out, f"nu_{nu:g}"))
        peak = analytic(width / 2, force, width, nu)
        error = np.sqrt(np.mean((u - analytic(y, force, width, nu)) ** 2)) / peak
        worst = max(worst, error)
        print(f"nu = {nu:g} m^2/s: peak {u.max():.4g} m/s (analytic {peak:.4g}), L2 error / peak {error:.2e}")
        line = np.linspace(0, width, 200)
        shown = ax.plot(line * 1e3, analytic(line, force, width, nu) * 1e6, lw=1)[0]
        ax.plot(y * 1e3, u * 1e6, ".", ms=3, color=shown.get_color(), label=f"nu = {nu:g} m²/s")
    ax.set(xlabel="y [mm]", ylabel="u [µm/s]", title="Poiseuille flow: particles (dots) and analytic (lines)")
    ax.legend()
    os.makedirs(args.out, exist_ok=True)
    figure = os.path.join(args.out, "poiseuille_sweep.png")
    fig.savefig(figure, dpi=120, bbox_inches="tight")
    print(f"figure: {figure}")
    if worst > settings["bound"]:
        print(f"L2 error / peak {worst:.3g} above the bound {settings['bound']:g}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
