#!/usr/bin/python3
"""PySPH beside the app on the piston wave maker: PySPH's EDAC scheme (EDACScheme, Ramachandran &
Puri 2019, its external-flow form with p_b = 0, Adami, Hu & Adams 2012 walls) on the set-up of
scenes/validation/piston_waves_2d.json, its wave height measured as validation/cases.py
(piston_waves) measures the app's: H crest to trough in each period of 3-5 s at x = 1.0 and
1.5 m, the mean over periods and probes, against Biesel's linear theory (H / S = 1.535,
H = 0.06139 m).

    /usr/bin/python3 validation/pysph_piston_waves.py [--dx 0.02] [--openmp] [--alpha 0.02]

Needs Debian's python3-pysph. The scene's tank (4 m long, walls at x = 0, x = 4 and y = 0, open
top, domain height 0.7 m) has three layers of wall particles outside it (the Wendland C2 kernel
at h = 1.5 dx reaches 3 dx), the water (0.08 <= x <= 4, 0 <= y <= 0.4) starts at rest with
hydrostatic pressure, and the piston is the scene's box 0.04 <= x <= 0.08, 0 <= y <= 0.6; all
particles stand on the app's lattice (cell centres). Kernel, h / dx, sound speed (c0 = 15 m/s,
10 x physics.max_speed) and artificial viscosity (alpha = 0.02, PySPH's
MomentumEquationArtificialViscosity, Monaghan's form as the app's) are the app's; the step is
PySPH's examples' 0.125 h / c0 (PEC integrator). The piston is a solid of the scheme (its
pressure from the wall condition, with the piston's acceleration, Adami et al. eq. 27; no-slip
through 2 u_w - u~). It moves by a post-stage callback: after each integrator stage, before the
forces at that stage's time t are evaluated, its particles are set to x0 + X(t) with velocity
u(t) = 0.02 * 2 pi cos(2 pi t) min(t, 1) (the scene's) and acceleration du/dt, X(t) the exact
integral of u (0.02 t sin(2 pi t) + 0.01 (cos(2 pi t) - 1) / pi up to t = 1, 0.02 sin(2 pi t)
after). The surface elevation is the app's reading (cases.surface_elevation: the fluid's areas
weighted by the 1D Wendland C2 kernel of support 3 dx around the probe, minus the still depth)
every 0.02 s, the app's output interval; the areas are m / rho0 = dx^2, since the EDAC scheme's
density is a kernel sum, short of rho0 near the surface (it is not the particle's volume there).
As a cross-check the height of the highest fluid particle within dx of the probe is read too."""
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
from pysph.base.kernels import WendlandQuintic  # noqa: E402
from pysph.base.utils import get_particle_array  # noqa: E402
from pysph.solver.application import Application  # noqa: E402
from pysph.sph.wc.edac import EDACScheme  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cases  # noqa: E402

with open(os.path.join(cases.SCENES, "piston_waves_2d.json")) as _scene:
    SCENE = json.load(_scene)
RHO0 = float(SCENE["materials"]["water"]["density"])
NU = float(SCENE["materials"]["water"]["viscosity"])
G_Y = float(SCENE["gravity"][1])
LENGTH, HEIGHT = (float(v) for v in SCENE["domain"]["max"])
FLUID_MIN, FLUID_MAX = SCENE["fluids"][0]["min"], SCENE["fluids"][0]["max"]
PISTON_MIN, PISTON_MAX = SCENE["bodies"][0]["min"], SCENE["bodies"][0]["max"]
C0 = 10 * float(SCENE["physics"]["max_speed"])  # the app's sound speed, 15 m/s
END = float(SCENE["time"]["end"])
EVERY = float(SCENE["output"]["every"])  # the app's output interval, 0.02 s
P = cases.PISTON
DEPTH = P["depth"]
AMPLITUDE, OMEGA = P["stroke"] / 2, 2 * math.pi / P["period"]  # 0.02 m, 2 pi / s; ramp over 1 period
HDX = 1.5  # the app's h / dx (Wendland C2)
WALL_LAYERS = math.ceil(2 * HDX - 1e-9)  # the kernel reaches 2 h = 3 dx
ALPHA = 0.02  # the app's artificial viscosity for this scene


def piston_motion(t):
    """(X, u, a): displacement, velocity and acceleration of the piston at time t, for the
    scene's u(t) = A omega cos(omega t) min(t / T, 1) (A = 0.02 m, T = 1 s)."""
    T = P["period"]
    c, s = math.cos(OMEGA * t), math.sin(OMEGA * t)
    if t < T:
        r = t / T
        X = AMPLITUDE * (r * s + (c - 1) / (OMEGA * T))
        u = AMPLITUDE * OMEGA * c * r
        a = AMPLITUDE * OMEGA * (c / T - OMEGA * s * r)
    else:
        X, u, a = AMPLITUDE * s, AMPLITUDE * OMEGA * c, -AMPLITUDE * OMEGA**2 * s
    return X, u, a


class PistonWaves(Application):
    def __init__(self, dx, alpha, **kw):
        self.dx, self.h, self.alpha = dx, HDX * dx, alpha
        self.samples, self.next_sample, self.piston_x0 = [], 0.0, None
        super().__init__(**kw)

    def create_scheme(self):
        return EDACScheme(["fluid"], ["wall", "piston"], dim=2, c0=C0, nu=NU, rho0=RHO0,
                          pb=0.0, gy=G_Y, h=self.h, alpha=self.alpha, clamp_p=True)

    def configure_scheme(self):
        self.scheme.configure_solver(kernel=WendlandQuintic(dim=2), dt=self.time_step(), tf=END,
                                     pfreq=10**9)

    def time_step(self):
        """PySPH's EDAC examples' step, 0.125 h / c0."""
        return 0.125 * self.h / C0

    def create_particles(self):
        arrays = lattice_tank(self.dx, self.h)
        self.scheme.setup_properties(arrays)
        fluid, _, piston = arrays
        fluid.p[:] = RHO0 * -G_Y * (DEPTH - fluid.y)  # the scene's hydrostatic pressure
        self.piston_x0 = piston.x.copy()
        return arrays

    def post_stage(self, current_time, dt, stage):
        """Put the piston where the prescribed motion has it at the time of the next force
        evaluation (t + dt/2 after stage 1, t + dt after stage 2)."""
        self.move_piston(current_time)

    def move_piston(self, t):
        piston = self.particles[2]
        X, u, a = piston_motion(t)
        piston.x[:] = self.piston_x0 + X
        piston.u[:] = u
        piston.au[:] = a  # the wall condition's wall acceleration (Adami et al. eq. 27)

    def post_step(self, solver):
        if solver.t < self.next_sample - 1e-9:
            return
        self.next_sample += EVERY
        fluid = self.particles[0]
        x, y, m = fluid.x.copy(), fluid.y.copy(), fluid.m.copy()
        p = {"kind": np.zeros(len(x), dtype=int), "x": x, "mass": m,
             "density": np.full(len(x), RHO0)}
        row = [solver.t]
        for x0 in P["probes_x"]:
            near = np.abs(x - x0) < self.dx
            top = float(y[near].max()) + self.dx / 2 - DEPTH if near.any() else float("nan")
            row += [cases.surface_elevation(p, x0, DEPTH, self.dx), top]
        self.samples.append(row)
        if round(solver.t / EVERY) % round(0.5 / EVERY) == 0:
            print(f"t = {solver.t:5.2f} s: eta(1.0) {row[1]:+.4f} m, eta(1.5) {row[3]:+.4f} m, "
                  f"piston X {piston_motion(solver.t)[0]:+.4f} m", flush=True)


def lattice_tank(dx, h):
    """The app's lattice (cell centres) as PySPH particle arrays [fluid, wall, piston]."""
    n = WALL_LAYERS
    ix, iy = np.meshgrid(np.arange(-n, round(LENGTH / dx) + n), np.arange(-n, round(HEIGHT / dx)))
    x, y = (ix.ravel() + 0.5) * dx, (iy.ravel() + 0.5) * dx
    wall = (x < 0) | (x > LENGTH) | (y < 0)
    piston = ((x > PISTON_MIN[0]) & (x < PISTON_MAX[0]) & (y > PISTON_MIN[1])
              & (y < PISTON_MAX[1]))
    fluid = ((x > FLUID_MIN[0]) & (x < FLUID_MAX[0]) & (y > FLUID_MIN[1]) & (y < FLUID_MAX[1])
             & ~piston & ~wall)
    m = RHO0 * dx * dx
    return [get_particle_array(name=name, x=x[sel], y=y[sel], h=h, m=m, rho=RHO0)
            for name, sel in (("fluid", fluid), ("wall", wall), ("piston", piston))]


def wave_heights(samples):
    """cases.piston_waves' H: crest to trough in each period of the window, per probe; from the
    columns 1 + 2 k of samples (the app's reading) or 2 + 2 k (the highest particle)."""
    s = np.array(samples)
    t = s[:, 0]
    w0, w1 = P["window"]
    inside = (t >= w0 - 1e-9) & (t <= w1 + 1e-9)
    out = {}
    for col, name in ((1, "reading"), (2, "top")):
        heights = {}
        for k, x0 in enumerate(P["probes_x"]):
            series, ts = s[inside, col + 2 * k], t[inside]
            start, hs = w0, []
            while start + P["period"] <= w1 + 1e-9:
                w = (ts >= start - 1e-9) & (ts < start + P["period"] - 1e-9)
                if w.any():  # a run stopped early has no samples there
                    hs.append(float(series[w].max() - series[w].min()))
                start += P["period"]
            heights[x0] = hs
        out[name] = heights
    return out


def report(app, seconds):
    ratio, k = cases.biesel_height_over_stroke(P["period"], DEPTH)
    ref = ratio * P["stroke"]
    fluid, wall, piston = app.particles
    print(f"PySPH {__import__('pysph').__version__} EDACScheme, dx = {app.dx:g} m, h = {app.h:g} m "
          f"(Wendland C2), c0 = {C0:g} m/s, alpha = {app.alpha:g}, dt = {app.time_step():.4g} s, "
          f"{app.solver.count} steps to t = {app.solver.t:.4g} s")
    print(f"particles: {fluid.get_number_of_particles()} fluid, {wall.get_number_of_particles()} "
          f"wall, {piston.get_number_of_particles()} piston")
    print(f"Biesel: kd = {k * DEPTH:.4g}, H/S = {ratio:.4f}, H_Biesel = {ref:.5f} m")
    for name, heights in wave_heights(app.samples).items():
        label = ("the app's reading (cases.surface_elevation, areas m / rho0)" if name == "reading"
                 else "highest fluid particle within dx of the probe (+ dx / 2)")
        print(f"{label}:")
        for x0, hs in heights.items():
            print(f"  x = {x0:g} m: H per period {', '.join(f'{v:.5f}' for v in hs)} m, mean "
                  f"{np.mean(hs):.5f} m ({(np.mean(hs) - ref) / ref:+.1%})")
        H = float(np.mean([v for hs in heights.values() for v in hs]))
        print(f"  H = {H:.5f} m against Biesel's {ref:.5f} m: relative error "
              f"{(H - ref) / ref:+.2%} (|H - H_B| / H_B = {abs(H - ref) / ref:.4f})")
    print(f"wall time {seconds:.0f} s (PySPH's code generation included)")


def main():
    ap = pysph_run.arguments(__doc__, 0.02, "spacing [m] (the app's CI spacing)")
    ap.add_argument("--alpha", type=float, default=ALPHA,
                    help="artificial viscosity (the app's 0.02 for this scene)")
    args = ap.parse_args()
    start = time.time()
    app = PistonWaves(args.dx, args.alpha, fname="piston_waves")
    pysph_run.solve_quietly(app, args.openmp, prepare=lambda a: a.move_piston(0.0))
    report(app, time.time() - start)


if __name__ == "__main__":
    main()
