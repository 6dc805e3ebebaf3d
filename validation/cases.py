#!/usr/bin/python3
"""Validation cases, run through the apps as a user runs them.

Each case runs a scene of scenes/validation/ with fluid_sim or fluid_sim_3d (the scene, the app,
the app's defaults; only the resolution is changed, with --set particles.spacing=...), reads the
app's own outputs (particle CSV, probes.csv, summary.json) and compares them with the case's
reference. One JSON result per run.

    cases.py list
    cases.py run CASE [--spacing DX] [--bin DIR] [--threads N] [--json FILE] [--check ci|gate]

--check ci exits 1 unless the result is within the case's CI bound (tests/validation); --check
gate exits 1 unless it meets the issue's gate. Needs Debian's python3-numpy only.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.path.join(ROOT, "scenes", "validation")
DATA = os.path.join(ROOT, "validation", "data")


# ---------------------------------------------------------------------------------------------
# Running an app and reading its outputs
# ---------------------------------------------------------------------------------------------


class Run:
    """One app run: the scene as run, summary.json, probes and the particle CSV frames."""

    def __init__(self, scene, out, summary, command, exit_code):
        self.scene, self.out, self.summary = scene, out, summary
        self.command, self.exit_code = command, exit_code
        self.spacing = scene["particles"]["spacing"]
        files = sorted(f for f in os.listdir(out)
                       if f.endswith(".csv") and f not in ("probes.csv", "bodies.csv"))
        every, final = scene["output"].get("every", 0.05), summary["final_time"]
        self.frames = [(min(k * every, final), os.path.join(out, f)) for k, f in enumerate(files)]

    def particles(self, k=-1):
        """Fluid particles of frame k as a dict of columns."""
        data = np.genfromtxt(self.frames[k][1], delimiter=",", names=True)
        return {n: np.atleast_1d(data[n]) for n in data.dtype.names}

    def time(self, k=-1):
        return self.frames[k][0]

    def bodies(self):
        """bodies.csv (the moving bodies over time) as a dict of columns."""
        path = os.path.join(self.out, "bodies.csv")
        data = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")
        return {n: np.atleast_1d(data[n]) for n in data.dtype.names}

    def probes(self):
        path = os.path.join(self.out, "probes.csv")
        data = np.genfromtxt(path, delimiter=",", names=True, deletechars="")
        return {n: np.atleast_1d(data[n]) for n in data.dtype.names}


def run_app(case, spacing, bin_dir, threads, sets=()):
    scene_path = os.path.join(SCENES, case["scene"])
    with open(scene_path) as f:
        text = "\n".join(l for l in f if not l.lstrip().startswith("//"))
    scene = json.loads(text)
    app = "fluid_sim" if scene["dimension"] == 2 else "fluid_sim_3d"
    exe = os.path.join(bin_dir, app, app) if os.path.isdir(os.path.join(bin_dir, app)) else os.path.join(bin_dir, app)
    all_sets = list(case.get("sets", ())) + list(sets)
    if spacing is not None:
        all_sets.append(f"particles.spacing={spacing:.10g}")
        scene["particles"]["spacing"] = spacing
    for s in all_sets:  # the scene as run, for the readings
        key, value = s.split("=", 1)
        node, parts = scene, key.split(".")
        for p in parts[:-1]:
            node = node[int(p)] if isinstance(node, list) else node[p]
        try:
            node[parts[-1]] = json.loads(value)
        except ValueError:  # a plain word, as the app takes it
            node[parts[-1]] = value
    out = tempfile.mkdtemp(prefix=f"val_{case['name']}_")
    cmd = [exe, scene_path, "--out", out, "--threads", str(threads), "-q"]
    for s in all_sets:
        cmd += ["--set", s]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    shown = " ".join([app, os.path.relpath(scene_path, ROOT)] + [f"--set {s}" for s in all_sets])
    summary_path = os.path.join(out, "summary.json")
    if proc.returncode != 0 or not os.path.exists(summary_path):
        raise RuntimeError(f"{shown} failed with exit code {proc.returncode}: {proc.stderr.strip()}")
    with open(summary_path) as f:
        summary = json.load(f)
    if summary.get("status") != "completed":
        raise RuntimeError(f"{shown}: status {summary.get('status')}: {summary.get('message')}")
    return Run(scene, out, summary, shown, proc.returncode)


# ---------------------------------------------------------------------------------------------
# References
# ---------------------------------------------------------------------------------------------


def poiseuille_exact(y, t, F=2e-4, nu=1e-6, L=1e-3, terms=200):
    """Morris, Fox & Zhu (1997): start-up Poiseuille flow (docs/reference_solutions.md sec. 2)."""
    u = F / (2 * nu) * y * (L - y)
    for n in range(terms):
        k = 2 * n + 1
        u -= 4 * F * L**2 / (nu * math.pi**3 * k**3) * np.sin(k * math.pi * y / L) * math.exp(-k * k * math.pi**2 * nu * t / L**2)
    return u


def couette_exact(y, t, V0=2.5e-5, nu=1e-6, L=1e-3, terms=400):
    """Morris (1997): start-up Couette flow (docs/reference_solutions.md sec. 3)."""
    u = V0 * y / L
    for n in range(1, terms + 1):
        u += 2 * V0 / (n * math.pi) * (-1) ** n * np.sin(n * math.pi * y / L) * math.exp(-nu * n * n * math.pi**2 * t / L**2)
    return u


def read_table(name):
    """A CSV table of validation/data (comment lines start with #) as a dict of columns."""
    with open(os.path.join(DATA, name)) as f:
        rows = [l.strip().split(",") for l in f if l.strip() and not l.startswith("#")]
    cols = {}
    for i, key in enumerate(rows[0]):
        values = [r[i] for r in rows[1:]]
        try:
            cols[key] = np.array([float(v) for v in values])
        except ValueError:
            cols[key] = np.array(values)
    return cols


# ---------------------------------------------------------------------------------------------
# Comparisons: each returns (checks, notes, profile) for a run
#   checks: list of {"metric", "value", "gate"} (value <= gate passes)
#   profile: {"xlabel", "ylabel", "series": [{"label", "x", "y", "style"}]} for the report's plot
# ---------------------------------------------------------------------------------------------


def channel(run, exact, scale, name):
    axis = "y" if run.scene["dimension"] == 2 else "z"
    errs = []
    for k in range(1, len(run.frames)):
        p = run.particles(k)
        errs.append(float(np.max(np.abs(p["vx"] - exact(p[axis], run.time(k)))) / scale))
    p, t = run.particles(), run.time()
    ys = np.linspace(0, 1e-3, 101)
    profile = {"xlabel": f"{axis} [m]", "ylabel": "u [m/s]", "series": [
        {"label": f"app, t = {t:g} s", "x": p[axis].tolist(), "y": p["vx"].tolist(), "style": "points"},
        {"label": "analytic", "x": ys.tolist(), "y": exact(ys, t).tolist(), "style": "line"}]}
    checks = [{"metric": f"max |u - u_exact| / {name} at t = {t:g} s", "value": errs[-1], "gate": 0.01}]
    notes = "largest over the outputs " + ", ".join(f"{e:.4g}" for e in errs)
    return checks, notes, profile


def poiseuille(run):
    return channel(run, poiseuille_exact, 2.5e-5, "u_max")


def couette(run):
    return channel(run, couette_exact, 2.5e-5, "V0")


def taylor_green(run):
    nu = next(iter(run.scene["materials"].values()))["viscosity"]
    p, t = run.particles(), run.time()
    decay = math.exp(-8 * math.pi**2 * nu * t)
    x, y = p["x"], p["y"]
    ue = -decay * np.cos(2 * math.pi * x) * np.sin(2 * math.pi * y)
    ve = decay * np.sin(2 * math.pi * x) * np.cos(2 * math.pi * y)
    vmag, vmag_e = np.hypot(p["vx"], p["vy"]), np.hypot(ue, ve)
    l1 = float(np.mean(np.abs(vmag - vmag_e)) / np.mean(vmag_e))
    maxv = float(abs(vmag.max() - decay) / decay)
    times, maxes = [], []
    for k in range(len(run.frames)):
        q = run.particles(k)
        times.append(run.time(k))
        maxes.append(float(np.hypot(q["vx"], q["vy"]).max()))
    tt = np.linspace(0, t, 101)
    profile = {"xlabel": "t", "ylabel": "max |v|", "series": [
        {"label": "app", "x": times, "y": maxes, "style": "points"},
        {"label": "exp(-8 pi^2 nu t)", "x": tt.tolist(), "y": np.exp(-8 * math.pi**2 * nu * tt).tolist(), "style": "line"}]}
    checks = [{"metric": f"l1 velocity error at t = {t:g} (PySPH's definition; anchor: PySPH EDAC, 50 x 50, Re = 100)",
               "value": l1, "gate": 0.022}]
    if abs(nu - 0.01) < 1e-12:
        checks.insert(0, {"metric": f"|max|v| - exp(-8 pi^2 nu t)| / exp(-8 pi^2 nu t) at t = {t:g}", "value": maxv, "gate": 0.02})
    notes = f"max|v| decay error {maxv:.4g}; l1 {l1:.4g}"
    return checks, notes, profile


def steady_rows(pr, window):
    """The outputs of the last `window` seconds of a run (a mask of run.probes()' rows), on which
    a steady case is measured (the mean over them)."""
    return pr["time"] >= pr["time"][-1] - window - 1e-9


def steady_frames(run, window):
    """The particle frames of the last `window` seconds of a run (their indices)."""
    return [k for k in range(len(run.frames)) if run.time(k) >= run.time() - window - 1e-9]


# The cavities are measured on the mean of their last 4 s (5 outputs, 1 s apart).
CAVITY_WINDOW = 4.0


def cavity(run, re, gate):
    """Ghia et al.'s steady centreline profiles against the app's particles, read at Ghia's points
    by quadratic_reading in each output of the last CAVITY_WINDOW seconds and averaged (as for
    natural convection: the flow is steady and the weakly compressible velocity carries noise of
    about 0.005 U_lid from one output to the next, so a single snapshot's error moves between
    0.019 and 0.030 U_lid at Re = 100, spacing 0.02). Until 2026-12-02 the probes were compared:
    their kernel average, cut by the lid, read u near it low (Re = 1000, 100 x 100: 0.0403 of
    U_lid at y = 0.9766 against 0.0308 read from the particles; Re = 100: 0.0089 against 0.0095)."""
    ref = read_table("ghia1982.csv")
    col = f"re{re}"
    h = run.summary["smoothing_length"]
    frames = steady_frames(run, CAVITY_WINDOW)
    pr = run.probes()
    rows = steady_rows(pr, CAVITY_WINDOW)
    outputs = [run.particles(k) for k in frames]
    dev, series, snapshots, probe_dev = [], [], [], []
    for line, comp in (("u", "vx"), ("v", "vy")):
        on = ref["line"] == line
        coord, ghia = ref["coordinate"][on], ref[col][on]
        points = [(0.5, c) for c in coord] if line == "u" else [(c, 0.5) for c in coord]
        values = np.array([quadratic_reading(p, comp, points, h) for p in outputs]).T
        num = values.mean(axis=1)
        dev.append(np.abs(num - ghia))
        snapshots.append(np.abs(values - ghia[:, None]).max(axis=0))
        probes = np.array([pr[f"{line}{int(round(c * 10000)):04d}.{comp}"][rows].mean() for c in coord])
        probe_dev.append(float(np.abs(probes - ghia).max()))
        series += [{"label": f"app {line} on the centreline", "x": coord.tolist(), "y": num.tolist(), "style": "points"},
                   {"label": f"Ghia et al. {line}", "x": coord.tolist(), "y": ghia.tolist(), "style": "line"}]
    t, t0 = run.time(), run.time(frames[0])
    single = np.maximum(snapshots[0], snapshots[1])
    du, dv = float(dev[0].max()), float(dev[1].max())
    checks = [{"metric": f"max |u - u_Ghia| on x = 0.5 and |v - v_Ghia| on y = 0.5 / U_lid, averaged over t = {t0:g} to {t:g} ({len(frames)} outputs)",
               "value": max(du, dv), "gate": gate}]
    notes = (f"u line {du:.4g}, v line {dv:.4g} (the probes: {probe_dev[0]:.4g}, {probe_dev[1]:.4g}); the single "
             f"outputs' error {single.min():.4g} to {single.max():.4g}, at t = {t:g} {single[-1]:.4g}")
    profile = {"xlabel": "y (u) or x (v)", "ylabel": "velocity / U_lid", "series": series}
    return checks, notes, profile


def hydrostatic(run):
    dim = run.scene["dimension"]
    up = "y" if dim == 2 else "z"
    g = abs(run.scene["gravity"][dim - 1])
    rho = next(iter(run.scene["materials"].values()))["density"]
    H = run.scene["fluids"][0]["max"][dim - 1]
    W = run.scene["fluids"][0]["max"][0]
    dx = run.spacing

    def surface(p):
        cols = np.floor(p["x"] / dx) if dim == 2 else np.floor(p["x"] / dx) * 100000 + np.floor(p["y"] / dx)
        tops = [p[up][cols == c].max() for c in np.unique(cols)]
        return float(np.mean(tops) + dx / 2)

    p, t = run.particles(), run.time()
    inside = (p[up] > 0.1 * H) & (p[up] < 0.9 * H) & (p["x"] > 0.1 * W) & (p["x"] < 0.9 * W)
    if dim == 3:
        inside &= (p["y"] > 0.1 * W) & (p["y"] < 0.9 * W)
    err = np.abs(p["pressure"] - rho * g * (H - p[up])) / (rho * g * H)
    drift = abs(surface(p) - surface(run.particles(0))) / H
    zz = np.linspace(0, H, 50)
    profile = {"xlabel": f"{up} [m]", "ylabel": "pressure [Pa]", "series": [
        {"label": f"app, t = {t:g} s", "x": p[up].tolist(), "y": p["pressure"].tolist(), "style": "points"},
        {"label": "rho g (H - y)", "x": zz.tolist(), "y": (rho * g * (H - zz)).tolist(), "style": "line"}]}
    checks = [{"metric": f"max interior |p - rho g (H - {up})| / (rho g H) at t = {t:g} s", "value": float(err[inside].max()), "gate": 0.01},
              {"metric": f"free-surface drift / H over {t:g} s", "value": drift, "gate": 0.01}]
    k = int(np.argmax(np.abs(p["vx"])))
    notes = (f"mean interior error {float(err[inside].mean()):.3g}; largest |vx| {abs(float(p['vx'][k])):.3g} m/s, "
             f"at x = {float(p['x'][k]):.3g} m, {up} = {float(p[up][k]):.3g} m")
    return checks, notes, profile


def surge_front(x, support, dx):
    """The surge front of particles at x, the column standing from x = 0: the farthest particle
    still connected to the bulk, connected meaning closer than the kernel support to the next
    particle along x (spray ahead is not the front), plus half a spacing (a particle stands
    for the water around it)."""
    x = np.sort(np.asarray(x))
    gaps = np.nonzero(np.diff(x) > support)[0]
    return (x[gaps[0]] if len(gaps) else x[-1]) + dx / 2


def dam_break(run):
    ref = read_table("martin_moyce1952.csv")
    a = run.scene["fluids"][0]["max"][0]
    g = abs(run.scene["gravity"][1])
    support = 2 * run.summary["smoothing_length"]
    ts, zs = [], []
    for k in range(len(run.frames)):
        ts.append(run.time(k) * math.sqrt(2 * g / a))
        zs.append(surge_front(run.particles(k)["x"], support, run.spacing) / a)
    ts, zs = np.array(ts), np.array(zs)
    sel = ref["T"] <= ts[-1]
    zsim = np.interp(ref["T"][sel], ts, zs)
    rel = np.abs(zsim - ref["Z"][sel]) / ref["Z"][sel]
    profile = {"xlabel": "T = t sqrt(2 g / a)", "ylabel": "Z = z / a", "series": [
        {"label": "app", "x": ts.tolist(), "y": zs.tolist(), "style": "line"},
        {"label": "Martin & Moyce (1952)", "x": ref["T"].tolist(), "y": ref["Z"].tolist(), "style": "points"}]}
    checks = [{"metric": "max |Z - Z_exp| / Z_exp over the tabulated times", "value": float(rel.max()), "gate": 0.10}]
    notes = "relative error at T = " + ", ".join(f"{T:g}: {e:+.3f}" for T, e in zip(ref["T"][sel], (zsim - ref["Z"][sel]) / ref["Z"][sel]))
    return checks, notes, profile


def smoothed(t, p, grid, width):
    """p(t) on grid (nan, i.e. no water at the probe, as 0), averaged over a centred window."""
    y = np.interp(grid, t, np.nan_to_num(np.asarray(p, dtype=float)))
    n = max(1, int(round(width / (grid[1] - grid[0]))))
    box = np.ones(n)
    return np.convolve(y, box, "same") / np.convolve(np.ones_like(y), box, "same")


def dam_break_pressure(run):
    """Wall pressure at sensor 2 of Lobovsky et al. (2014) against the median and the 2.5-97.5 %
    band of their repeated runs. Simulation and experiment alike are averaged over a window of
    T = 0.05 (9 ms; the spread of the experiment's arrival times), so that the result does not
    hinge on the output interval or on a single sample, then compared on: the time
    the pressure first reaches 0.5 rho g H, the impact peak (the largest P within T = 1 of the
    arrival) and the mean over T = 3.5 to 5.5 (after the impact, before the plunging wave
    returns). Each gate is half the width of the experiment's band there (for the arrival: half
    the time between its 97.5 % and its 2.5 % curve reaching 0.5), over the median."""
    g = abs(run.scene["gravity"][1])
    rho = next(iter(run.scene["materials"].values()))["density"]
    H = run.scene["fluids"][0]["max"][1]
    pr = run.probes()
    return sensor2_figures(pr["time"] * math.sqrt(g / H), pr["sensor2.pressure"] / (rho * g * H))


def sensor2_figures(ts, ps):
    """dam_break_pressure's checks, notes and plot from P = p / (rho g H) at sensor 2 against
    T = t sqrt(g / H)."""
    ref = read_table("lobovsky2014_sensor2.csv")
    grid = np.arange(0.0, ts[-1] + 5e-4, 1e-3)
    width, level, window = 0.05, 0.5, (3.5, 5.5)
    sim = smoothed(ts, ps, grid, width)
    lo, med, hi = (smoothed(ref["T"], ref[k], grid, width) for k in ("p2_5", "median", "p97_5"))

    def arrival(y):
        i = int(np.argmax(y >= level))
        if y[i] < level:
            return float("nan")
        return float(grid[i - 1] + (level - y[i - 1]) * (grid[i] - grid[i - 1]) / (y[i] - y[i - 1]))

    def first_peak(y, t0):
        near = (grid >= t0) & (grid <= t0 + 1.0)
        j = int(np.argmax(np.where(near, y, -np.inf)))
        return float(y[j]), float(grid[j]), j

    ta_med, ta_early, ta_late = arrival(med), arrival(hi), arrival(lo)
    ta = arrival(sim)
    pk_med, tp_med, j = first_peak(med, ta_med)
    pk, tp, _ = first_peak(sim, ta) if ta == ta else (float("nan"), float("nan"), 0)
    win = (grid >= window[0]) & (grid <= window[1])
    if grid[-1] < window[1]:
        raise RuntimeError(f"the run ends at T = {grid[-1]:.3g}, before the window T = {window[0]:g} to {window[1]:g}")
    mean, mean_med = float(sim[win].mean()), float(med[win].mean())
    missing = float("inf")  # no arrival or peak: the check fails

    def round3(x):  # a gate as the report prints it
        return float(f"{x:.3g}")
    checks = [
        {"metric": f"|T_arrival - {ta_med:.4g}| / {ta_med:.4g} (P first reaches {level:g}; gate: half the band's crossing spread)",
         "value": abs(ta - ta_med) / ta_med if ta == ta else missing, "gate": round3((ta_late - ta_early) / 2 / ta_med)},
        {"metric": f"|P_peak - {pk_med:.4g}| / {pk_med:.4g} (impact peak: largest P within T = 1 of the arrival; gate: half the band there)",
         "value": abs(pk - pk_med) / pk_med if pk == pk else missing, "gate": round3((hi[j] - lo[j]) / 2 / pk_med)},
        {"metric": f"|mean P - {mean_med:.4g}| / {mean_med:.4g} over T = {window[0]:g} to {window[1]:g} (gate: half the band's mean width)",
         "value": abs(mean - mean_med) / mean_med, "gate": round3((hi[win].mean() - lo[win].mean()) / 2 / mean_med)}]
    notes = (f"arrival T = {ta:.4g} (experiment {ta_med:.4g}, band {ta_early:.4g} to {ta_late:.4g}); "
             f"impact peak P = {pk:.4g} at T = {tp:.4g} (experiment {pk_med:.4g} at T = {tp_med:.4g}, band {lo[j]:.4g} to {hi[j]:.4g}); "
             f"mean P over T = {window[0]:g} to {window[1]:g}: {mean:.4g} (experiment {mean_med:.4g}, band {lo[win].mean():.4g} to {hi[win].mean():.4g}); "
             f"largest unaveraged P {float(np.nanmax(ps)):.4g}")
    profile = {"xlabel": "T = t sqrt(g / H)", "ylabel": "P = p / (rho g H) at sensor 2 (15 mm)", "series": [
        {"label": "app (averaged over T = 0.05)", "x": grid.tolist(), "y": sim.tolist(), "style": "line"},
        {"label": "Lobovsky et al. (2014) median", "x": grid.tolist(), "y": med.tolist(), "style": "line"},
        {"label": "2.5 % percentile", "x": grid.tolist(), "y": lo.tolist(), "style": "line"},
        {"label": "97.5 % percentile", "x": grid.tolist(), "y": hi.tolist(), "style": "line"}]}
    return checks, notes, profile


# The convection cells are measured on the mean of their last 10 s: 41 outputs 0.25 s apart. The
# probes carry acoustic noise: at Ra = 1e4, 100 x 100, v_max of a single output moves by 1.4 %
# (one standard deviation; 1.7 % in a second run) and the mean of the window used until
# 2026-12-02 (the last 5 outputs, 1 s apart) by 0.6 % (0.9 %): ending anywhere in t = 19 to 30 s
# of one steady run, that window read v_max from 19.01 to 19.45 (18.96 to 19.72 in the second).
# The mean of 41 outputs moves by about 0.25 %. Since 2026-12-02 the profiles are read from the
# particles (quadratic_reading), not the probes, whose kernel average read v_max at Ra = 1e5 low
# by 0.7 to 4.1 % from 125 x 125 to 50 x 50; the particles' reading is the noisier (a single
# output's v_max moves by 2.7 % at 125 x 125, 3.4 % at 100 x 100, against the probes' 1.8 and
# 1.7 %; the two halves of the window differ by 0.3 % at both, by 3.4 % at 80 x 80).
NATURAL_CONVECTION_WINDOW = 10.0

DE_VAHL_DAVIS = {"1e3": (3.649, 3.697, 1.118), "1e4": (16.178, 19.617, 2.243), "1e5": (34.73, 68.59, 4.519)}


def peak(coord, values):
    """Largest value of a sampled profile, refined by a parabola through the top three samples."""
    i = int(np.argmax(values))
    if 0 < i < len(values) - 1:
        y0, y1, y2 = values[i - 1], values[i], values[i + 1]
        d = y0 - 2 * y1 + y2
        if d < 0:
            s = 0.5 * (y0 - y2) / d
            return float(y1 - 0.25 * (y0 - y2) * s), float(coord[i] + s * (coord[i + 1] - coord[i]))
    return float(values[i]), float(coord[i])


def quadratic_reading(p, field, points, h):
    """A particle field at `points` (2D) by moving least squares: at each point, the quadratic in
    x and y fitted by weighted least squares to the particles within 2 h (weights the Wendland C2
    kernel), read at the point. Exact for a quadratic field. The apps' probes average a field over
    the kernel (Shepard-normalised SPH interpolation), which reads a peak low by about
    sigma^2 |f''| / 2, sigma^2 = 0.28 h^2 for Wendland C2 in 2D: for a boundary-layer profile
    (x / d) exp(1 - x / d) with d = 0.066 (the hot wall at Ra = 1e5) 2.8, 1.1 and 0.46 % at
    h = 0.03, 0.019 and 0.012 (50 x 50, 80 x 80, 125 x 125), where this reading is within 0.1 %."""
    radius = 2 * h
    x, y, f = p["x"], p["y"], p[field]
    values = []
    for px, py in points:
        near = (np.abs(x - px) < radius) & (np.abs(y - py) < radius)
        rx, ry, fn = x[near] - px, y[near] - py, f[near]
        q = np.hypot(rx, ry) / h
        inside = q < 2
        rx, ry, fn, q = rx[inside], ry[inside], fn[inside], q[inside]
        if len(fn) < 12:
            raise RuntimeError(f"{len(fn)} particles within 2 h of ({px:g}, {py:g}): too few to fit a quadratic")
        w = np.sqrt((1 - q / 2) ** 4 * (2 * q + 1))
        basis = np.stack([np.ones_like(rx), rx, ry, rx * rx, rx * ry, ry * ry], axis=1)
        coef = np.linalg.lstsq(basis * w[:, None], fn * w, rcond=None)[0]
        values.append(coef[0])
    return np.array(values)


def natural_convection_nusselt(run, L, alpha, dT):
    """The mean Nusselt number of the last output of natural_convection's cavity."""
    # Mean Nusselt number: the heat flux q_x = rho c (u T - alpha dT/dx), averaged over the fluid
    # between its first and last column of particles (the conduction part from their mean
    # temperatures), over alpha rho c dT / L.
    p = run.particles()
    dx = run.spacing
    cols = np.clip(np.floor(p["x"] / dx).astype(int), 0, int(round(L / dx)) - 1)
    first, last = cols.min(), cols.max()
    t_first, t_last = p["temperature"][cols == first].mean(), p["temperature"][cols == last].mean()
    x_first, x_last = p["x"][cols == first].mean(), p["x"][cols == last].mean()
    conduction = (t_first - t_last) / (x_last - x_first) * L / dT
    band = (p["x"] >= x_first) & (p["x"] <= x_last)
    convection = np.mean(p["vx"][band] * (p["temperature"][band] - p["temperature"][band].mean())) * L / (alpha * dT)
    return float(conduction + convection)


def natural_convection(run, ra):
    mat = next(iter(run.scene["materials"].values()))
    alpha = mat["conductivity"] / (mat["density"] * mat["heat_capacity"])
    th, tc = (run.scene["boundaries"][s]["thermal"]["temperature"] for s in ("x_min", "x_max"))
    dT, L = th - tc, 1.0
    h = run.summary["smoothing_length"]
    # The profiles u(y) on x = 0.5 and v(x) on y = 0.5, read from the particles of every output of
    # the last NATURAL_CONVECTION_WINDOW seconds at 161 points (1/168 apart, from 1/42 to 41/42)
    # and averaged over the outputs (the flow is steady; the weakly compressible velocity carries
    # acoustic noise from one output to the next, which a single snapshot would report as error or
    # hide as luck).
    line = np.linspace(1 / 42, 41 / 42, 161) * L
    frames = steady_frames(run, NATURAL_CONVECTION_WINDOW)
    u_rows, v_rows = [], []
    for k in frames:
        p = run.particles(k)
        u_rows.append(quadratic_reading(p, "vx", [(0.5 * L, c) for c in line], h) * L / alpha)
        v_rows.append(quadratic_reading(p, "vy", [(c, 0.5 * L) for c in line], h) * L / alpha)
    u_rows, v_rows = np.array(u_rows).T, np.array(v_rows).T
    k = len(frames)
    u, v = u_rows.mean(axis=1), v_rows.mean(axis=1)
    umax, yu = peak(line, u)
    vmax, xv = peak(line, v)
    snapshots = [peak(line, v_rows[:, j])[0] for j in range(k)]
    halves = [peak(line, half.mean(axis=1))[0] for half in (v_rows[:, : k // 2], v_rows[:, k // 2 :])]
    # The app's probes (41 on each line, 1/42 apart) over the same outputs, for comparison.
    pr = run.probes()
    rows = steady_rows(pr, NATURAL_CONVECTION_WINDOW)
    n = len([c for c in pr if c.startswith("u") and c.endswith(".vx")])
    ys = np.array([(i + 1) / (n + 1) for i in range(n)]) * L
    probe_u = peak(ys, np.array([pr[f"u{i:02d}.vx"][rows].mean() for i in range(n)]) * L / alpha)[0]
    probe_v = peak(ys, np.array([pr[f"v{i:02d}.vy"][rows].mean() for i in range(n)]) * L / alpha)[0]
    nu_mean = natural_convection_nusselt(run, L, alpha, dT)
    ref = DE_VAHL_DAVIS[ra]
    t, t0 = run.time(), run.time(frames[0])
    window = f"averaged over t = {t0:g} to {t:g} s ({k} outputs)"
    checks = [{"metric": f"|u_max - {ref[0]}| / {ref[0]} (u_max on x = 0.5, L / alpha units) {window}", "value": abs(umax - ref[0]) / ref[0], "gate": 0.03},
              {"metric": f"|v_max - {ref[1]}| / {ref[1]} (v_max on y = 0.5) {window}", "value": abs(vmax - ref[1]) / ref[1], "gate": 0.03},
              {"metric": f"|Nu - {ref[2]}| / {ref[2]} (mean Nusselt number) at t = {t:g} s", "value": abs(nu_mean - ref[2]) / ref[2], "gate": 0.03}]
    notes = (f"u_max {umax:.4g} at y = {yu:.3f}, v_max {vmax:.4g} at x = {xv:.3f}, Nu {nu_mean:.4g} "
             f"(de Vahl Davis: {ref[0]}, {ref[1]}, {ref[2]}); the probes (Shepard interpolation) read "
             f"u_max {probe_u:.4g}, v_max {probe_v:.4g}; v_max of single outputs {min(snapshots):.4g} "
             f"to {max(snapshots):.4g} (standard deviation {np.std(snapshots):.2g}), of the window's first "
             f"and second half {halves[0]:.4g} and {halves[1]:.4g}")
    profile = {"xlabel": "y (u on x = 0.5) or x (v on y = 0.5)", "ylabel": "velocity L / alpha", "series": [
        {"label": "u on x = 0.5", "x": line.tolist(), "y": u.tolist(), "style": "line"},
        {"label": "v on y = 0.5", "x": line.tolist(), "y": v.tolist(), "style": "line"},
        {"label": "de Vahl Davis u_max, v_max", "x": [yu, xv], "y": [ref[0], ref[1]], "style": "points"}]}
    return checks, notes, profile


def heat_pulse(run):
    dim = run.scene["dimension"]
    p, t = run.particles(), run.time()
    t0, alpha = 0.0025, 1.0
    r2 = sum(p[c] ** 2 for c in "xyz"[:dim])
    exact = (t0 / (t0 + t)) ** (dim / 2) * np.exp(-r2 / (4 * alpha * (t0 + t)))
    err = np.abs(p["temperature"] - exact)
    line = np.abs(p["y"]) < run.spacing * 0.6
    if dim == 3:
        line &= np.abs(p["z"]) < run.spacing * 0.6
    xs = np.linspace(p["x"].min(), p["x"].max(), 200)
    profile = {"xlabel": "x", "ylabel": "T", "series": [
        {"label": f"app near the x axis, t = {t:g}", "x": p["x"][line].tolist(), "y": p["temperature"][line].tolist(), "style": "points"},
        {"label": "analytic", "x": xs.tolist(), "y": ((t0 / (t0 + t)) ** (dim / 2) * np.exp(-xs**2 / (4 * alpha * (t0 + t)))).tolist(), "style": "line"}]}
    near = r2 < 9 * 2 * alpha * (t0 + t)
    checks = [{"metric": f"max |T - T_exact| / initial peak at t = {t:g}", "value": float(err.max()), "gate": 0.01},
              {"metric": "mean |T - T_exact| within 3 sigma / initial peak", "value": float(err[near].mean()), "gate": 0.003}]
    return checks, f"heat drift {abs(run.summary['conservation']['thermal_energy']['end'] / run.summary['conservation']['thermal_energy']['start'] - 1):.3g}", profile


def heat_slabs(run):
    from math import erf
    mats = run.scene["materials"]
    kl, kr = mats["left"]["conductivity"], mats["right"]["conductivity"]
    al = kl / (mats["left"]["density"] * mats["left"]["heat_capacity"])
    ar = kr / (mats["right"]["density"] * mats["right"]["heat_capacity"])
    el = math.sqrt(kl * mats["left"]["density"] * mats["left"]["heat_capacity"])
    er = math.sqrt(kr * mats["right"]["density"] * mats["right"]["heat_capacity"])
    tc = el / (el + er)
    verf = np.vectorize(erf)

    def exact(x, t):
        return np.where(x < 0, tc + (1 - tc) * verf(-x / (2 * math.sqrt(al * t))), tc - tc * verf(x / (2 * math.sqrt(ar * t))))

    p, t = run.particles(), run.time()
    err = np.abs(p["temperature"] - exact(p["x"], t))
    xs = np.linspace(-0.5, 0.5, 201)
    profile = {"xlabel": "x", "ylabel": "T", "series": [
        {"label": f"app, t = {t:g}", "x": p["x"].tolist(), "y": p["temperature"].tolist(), "style": "points"},
        {"label": "erf solution", "x": xs.tolist(), "y": exact(xs, t).tolist(), "style": "line"}]}
    near = np.abs(p["x"]) < 0.5
    checks = [{"metric": f"max |T - T_exact| / (T_L - T_R) at t = {t:g}", "value": float(err.max()), "gate": 0.01},
              {"metric": "mean |T - T_exact| for |x| < 0.5", "value": float(err[near].mean()), "gate": 0.003}]
    return checks, f"k_R / k_L = {kr / kl:g}, interface T_c = {tc:.6f}", profile


def conduction_walls(run):
    th, tc = (run.scene["boundaries"][s]["thermal"]["temperature"] for s in ("x_min", "x_max"))
    p, t, dx = run.particles(), run.time(), run.spacing
    exact = th + (tc - th) * p["x"]
    err = np.abs(p["temperature"] - exact) / (th - tc)
    # Nusselt number from the mean temperatures of the first and last particle columns.
    first, last = p["x"] < dx, p["x"] > 1 - dx
    nu = (p["temperature"][first].mean() - p["temperature"][last].mean()) / (p["x"][last].mean() - p["x"][first].mean()) / (th - tc)
    xs = np.linspace(0, 1, 101)
    profile = {"xlabel": "x", "ylabel": "T", "series": [
        {"label": f"app, t = {t:g}", "x": p["x"].tolist(), "y": p["temperature"].tolist(), "style": "points"},
        {"label": "T_h + (T_c - T_h) x", "x": xs.tolist(), "y": (th + (tc - th) * xs).tolist(), "style": "line"}]}
    checks = [{"metric": f"max |T - T_exact| / (T_h - T_c) at t = {t:g}", "value": float(err.max()), "gate": 0.01},
              {"metric": "|Nu - 1| (first and last particle columns)", "value": abs(nu - 1), "gate": 0.01}]
    return checks, f"Nu {nu:.5f}; mean |T - T_exact| / (T_h - T_c) {float(err.mean()):.3g}", profile


def buoyancy(run):
    """The force the water at rest exerts on a submerged body (probe "body") against the buoyancy
    rho g V, its mean over the last second: the weakly-compressible water rings acoustically
    about its rest state, a few per cent of rho g V from one output to the next."""
    rho = next(iter(run.scene["materials"].values()))["density"]
    g = abs(run.scene["gravity"][1])
    body = run.scene["bodies"][0]
    ref = rho * g * math.prod(hi - lo for lo, hi in zip(body["min"], body["max"]))
    pr = run.probes()
    last = steady_rows(pr, 1.0)
    fx, fy = float(pr["body.force_x"][last].mean()), float(pr["body.force_y"][last].mean())
    profile = {"xlabel": "t [s]", "ylabel": "F_y [N/m]", "series": [
        {"label": "app: force on the body", "x": pr["time"].tolist(), "y": pr["body.force_y"].tolist(), "style": "line"},
        {"label": "rho g V", "x": [0.0, float(pr["time"][-1])], "y": [ref, ref], "style": "line"}]}
    checks = [{"metric": "|F_y - rho g V| / (rho g V), mean over the last 1 s", "value": abs(fy - ref) / ref, "gate": 0.01},
              {"metric": "|F_x| / (rho g V), mean over the last 1 s", "value": abs(fx) / ref, "gate": 0.01}]
    return checks, f"F = ({fx:.4g}, {fy:.5g}) N/m against rho g V = {ref:.5g} N/m", profile


# Schaefer & Turek (1996), benchmark 2D-1: c_D = 5.57 to 5.59 (their bounds; 5.5795 the later
# reference value, John 2004) for a cylinder of diameter D = 0.1 m, 0.2 m above the floor of a
# channel H = 0.41 m high (blockage D / H = 0.244), Re = U D / nu = 20 with U the mean velocity.
SCHAEFER_TUREK_CD = 5.5795


def channel_mean_velocity(pr, names, ys, height):
    """The mean velocity of a channel flow, its flux over its height, from the probes `names` at
    heights `ys` across one section: the trapezoidal rule over the probes and the no-slip walls
    (u = 0 at y = 0 and y = height), one value per row. The flux is the same at every section,
    whatever the profile there (the wake of a body has not recovered to a parabola 5 D on)."""
    y = np.concatenate([[0.0], np.asarray(ys, dtype=float), [height]])
    u = np.array([np.zeros_like(pr[names[0]])] + [pr[n] for n in names] +
                 [np.zeros_like(pr[names[0]])])
    return np.trapz(u, y, axis=0) / height


def cylinder_drag(run):
    """Drag coefficient c_D = 2 F / (rho U^2 D) of the cylinder (probe "cylinder") in a channel
    periodic along x, driven by a body force g, against Schaefer & Turek's 2D-1 at Re = 20: U is
    the mean velocity (the flux over the height) through the section half a period from the
    cylinder (the "u<k>" probes, across the whole height), F and U their means over the last 2 s.
    F is the force the benchmark's pressure-driven flow exerts: with p* = p - rho g x the momentum equation rho Du/Dt = -grad p + mu lap u + rho g
    becomes rho Du/Dt = -grad p* + mu lap u, the same flow driven by a pressure falling along the
    channel, and the force of p* on the cylinder is that of p plus rho g V (the divergence theorem
    over the cylinder's area V = pi D^2 / 4): F = F_x + rho g V. The reading of the former set-up
    (scenes/validation/cylinder_re20_periodic.json), for validation/test_readings.py and
    validation/pysph_cylinder_re20.py; since 2026-12-06 cylinder_re20 runs the benchmark's own
    set-up (cylinder_benchmark)."""
    mat = next(iter(run.scene["materials"].values()))
    rho, nu = mat["density"], mat["viscosity"]
    D, H = 2 * run.scene["bodies"][0]["radius"], run.scene["domain"]["max"][1]
    displaced = rho * float(run.scene["gravity"][0]) * math.pi * D**2 / 4
    pr = run.probes()
    names = sorted(n for n in pr if n.startswith("u") and n.endswith(".vx"))
    ys = [next(p["point"][1] for p in run.scene["probes"] if p["name"] == n[:-3]) for n in names]
    U = channel_mean_velocity(pr, names, ys, H)
    last = steady_rows(pr, 2.0)
    Fx, Um = float(pr["cylinder.force_x"][last].mean()), float(U[last].mean())
    F = Fx + displaced
    cd, re = 2 * F / (rho * Um**2 * D), Um * D / nu
    with np.errstate(divide="ignore", invalid="ignore"):
        cd_t = 2 * (pr["cylinder.force_x"] + displaced) / (rho * U**2 * D)
    profile = {"xlabel": "t [s]", "ylabel": "c_D", "series": [
        {"label": "app (each output)", "x": pr["time"].tolist(), "y": np.nan_to_num(cd_t).tolist(), "style": "line"},
        {"label": "Schaefer & Turek (1996), 2D-1", "x": [0.0, float(pr["time"][-1])],
         "y": [SCHAEFER_TUREK_CD] * 2, "style": "line"}]}
    checks = [{"metric": "|c_D - 5.5795| / 5.5795 (Schaefer & Turek 1996, 2D-1), means over the last 2 s",
               "value": abs(cd - SCHAEFER_TUREK_CD) / SCHAEFER_TUREK_CD, "gate": 0.05},
              {"metric": "|Re - 20| / 20, Re = U D / nu", "value": abs(re - 20) / 20, "gate": 0.05}]
    notes = (f"c_D {cd:.4f} at Re {re:.3f} (U {Um:.5f} m/s, F = F_x + rho g V = {Fx:.4f} + "
             f"{displaced:.4f} N/m, lift "
             f"{float(pr['cylinder.force_y'][last].mean()):+.4f} N/m); D / dx {D / run.spacing:g}")
    return checks, notes, profile


# Schaefer & Turek's 2D-1 as the benchmark defines it: inflow u = 4 U_m y (H - y) / H^2 at x = 0
# (U_m = 0.3 m/s, mean U = 2 U_m / 3 = 0.2 m/s), outflow at x = 2.2 m, the pressure difference
# between the cylinder's front and back points (0.15, 0.2) and (0.25, 0.2), for rho = 1 (John 2004's
# reference values; the benchmark's bounds: c_D 5.57 to 5.59, c_L 0.0104 to 0.0110, Delta p 0.1172
# to 0.1176).
SCHAEFER_TUREK_CL = 0.010619
SCHAEFER_TUREK_DP = 0.11752
SCHAEFER_TUREK_U = 0.2
# The forces and the pressures are means over the last 3 s of the run (t = 2 to 5 s; the start
# is over by t = 2 s): c_D of single outputs 0.02 s apart scatters by 7 % (acoustic), its
# means over 0.5 s by 2 %.
CYLINDER_WINDOW = 3.0


def cylinder_benchmark(run):
    """Drag and lift coefficients c_D = 2 F_x / (rho U^2 D), c_L = 2 F_y / (rho U^2 D) of the
    cylinder (probe "cylinder") between the benchmark's inflow and outflow, U = 0.2 m/s the mean
    inflow velocity, and the pressure difference (probes "front" and "back", on the cylinder's
    surface) over rho, against Schaefer & Turek's 2D-1; means over the last CYLINDER_WINDOW s."""
    mat = next(iter(run.scene["materials"].values()))
    rho, nu = mat["density"], mat["viscosity"]
    D, U = 2 * run.scene["bodies"][0]["radius"], SCHAEFER_TUREK_U
    pr = run.probes()
    last = steady_rows(pr, CYLINDER_WINDOW)
    scale = 2 / (rho * U**2 * D)
    cd_t = scale * pr["cylinder.force_x"]
    cd, cl = float(cd_t[last].mean()), float(scale * pr["cylinder.force_y"][last].mean())
    dp = float((pr["front.pressure"][last] - pr["back.pressure"][last]).mean()) / rho
    t0, t = float(pr["time"][last][0]), float(pr["time"][-1])
    leftover = abs(books(run)) / run.summary["conservation"]["mass"]["start"]
    shown = pr["time"] >= 1.0  # after the start's spikes (c_D up to 40)
    profile = {"xlabel": "t [s]", "ylabel": "c_D", "series": [
        {"label": "app (each output, from t = 1 s)", "x": pr["time"][shown].tolist(), "y": cd_t[shown].tolist(), "style": "line"},
        {"label": f"app, mean over t = {t0:g} to {t:g} s", "x": [t0, t], "y": [cd, cd], "style": "line"},
        {"label": "Schaefer & Turek (1996), 2D-1", "x": [1.0, t], "y": [SCHAEFER_TUREK_CD] * 2, "style": "line"}]}
    checks = [{"metric": f"|c_D - {SCHAEFER_TUREK_CD}| / {SCHAEFER_TUREK_CD} (Schaefer & Turek 1996, 2D-1), "
               f"mean over t = {t0:g} to {t:g} s", "value": abs(cd - SCHAEFER_TUREK_CD) / SCHAEFER_TUREK_CD, "gate": 0.05}]
    notes = (f"c_D {cd:.4f} (F_x {cd / scale:.4f} N/m), c_L {cl:+.4f} (F_y {cl / scale:+.4f} N/m; the benchmark "
             f"{SCHAEFER_TUREK_CL}), Delta p / rho {dp:.4f} m^2/s^2 from the probes on the surface (the "
             f"benchmark {SCHAEFER_TUREK_DP}: {abs(dp - SCHAEFER_TUREK_DP) / SCHAEFER_TUREK_DP:.0%} off); Re = U D / nu "
             f"{U * D / nu:g}; mass books |end - (start + in - out)| / start {leftover:.2g}; D / dx {D / run.spacing:g}")
    return checks, notes, profile


def water_height(p, x0, y0, radius):
    """The depth of water at (x0, y0): the particles' volumes m / rho in the vertical column
    around it, weighted by the 2D Wendland C2 kernel of support `radius` (unit integral)."""
    q = np.hypot(p["x"] - x0, p["y"] - y0) / radius
    w = np.where(q < 1, 7 / (math.pi * radius**2) * (1 - q)**4 * (1 + 4 * q), 0.0)
    return float(np.sum(p["mass"] / p["density"] * w))


def floating_draft(run):
    """A free box lighter than water at its Archimedes draft d = (rho_b / rho_w) H: the mean
    height of its centre after the first 0.5 s (it bobs about its rest), with the still water
    level L from the water's area A and the box's displacement, L W = A + B d_m, so that
    d_m = (A / W - y_bottom) / (1 - B / W); and upright (its angle)."""
    body = run.scene["bodies"][0]
    rho_w = next(iter(run.scene["materials"].values()))["density"]
    B, H = (body["max"][0] - body["min"][0]), (body["max"][1] - body["min"][1])
    W = run.scene["domain"]["max"][0] - run.scene["domain"]["min"][0]
    d = body["motion"]["density"] / rho_w * H
    area = run.summary["fluid_particles"] * run.spacing**2
    b = run.bodies()
    late = b["time"] >= 0.5
    bottom = float(b["y"][late].mean()) - H / 2
    d_m = (area / W - bottom) / (1 - B / W)
    rest = area / W + B * d / W - d + H / 2  # the centre's height at rest
    profile = {"xlabel": "t [s]", "ylabel": "y of the box's centre [m]", "series": [
        {"label": "app: the box's centre", "x": b["time"].tolist(), "y": b["y"].tolist(), "style": "line"},
        {"label": "at the Archimedes draft", "x": [0.0, float(b["time"][-1])], "y": [rest, rest], "style": "line"}]}
    checks = [{"metric": "|d - d_Archimedes| / d_Archimedes (mean after 0.5 s)", "value": abs(d_m - d) / d, "gate": 0.05},
              {"metric": "largest |angle| [rad]", "value": float(np.abs(b["angle"]).max()), "gate": 0.05}]
    return checks, f"draft {d_m:.4g} m against {d:.4g} m", profile


def water_entry(run):
    """Greenhow & Lin's (1983) half-buoyant cylinder entering still water: the depth of its
    centre below its place at first contact (its bottom at the still surface L), over D, against
    the experiment at T = t sqrt(g / D) from first contact (interpolated in bodies.csv's rows);
    gate 10 % of the experiment's depth, as for Martin & Moyce's surge front (both are read off
    a figure)."""
    ref = read_table("greenhow_lin1983.csv")
    body = run.scene["bodies"][0]
    D, g = 2 * body["radius"], abs(run.scene["gravity"][1])
    contact = run.scene["fluids"][0]["max"][1] + D / 2
    b = run.bodies()
    t, y = np.asarray(b["time"], float), np.asarray(b["y"], float)
    k = int(np.argmax(y <= contact))  # the first row at or below contact
    t0 = t[k - 1] + (t[k] - t[k - 1]) * (y[k - 1] - contact) / (y[k - 1] - y[k])
    T, Z = (t - t0) * math.sqrt(g / D), (contact - y) / D
    sel = ref["T"] <= T[-1]
    zsim = np.interp(ref["T"][sel], T, Z)
    rel = (zsim - ref["Z"][sel]) / ref["Z"][sel]
    profile = {"xlabel": "T = t sqrt(g / D) from first contact", "ylabel": "penetration / D", "series": [
        {"label": "app", "x": T[k - 1:].tolist(), "y": Z[k - 1:].tolist(), "style": "line"},
        {"label": "Greenhow & Lin (1983)", "x": ref["T"].tolist(), "y": ref["Z"].tolist(), "style": "points"}]}
    checks = [{"metric": "max |Z - Z_exp| / Z_exp over the tabulated times", "value": float(np.abs(rel).max()),
               "gate": 0.10}]
    notes = "relative error at T = " + ", ".join(f"{x:g}: {e:+.3f}" for x, e in zip(ref["T"][sel], rel))
    return checks, notes, profile


def floating_sphere(run):
    """A free sphere lighter than water at its Archimedes draft: the submerged cap
    V(d) = pi d^2 (3 r - d) / 3 weighs as the sphere, rho_w V(d) = rho_b 4/3 pi r^3 (d = r for
    half the water's density). Measured from the mean height of its centre after 0.5 s and the
    still water level L, A L = V_water + V(d_m) (A the tank's section, V_water from the fluid
    particles' count), solved for d_m = L - (z - r)."""
    body = run.scene["bodies"][0]
    rho_w = next(iter(run.scene["materials"].values()))["density"]
    r = body["radius"]
    lo, hi = run.scene["domain"]["min"], run.scene["domain"]["max"]
    A = (hi[0] - lo[0]) * (hi[1] - lo[1])
    cap = lambda d: math.pi * d * d * (3 * r - d) / 3
    target = body["motion"]["density"] / rho_w * 4 / 3 * math.pi * r**3
    d = r  # the Archimedes draft: cap(d) = target, by bisection
    a, b = 0.0, 2 * r
    for _ in range(100):
        d = (a + b) / 2
        a, b = (d, b) if cap(d) < target else (a, d)
    water = run.summary["fluid_particles"] * run.spacing**3
    bodies = run.bodies()
    late = bodies["time"] >= 0.5
    bottom = float(bodies["z"][late].mean()) - r
    a, b = 0.0, 2 * r  # d_m = (water + cap(d_m)) / A - bottom
    for _ in range(100):
        d_m = (a + b) / 2
        a, b = (d_m, b) if (water + cap(d_m)) / A - bottom > d_m else (a, d_m)
    profile = {"xlabel": "t [s]", "ylabel": "z of the sphere's centre [m]", "series": [
        {"label": "app: the sphere's centre", "x": bodies["time"].tolist(), "y": bodies["z"].tolist(), "style": "line"},
        {"label": "at the Archimedes draft", "x": [0.0, float(bodies["time"][-1])],
         "y": [(water + cap(d)) / A - d + r] * 2, "style": "line"}]}
    checks = [{"metric": "|d - d_Archimedes| / d_Archimedes (mean after 0.5 s)", "value": abs(d_m - d) / d, "gate": 0.05}]
    return checks, f"draft {d_m:.4g} m against {d:.4g} m", profile


def biesel_height_over_stroke(period, depth, g=9.81):
    """Linear piston wave-maker theory (Biesel & Suquet 1951; Dean & Dalrymple 1991, eq. 6.9):
    H / S = 2 (cosh 2kd - 1) / (sinh 2kd + 2kd), k from omega^2 = g k tanh(kd)."""
    omega = 2 * math.pi / period
    k = omega**2 / g
    for _ in range(50):  # Newton on f(k) = g k tanh(kd) - omega^2
        f = g * k * math.tanh(k * depth) - omega**2
        df = g * math.tanh(k * depth) + g * k * depth / math.cosh(k * depth)**2
        k -= f / df
    kd2 = 2 * k * depth
    return 2 * (math.cosh(kd2) - 1) / (math.sinh(kd2) + kd2), k


# The sphere's draft at the CI spacing 0.02 (2.5 spacings in radius) is 18.3 % off
# (2026-12-06) -> regression bound 0.28 (times 1.5); at 0.01 it meets the gate (4.4 %).
FLOATING_SPHERE_CI_BOUND = 0.28
PISTON_MISS = (
    "H is 8.4 % low at spacing 0.01 and 9.3 % at 0.02: the waves lose height as they travel (0.059 m 0.5 m "
    "from the paddle, 0.055 m at 2 m) to the default artificial viscosity, alpha = 0.02 (5.8 % low at 0.02 with "
    "alpha = 0.002). PySPH's EDAC scheme on this set-up (validation/pysph_piston_waves.py) misses as much: "
    "12.2 % low at 0.02, 7.0 % at 0.01.")
# H at the CI spacing 0.02 is 9.3 % low (2026-12-06) -> regression bound 0.14 (times 1.5).
PISTON_CI_BOUND = 0.14
PISTON = {"stroke": 0.04, "period": 1.0, "depth": 0.4, "probes_x": (1.0, 1.5), "window": (3.0, 5.0)}


def surface_elevation(p, x0, depth, dx):
    """The water's depth at x0 minus the still depth: the fluid particles' areas m / rho
    weighted by the 1D Wendland C2 kernel of support 3 dx (unit integral)."""
    fluid = p["kind"] == 0
    R = 3 * dx
    q = np.abs(p["x"][fluid] - x0) / R
    w = np.where(q < 1, 1.25 / R * (1 - q)**3 * (1 + 3 * q), 0.0)
    return float(np.sum(p["mass"][fluid] / p["density"][fluid] * w)) - depth


def piston_waves(run):
    """Wave height H 1.0 and 1.5 m from the paddle (surface_elevation), crest to trough in each
    period of the window 3-5 s (the first waves of full height have passed, the reflection from
    the far wall has not come back: group velocity 0.89 m/s), the mean over periods and probes,
    against Biesel's H = S (H / S)."""
    P = PISTON
    ratio, k = biesel_height_over_stroke(P["period"], P["depth"])
    frames = [i for i in range(len(run.frames))
              if P["window"][0] - 1e-9 <= run.time(i) <= P["window"][1] + 1e-9]
    ts = np.array([run.time(i) for i in frames])
    eta = {x: [] for x in P["probes_x"]}
    for i in frames:
        p = run.particles(i)
        for x in P["probes_x"]:
            eta[x].append(surface_elevation(p, x, P["depth"], run.spacing))
    heights = []
    for x, series in eta.items():
        series = np.array(series)
        start = P["window"][0]
        while start + P["period"] <= P["window"][1] + 1e-9:
            w = (ts >= start - 1e-9) & (ts < start + P["period"] - 1e-9)
            heights.append(float(series[w].max() - series[w].min()))
            start += P["period"]
    H, ref = float(np.mean(heights)), ratio * P["stroke"]
    x0 = P["probes_x"][-1]
    profile = {"xlabel": "t [s]", "ylabel": f"eta at x = {x0} m [m]", "series": [
        {"label": "app: surface elevation", "x": ts.tolist(), "y": eta[x0], "style": "line"},
        {"label": "Biesel: H / 2", "x": [float(ts[0]), float(ts[-1])], "y": [ref / 2, ref / 2], "style": "line"},
        {"label": "Biesel: -H / 2", "x": [float(ts[0]), float(ts[-1])], "y": [-ref / 2, -ref / 2], "style": "line"}]}
    checks = [{"metric": "|H - H_Biesel| / H_Biesel (3-5 s, x = 1 and 1.5 m)", "value": abs(H - ref) / ref, "gate": 0.05}]
    return checks, f"H = {H:.4g} m against Biesel's {ref:.4g} m (kd = {k * P['depth']:.3g}, H/S = {ratio:.3f})", profile


def hot_ball(run):
    """A hot conducting ball dropped into cold water: the heat it gives (its heat sum m c T in
    bodies.csv, first and last rows) equals the heat the water gains (summary.json's thermal
    energy of the fluid; adiabatic walls), and, denser than water, it comes to rest on the floor:
    its centre one radius above it within one spacing (its particles sit on the lattice inside
    the sphere, up to half a spacing in from its surface, and rest in the hollows between the
    floor's particles, up to 0.3 spacing deep)."""
    b = run.bodies()
    given = float(b["heat"][0] - b["heat"][-1])
    water = run.summary["conservation"]["thermal_energy"]
    gained = water["end"] - water["start"]
    radius = run.scene["bodies"][0]["radius"]
    z, speed = float(b["z"][-1]), float(np.sqrt(b["vx"][-1]**2 + b["vy"][-1]**2 + b["vz"][-1]**2))
    profile = {"xlabel": "t [s]", "ylabel": "z of the ball's centre [m]", "series": [
        {"label": "app: the ball's centre", "x": b["time"].tolist(), "y": b["z"].tolist(), "style": "line"},
        {"label": "resting on the floor", "x": [0.0, float(b["time"][-1])], "y": [radius, radius], "style": "line"}]}
    checks = [{"metric": "|heat gained by the water - heat given by the ball| / heat given",
               "value": abs(gained - given) / given if given > 0 else math.inf, "gate": 0.01},
              {"metric": "|z - r| / spacing at the end", "value": abs(z - radius) / run.spacing, "gate": 1.0},
              {"metric": "the ball's speed at the end [m/s]", "value": speed, "gate": 0.01}]
    return checks, f"ball gave {given:.5g} J, water gained {gained:.5g} J; ball at rest at z = {z:.4g} m", profile


# Kleefsman et al. (2005): the probes H2 and H4 (x, y) and the initial depth of the water.
KLEEFSMAN_PROBES = {"h2": (0.992, 0.5), "h4": (2.638, 0.5)}
KLEEFSMAN_DEPTH = 0.55


def dam_break_obstacle(run):
    """Water heights at H2 and H4 against Kleefsman et al. (2005) at the tabulated times: the mean
    of |h - h_exp| over them, over the initial depth 0.55 m. The depth is read from the particle
    frames within the kernel support (2 h) around each probe's vertical line."""
    ref = read_table("kleefsman2005_h2_h4.csv")
    radius = 2 * run.summary["smoothing_length"]
    ts = np.array([run.time(k) for k in range(len(run.frames))])
    frames = [run.particles(k) for k in range(len(run.frames))]
    checks, series, notes = [], [], []
    sel = ref["t"] <= ts[-1] + 1e-9
    for key, (x0, y0) in KLEEFSMAN_PROBES.items():
        h = np.array([water_height(p, x0, y0, radius) for p in frames])
        err = np.abs(np.interp(ref["t"][sel], ts, h) - ref[key][sel]) / KLEEFSMAN_DEPTH
        checks.append({"metric": f"mean |{key.upper()} - {key.upper()}_exp| / 0.55 m over the tabulated times",
                       "value": float(err.mean()), "gate": 0.05})
        notes.append(f"{key.upper()}: mean {err.mean():.4f}, largest {err.max():.4f} at t = {ref['t'][sel][np.argmax(err)]:g} s")
        series += [{"label": f"app {key.upper()}", "x": ts.tolist(), "y": h.tolist(), "style": "line"},
                   {"label": f"Kleefsman et al. (2005) {key.upper()}", "x": ref["t"].tolist(), "y": ref[key].tolist(), "style": "points"}]
    return checks, "; ".join(notes), {"xlabel": "t [s]", "ylabel": "water height [m]", "series": series}


# ---------------------------------------------------------------------------------------------
# Inlets and outlets
# ---------------------------------------------------------------------------------------------

# The mean velocity U of the scenes' parabolic inflow u = 6 U y (H - y) / H^2 (1200 y (0.01 - y)).
INLET_MEAN_VELOCITY = 0.02
# channel_inflow_2d is measured over the last 2 s of its run (41 outputs): the pressure drop,
# 0.96 Pa over the channel against rho c0^2 = 90 Pa, rings acoustically (the slope of a single
# output is up to 29 % off at spacing 0.0005, the mean of 41 outputs 1 %).
CHANNEL_INFLOW_WINDOW = 2.0


def books(run, field="mass"):
    """What a quantity's books leave over: end - (start + in - out [+ walls])."""
    b = run.summary["conservation"][field]
    return b["end"] - (b["start"] + b["in"] - b["out"] + b.get("walls", 0.0))


def flow_checks(run, bins, window, profile_err, slope, dpdx):
    """The checks of a flow between an inlet and an outlet: the velocity profile over the middle half
    (the largest mean deviation over the `bins` one spacing thick), the pressure gradient there
    against dpdx, and the mass books."""
    mass = run.summary["conservation"]["mass"]
    return [
        {"metric": f"max |mean(u - u_exact)| / u_max over the {bins} one spacing thick, L / 4 < x < 3 L / 4, {window} "
                   "(gate: issue 9's for the Poiseuille cases)", "value": profile_err, "gate": 0.01},
        {"metric": f"|dp/dx - ({dpdx:g} Pa/m)| / {-dpdx:g} Pa/m, dp/dx the slope fitted over L / 4 < x < 3 L / 4, "
                   "mean over the outputs (gate: issue 48's for the drag on a body)", "value": abs(slope - dpdx) / abs(dpdx), "gate": 0.05},
        {"metric": "mass books |end - (start + in - out)| / start (gate: round-off)", "value": abs(books(run)) / mass["start"], "gate": 1e-9}]


def channel_inflow(run):
    """Plane Poiseuille flow between a parabolic inlet and an outlet at p = 0, U the mean inflow
    velocity: over the middle half of the channel (L / 4 < x < 3 L / 4) the velocity profile,
    the mean of u - 6 U y (H - y) / H^2 over the particles of each layer one spacing thick and the
    outputs of the last CHANNEL_INFLOW_WINDOW seconds, against u_max = 1.5 U; the pressure
    gradient, the slope of a straight line fitted to p(x) of the particles there, one per output,
    its mean against -12 mu U / H^2; and the mass books."""
    mat = next(iter(run.scene["materials"].values()))
    mu = mat["density"] * mat["viscosity"]
    L, H = run.scene["domain"]["max"][0], run.scene["domain"]["max"][1]
    U, dx = INLET_MEAN_VELOCITY, run.spacing
    umax, dpdx = 1.5 * U, -12 * mu * U / H**2
    layers = int(round(H / dx))
    dev, count, ysum, usum = (np.zeros(layers) for _ in range(4))
    slopes = []
    xbins = np.linspace(0, L, 17)
    psum, pcount = np.zeros(16), np.zeros(16)
    frames = steady_frames(run, CHANNEL_INFLOW_WINDOW)
    for k in frames:
        p = run.particles(k)
        mid = (p["x"] > L / 4) & (p["x"] < 3 * L / 4)
        y, u = p["y"][mid], p["vx"][mid]
        j = np.clip((y / dx).astype(int), 0, layers - 1)
        dev += np.bincount(j, u - 6 * U * y * (H - y) / H**2, layers)
        count += np.bincount(j, minlength=layers)
        ysum += np.bincount(j, y, layers)
        usum += np.bincount(j, u, layers)
        slopes.append(np.polyfit(p["x"][mid], p["pressure"][mid], 1)[0])
        i = np.clip(np.digitize(p["x"], xbins) - 1, 0, 15)
        psum += np.bincount(i, p["pressure"], 16)
        pcount += np.bincount(i, minlength=16)
    profile_err = float(np.abs(dev / count).max() / umax)
    slope = float(np.mean(slopes))
    last = run.particles(frames[-1])
    mid = (last["x"] > L / 4) & (last["x"] < 3 * L / 4)
    single = float(np.abs(last["vx"] - 6 * U * last["y"] * (H - last["y"]) / H**2)[mid].max() / umax)
    mass = run.summary["conservation"]["mass"]
    t0, t = run.time(frames[0]), run.time()
    window = f"t = {t0:g} to {t:g} s ({len(frames)} outputs)"
    checks = flow_checks(run, "layers", window, profile_err, slope, dpdx)
    notes = (f"dp/dx {slope:.4g} Pa/m against {dpdx:g} (single outputs {min(slopes):.4g} to {max(slopes):.4g}), the drop "
             f"over the channel {-slope * L:.4g} Pa against {-dpdx * L:.4g}; the largest single particle's |u - u_exact| "
             f"at t = {t:g} s {single:.3g} u_max; mass in {mass['in']:.5g} kg/m, out {mass['out']:.5g}, start "
             f"{mass['start']:.5g}, end {mass['end']:.5g}")
    ys, xs = np.linspace(0, 1, 101), (xbins[:-1] + xbins[1:]) / 2
    profile = {"xlabel": "y / H (u) or x / L (p)", "ylabel": "u / u_max or p / (12 mu U L / H^2)", "series": [
        {"label": f"app u, L / 4 < x < 3 L / 4, mean over {window}", "x": (ysum / count / H).tolist(),
         "y": (usum / count / umax).tolist(), "style": "points"},
        {"label": "u exact", "x": ys.tolist(), "y": (4 * ys * (1 - ys)).tolist(), "style": "line"},
        {"label": "app p, mean over 1/16 of the length and the outputs", "x": (xs / L).tolist(),
         "y": (psum / pcount / (-dpdx * L)).tolist(), "style": "points"},
        {"label": "p exact (0 at the outlet)", "x": [0.0, 1.0], "y": [1.0, 0.0], "style": "line"}]}
    return checks, notes, profile


# pipe_inflow_3d is measured over the last 0.5 s of its run (6 outputs).
PIPE_WINDOW = 0.5


def pipe_flow(run):
    """Hagen-Poiseuille flow in a pipe of radius R between an inlet with the profile
    u = 2 U (1 - r^2 / R^2) and an outlet at p = 0: over the middle half of the pipe the velocity,
    the mean of u - u_exact over the particles of each shell one spacing thick and the outputs of
    the last PIPE_WINDOW seconds, against u_max = 2 U; the pressure gradient, the slope of a
    straight line fitted to p(x) there, its mean over the outputs against -8 mu U / R^2; and the
    mass books."""
    mat = next(iter(run.scene["materials"].values()))
    mu = mat["density"] * mat["viscosity"]
    L = run.scene["domain"]["max"][0]
    R = next(sh["radius"] for sh in run.scene["walls"][0]["shapes"] if sh["shape"] == "cylinder")
    U, dx = INLET_MEAN_VELOCITY, run.spacing
    umax, dpdx = 2 * U, -8 * mu * U / R**2
    shells = int(np.ceil(R / dx))
    dev, count, rsum, usum = (np.zeros(shells) for _ in range(4))
    slopes = []
    frames = steady_frames(run, PIPE_WINDOW)
    for k in frames:
        p = run.particles(k)
        mid = (p["x"] > L / 4) & (p["x"] < 3 * L / 4)
        r, u = np.hypot(p["y"], p["z"])[mid], p["vx"][mid]
        j = np.clip((r / dx).astype(int), 0, shells - 1)
        dev += np.bincount(j, u - umax * (1 - r**2 / R**2), shells)
        count += np.bincount(j, minlength=shells)
        rsum += np.bincount(j, r, shells)
        usum += np.bincount(j, u, shells)
        slopes.append(np.polyfit(p["x"][mid], p["pressure"][mid], 1)[0])
    held = count > 0
    profile_err = float(np.abs(dev[held] / count[held]).max() / umax)
    slope = float(np.mean(slopes))
    mass = run.summary["conservation"]["mass"]
    window = f"t = {run.time(frames[0]):g} to {run.time():g} s ({len(frames)} outputs)"
    checks = flow_checks(run, "shells", window, profile_err, slope, dpdx)
    notes = (f"dp/dx {slope:.4g} Pa/m against {dpdx:g} (single outputs {min(slopes):.4g} to {max(slopes):.4g}); "
             f"R / dx {R / dx:g}; mass in {mass['in']:.5g} kg, out {mass['out']:.5g}")
    rs = np.linspace(0, 1, 101)
    profile = {"xlabel": "r / R", "ylabel": "u / u_max", "series": [
        {"label": f"app, L / 4 < x < 3 L / 4, mean over {window}", "x": (rsum[held] / count[held] / R).tolist(),
         "y": (usum[held] / count[held] / umax).tolist(), "style": "points"},
        {"label": "2 U (1 - r^2 / R^2)", "x": rs.tolist(), "y": (1 - rs**2).tolist(), "style": "line"}]}
    return checks, notes, profile


# Schaefer & Turek (1996), benchmark 2D-2 (Re = 100, periodic shedding): St = f D / U in
# [0.295, 0.305], the largest c_D in [3.22, 3.24], the largest c_L in [0.99, 1.01]; the
# references are the middles of those bounds. Measured over the last SHEDDING_WINDOW seconds.
SHEDDING_REFERENCE = {"St": 0.300, "c_D max": 3.23, "c_L max": 1.00}
SHEDDING_WINDOW = 2.0


def cylinder_shedding(run):
    """Strouhal number, largest drag and lift coefficients of the cylinder (probe "cylinder") in
    Schaefer & Turek's 2D-2 channel, U = 1 m/s the mean inflow: c = 2 F / (rho U^2 D)
    (shedding_figures)."""
    rho = next(iter(run.scene["materials"].values()))["density"]
    D, U = 2 * run.scene["bodies"][0]["radius"], 1.0
    pr = run.probes()
    cd = 2 * pr["cylinder.force_x"] / (rho * U**2 * D)
    cl = 2 * pr["cylinder.force_y"] / (rho * U**2 * D)
    return shedding_figures(pr["time"], cd, cl, D / U, f"D / dx {D / run.spacing:g}")


def shedding_figures(t, cd, cl, time_scale, extra):
    """Checks, notes and plot of a shedding cylinder from its drag and lift coefficients cd, cl at
    times t: the shedding frequency f the peak of the lift's spectrum between 0.5 and 10 Hz over
    the last SHEDDING_WINDOW seconds (robust to the acoustic ringing a weakly-compressible force
    carries), St = f D / U (time_scale = D / U); the largest values over the same window of the
    forces averaged over 0.05 s. `extra` ends the notes."""
    last = t >= t[-1] - SHEDDING_WINDOW
    dt = float(np.median(np.diff(t)))
    lift = cl[last] - cl[last].mean()
    f = np.fft.rfftfreq(len(lift), dt)
    band = (f > 0.5) & (f < 10)
    peak = float(f[band][np.argmax(np.abs(np.fft.rfft(lift))[band])])
    box = np.ones(max(1, int(round(0.05 / dt))))
    smooth = lambda c: np.convolve(c[last], box / len(box), mode="valid")
    values = {"St": peak * time_scale, "c_D max": float(smooth(cd).max()), "c_L max": float(smooth(cl).max())}
    checks = [{"metric": f"|{k} - {ref:g}| / {ref:g} (Schaefer & Turek 1996, 2D-2), over the last {SHEDDING_WINDOW:g} s",
               "value": abs(values[k] - ref) / ref if math.isfinite(values[k]) else float("inf"), "gate": 0.05}
              for k, ref in SHEDDING_REFERENCE.items()]
    notes = (f"St {values['St']:.4g} (lift spectrum peak {peak:.3g} Hz), c_D max {values['c_D max']:.4g} "
             f"(mean {float(cd[last].mean()):.4g}), c_L max {values['c_L max']:.4g}; {extra}")
    profile = {"xlabel": "t [s]", "ylabel": "c_D, c_L", "series": [
        {"label": "app c_D", "x": t.tolist(), "y": cd.tolist(), "style": "line"},
        {"label": "app c_L", "x": t.tolist(), "y": cl.tolist(), "style": "line"},
        {"label": "c_D max 3.23, c_L max 1.00 (Schaefer & Turek 1996)", "x": [0.0, float(t[-1])],
         "y": [3.23, 3.23], "style": "line"}]}
    return checks, notes, profile


def graetz_plates(terms=30, n=500):
    """The Graetz problem between parallel plates (Shah & London 1978, ch. VII): fully developed
    flow u = 1.5 U (1 - eta^2), eta = y / b from the centre line to the wall (b = H / 2), fluid at
    T_in entering between walls held at T_w, axial conduction neglected. theta = (T - T_w) /
    (T_in - T_w) = sum_n c_n phi_n(eta) exp(-lambda_n xh), xh = x alpha / (U b^2), where
    phi'' + lambda w phi = 0, w = 1.5 (1 - eta^2), phi'(0) = 0, phi(1) = 0: solved here by second-
    order finite differences on n cells (symmetrised, numpy's eigh). The bulk temperature is
    theta_b = sum_n a_n exp(-lambda_n xh), a_n = (int w phi_n)^2 / int w phi_n^2 (int w = 1), and
    the local Nusselt number on the hydraulic diameter 4 b, Nu = -4 d ln(theta_b) / d xh, tends to
    4 lambda_1 = 7.5407 (Shah & London's 7.541). Returns (lambda_n, a_n)."""
    lam, phi, weight, h = sturm_liouville(n)
    lam, phi = lam[:terms], phi[:, :terms]
    g = (phi * weight[:, None]).sum(axis=0) * h
    return lam, g * g / ((phi**2 * weight[:, None]).sum(axis=0) * h)


def sturm_liouville(n, extra=0.0):
    """Eigenpairs of -phi'' = lambda (w + extra) phi on [0, 1], phi'(0) = 0, phi(1) = 0, w =
    1.5 (1 - eta^2): nodes eta_i = i / n, i < n; the row of eta = 0 (phi(-h) = phi(h)) halved, so
    that the matrix is symmetric. Returns lambda (increasing), phi (columns), the quadrature
    weights times w, the cell size."""
    h = 1.0 / n
    eta = np.arange(n) * h
    half = np.ones(n)
    half[0] = 0.5
    K = (np.diag(np.full(n, 2.0)) - np.diag(np.ones(n - 1), 1) - np.diag(np.ones(n - 1), -1)) / h**2
    K[0, 1] = -2 / h**2
    S = K * half[:, None]
    w = 1.5 * (1 - eta**2)
    M = half * (w + extra)
    d = 1 / np.sqrt(M)
    lam, v = np.linalg.eigh(S * d[:, None] * d[None, :])
    return lam, v * d[:, None], half * w, h


def graetz_developed(peb):
    """The developed Graetz mode with axial conduction, Peclet number peb = U b / alpha: theta =
    phi(eta) exp(-lambda xh) with phi'' + (lambda w + lambda^2 / peb^2) phi = 0 (by fixed-point
    iteration on lambda). Returns lambda, the Nusselt number on 4 b from the wall flux,
    Nu = -4 phi'(1) / int w phi = 4 lambda (1 + lambda r / peb^2) (the energy balance over a
    section: the axial conduction of the developed profile added), and r = int phi / int w phi."""
    lam = 1.885
    for _ in range(100):
        values, phi, weight, h = sturm_liouville(500, lam / peb**2)
        lam, previous = float(values[0]), lam
        if abs(lam - previous) < 1e-12:
            break
    phi = phi[:, 0]
    half = np.ones(len(phi))
    half[0] = 0.5
    r = (half * phi).sum() / (weight * phi).sum()
    return float(lam), float(4 * lam * (1 + lam * r / peb**2)), float(r)


def graetz_axial(peb, xh_end, nx=1200, ny=40):
    """The Graetz problem with axial conduction, w theta_xh = theta_xh,xh / peb^2 + theta_eta,eta,
    as the apps pose it: the inlet's and the outlet's buffer particles exchange no heat, so no
    heat is conducted across x = 0 (the fluid's heat there is the heat carried in at T_in,
    Danckwerts' (1953) condition w theta - theta_xh / peb^2 = w) nor across the outlet
    (theta_xh = 0 at xh_end); theta = 0 at the wall. Central differences on nx nodes from xh = 0
    to xh_end and ny cells across, solved by block tridiagonal elimination along x. Returns xh
    and theta_b (mixing cup)."""
    dx, de = xh_end / (nx - 1), 1.0 / ny
    eta = np.arange(ny) * de
    w = 1.5 * (1 - eta**2)
    K = (np.diag(np.full(ny, 2.0)) - np.diag(np.ones(ny - 1), 1) - np.diag(np.ones(ny - 1), -1)) / de**2
    K[0, 1] = -2 / de**2
    a = 1 / (peb * dx)**2
    lower, upper = -a - w / (2 * dx), -a + w / (2 * dx)
    diag = K + 2 * a * np.eye(ny)
    C, d = [None] * nx, [None] * nx
    # node 0: the ghost theta_{-1} = theta_1 - 2 dx peb^2 w (theta_0 - 1) of Danckwerts' condition
    g = 2 * dx * peb**2 * w
    B = diag - np.diag(lower * g)
    C[0], d[0] = np.linalg.solve(B, np.diag(upper + lower)), np.linalg.solve(B, -lower * g)
    for i in range(1, nx):  # forward elimination; at the outlet theta_nx = theta_{nx-2}
        lo = lower + upper if i == nx - 1 else lower
        B = diag - lo[:, None] * C[i - 1]
        C[i] = np.linalg.solve(B, np.diag(upper)) if i < nx - 1 else None
        d[i] = np.linalg.solve(B, -lo * d[i - 1])
    theta = [None] * nx
    theta[-1] = d[-1]
    for i in range(nx - 2, -1, -1):
        theta[i] = d[i] - C[i] @ theta[i + 1]
    quad = w * de
    quad[0] /= 2
    return np.arange(nx) * dx, np.array(theta) @ quad / quad.sum()


# graetz_2d is measured on the mean of its last 3 s (31 outputs), after two flow-through times.
GRAETZ_WINDOW = 3.0


def graetz_bulk_temperature(run, L, dx, t_in, t_w):
    """graetz_2d's frames of its last GRAETZ_WINDOW s, its slices' centres x and their theta_b."""
    edges = np.arange(0, L + dx, 2 * dx)
    edges[-1] = L
    n = len(edges) - 1
    num, den, xsum, count = (np.zeros(n) for _ in range(4))
    frames = steady_frames(run, GRAETZ_WINDOW)
    for k in frames:
        p = run.particles(k)
        i = np.clip(np.digitize(p["x"], edges) - 1, 0, n - 1)
        uv = p["vx"] * p["mass"] / p["density"]
        num += np.bincount(i, uv * (p["temperature"] - t_w), n)
        den += np.bincount(i, uv, n)
        xsum += np.bincount(i, p["x"], n)
        count += np.bincount(i, minlength=n)
    return frames, xsum / count, num / den / (t_in - t_w)


def graetz_series_developed_at(L, scale, lam, a):
    """The series' points xs, its modes' decay there, and where it is developed (local Nu in 1 %)."""
    xs = np.linspace(0, L, 2001)
    decay = np.exp(-np.outer(xs * scale, lam))
    local = 4 * (decay @ (a * lam)) / (decay @ a)
    return xs, decay, float(xs[np.argmax(np.abs(local / (4 * lam[0]) - 1) < 0.01)])


def graetz(run):
    """Hot water (T_in) entering with the parabolic profile of mean velocity U between walls held
    at T_w: the bulk (mixing-cup) temperature theta_b = sum u T V / sum u V over slices two
    spacings thick (V = m / rho; the outputs of the last GRAETZ_WINDOW seconds summed), as
    (T_b - T_w) / (T_in - T_w), against the Graetz series (graetz_plates) over the whole channel;
    the Nusselt number where the series is developed (its local Nu within 1 % of 7.5407) up to
    H / 2 before the outlet: the decay rate lambda of a straight line fitted to ln theta_b
    against xh = x alpha / (U b^2), Nu = 4 lambda (1 + lambda r / Pe_b^2) (graetz_developed: the
    wall's heat from the energy balance of a section, with the axial conduction of the developed
    profile), against the developed Nu at the scene's Peclet number; and the heat books, what the
    walls gave against what the fluid's heat, inflow and outflow say they gave."""
    mat = next(iter(run.scene["materials"].values()))
    alpha = mat["conductivity"] / (mat["density"] * mat["heat_capacity"])
    L, H = run.scene["domain"]["max"][0], run.scene["domain"]["max"][1]
    sides = run.scene["boundaries"]
    t_in, t_w = sides["x_min"]["temperature"], sides["y_min"]["thermal"]["temperature"]
    U, b, dx = INLET_MEAN_VELOCITY, H / 2, run.spacing
    peb = U * b / alpha
    scale = alpha / (U * b * b)  # xh per metre
    frames, x, theta = graetz_bulk_temperature(run, L, dx, t_in, t_w)
    lam, a = graetz_plates()
    series = np.exp(-np.outer(x * scale, lam)) @ a
    err = np.abs(theta - series)
    # where the series is developed: its local Nu within 1 % of 4 lambda_1
    xs, decay, x_dev = graetz_series_developed_at(L, scale, lam, a)
    fit = (x >= x_dev) & (x <= L - H / 2)
    lam_app = -float(np.polyfit(x[fit] * scale, np.log(theta[fit]), 1)[0])
    lam_pe, nu_pe, r = graetz_developed(peb)
    nu_app = 4 * lam_app * (1 + lam_app * r / peb**2)
    xh_axial, theta_axial = graetz_axial(peb, L * scale)
    axial = np.interp(x * scale, xh_axial, theta_axial)
    heat = run.summary["conservation"]["thermal_energy"]
    t0, t = run.time(frames[0]), run.time()
    window = f"t = {t0:g} to {t:g} s ({len(frames)} outputs)"
    checks = [
        {"metric": f"max |theta_b - theta_b,Graetz| over 0 < x < L (slices 2 spacings thick), {window} (gate: 5 % of "
                   "T_in - T_w, set with the case)", "value": float(err.max()), "gate": 0.05},
        {"metric": f"|Nu - {nu_pe:.4g}| / {nu_pe:.4g}, Nu from the decay of theta_b over {x_dev / H:.3g} H < x < L - H / 2 "
                   f"(developed Nu at Pe = {4 * peb:g}; 7.541 without axial conduction, Shah & London 1978; gate: 5 %, set with "
                   "the case)",
         "value": abs(nu_app - nu_pe) / nu_pe, "gate": 0.05},
        {"metric": "heat books |end - (start + in - out + walls)| / |walls| (gate: issue 59's heat balance of hot_ball_3d)",
         "value": abs(books(run, "thermal_energy")) / abs(heat["walls"]), "gate": 0.01}]
    notes = (f"Pe = U D_h / alpha = {4 * peb:g} (D_h = 2 H), Re = U H / nu = {U * H / mat['viscosity']:g}; theta_b's "
             f"largest deviation {float((theta - series)[np.argmax(err)]):+.4f} at x = {float(x[np.argmax(err)]):.4g} m; "
             f"against the Graetz problem with axial conduction and no conduction across the inlet and the outlet "
             f"(graetz_axial) {float(np.abs(theta - axial).max()):.4f}, which itself departs from the series by up to "
             f"{float(np.abs(axial - series).max()):.4f}; "
             f"decay rate of theta_b {lam_app:.4f} (4 lambda = {4 * lam_app:.4f}; the developed mode's at this Pe "
             f"{4 * lam_pe:.4f}, without axial conduction {4 * lam[0]:.4f}), Nu {nu_app:.4f}; heat from the walls "
             f"{heat['walls']:.6g} J/m, the books leave {books(run, 'thermal_energy'):.3g} J/m; mass books leave "
             f"{books(run):.2g} kg/m")
    profile = {"xlabel": "x [m]", "ylabel": "theta_b = (T_b - T_w) / (T_in - T_w)", "series": [
        {"label": f"app, mean over {window}", "x": x.tolist(), "y": theta.tolist(), "style": "points"},
        {"label": "Graetz series (no axial conduction)", "x": xs.tolist(), "y": (decay @ a).tolist(), "style": "line"},
        {"label": f"with axial conduction, Pe = {4 * peb:g}, adiabatic inlet and outlet (finite differences)", "x": (xh_axial / scale).tolist(),
         "y": theta_axial.tolist(), "style": "line"}]}
    return checks, notes, profile


# ---------------------------------------------------------------------------------------------
# The cases. "doc": documentation resolution; "study": spacings of the convergence study;
# "ci": the fast check of tests/validation (spacing, bound, where the bound comes from).
# ---------------------------------------------------------------------------------------------

GATE = "issue 9 gate"
CASES = {}


def case(name, scene, compare, doc, study, ci, **kw):
    CASES[name] = dict(name=name, scene=scene, compare=compare, doc=doc, study=study, ci=ci, **kw)


# ci = (spacing, bounds): the fast check of tests/validation at a coarse spacing. bounds None:
# every check must meet the issue's gate. Otherwise one entry per check: None (the gate) or a
# REGRESSION BOUND, NOT THE ISSUE'S GATE, for a check that misses its gate today or comes close to
# it: the error measured at that spacing (at REGRESSION_BUILD, later where noted) times 1.5,
# rounded up to two digits; the 50 % margin because the scheme is still being changed. A bound is
# tightened as the scheme improves and never raised to pass. Measured at REGRESSION_BUILD (error
# at the CI spacing -> bound):
#   poiseuille_3d 0.0206 -> 0.031; taylor_green_re100 l1 0.0231 -> 0.035 (max|v| 0.00069: gate);
#   taylor_green_re1000 l1 0.0367 -> 0.056; cavity_re100 0.262 -> 0.40; cavity_re1000 0.534 ->
#   0.81; hydrostatic_tank_3d pressure 0.0118 -> 0.018 (drift 0.0017: gate); dam break 0.988 ->
#   1.5; natural convection u_max, v_max, Nu: Ra 1e3 0.123, 0.095, 0.051 -> 0.19, 0.15, 0.077;
#   Ra 1e4 0.224, 0.259, 0.157 -> 0.34, 0.39, 0.24; Ra 1e5 0.479, 0.620, 0.397 -> 0.72, 0.93,
#   0.60; heat_pulse_3d max 0.0194 -> 0.030. At the gate: poiseuille_2d 0.0085, couette_2d
#   0.00065, couette_3d 0.0012, hydrostatic_tank_2d 0.0091 and drift 0.0068, heat_pulse_2d,
#   heat_slabs_2d, heat_slabs_k2_2d.
# Tightened at dba6dc9 (mirrored wall temperature; the free-surface scheme of 7562ed7): dam break
#   0.273 -> 0.41; natural convection u_max, v_max, Nu: Ra 1e3 0.068, 0.056, 0.0024 -> 0.11,
#   0.085, gate; Ra 1e4 0.155, 0.185, 0.024 -> 0.24, 0.28, gate; Ra 1e5 0.411, 0.562, 0.266 ->
#   0.62, 0.85, 0.40.
# Added at a84d206: dam_break_pressure_lobovsky arrival time 0.104 -> 0.16, impact peak 3.29 ->
#   5.0 (mean pressure 0.044: gate).
# Set at 94eaf21 (shifting along walls only; continuity with wall particles at rest):
#   cavity_re100 0.0577 -> 0.087; cavity_re1000 (its runs hold now) 0.137 -> 0.21; dam break
#   0.222 -> 0.34; natural convection u_max, v_max, Nu: Ra 1e3 0.040, 0.053, 0.0042 -> 0.061,
#   0.080, gate; Ra 1e4 0.100, 0.113, 0.0032 -> 0.15, 0.17, gate; Ra 1e5 at spacing 0.02 (at
#   0.04 a probe on the u line sits in a gap under the top wall and reads no fluid) 0.060,
#   0.088, 0.0061 -> 0.091, 0.14, gate; dam_break_pressure_lobovsky arrival 0.117 (bound 0.16
#   kept), peak 1.84 -> 2.8. hydrostatic_tank_2d checked at 1 / 15 (0.0097, gate): at 0.1 it is
#   0.0114, over the gate.
# Tightened at 6f7d79b (density by summation in closed, full boxes under gravity): natural
#   convection u_max, v_max: Ra 1e3 0.035, 0.030 -> 0.053, 0.045; Ra 1e4 0.046, 0.050 -> 0.069,
#   0.075; Ra 1e5 (at 0.02; at 0.04 and 0.05 the probes under the top wall see fluid again)
#   0.045, 0.066 -> 0.067, 0.099.
# Ra 1e4 re-measured after the Verlet lists (068c347: neighbours in increasing index, another
#   order of the additions): one run is not enough at 0.04, where u_max and v_max move by up to
#   0.08 with round-off. Over four runs (the default; the symmetric pair loop; time.cfl 0.249
#   and 0.251) u_max 0.015-0.091, v_max 0.022-0.077 -> 0.14, 0.12 (below the bounds of
#   94eaf21). Ra 1e3 over the same four: u_max 0.0008-0.060, v_max 0.021-0.062 (bounds kept:
#   0.053, 0.045 hold for the default run, 0.035, 0.030).
# Since the convection profiles are averaged over the last 5 outputs (one snapshot moved u_max
#   by up to 9 % between outputs at Ra 1e5), over the default, time.cfl 0.249 and 0.251 and the
#   symmetric pair loop: Ra 1e3 at 0.04 u_max 0.001-0.055, v_max 0.004-0.028 (bounds kept at
#   0.053 for u_max, which the default run meets at 0.009; v_max tightened 0.045 -> 0.042);
#   Ra 1e4 at 0.04 u_max 0.016-0.042, v_max 0.003-0.041 -> 0.063, 0.062; Ra 1e5 at 0.02 (the
#   default, cfl 0.249 and symmetric) u_max 0.020-0.063, v_max 0.035-0.068 (bounds kept).
# With the free-surface tension limit (density floor 0.99 rho0, 2026-12-03), over the default, the
#   symmetric pair loop and time.cfl 0.249 and 0.251: dam_break_pressure_lobovsky at H / 20 arrival
#   0.132-0.137 (bound 0.16 kept), peak 0.67-1.28 -> 1.9 (was 2.8), mean 0.059-0.095 (gate);
#   dam_break_martin_moyce at a / 20 0.224-0.296 (bound 0.34 kept); the cavities below.
# note: a finding about the case that its numbers alone do not show, in a sentence or two; the
# report prints it. gates: where the case's gates come from, for the report's table (default: the
# issue, "issue"). doc_note: where the documentation resolution is coarser than the case deserves
# (run.sh has to finish on 2 cores), it says so; the report prints it. miss_note: for a case that
# misses its gate, at most three sentences: the miss, its known cause, a peer's figure on the same
# set-up where one was measured. details: the report prints the run's notes (figures its checks
# table lacks). shared_cores: the wall times were measured on cores shared with other work.
# not_in_ci: why the case is not in tests/validation.
REGRESSION_BUILD = "94eaf21"
_TIME = "documented at 5e-5 (20 particles across the channel), coarser than the case deserves, so that "
_TIME += "validation/run.sh finishes on 2 cores"
case("poiseuille_2d", "poiseuille_2d.json", poiseuille, 2.5e-5, [1e-4, 5e-5, 2.5e-5], (5e-5, None))
case("poiseuille_3d", "poiseuille_3d.json", poiseuille, 5e-5, [1e-4, 1e-3 / 15, 5e-5], (1e-4, [0.031]),
     doc_note=_TIME)
case("couette_2d", "couette_2d.json", couette, 2.5e-5, [1e-4, 5e-5, 2.5e-5], (5e-5, None))
case("couette_3d", "couette_3d.json", couette, 5e-5, [1e-4, 1e-3 / 15, 5e-5], (1e-4, None),
     doc_note=_TIME)
_PYSPH_TG = ("PySPH's EDAC scheme on the same vortex (Debian's python3-pysph 1.0b1, "
             "`python3 -m pysph.examples.taylor_green --scheme edac --re {re} --nx NX --tf 2`): {pysph}.")
case("taylor_green_re100", "taylor_green_re100.json", taylor_green, 0.01, [0.04, 0.02, 0.01], (0.02, [None, 0.035]),
     note=_PYSPH_TG.format(re=100, pysph="l1 0.0216 and max|v| error 0.0185 at 50 x 50, 0.0179 and "
                           "0.0145 at 100 x 100"))
case("taylor_green_re1000", "taylor_green_re1000.json", taylor_green, 0.01, [0.04, 0.02, 0.01], (0.02, [0.056]),
     note=_PYSPH_TG.format(re=1000, pysph="l1 0.0630 and max|v| error 0.0654 at 50 x 50, 0.0223 and "
                           "0.0117 at 100 x 100"))
# Cavities read from the particles (quadratic_reading, 2026-12-02), four runs at 0.04 (the
# default, the symmetric pair loop, time.cfl 0.249 and 0.251): Re 100 0.011-0.046 -> 0.07; Re 1000
# 0.131-0.165, bound 0.21 kept. With the free-surface tension limit (2026-12-03): Re 100
# 0.0138-0.0164 -> 0.025; Re 1000 0.119-0.155, bound 0.21 kept.
case("cavity_re100", "cavity_re100.json", lambda r: cavity(r, 100, 0.03), 0.01, [0.05, 0.04, 0.02, 0.0125, 0.01], (0.04, [0.025]))
case("cavity_re1000", "cavity_re1000.json", lambda r: cavity(r, 1000, 0.05), 0.01, [0.05, 0.04, 0.02, 0.01], (0.04, [0.21]))
case("hydrostatic_tank_2d", "hydrostatic_tank_2d.json", hydrostatic, 0.025, [0.1, 0.0666666667, 0.05, 0.025],
     (0.0666666667, None))
case("hydrostatic_tank_3d", "hydrostatic_tank_3d.json", hydrostatic, 0.0666666667, [0.2, 0.125, 0.1, 0.0666666667],
     (0.125, [0.018, None]))
# The study adds a / 80 (12,800 particles, 9 min on 2 cores); documented at a / 40.
case("dam_break_martin_moyce", "dam_break_martin_moyce.json", dam_break, 0.05715 / 40,
     [0.05715 / 10, 0.05715 / 20, 0.05715 / 40, 0.05715 / 80], (0.05715 / 20, [0.34]),
     miss_note="The front leads the experiment by +0.12 to +0.16 at T = 0.83 to 2.0, at a / 40 and"
               " a / 80 alike: an offset in time, since the dam is removed at once (shifted by T ="
               " 0.175, the release-time correction of the Lethe CFD code's example, it is within "
               "0.113). PySPH on the same column (validation/pysph_martin_moyce.py) leads as much:"
               " +0.128 to +0.169 at a / 80.")
# Documented at H / 80 (4 to 5 min on 2 cores); at H / 100 the averaged impact peak is 3.07.
case("dam_break_pressure_lobovsky", "dam_break_pressure_lobovsky.json", dam_break_pressure, 0.3 / 80,
     [0.3 / 20, 0.3 / 40, 0.3 / 60, 0.3 / 80], (0.3 / 20, [0.16, 1.9, None]),
     details=True,
     miss_note="The impact peak is 63 % high and does not converge (3.92, 4.01, 2.81, 3.02 at H / "
               "20 to H / 80; its impulse 1.134 against 1.126), and the front arrives 2.4 % late: "
               "the wall pressure rings at the model's sound speed (34 m/s), and the free-surface "
               "density floor and the walls' artificial viscosity hold the thin front back. PySPH "
               "in the same tank (validation/pysph_lobovsky.py) arrives within the gate at H / 80 "
               "and misses the peak by more (3.37).")
# Each is documented at the finest spacing of its study: Ra = 1e3 and 1e4 at 0.01 (100 x 100),
# Ra = 1e5 at 0.008 (125 x 125, 25 min). Until 2026-12-02 Ra = 1e3 and 1e4 were documented at 0.02
# and Ra = 1e5 at 0.01, where they passed by errors that do not hold as the spacing shrinks; until
# a73f4e9 the profiles were the mean of 5 outputs 1 s apart, whose noise (0.6 to 0.9 % in v_max)
# made Ra = 1e4 read 3.4 % low at 100 x 100; until the change that brought quadratic_reading they
# were the probes', whose kernel average made Ra = 1e5 miss at 125 x 125 (v_max 66.40, 3.2 % low).
_V_MAX_LOW = ("v_max, the peak of the upward flow along the hot wall, converges low, within the gate (2.5 % "
              "low at 125 x 125). The flow depends on the sound speed, which at a Mach number of 0.03 it "
              "should not (Ra = 1e5, 50 x 50: v_max 69.95, 68.73 and 60.12 with c0 = 7, 10 and 20 m/s); "
              "the cause is not found.")
_V_MAX_LOW_1E4 = ("v_max converges low, within the gate (2.0 % low at 100 x 100; natural_convection_ra1e5 "
                  "says what is known of why).")
# CI bounds measured with quadratic_reading (2026-12-02) for the default, the symmetric pair loop
# and time.cfl 0.249 and 0.251, at 0.02 (at 0.04 the quadratic over a kernel of 0.12 overshoots
# the boundary layers: v_max 5.8 % high at Ra = 1e4, 4.1 % at Ra = 1e3): Ra 1e3 every check within
# 0.0096 and Ra 1e4 within 0.011, so the gate; Ra 1e5 u_max 0.017-0.038 -> 0.057, v_max
# 0.002-0.027 and Nu 0.0095-0.018, the gate.
_STUDY = [0.05, 0.04, 0.02, 0.0125, 0.01]
for _ra, _doc, _study, _ci, _bounds, _kw in (
        ("1e3", 0.01, _STUDY, 0.02, None, {}),
        ("1e4", 0.01, _STUDY, 0.02, None, {"note": _V_MAX_LOW_1E4}),
        ("1e5", 0.008, _STUDY + [0.008], 0.02, [0.057, None, None], {"note": _V_MAX_LOW})):
    case(f"natural_convection_ra{_ra}", f"natural_convection_ra{_ra}.json", (lambda ra: lambda r: natural_convection(r, ra))(_ra),
         _doc, _study, (_ci, _bounds), **_kw)
case("conduction_walls_2d", "conduction_walls_2d.json", conduction_walls, 0.04, [0.1, 0.05, 0.04], (0.05, None))
case("heat_pulse_2d", "heat_pulse_2d.json", heat_pulse, 0.01, [0.02, 0.01, 0.005], (0.02, None), details=True)
case("heat_pulse_3d", "heat_pulse_3d.json", heat_pulse, 0.02, [0.04, 0.03, 0.02], (0.04, [0.030, None]),
     details=True)
case("heat_slabs_2d", "heat_slabs_2d.json", heat_slabs, 0.005, [0.02, 0.01, 0.005], (0.02, None))
case("heat_slabs_k2_2d", "heat_slabs_2d.json", heat_slabs, 0.005, [0.02, 0.01, 0.005], (0.02, None),
     sets=["materials.right.conductivity=2"])

# The cases with geometry (issue 48): the force on a body, a curved wall, a mesh wall.
case("buoyancy_box_2d", "buoyancy_box_2d.json", buoyancy, 0.02, [0.05, 0.04, 0.02], (0.04, None), issue=48,
     shared_cores=True)
# c_D at D / dx = 10 (the CI spacing) misses the gate: 0.194 (2026-12-06, the set-up with inlet and
# outlet; 872ef69) -> regression bound 0.30 (times 1.5).
CYLINDER_CI_BOUND = 0.30
CYLINDER_NORMAL_NOTE = (
    "With `physics.shifting_normal_to_walls: true` particles near the body are shifted towards and away "
    "from it too, and the front stagnation point keeps its pressure: the drag is within the gate at both "
    "spacings, as PySPH's (+5.0 % and +2.8 %). It is not the default: the lid-driven cavity at Re 100 then "
    "misses its gate (0.0356 against 0.03 at spacing 0.01; 0.0122 with the default) and so does the 2D "
    "hydrostatic tank (0.0148 against 0.01 at 0.025; 0.0061 with the default), while natural "
    "convection at Ra 1e4 meets its gates either way (u_max, v_max, Nu 0.7, 1.5, 0.1 % with it at "
    "spacing 0.01; 1.0, 2.0, 0.0 % by default; 2026-12-07).")
CYLINDER_MISS = (
    "c_D is 6.1 % low at D / dx = 20 (19.4 % at 10); PySPH's inlet and outlet on this set-up "
    "(validation/pysph_cylinder_inlet.py) meets the gate, +2.8 % at 20, so the miss is ours: "
    "shifting along walls leaves the particles at the front stagnation point about 100 Pa below "
    "their neighbours (docs/physics.md). With the shifting's normal component kept near walls "
    "(cylinder_re20_normal_shift) c_D is within the gate, +1.3 %, but the lid-driven cavity at Re 100 "
    "and the hydrostatic tank then miss their gates, so the default keeps the shifting along walls only.")
case("cylinder_re20", "cylinder_re20.json", cylinder_benchmark, 0.005, [0.01, 0.005],
     (0.01, [CYLINDER_CI_BOUND]), issue=48, miss_note=CYLINDER_MISS,
     shared_cores=True)
# The same scene with the shifting's normal component kept near walls and bodies, the setting
# docs/physics.md recommends for flow onto a body; not the default, for the cavity's sake (the note).
case("cylinder_re20_normal_shift", "cylinder_re20.json", cylinder_benchmark, 0.005, [0.01, 0.005],
     (0.01, None), issue=56, sets=["physics.shifting_normal_to_walls=true"], note=CYLINDER_NORMAL_NOTE,
     shared_cores=True)
OBSTACLE_NOTE = (
    "The box is a triangle mesh (scenes/meshes/obstacle.stl). The front reaches H2 later than in the "
    "experiment, then follows it within about 2.5 cm; H4 follows within 2 cm throughout.")
case("dam_break_obstacle", "dam_break_obstacle.json", dam_break_obstacle, 0.05, [0.1, 0.05], (0.1, None),
     issue=48, note=OBSTACLE_NOTE, shared_cores=True)
case("floating_box_2d", "floating_box_2d.json", floating_draft, 0.01, [0.02, 0.01, 0.005], (0.01, None),
     issue=59)
case("piston_waves_2d", "piston_waves_2d.json", piston_waves, 0.01, [0.02, 0.01], (0.02, [PISTON_CI_BOUND]),
     issue=59, miss_note=PISTON_MISS)
# water_entry_2d at its CI spacing 0.011 (D / dx = 10) misses: 0.113 (2026-12-06) -> regression
# bound 0.17 (times 1.5).
WATER_ENTRY_CI_BOUND = 0.17
WATER_ENTRY_MISS = (
    "Only T = 0.10 misses: +20 % at D / dx = 40 (+11 %, +7 % at 10, 20); from T = 0.28 on the "
    "depth is within 8.4 %. That point hangs on the instant of first contact (1 ms is 16 % of it),"
    " and the data are read off a figure. PySPH's rigid-body scheme "
    "(validation/pysph_water_entry.py) misses too: 0.123 at D / dx = 20, this app 0.101.")
case("water_entry_2d", "water_entry_2d.json", water_entry, 0.00275, [0.011, 0.0055, 0.00275],
     (0.011, [WATER_ENTRY_CI_BOUND]), issue=59, gates="10 % of the experiment's depth (as Martin & Moyce's front)",
     miss_note=WATER_ENTRY_MISS)
case("hot_ball_3d", "hot_ball_3d.json", hot_ball, 0.02, [0.02], (0.02, None), issue=59)
case("floating_sphere_3d", "floating_sphere_3d.json", floating_sphere, 0.01, [0.02, 0.01], (0.02, [FLOATING_SPHERE_CI_BOUND]),
     issue=59, not_in_ci="4 min on 2 cores at 0.01, where it meets the gate; floating_box_2d holds the same "
     "coupling in CI")

# Inlets and outlets (the apps' "inlet" and "outlet" sides).
CHANNEL_INFLOW_NOTE = (
    "The water rings acoustically along the channel (the pressure drop, 0.96 Pa, is 1 % of rho c0^2): the "
    "slope of single outputs is up to 15 % off at 40 particles across. Within about 2 mm of the outlet the "
    "flow is disturbed (|v| up to 3 % of u_max).")
GRAETZ_NOTE = (
    "Nu is 3.3 % low at 20 and 40 particles across: it does not converge to the reference, as if heat spread "
    "across the flow about 3 % too slowly. theta_b's largest deviation sits at the inlet, across which the apps "
    "conduct no heat.")
case("channel_inflow_2d", "channel_inflow_2d.json", channel_inflow, 0.00025, [0.001, 0.0005, 0.00025], (0.0005, None),
     gates="the source each check names", note=CHANNEL_INFLOW_NOTE, shared_cores=True)
case("graetz_2d", "graetz_2d.json", graetz, 0.00025, [0.001, 0.0005, 0.00025], (0.001, None),
     gates="the source each check names", note=GRAETZ_NOTE, shared_cores=True)
# pipe_inflow_3d at its CI spacing (R / dx = 5) misses both gates: the profile 0.0343 -> regression
# bound 0.052, the pressure gradient 0.267 (single outputs ring from -25 to -79 Pa/m) -> 0.40
# (2026-12-06, the engine of 872ef69).
PIPE_CI_BOUNDS = [0.052, 0.40, None]
case("cylinder_re100", "cylinder_re100.json", cylinder_shedding, 0.005, [0.01, 0.005], (0.01, None),
     gates="Schaefer & Turek 1996, 2D-2", not_in_ci="40 min at D / dx = 20 on one core", shared_cores=True,
     miss_note="The wake does not shed as the benchmark's at D / dx = 10 or 20. At 20 pressure "
               "noise dominates the forces (c_L jumps by about 1 between outputs 5 ms apart, with "
               "no regular period even averaged over 0.05 s; its spectrum peaks at St 0.15 against"
               " 0.30), so c_D max within the gate is a noise peak; the mean c_D is 2.40 against "
               "about 3.2, low as in cylinder_re20. PySPH's inlet and outlet on this set-up "
               "(validation/pysph_cylinder_inlet.py --re 100, EDAC) at D / dx = 10 sheds at St 0.294 "
               "(within the gate) but misses the other two: c_D max 3.744 (+16 %), c_L max 1.164 (+16 %); "
               "the app there: St 0.55, c_D max 34 % off, c_L max 7 % off. With shifting_normal_to_walls "
               "(docs/physics.md) the wake sheds as the benchmark's at D / dx = 20: St 0.299 (0.4 % off), "
               "c_D max 3.681 (+14 %, mean 3.53), c_L max 1.392 (+39 %); at 10 St 0.199.")
case("pipe_inflow_3d", "pipe_inflow_3d.json", pipe_flow, 0.0005, [0.001, 0.0005], (0.001, PIPE_CI_BOUNDS),
     gates="the source each check names", details=True, shared_cores=True,
     note="The pipe is a wall (the difference of a box and a cylinder); where it meets the inlet's side its "
     "layers are wall, so the inlet's profile is zero outside the pipe.",
     miss_note="The profile is 1.4 % of u_max off at R / dx = 10 (3.4 % at 5), the pressure gradient within its "
     "gate there (3.0 %; 27 % at 5): both fall with the spacing, and R / dx = 20 (some 150,000 fluid particles, "
     "hours on 2 cores) is not run.")

# setup: each case in a sentence or two for the report, with its reference (the scene's
# "description" gives it all).
_CHANNEL = "Water between no-slip plates 1 mm apart{d}, "
_CONVECTION = ("De Vahl Davis's (1983) square cavity, L = 1 m, a hot and a cold wall, Boussinesq buoyancy, "
               "Pr = 0.71, Ra = {ra}, run to t = {t} s")
_PULSE = ("A Gaussian temperature pulse conducting in a periodic {d} box at rest (alpha = 1), against the "
          "analytic solution (reference_solutions.md sec. 5)")
_SLABS = ("Two slabs at rest, T = 1 and T = 0, {k}; the profile against the erf solution at t = 0.01 "
          "(reference_solutions.md sec. 5)")
_POISEUILLE = ("driven from rest by a body force 2e-4 m/s^2; the start-up series of Morris, Fox & Zhu (1997) "
               "(reference_solutions.md sec. 2)")
_COUETTE = "the upper one moving at 2.5e-5 m/s from t = 0; the start-up series (reference_solutions.md sec. 3)"
_CAVITY = ("Lid-driven unit square, Re = {re}, steady at t = {t}; velocities on the centre lines against Ghia, "
           "Ghia & Shin (1982)")
_TANK = "Water at rest 1 m deep in a 1 m wide open tank for 10 s{d} (reference_solutions.md sec. 6)"
SETUPS = {
    "poiseuille_2d": _CHANNEL.format(d="") + _POISEUILLE,
    "poiseuille_3d": _CHANNEL.format(d=" (3D)") + _POISEUILLE,
    "couette_2d": _CHANNEL.format(d="") + _COUETTE,
    "couette_3d": _CHANNEL.format(d=" (3D)") + _COUETTE,
    "taylor_green_re100": "Taylor-Green vortex in the periodic unit square, U = 1, Re = 100"
    " (reference_solutions.md sec. 4)",
    "taylor_green_re1000": "Taylor-Green vortex in the periodic unit square, U = 1, Re = 1000"
    " (reference_solutions.md sec. 4)",
    "cavity_re100": _CAVITY.format(re=100, t=20),
    "cavity_re1000": _CAVITY.format(re=1000, t=40),
    "hydrostatic_tank_2d": _TANK.format(d=""),
    "hydrostatic_tank_3d": _TANK.format(d=", in 3D"),
    "dam_break_martin_moyce": "A water column a = 57.15 mm wide and 2a high collapses along a dry floor; the "
    "surge front Z = z / a against Martin & Moyce (1952) to T = t sqrt(2 g / a) = 9.3",
    "dam_break_pressure_lobovsky": "Lobovsky et al.'s (2014) dam break, H = 0.3 m: the pressure P = p / (rho g H) "
    "on the far wall 15 mm above the floor (sensor 2) against the median and band of the repeated experiments",
    "natural_convection_ra1e3": _CONVECTION.format(ra="1e3", t=20),
    "natural_convection_ra1e4": _CONVECTION.format(ra="1e4", t=30),
    "natural_convection_ra1e5": _CONVECTION.format(ra="1e5", t=40),
    "conduction_walls_2d": "The convection cavity without gravity: walls at 70 and -30 C reach the linear "
    "profile (Nusselt number 1), compared at t = 40 s",
    "heat_pulse_2d": _PULSE.format(d="2D"),
    "heat_pulse_3d": _PULSE.format(d="3D"),
    "heat_slabs_2d": _SLABS.format(k="equal conductivities"),
    "heat_slabs_k2_2d": _SLABS.format(k="the right one twice as conductive"),
    "buoyancy_box_2d": "A fixed square body 0.2 m across, 0.5 m deep in water at rest; the water's force on it "
    "against the buoyancy rho g V = 392.4 N/m",
    "cylinder_re20": "Schaefer & Turek's (1996) benchmark 2D-1: a cylinder D = 0.1 m in a channel 2.2 m by "
    "0.41 m, parabolic inflow of mean 0.2 m/s, outflow at p = 0, Re = 20: c_D = 5.5795",
    "floating_box_2d": "A box of density 500 kg/m^3, 0.2 m by 0.1 m, released just above its rest into water "
    "0.3 m deep: it settles upright at the Archimedes draft d = 0.05 m",
    "piston_waves_2d": "A piston wave maker (stroke 0.04 m, period 1 s) in water 0.4 m deep: the wave height "
    "1 and 1.5 m from the paddle against Biesel's linear theory, H = 1.535 S",
    "water_entry_2d": "Greenhow & Lin's (1983) water entry: a cylinder D = 0.11 m of half the water's density "
    "enters still water 0.3 m deep at 2.955 m/s; the depth of its centre against the experiment to t sqrt(g / D) "
    "= 1.13",
    "hot_ball_3d": "A hot (90 C) ball of density 3000 kg/m^3, radius 0.04 m, falls into cold (10 C) water: "
    "the heat it gives against the heat the water gains, and its rest on the floor",
    "floating_sphere_3d": "A sphere of density 500 kg/m^3, radius 0.05 m, released just above its rest "
    "into water 0.2 m deep: it settles half under water (draft 0.05 m)",
    "channel_inflow_2d": "Plane Poiseuille flow (Re = 20, walls 0.01 m apart) from an inlet with the parabolic "
    "profile of mean 0.02 m/s to an outlet at p = 0: the profile, the pressure gradient -12 mu U / H^2 and the "
    "mass books",
    "cylinder_re20_normal_shift": "cylinder_re20 with `--set physics.shifting_normal_to_walls=true`: the "
    "particle shifting keeps its component towards and away from walls and bodies",
    "cylinder_re100": "Schaefer & Turek's (1996) benchmark 2D-2: the 2D-1 channel and cylinder at a mean "
    "inflow of 1 m/s, Re = 100: the Strouhal number of the shedding and the largest drag and lift",
    "pipe_inflow_3d": "Hagen-Poiseuille flow (Re = 20) in a pipe of radius R = 5 mm and length 6 R from an inlet "
    "with the parabolic profile of mean 0.02 m/s to an outlet at p = 0: the profile, the pressure gradient "
    "-8 mu U / R^2 and the mass books",
    "graetz_2d": "The Graetz problem between parallel plates: water at 60 C enters with the parabolic profile "
    "(Re = 20, Pe = 40) a channel 6 H long with walls at 20 C; the bulk temperature against the Graetz series, "
    "the developed Nusselt number and the heat books",
    "dam_break_obstacle": "MARIN's dam break (SPHERIC test 2, Kleefsman et al. 2005) in 3D: a water column "
    "0.55 m deep hits a box on the floor; water heights H2 and H4 against the experiment to t = 1.5 s",
}
for _name, _text in SETUPS.items():
    CASES[_name]["setup"] = _text
assert set(SETUPS) == set(CASES), "every case has its set-up"


def app_commit():
    # NUMERICS_APP_BUILD names the build where the apps do not come from this working tree
    # (e.g. built from a clean export of a commit while the tree holds others' edits).
    if os.environ.get("NUMERICS_APP_BUILD"):
        return os.environ["NUMERICS_APP_BUILD"]
    try:
        head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no", "--", "include", "src", "apps"],
                               capture_output=True, text=True).stdout.strip()
        return head + ("+uncommitted changes in include/ src/ apps/" if dirty else "")
    except OSError:
        return "unknown"


def run_case(name, spacing, bin_dir, threads, sets=()):
    c = CASES[name]
    run = run_app(c, spacing, bin_dir, threads, sets)
    try:
        checks, notes, profile = c["compare"](run)
    finally:
        shutil.rmtree(run.out, ignore_errors=True)
    for ch in checks:
        ch["passed"] = bool(ch["value"] <= ch["gate"])
    for ser in profile["series"]:
        step = max(1, len(ser["x"]) // 3000)
        ser["x"], ser["y"] = ser["x"][::step], ser["y"][::step]
    main = max(checks, key=lambda ch: ch["value"] / ch["gate"])
    s = run.summary
    return {"case": name, "scene": "scenes/validation/" + c["scene"], "spacing": run.spacing,
            "fluid_particles": s.get("fluid_particles"), "steps": s.get("steps"), "final_time": s.get("final_time"),
            "wall_seconds": s.get("wall_seconds"), "threads": threads, "command": run.command,
            "error": main["value"], "gate": main["gate"], "metric": main["metric"],
            "passed": all(ch["passed"] for ch in checks), "checks": checks, "notes": notes,
            "app_build": app_commit(), "profile": profile}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("list")
    sp = sub.add_parser("spacings", help="the spacings of a case's convergence study, finest last")
    sp.add_argument("case", choices=sorted(CASES))
    r = sub.add_parser("run")
    r.add_argument("case", choices=sorted(CASES))
    r.add_argument("--spacing", type=float, help="particle spacing (default: the documentation resolution; 'ci' with --check ci)")
    r.add_argument("--bin", default=os.path.join(ROOT, "build", "release", "apps"), help="directory of the apps")
    r.add_argument("--threads", type=int, default=2)
    r.add_argument("--json", help="write the result here")
    r.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="passed on to the app (a study of one option; not for the report)")
    r.add_argument("--check", choices=["ci", "gate"], help="exit 1 unless within the CI bound or the issue's gate")
    a = ap.parse_args()
    if a.cmd == "list":
        for n, c in sorted(CASES.items()):
            print(n, c["scene"], "doc", c["doc"], "study", c["study"], "ci", c["ci"][0])
        return 0
    c = CASES[a.case]
    if a.cmd == "spacings":
        print(" ".join(f"{x:.10g}" for x in sorted(c["study"], reverse=True)))
        return 0
    spacing = a.spacing if a.spacing else (c["ci"][0] if a.check == "ci" else c["doc"])
    try:
        res = run_case(a.case, spacing, a.bin, a.threads, a.set)
    except RuntimeError as e:
        # The run itself failed (unstable, refused scene...): recorded, never hidden.
        if a.json:
            with open(a.json, "w") as f:
                json.dump({"case": a.case, "spacing": spacing, "failed": str(e), "app_build": app_commit()}, f, indent=1)
        print(f"{a.case}: {e}", file=sys.stderr)
        return 1
    if a.check == "ci":
        bounds = c["ci"][1] or [None] * len(res["checks"])
        for ch, b in zip(res["checks"], bounds):
            ch["ci_bound"] = ch["gate"] if b is None else b
            ch["ci_bound_kind"] = "gate" if b is None else "regression bound, not the issue's gate (an error measured at the CI spacing + 50 %; validation/cases.py gives when)"
    text = json.dumps(res, indent=1)
    if a.json:
        with open(a.json, "w") as f:
            f.write(text + "\n")
    for ch in res["checks"]:
        print(f"{a.case}: {ch['metric']}: {ch['value']:.5g} (gate {ch['gate']:g}): {'pass' if ch['passed'] else 'MISSED'}")
    print(f"{a.case}: {res['notes']}")
    print(f"{a.case}: spacing {res['spacing']:g}, {res['fluid_particles']} fluid particles, {res['steps']} steps, {res['wall_seconds']:.1f} s")
    if a.check == "gate":
        return 0 if res["passed"] else 1
    if a.check == "ci":
        ok = True
        for ch in res["checks"]:
            good = ch["value"] <= ch["ci_bound"]
            ok &= good
            print(f"{a.case}: CI: {ch['metric']}: {ch['value']:.5g} <= {ch['ci_bound']:g} ({ch['ci_bound_kind']}): {'pass' if good else 'FAIL'}")
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
