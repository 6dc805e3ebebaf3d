#!/usr/bin/python3
"""PySPH beside the app on Greenhow & Lin's (1983) water entry of a half-buoyant cylinder: PySPH's
own weakly-compressible rigid-body example, pysph/examples/rigid_body/sphere_in_vessel_akinci.py
(subclassed; its equations are used unchanged): the fluid's density by summation with the walls'
and the body's share (SummationDensityBoundary, rho_w V_b W), Tait's equation of state with
Hughes & Graham's correction (TaitEOSHGCorrection, gamma = 7), the WCSPH momentum equation with
artificial viscosity (alpha = 0.1, beta = 0, no physical viscosity) and XSPH, the fluid-body and
fluid-wall coupling of Akinci et al. (2012) (AkinciRigidFluidCoupling: the pressure force on a
fluid particle from each boundary particle, its reaction summed on the body), the body moved
rigidly (RigidBodyMoments, RigidBodyMotion, RK2StepRigidBody; EPECIntegrator, WCSPHStep for the
fluid), CubicSpline, h = 1.2 dx, the example's fixed step 0.125 h / (1.1 c0) / 2, on the set-up of
scenes/validation/water_entry_2d.json with the app's sound speed for it, c0 = 10 x 3 m/s. The
cylinder's depth is read as validation/cases.py (water_entry) reads the app's bodies.csv (that
function is called on the centre's y, recorded every step): Z = (L + D/2 - y) / D against
T = (t - t0) sqrt(g / D), t0 when y first reaches L + D/2, L = 0.3 m the still surface.

    /usr/bin/python3 validation/pysph_water_entry.py [--dx 0.0055] [--end 0.125] [--openmp]

Needs Debian's python3-pysph. The fluid and the walls stand on the app's lattice (cell centres),
three layers of wall particles outside x = 0, x = 1 (up to y = 0.5) and y = 0; the water is in
hydrostatic balance through its particles' masses, m = rho(y) dx^2 with rho(y) from Tait's
equation for p = rho_w g (L - y) (as PySPH's solid_body_floating_in_tank example does, the
density being summed). The cylinder, as in the example, is a lattice of half the spacing,
centred on its centre, the points inside the circle, their masses making its mass exactly
500 pi D^2 / 4 per metre. With --openmp the reaction on the body is summed from all threads
without atomics (PySPH's own equation), so a term may be lost; at dx = 0.011 the run with two
threads and the serial one agreed to 1e-5 m in the centre's y (2026-12-06).

At dx = 0.0055 (12384 particles, 10000 steps, 2 threads, 821 s on a loaded 2-core machine):
Z - Z_exp relative +0.088, -0.123, -0.084, -0.084, -0.009 at T = 0.1004, 0.2773, 0.3777, 0.7969,
1.131, max 0.123; at dx = 0.011: +0.118, -0.156, -0.123, -0.112, -0.046, max 0.156."""
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
from pysph.base.utils import get_particle_array_rigid_body, get_particle_array_wcsph  # noqa: E402
from pysph.examples.rigid_body.sphere_in_vessel_akinci import RigidFluidCoupling  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cases  # noqa: E402

with open(os.path.join(cases.SCENES, "water_entry_2d.json")) as _scene:
    SCENE = json.load(_scene)
BODY = SCENE["bodies"][0]
RHO_W = SCENE["materials"]["water"]["density"]
RHO_B = BODY["motion"]["density"]
G = abs(SCENE["gravity"][1])
WIDTH, TOP = SCENE["domain"]["max"]
DEPTH = SCENE["fluids"][0]["max"][1]  # the still surface L
RADIUS, CENTRE, VELOCITY = BODY["radius"], BODY["center"], BODY["motion"]["velocity"]
C0 = 10 * SCENE["physics"]["max_speed"]  # the app's sound speed, 10 x max_speed
HDX, GAMMA, WALL_LAYERS = 1.2, 7.0, 3  # the cubic spline reaches 2 h = 2.4 dx


class WaterEntry(RigidFluidCoupling):
    """PySPH's sphere_in_vessel_akinci example on the scene's tank, water and cylinder."""

    def __init__(self, dx, end, **kw):
        self.spacing, self.end = dx, end
        self.record = []  # (t, y of the cylinder's centre of mass)
        super().__init__(**kw)

    def initialize(self):
        super().initialize()  # the example's hdx 1.2, alpha 0.1, then ours:
        self.dx, self.hdx, self.ro, self.solid_rho, self.co = self.spacing, HDX, RHO_W, RHO_B, C0
        self.m = RHO_W * self.dx**2

    def create_particles(self):
        dx, h = self.dx, HDX * self.dx
        nx, ny = round(WIDTH / dx), round(TOP / dx)
        ix, iy = np.meshgrid(np.arange(-WALL_LAYERS, nx + WALL_LAYERS), np.arange(-WALL_LAYERS, ny))
        x, y = (ix.ravel() + 0.5) * dx, (iy.ravel() + 0.5) * dx
        keep = (x < WIDTH + WALL_LAYERS * dx) & (y < TOP)
        x, y = x[keep], y[keep]
        wall = (x < 0) | (x > WIDTH) | (y < 0)
        water = ~wall & (y < DEPTH)
        yf = y[water]
        B = RHO_W * C0**2 / GAMMA  # Tait: p = B ((rho / rho_w)^gamma - 1)
        rho = RHO_W * (1 + RHO_W * G * (DEPTH - yf) / B)**(1 / GAMMA)
        fluid = get_particle_array_wcsph(name="fluid", x=x[water], y=yf, h=h, m=rho * dx * dx,
                                         rho=rho)
        tank = get_particle_array_wcsph(name="tank", x=x[wall], y=y[wall], h=h, m=RHO_W * dx * dx,
                                        rho=RHO_W, rad_s=dx / 2, V=dx * dx)
        for name in ("fx", "fy", "fz"):
            tank.add_property(name)
        db = dx / 2  # the example's body lattice, half the fluid's spacing
        n = math.ceil(RADIUS / db)
        jx, jy = np.meshgrid(np.arange(-n, n), np.arange(-n, n))
        bx, by = (jx.ravel() + 0.5) * db, (jy.ravel() + 0.5) * db
        inside = np.hypot(bx, by) < RADIUS
        bx, by = bx[inside] + CENTRE[0], by[inside] + CENTRE[1]
        cylinder = get_particle_array_rigid_body(
            name="cube", x=bx, y=by, h=h, m=RHO_B * math.pi * RADIUS**2 / len(bx), rho=RHO_B,
            rad_s=db / 2, V=db * db, cs=0.0, u=VELOCITY[0], v=VELOCITY[1])
        cylinder.vc[:2] = VELOCITY  # the body's velocity; RigidBodyMotion sets the particles'
        return [fluid, tank, cylinder]

    def create_solver(self):
        solver = super().create_solver()
        solver.set_final_time(self.end)
        return solver

    def post_step(self, solver):
        body = self.particles[2]
        # called before the solver adds dt to its time
        self.record.append((solver.t + solver.dt, float(np.sum(body.m * body.y) / np.sum(body.m))))
        if solver.count % 1000 == 0:
            print(f"t = {self.record[-1][0]:.4f} s, centre y = {self.record[-1][1]:.5f} m", flush=True)


class Run:
    """What validation/cases.py (water_entry) reads of a run: the scene and bodies.csv's rows."""

    def __init__(self, record):
        self.scene, self.rows = SCENE, np.array(record)

    def bodies(self):
        return {"time": self.rows[:, 0], "y": self.rows[:, 1]}


def report(app, seconds):
    rows = np.array([(0.0, CENTRE[1])] + app.record)
    t, y = rows[:, 0], rows[:, 1]
    D = 2 * RADIUS
    contact = DEPTH + D / 2
    k = int(np.argmax(y <= contact))
    t0 = t[k - 1] + (t[k] - t[k - 1]) * (y[k - 1] - contact) / (y[k - 1] - y[k])
    T, Z = (t - t0) * math.sqrt(G / D), (contact - y) / D
    ref = cases.read_table("greenhow_lin1983.csv")
    sizes = [pa.get_number_of_particles() for pa in app.particles]
    print(f"PySPH {__import__('pysph').__version__}, sphere_in_vessel_akinci (WCSPH, Akinci "
          f"coupling), dx = {app.dx:g} m (D / dx = {D / app.dx:g}), c0 = {C0:g} m/s, particles: "
          f"{sizes[0]} fluid, {sizes[1]} wall, {sizes[2]} cylinder; dt = {app.solver.dt:.4g} s, "
          f"{app.solver.count} steps to t = {app.solver.t:.4g} s; t0 = {t0:.5f} s")
    print(f"{'T':>7} {'Z_pysph':>8} {'Z_exp':>7} {'rel err':>8}")
    for Te, Ze in zip(ref["T"], ref["Z"]):
        if Te <= T[-1]:
            Zs = float(np.interp(Te, T, Z))
            print(f"{Te:7.4f} {Zs:8.4f} {Ze:7.4f} {(Zs - Ze) / Ze:+8.3f}")
    if ref["T"][0] <= T[-1]:
        checks, notes, _ = cases.water_entry(Run(rows))
        print(f"{checks[0]['metric']}: {checks[0]['value']:.4f} (gate {checks[0]['gate']:g}); {notes}")
    print("centre every 0.0025 s: t, y, T, Z")
    for ts in np.arange(0.0, t[-1] + 1e-9, 0.0025):
        ys = float(np.interp(ts, t, y))
        print(f"  {ts:.4f} {ys:.5f} {(ts - t0) * math.sqrt(G / D):+.4f} {(contact - ys) / D:+.4f}")
    print(f"wall time {seconds:.0f} s (PySPH's code generation included)")


def main():
    ap = pysph_run.arguments(__doc__, SCENE["particles"]["spacing"],
                             "spacing [m] (the scene's 0.0055, D / 20, by default)")
    ap.add_argument("--end", type=float, default=SCENE["time"]["end"],
                    help="end time [s] (the scene's 0.125)")
    args = ap.parse_args()
    start = time.time()
    app = WaterEntry(args.dx, args.end, fname="water_entry")
    pysph_run.solve_quietly(app, args.openmp)
    report(app, time.time() - start)


if __name__ == "__main__":
    main()
