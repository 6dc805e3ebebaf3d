#!/usr/bin/python3
"""PySPH beside the app on the cylinder in a channel at Re = 20: PySPH's transport-velocity
formulation (TVFScheme, Adami, Hu & Adams 2013: QuinticSpline, h = 1.2 dx, p0 = pb = rho0 c0^2
with the app's sound speed for this scene, c0 = 3 m/s) on the set-up of
scenes/validation/cylinder_re20_periodic.json, its drag measured as validation/cases.py (cylinder_drag)
measures the app's: c_D = 2 F / (rho0 U^2 D), F = F_x + rho0 g_x pi D^2 / 4, F_x and U means
over the last 2 s.

    /usr/bin/python3 validation/pysph_cylinder_re20.py [--dx 0.005] [--openmp]

Needs Debian's python3-pysph. The channel, 1 m long and periodic along x, has four layers of
wall particles below y = 0 and above y = 0.41; the particles stand on the app's lattice (cell
centres), those inside the circle forming the fixed cylinder. Every 0.02 s of simulated time F_x
is evaluated with the scheme's own cylinder terms (as PySPH's periodic_cylinders example does):
on a copy of the fluid, its density, pressure and volume at the current positions, the
cylinder's pressure and no-slip velocity from them, and F_x = -sum_i m_i a_i over the fluid of
the pressure and viscous accelerations due to the cylinder alone. U is the mean velocity, the
flux over the height, as the app's case reads it: here Q / H = sum_i V_i u_i / (L H) over all the
fluid (V_i = m_i / rho_i; the flux is the same through every section). The body force g_x is the
scene's."""
import json
import math
import os
import sys
import time

# OpenMP threads that spin while they wait make a step ten times slower on a loaded machine; set
# before PySPH loads the OpenMP runtime.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

import numpy as np  # noqa: E402
import pysph_run  # noqa: E402
from pysph.base.kernels import QuinticSpline
from pysph.base.nnps import DomainManager
from pysph.base.utils import get_particle_array
from pysph.solver.application import Application
from pysph.sph.equation import Group
from pysph.sph.scheme import TVFScheme
from pysph.sph.wc.transport_velocity import (
    MomentumEquationPressureGradient, SetWallVelocity, SolidWallNoSlipBC, SolidWallPressureBC,
    StateEquation, SummationDensity)
from pysph.tools.sph_evaluator import SPHEvaluator

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cases  # noqa: E402

LENGTH, HEIGHT, DIAMETER, CENTRE = 1.0, 0.41, 0.1, (0.5, 0.2)
RHO0, NU = 1000.0, 1e-3
with open(os.path.join(cases.SCENES, "cylinder_re20_periodic.json")) as _scene:
    G_X = float(json.load(_scene)["gravity"][0])  # the scene's body force [m/s^2]
PROFILE, U_MAX = 7.138607971, 0.3  # initial u = PROFILE y (H - y), its largest value
C0, HDX = 3.0, 1.2  # the app's c0 (10 x physics.max_speed); PySPH's h / dx for TVF
P0 = RHO0 * C0**2  # p0 = pb, as PySPH's periodic_cylinders example
WALL_LAYERS = math.ceil(3 * HDX)  # the quintic spline reaches 3 h
EVERY, WINDOW = 0.02, 2.0  # sampling interval and averaging window [s], as the app's case
DISPLACED = RHO0 * G_X * math.pi * DIAMETER**2 / 4  # rho0 g_x V [N/m]


class CylinderChannel(Application):
    def __init__(self, dx, end, **kw):
        self.dx, self.h, self.end = dx, HDX * dx, end
        self.samples, self.next_sample, self.force = [], 0.0, None
        super().__init__(**kw)

    def create_domain(self):
        return DomainManager(xmin=0.0, xmax=LENGTH, periodic_in_x=True)

    def create_scheme(self):
        return TVFScheme(["fluid"], ["wall", "cylinder"], dim=2, rho0=RHO0, c0=C0, nu=NU, p0=P0,
                         pb=P0, h0=self.h, gx=G_X)

    def configure_scheme(self):
        self.scheme.configure_solver(kernel=QuinticSpline(dim=2), dt=self.time_step(),
                                     tf=self.end, n_damp=100, pfreq=10**9)

    def time_step(self):
        """PySPH's example's step: the least of 0.25 h / (c0 + u_max), 0.125 h^2 / nu and
        0.25 sqrt(h / g_x)."""
        return min(0.25 * self.h / (C0 + U_MAX), 0.125 * self.h**2 / NU,
                   0.25 * np.sqrt(self.h / G_X))

    def create_particles(self):
        arrays = lattice_channel(self.dx, self.h)
        self.scheme.setup_properties(arrays)
        for pa in arrays:
            pa.V[:] = 1.0 / self.dx**2  # number density; recomputed for the fluid
        return arrays

    def post_step(self, solver):
        if solver.t < self.next_sample - 1e-9:
            return
        self.next_sample += EVERY
        fluid = real(self.particles[0])
        flux = float(np.sum(fluid.m / fluid.rho * fluid.u)) / (LENGTH * HEIGHT)
        fx, fy = self.force.on_cylinder(fluid, solver.t, solver.dt)  # changes the copy's rho
        self.samples.append((solver.t, fx, fy, flux))
        if round(solver.t / EVERY) % round(1.0 / EVERY) == 0:
            self.progress(solver.t)

    def progress(self, t):
        """One line on the last second of samples: their mean F_x, U and the c_D of these."""
        s = np.array([row for row in self.samples if row[0] > t - 1.0 + 1e-9])
        F, U = s[:, 1].mean(), s[:, 3].mean()
        print(f"t = {t:5.2f} s, last second: F_x {F:8.4f} N/m, U {U:.5f} m/s, "
              f"c_D {drag_coefficient(F, U):.4f}", flush=True)


def real(pa):
    """A copy of the particle array without the periodic ghosts that PySPH appends to it."""
    return pa.extract_particles(np.flatnonzero(pa.tag == 0))


def lattice_channel(dx, h):
    """The app's lattice (cell centres) as PySPH particle arrays [fluid, wall, cylinder]: fluid in
    [0, L] x [0, H] outside the circle, WALL_LAYERS layers of wall below and above, and the
    cylinder made of the lattice points inside the circle."""
    nx, ny = round(LENGTH / dx), round(HEIGHT / dx)
    ix, iy = np.meshgrid(np.arange(nx), np.arange(-WALL_LAYERS, ny + WALL_LAYERS))
    x, y = (ix.ravel() + 0.5) * dx, (iy.ravel() + 0.5) * dx
    wall = (y < 0) | (y > HEIGHT)
    inside = np.hypot(x - CENTRE[0], y - CENTRE[1]) < DIAMETER / 2
    fluid = ~wall & ~inside
    m = RHO0 * dx * dx
    return [get_particle_array(name="fluid", x=x[fluid], y=y[fluid], h=h, m=m, rho=RHO0,
                               u=PROFILE * y[fluid] * (HEIGHT - y[fluid])),
            get_particle_array(name="wall", x=x[wall], y=y[wall], h=h, m=m, rho=RHO0),
            get_particle_array(name="cylinder", x=x[inside], y=y[inside], h=h, m=m, rho=RHO0)]


class CylinderForce:
    """The force of the fluid on the cylinder, evaluated with the TVF scheme's terms between the
    fluid and the cylinder on a copy of the fluid (the run's own arrays stay untouched)."""

    def __init__(self, fluid, cylinder, h):
        self.cylinder = real(cylinder)
        eqs = [Group([SummationDensity(dest="fluid", sources=["fluid", "cylinder"])], real=False),
               Group([StateEquation(dest="fluid", sources=None, p0=P0, rho0=RHO0, b=1.0),
                      SetWallVelocity(dest="cylinder", sources=["fluid"])], real=False),
               Group([SolidWallPressureBC(dest="cylinder", sources=["fluid"], b=1.0, rho0=RHO0,
                                          p0=P0, gx=G_X)], real=False),
               Group([MomentumEquationPressureGradient(dest="fluid", sources=["cylinder"], pb=P0),
                      SolidWallNoSlipBC(dest="fluid", sources=["cylinder"], nu=NU)], real=True)]
        self.evaluator = SPHEvaluator([real(fluid), self.cylinder], eqs, dim=2,
                                      kernel=QuinticSpline(dim=2))

    def on_cylinder(self, f, t, dt):
        """(F_x, F_y) per unit depth [N/m]: minus the fluid's momentum change due to the cylinder
        (gravity left out, g = 0 in the momentum equation)."""
        self.evaluator.update_particle_arrays([f, self.cylinder])  # f: a copy, changed here
        self.evaluator.evaluate(t, dt)
        return -float(np.sum(f.m * f.au)), -float(np.sum(f.m * f.av))


def drag_coefficient(fx, U):
    """c_D = 2 F / (rho0 U^2 D) with F = F_x + rho0 g_x V, as validation/cases.py (cylinder_drag):
    the force the benchmark's pressure-driven flow exerts, p* = p - rho0 g_x x adding rho0 g_x V
    (V = pi D^2 / 4) to the force of p."""
    return 2 * (fx + DISPLACED) / (RHO0 * U**2 * DIAMETER)


def report(app, seconds):
    s = np.array(app.samples)
    t, fx, fy, U = s[:, 0], s[:, 1], s[:, 2], s[:, 3]
    last = t >= t[-1] - WINDOW - 1e-9
    F, Um = fx[last].mean(), U[last].mean()
    print(f"PySPH TVF, dx = {app.dx:g} m (D / dx = {DIAMETER / app.dx:g}), "
          f"{real(app.particles[0]).get_number_of_particles()} fluid particles, dt = "
          f"{app.time_step():.4g} s, {app.solver.count} steps to t = {app.solver.t:.4g} s")
    print(f"last {WINDOW:g} s: c_D {drag_coefficient(F, Um):.4f} at Re {Um * DIAMETER / NU:.3f} "
          f"(U {Um:.5f} m/s, F = F_x + rho g V = {F:.4f} + {DISPLACED:.4f} N/m, "
          f"lift {fy[last].mean():+.4f} N/m)")
    for a in np.arange(0.0, t[-1] - 1e-9, WINDOW):
        w = (t >= a - 1e-9) & (t < a + WINDOW - 1e-9)
        Fw, Uw = fx[w].mean(), U[w].mean()
        print(f"  t in [{a:g}, {a + WINDOW:g}): c_D {drag_coefficient(Fw, Uw):.4f}, "
              f"U {Uw:.5f} m/s, F_x {Fw:.4f} N/m")
    print(f"wall time {seconds:.0f} s (PySPH's code generation included)")


def main():
    ap = pysph_run.arguments(__doc__, 0.005, "spacing [m] (D / 20 by default)")
    ap.add_argument("--end", type=float, default=10.0, help="end time [s] (the scene's 10)")
    args = ap.parse_args()
    start = time.time()
    app = CylinderChannel(args.dx, args.end, fname="cylinder_re20")
    pysph_run.solve_quietly(app, args.openmp, prepare=lambda a: setattr(
        a, "force", CylinderForce(a.particles[0], a.particles[2], a.h)))
    report(app, time.time() - start)


if __name__ == "__main__":
    main()
