#!/usr/bin/python3
"""PySPH beside the app on Lobovsky et al.'s wall pressure: PySPH's weakly-compressible scheme
(WCSPHScheme: Tait with the app's sound speed for this scene, 34.3 m/s; artificial viscosity
alpha = 0.1; delta-SPH) on the tank of scenes/validation/dam_break_pressure_lobovsky.json, its
pressure read at sensor 2 every step as the app's probe reads it (a Shepard sum over the fluid
particles within the kernel support) and measured as validation/cases.py measures the app's.

    /usr/bin/python3 validation/pysph_lobovsky.py [--dx 0.0075] [--openmp]

Needs Debian's python3-pysph. The particles stand on the app's lattice (cell centres), with three
layers of wall particles around the tank; the tank is a whole number of spacings long, 1.6125 m
at the default H / 40 instead of 1.61."""
import os
import sys

import numpy as np
import pysph_run
from pysph.base.kernels import WendlandQuintic
from pysph.solver.application import Application
from pysph.sph.scheme import WCSPHScheme

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "bench"))
import cases  # noqa: E402
import pysph_dam_break_2d as bench  # noqa: E402

G, RHO0 = bench.G, bench.RHO0
H, C0, HDX = 0.3, 34.31, 1.5  # the app's c0 and h / dx for this scene
TANK, TOP, COLUMN, SENSOR2 = 1.61, 0.6, 0.6, 0.015


class WallPressure(Application):
    def __init__(self, dx, end, **kw):
        self.dx, self.h, self.end = dx, HDX * dx, end
        self.probe = np.array([round(TANK / dx) * dx, SENSOR2])  # on the far wall's face
        self.samples = []
        super().__init__(**kw)

    def create_scheme(self):
        return WCSPHScheme(["fluid"], ["wall"], dim=2, rho0=RHO0, c0=C0, h0=self.h, hdx=HDX,
                           gy=-G, alpha=0.1, beta=0.0, gamma=7.0, delta_sph=True, delta=0.1)

    def configure_scheme(self):
        self.scheme.configure_solver(kernel=WendlandQuintic(dim=2), dt=0.125 * self.h / C0,
                                     tf=self.end, adaptive_timestep=False, pfreq=10**9)

    def create_particles(self):
        arrays = bench.lattice_tank(self.dx, self.h, (TANK, TOP), (COLUMN, H), top=True,
                                    wall_name="wall")
        self.scheme.setup_properties(arrays)
        return arrays

    def post_step(self, solver):
        f = self.particles[0]
        q = np.hypot(f.x - self.probe[0], f.y - self.probe[1]) / self.h
        near = q < 2
        w = f.m[near] / f.rho[near] * (1 - q[near] / 2) ** 4 * (2 * q[near] + 1)
        p = float(np.sum(w * f.p[near]) / np.sum(w)) if near.any() else float("nan")
        self.samples.append((solver.t, p))


def main():
    ap = pysph_run.arguments(__doc__, H / 40, "spacing [m] (H / 40 by default)")
    args = ap.parse_args()
    app = WallPressure(args.dx, 5.7 / np.sqrt(G / H), fname="lobovsky")
    pysph_run.solve_quietly(app, args.openmp)
    t, p = np.array(app.samples).T
    checks, notes, _ = cases.sensor2_figures(t * np.sqrt(G / H), p / (RHO0 * G * H))
    print(f"PySPH WCSPH, dx = {args.dx:g} m (H / {H / args.dx:g}), "
          f"{app.particles[0].get_number_of_particles()} fluid particles, {len(t)} steps")
    for c in checks:
        print(f"{c['metric']}: {c['value']:.4g} (gate {c['gate']:g})")
    print(notes)


if __name__ == "__main__":
    main()
