"""PySPH application mirroring bench scene dam_break_2d: a 1 m x 2 m water column in a
4 m x 4 m tank, h = 1.3 dx, Wendland C2 kernel (PySPH's WendlandQuintic), Tait EOS with
c0 = 10 sqrt(2 g H), artificial viscosity alpha = 0.1, delta-SPH density diffusion.

Unlike PySPH's own dam_break_2d example, h and the particle mass follow --dx. Prints one line
'fluid_particles=N steps=S seconds=T' where T times the solver loop only (the one-time
compilation of the generated code happens in setup and is excluded).

Usage: /usr/bin/python3 pysph_dam_break_2d.py --dx 0.01 (--steps 100 | --time 0.05) [--openmp]
"""
import argparse
import sys
import time

import numpy as np
from pysph.base.kernels import WendlandQuintic
from pysph.sph.scheme import WCSPHScheme
from pysph.solver.application import Application
from pysph.base.utils import get_particle_array

G = 9.81
RHO0 = 1000.0
H_COLUMN = 2.0
C0 = 10.0 * np.sqrt(2.0 * G * H_COLUMN)
HDX = 1.3


class DamBreakBench(Application):
    def __init__(self, dx, steps, end_time=None, pfreq=10**9, **kw):
        self.dx = dx
        self.h = HDX * dx
        self.steps = steps
        self.end_time = end_time
        self.pfreq = pfreq  # particle files every pfreq steps (by default none but the first)
        super().__init__(**kw)

    def create_scheme(self):
        return WCSPHScheme(['fluid'], ['boundary'], dim=2, rho0=RHO0, c0=C0, h0=self.h,
                           hdx=HDX, gy=-G, alpha=0.1, beta=0.0, gamma=7.0,
                           delta_sph=True, delta=0.1)

    def configure_scheme(self):
        dt = 0.125 * self.h / C0
        self.scheme.configure_solver(kernel=WendlandQuintic(dim=2), dt=dt,
                                     tf=self.end_time or dt * self.steps,
                                     adaptive_timestep=False,
                                     pfreq=self.pfreq)

    def create_particles(self):
        # A 1 m x 2 m column in a 4 m x 4 m tank, open at the top, so both codes step exactly
        # the same particles.
        arrays = lattice_tank(self.dx, self.h, (4.0, 4.0), (1.0, H_COLUMN), top=False)
        self.scheme.setup_properties(arrays)
        return arrays


def lattice_tank(dx, h, tank, column, top, wall_name='boundary', layers=3):
    """numerics' lattice (cell centres, x = (i + 1/2) dx) as PySPH particle arrays [fluid,
    walls]: a column [0, column[0]] x [0, column[1]] of fluid, and `layers` layers of wall
    particles outside the left, right and bottom sides of the tank [0, tank[0]] x [0, tank[1]]
    (and above it when top)."""
    nx, ny = int(round(tank[0] / dx)), int(round(tank[1] / dx))
    ix, iy = np.meshgrid(np.arange(-layers, nx + layers),
                         np.arange(-layers, ny + (layers if top else 0)))
    ix, iy = ix.ravel(), iy.ravel()
    wall = (ix < 0) | (ix >= nx) | (iy < 0) | (iy >= ny)
    jx, jy = np.meshgrid(np.arange(int(round(column[0] / dx))),
                         np.arange(int(round(column[1] / dx))))
    m = RHO0 * dx * dx
    fluid = get_particle_array(name='fluid', x=(jx.ravel() + 0.5) * dx, y=(jy.ravel() + 0.5) * dx,
                               h=h, m=m, rho=RHO0)
    walls = get_particle_array(name=wall_name, x=(ix[wall] + 0.5) * dx, y=(iy[wall] + 0.5) * dx,
                               h=h, m=m, rho=RHO0)
    return [fluid, walls]


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--dx', type=float, default=0.01)
    p.add_argument('--steps', type=int, default=100)
    p.add_argument('--time', type=float, default=None,
                   help='simulated time [s] (instead of --steps)')
    p.add_argument('--openmp', action='store_true')
    args, rest = p.parse_known_args()
    app = DamBreakBench(args.dx, args.steps, args.time, fname='pysph_bench')
    argv = ['--disable-output', '-q'] + (['--openmp'] if args.openmp else []) + rest
    app.setup(argv)
    n_fluid = app.particles[0].get_number_of_particles()
    start = time.perf_counter()
    app.solver.solve(show_progress=False)
    seconds = time.perf_counter() - start
    n_all = n_fluid + app.particles[1].get_number_of_particles()
    print(f"fluid_particles={n_fluid} particles={n_all} steps={app.solver.count} "
          f"seconds={seconds:.6f} particle_steps_per_second={n_fluid * app.solver.count / seconds:.4e}")


if __name__ == '__main__':
    sys.exit(main())
