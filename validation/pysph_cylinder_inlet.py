#!/usr/bin/python3
"""PySPH's own inlet and outlet on Schaefer & Turek's (1996) benchmarks 2D-1 (Re 20) and 2D-2 (Re 100),
the set-ups of scenes/validation/cylinder_re20.json and cylinder_re100.json: PySPH's flow_past_cylinder_2d example (its WindTunnel
application, subclassed here) with its EDAC scheme (EDACScheme with p_b = p0 = rho0 c0^2, i.e. the
transport-velocity variant; QuinticSpline, h = 1.2 dx) and its inlet-outlet manager
(pysph.sph.bc, the example's default 'donothing' method; --io-method takes the example's others),
on a channel [0, 2.2] x [0, 0.41] m with the cylinder D = 0.1 m centred at (0.2, 0.2), the inflow
u = 4 U_m y (H - y) / H^2 (Re 20: U_m = 0.3 m/s, mean U = 0.2 m/s; Re 100: U_m = 1.5 m/s, U = 1 m/s)
at x = 0, the outflow at x = 2.2 m, rho0 = 1000, nu = 1e-3 m^2/s (Re = U D / nu) and the app's sound
speed c0 = 10 U_m.

    /usr/bin/python3 validation/pysph_cylinder_inlet.py [--re 20|100] [--dx 0.01] [--openmp]

Needs Debian's python3-pysph. What differs from the example: the geometry and the parabolic inflow
(an equation like the example's ResetInletVelocity that sets u(y) on the inlet and -u(y) on its
mirror ghost), the fluid, inlet and outlet starting with the inflow profile, the channel walls
no-slip (EDAC 'solids', where the example makes them inviscid), c0 = 10 U_m and the example's step
min(0.25 h / (c0 + U_m), 0.125 h^2 / nu). The example's frame is centred on the channel's axis, so
its y is the benchmark's y - H / 2. The cylinder is made of the lattice points (cell centres
(i + 1/2) dx, as the app) inside the circle and the fluid of those outside (--cylinder rings takes
the example's concentric rings instead, whose outer ring lies on the circle). The outlet is the
example's: no pressure is imposed there (its particles keep what they carried out, or get it
from the method), where the benchmark holds p = 0 at x = 2.2 m.

Every 0.02 s of simulated time (Re 100: 0.005 s, as the scene's probes) the force on the cylinder
is evaluated as the example's post-processing does (_plot_force_vs_t): on copies of the fluid and the cylinder, their number
density and density by summation over both, the cylinder's ghost velocity (SetWallVelocity), and
F = sum over the cylinder of m a with TVF's MomentumEquationPressureGradient (p_b = p0) and the
example's SolidWallNoSlipBCReverse from the fluid. c_D = 2 F_x / (rho0 U^2 D), c_L = 2 F_y /
(rho0 U^2 D). Re 20: reported as means over the last 3 s of the 5 s (as validation/cases.py reads
the app's); a run stopped early by --max-wall is averaged over the last 40 % of the time it
reached, and says so. Re 100 (6 s): the Strouhal number and the largest c_D and c_L over the last
2 s, read by validation/cases.py's shedding_figures as the app's."""
import os
import time

# OpenMP threads that spin while they wait make a step ten times slower on a loaded machine; set
# before PySPH loads the OpenMP runtime.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

import cases  # noqa: E402
import numpy as np  # noqa: E402
import pysph_run  # noqa: E402
from pysph.base.kernels import QuinticSpline  # noqa: E402
from pysph.base.utils import get_particle_array  # noqa: E402
from pysph.examples import flow_past_cylinder_2d as example  # noqa: E402
from pysph.sph.equation import Equation, Group  # noqa: E402
from pysph.sph.wc.edac import EDACScheme  # noqa: E402
from pysph.sph.wc.transport_velocity import (  # noqa: E402
    MomentumEquationPressureGradient, SetWallVelocity, SummationDensity)
from pysph.tools.sph_evaluator import SPHEvaluator  # noqa: E402

LENGTH, HEIGHT, DIAMETER, CENTRE = 2.2, 0.41, 0.1, (0.2, 0.2)
RHO0, NU = 1000.0, 1e-3
HDX = 1.2  # the example's h / dx
REFERENCE_CD, REFERENCE_CL = 5.5795, 0.0106  # 2D-1


class Flow:
    """The benchmark's numbers at Reynolds number re (20: 2D-1, 100: 2D-2)."""

    def __init__(self, re):
        self.re = re
        self.umax = 0.3 if re == 20 else 1.5  # U_m, the inflow's largest speed
        self.umean = 2.0 * self.umax / 3.0  # the benchmark's U
        self.c0 = 10 * self.umax  # the app's sound speed for these scenes
        self.p0 = RHO0 * self.c0**2  # the example's p_b = p0
        self.every = 0.02 if re == 20 else 0.005  # force sampling interval [s], as the scene's probes
        self.end = 5.0 if re == 20 else 6.0  # the scene's end time [s]

    def coefficient(self, f):
        """2 F / (rho0 U^2 D)."""
        return 2.0 * f / (RHO0 * self.umean**2 * DIAMETER)
# arrays of the force evaluation need these (the example's list)
FORCE_PROPS = ['awhat', 'auhat', 'avhat', 'wg', 'vg', 'ug', 'V', 'uf', 'vf', 'wf', 'wij',
               'vmag', 'pavg', 'nnbr', 'auf', 'avf', 'awf']


def inflow(y, umax):
    """u = 4 U_m y (H - y) / H^2 at the example's y (the benchmark's y - H / 2)."""
    yb = y + HEIGHT / 2
    return 4 * umax * yb * (HEIGHT - yb) / HEIGHT**2


class ParabolicInletVelocity(Equation):
    """The example's ResetInletVelocity with the benchmark's profile: u = sign 4 U_m y (H - y) /
    H^2 (sign -1 on the inlet's mirror ghost, as the example's -U), v = w = 0."""

    def __init__(self, dest, sources, umax, height, sign):
        self.umax, self.height, self.sign = umax, height, sign
        super().__init__(dest, sources)

    def loop(self, d_idx, d_u, d_v, d_w, d_y, d_uref):
        yb = d_y[d_idx] + 0.5 * self.height
        if d_idx == 0:
            d_uref[0] = self.umax
        d_u[d_idx] = self.sign * 4.0 * self.umax * yb * (self.height - yb) / \
            (self.height * self.height)
        d_v[d_idx] = 0.0
        d_w[d_idx] = 0.0


class Benchmark(example.WindTunnel):
    """PySPH's WindTunnel example on the benchmark's channel."""

    def __init__(self, flow, dx, end, io_method, cylinder, max_wall, **kw):
        self.flow, self.bench_dx, self.end, self.bench_io = flow, dx, end, io_method
        self.cylinder, self.max_wall = cylinder, max_wall
        self.samples, self.next_sample, self.start = [], 0.0, time.time()
        self.force_eval = None
        super().__init__(**kw)

    def consume_user_options(self):
        """The example's consume_user_options with the benchmark's numbers (its own options,
        --re, --nx, --lt, ..., are not read)."""
        self.dc = DIAMETER
        self.Lt, self.Wt = LENGTH, HEIGHT / 2
        self.io_method = self.bench_io
        self.nu = NU
        self.cxy = CENTRE[0], CENTRE[1] - HEIGHT / 2
        self.dx = dx = self.bench_dx
        self.volume = dx * dx
        self.nl = int(6.0 * HDX)
        self.h = h = HDX * dx
        self.dt = min(0.25 * h / (self.flow.c0 + self.flow.umax), 0.125 * h**2 / NU)
        self.tf = self.end

    def create_scheme(self):
        """The example's EDACScheme, with c0 = 10 U_m and the channel walls no-slip."""
        return EDACScheme(['fluid'], ['solid', 'wall'], dim=2, rho0=RHO0, c0=self.flow.c0, h=None,
                          pb=self.flow.p0,
                          nu=None, inlet_outlet_manager=None)

    def _create_fluid(self):
        fluid = super()._create_fluid()
        fluid.u[:] = inflow(fluid.y, self.flow.umax)
        return fluid

    def _create_inlet(self):
        inlet = super()._create_inlet()
        inlet.u[:] = inflow(inlet.y, self.flow.umax)
        return inlet

    def _create_outlet(self):
        outlet = super()._create_outlet()
        outlet.u[:] = outlet.uhat[:] = inflow(outlet.y, self.flow.umax)
        return outlet

    def _create_solid(self):
        if self.cylinder == 'rings':  # the example's rings, moved to the cylinder's y
            solid = super()._create_solid()
            solid.y[:] += self.cxy[1]
            return solid
        dx = self.dx
        x, y = np.mgrid[dx / 2:self.Lt:dx, -self.Wt + dx / 2:self.Wt:dx]  # the fluid's lattice
        x, y = x.ravel(), y.ravel()
        inside = np.hypot(x - self.cxy[0], y - self.cxy[1]) < self.dc / 2
        return get_particle_array(name='solid', x=x[inside], y=y[inside], m=dx * dx * RHO0,
                                  rho=RHO0, h=self.h, V=1.0 / (dx * dx))

    def create_particles(self):
        particles = super().create_particles()
        if self.io_method == 'hybrid':  # the example sets these to its uniform inflow
            arrays = {pa.name: pa for pa in particles}
            fluid, outlet = arrays['fluid'], arrays['outlet']
            u = inflow(fluid.y, self.flow.umax)
            fluid.uag[:] = np.repeat(u, fluid.uag.size // max(u.size, 1))
            fluid.uta[:] = u
            outlet.uta[:] = inflow(outlet.y, self.flow.umax)
        return particles

    def _get_io_info(self):
        inlet_info, outlet_info, manager = super()._get_io_info()
        inlet_info.equations = [
            ParabolicInletVelocity('ghost_inlet', [], umax=self.flow.umax, height=HEIGHT, sign=-1.0),
            ParabolicInletVelocity('inlet', [], umax=self.flow.umax, height=HEIGHT, sign=1.0)]
        inlet_info.umax = self.flow.umax
        return inlet_info, outlet_info, manager

    def post_step(self, solver):
        super().post_step(solver)
        if solver.t < self.next_sample - 1e-9:
            return
        self.next_sample += self.flow.every
        fx, fy = self.force()
        self.samples.append((solver.t, fx, fy))
        if solver.t > 0.25 and round(solver.t / self.flow.every) % round(0.5 / self.flow.every) == 0:
            s = np.array([row for row in self.samples if row[0] > solver.t - 0.5 + 1e-9])
            print(f"t = {solver.t:5.2f} s, wall {time.time() - self.start:6.0f} s, "
                  f"{self.particles[0].get_number_of_particles()} fluid, last 0.5 s: c_D "
                  f"{self.flow.coefficient(s[:, 1].mean()):.4f}, "
                  f"c_L {self.flow.coefficient(s[:, 2].mean()):+.4f}",
                  flush=True)
        if self.max_wall and time.time() - self.start > self.max_wall:
            print(f"stopping at t = {solver.t:.3f} s: --max-wall {self.max_wall:g} s reached",
                  flush=True)
            solver.tf = solver.t

    def force(self):
        """(F_x, F_y) on the cylinder [N/m], as the example's _plot_force_vs_t, on copies."""
        arrays = {pa.name: pa for pa in self.particles}
        fluid, solid = (arrays[n].extract_particles(
            np.arange(arrays[n].get_number_of_particles())) for n in ('fluid', 'solid'))
        for pa in (fluid, solid):
            for p in FORCE_PROPS:
                pa.add_property(p)
        if self.force_eval is None:
            equations = [
                Group(equations=[
                    SummationDensity(dest='fluid', sources=['fluid', 'solid']),
                    SummationDensity(dest='solid', sources=['fluid', 'solid']),
                    SetWallVelocity(dest='solid', sources=['fluid'])], real=False),
                Group(equations=[
                    MomentumEquationPressureGradient(dest='solid', sources=['fluid'], pb=self.flow.p0),
                    example.SolidWallNoSlipBCReverse(dest='solid', sources=['fluid'], nu=NU)],
                    real=True)]
            self.force_eval = SPHEvaluator(arrays=[solid, fluid], equations=equations, dim=2,
                                           kernel=QuinticSpline(dim=2))
        self.force_eval.update_particle_arrays([solid, fluid])
        self.force_eval.evaluate()
        fx = float(np.sum(solid.m * solid.au) + np.sum(solid.m * solid.auf))
        fy = float(np.sum(solid.m * solid.av) + np.sum(solid.m * solid.avf))
        return fx, fy


def describe(app, reached):
    """The run: scheme, spacing, step and the particles at the end."""
    arrays = {pa.name: pa for pa in app.particles}
    counts = ", ".join(f"{n} {pa.get_number_of_particles()}" for n, pa in arrays.items())
    print(f"PySPH {__import__('pysph').__version__} EDACScheme (TVF, p_b = {app.flow.p0:g} Pa), "
          f"Re {app.flow.re}, inlet/outlet '{app.io_method}', cylinder '{app.cylinder}', "
          f"dx = {app.dx:g} m (D / dx = {DIAMETER / app.dx:g}), h = {app.h:g} m, "
          f"dt = {app.dt:.4g} s, {app.solver.count} steps to t = {reached:.4g} s")
    print(f"particles at the end: {counts}")


def report_steady(app, t, fx, fy, end):
    """2D-1: c_D and c_L as means over the last 3 s, and over each second."""
    coefficient, reached = app.flow.coefficient, app.solver.t
    if reached >= end - 1e-6:
        a, how = reached - 3.0, "last 3 s"
    else:
        a = 0.6 * reached
        how = f"last 40 % of the {reached:.3f} s reached (stopped before {end:g} s)"
    w = t >= a - 1e-9
    cd, cl = coefficient(fx[w].mean()), coefficient(fy[w].mean())
    print(f"{how}, t in [{a:.3f}, {reached:.3f}] s: c_D {cd:.4f} ({100 * (cd / REFERENCE_CD - 1):+.1f} % "
          f"against {REFERENCE_CD}), c_L {cl:+.4f} (reference {REFERENCE_CL}); "
          f"F_x {fx[w].mean():.4f} N/m, F_y {fy[w].mean():+.4f} N/m")
    for b in np.arange(0.0, reached - 1e-9, 1.0):
        v = (t >= b - 1e-9) & (t < b + 1.0 - 1e-9)
        print(f"  t in [{b:g}, {b + 1:g}): c_D {coefficient(fx[v].mean()):.4f}, "
              f"c_L {coefficient(fy[v].mean()):+.4f}")


def report_shedding(app, t, fx, fy):
    """2D-2: the Strouhal number and the largest c_D and c_L, as validation/cases.py reads the
    app's (cases.shedding_figures)."""
    coefficient = app.flow.coefficient
    checks, notes, _ = cases.shedding_figures(t, coefficient(fx), coefficient(fy),
                                              DIAMETER / app.flow.umean, f"D / dx {DIAMETER / app.dx:g}")
    print(notes)
    for c in checks:
        print(f"  {c['metric']}: {c['value']:.4f} (gate {c['gate']:g})")


def report(app, seconds, args):
    s = np.array(app.samples)
    t, fx, fy = s[:, 0], s[:, 1], s[:, 2]
    describe(app, app.solver.t)
    if app.flow.re == 20:
        report_steady(app, t, fx, fy, args.end)
    else:
        report_shedding(app, t, fx, fy)
    print(f"wall time {seconds:.0f} s (PySPH's code generation included)")


def main():
    ap = pysph_run.arguments(__doc__, 0.01, "spacing [m] (D / 10 by default)")
    ap.add_argument("--re", type=int, default=20, choices=[20, 100],
                    help="Reynolds number: 20 (2D-1, steady) or 100 (2D-2, shedding)")
    ap.add_argument("--end", type=float, help="end time [s] (the scene's: 5 at Re 20, 6 at Re 100)")
    ap.add_argument("--io-method", default="donothing",
                    choices=["donothing", "mirror", "hybrid", "mod_donothing", "characteristic"],
                    help="the example's inlet/outlet method (its default: donothing)")
    ap.add_argument("--cylinder", default="lattice", choices=["lattice", "rings"])
    ap.add_argument("--max-wall", type=float, default=0.0,
                    help="stop after this many seconds of wall time (0: never)")
    args = ap.parse_args()
    flow = Flow(args.re)
    args.end = args.end or flow.end
    start = time.time()
    app = Benchmark(flow, args.dx, args.end, args.io_method, args.cylinder, args.max_wall,
                    fname=f"cylinder_inlet_re{args.re}")
    pysph_run.solve_quietly(app, args.openmp, prepare=lambda a: setattr(a, "start", time.time()))
    report(app, time.time() - start, args)


if __name__ == "__main__":
    main()
