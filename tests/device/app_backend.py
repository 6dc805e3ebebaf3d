#!/usr/bin/env python3
"""The apps on the CUDA back end (--backend cuda) against the CPU back end.

  app_backend.py FLUID_SIM FLUID_SIM_3D SCENES_DIR WORK_DIR --mode host|gpu

--mode host (label device, every build): the device step runs on the host execution
  (NUMERICS_TEST_DEVICE_EXECUTION=host: the same functors the CUDA kernels run, in loops), so
  the apps' use of it is tested without a GPU: short runs of the 2D and 3D dam breaks and of the
  2D default scene (bodies and heat) against the CPU back end, two runs bitwise identical, a
  restart CPU -> cuda -> CPU, every shipped scene that runs on the back end (coarse, short)
  against the CPU back end, water leaving through an open side, and the refusals.
--mode gpu (label gpu): the same on the GPU, longer, with the figures within 1 %; exits 77
  (ctest: skipped) with the reason when the build has no CUDA back end or there is no GPU.
--short (with --mode gpu): the runs a fifth as long (the GPU check bundle's first contact,
  bench/gpu_bundle.sh); --mode host is short already.
"""
import argparse
import filecmp
import json
import os
import shutil
import subprocess
import sys

SKIP = 77


def run(app, args, env_extra=None, check=True):
    env = dict(os.environ)
    env.update(env_extra or {})
    p = subprocess.run([app] + args, capture_output=True, text=True, env=env)
    if check and p.returncode != 0:
        sys.exit(f"FAILED: {' '.join([app] + args)} exit {p.returncode}\n{p.stderr}")
    return p


def summary(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def particles(directory, index):
    """The last particle CSV as {id: row of floats}."""
    rows = {}
    with open(os.path.join(directory, f"particles_{index:04d}.csv")) as f:
        header = f.readline().strip().split(",")
        for line in f:
            values = [float(v) for v in line.split(",")]
            rows[int(values[header.index("id")])] = values
    return header, rows


def last_csv(directory):
    files = sorted(n for n in os.listdir(directory) if n.startswith("particles_") and n.endswith(".csv"))
    return int(files[-1][10:14])


def close(name, a, b, tolerance, scale=None):
    scale = scale if scale is not None else max(abs(a), abs(b), 1e-300)
    ok = abs(a - b) <= tolerance * scale
    print(f"  {'ok  ' if ok else 'FAIL'} {name}: {a:.9g} against the cpu run {b:.9g} (tolerance {tolerance:g} of {scale:.3g})")
    return ok


def dims(header):
    return 3 if "z" in header else 2


def paired(pg, pc, dim):
    """The two runs' particles in pairs, by id. An inlet's new particles take their ids in each
    engine's storage order, so two made in the same step may swap ids: a pair whose places
    differ by more than 1e-9 m is made again by place."""
    near = lambda a, b: sum((a[k] - b[k]) ** 2 for k in range(dim)) <= 1e-18
    pairs = [(pg[i], pc[i]) for i in pc if i in pg and near(pg[i], pc[i])]
    left_g = [pg[i] for i in pg if i not in pc or not near(pg[i], pc[i])]
    for i in pc:
        if i in pg and near(pg[i], pc[i]):
            continue
        best = min(left_g, key=lambda g: sum((g[k] - pc[i][k]) ** 2 for k in range(dim)))
        left_g.remove(best)
        pairs.append((best, pc[i]))
    return pairs


def compare_runs(gpu_dir, cpu_dir, tolerance, same_steps):
    g, c = summary(gpu_dir), summary(cpu_dir)
    ok = g["status"] == "completed" and c["status"] == "completed"
    print(f"  backend {g['backend']} ({g.get('device', '')}), {g['steps']} steps; cpu {c['steps']} steps")
    if same_steps:
        ok &= g["steps"] == c["steps"]
    ok &= close("final time", g["final_time"], c["final_time"], 1e-12)
    cg, cc = g["conservation"], c["conservation"]
    ok &= close("mass", cg["mass"]["end"], cc["mass"]["end"], 1e-12)
    for books in ("in", "out"):  # inlets and outlets: the mass that crossed them
        if books in cc["mass"]:
            ok &= close(f"mass {books}", cg["mass"][books], cc["mass"][books], 1e-12,
                        max(cc["mass"]["end"], 1e-300))
    ok &= close("kinetic energy", cg["kinetic_energy"]["end"], cc["kinetic_energy"]["end"], tolerance)
    ok &= close("potential energy", cg["potential_energy"]["end"], cc["potential_energy"]["end"], tolerance)
    scale = max(abs(x) for x in cc["momentum"]["end"] + [1e-300]) + 1e-3 * cc["mass"]["end"]
    for k, (a, b) in enumerate(zip(cg["momentum"]["end"], cc["momentum"]["end"])):
        ok &= close(f"momentum[{k}]", a, b, tolerance, scale)
    tg, tc = cg["thermal_energy"], cc["thermal_energy"]
    change = tc["end"] - tc["start"]
    if abs(change) > 1e-9 * abs(tc["end"]):  # heat flowed: the change of the fluid's thermal energy
        ok &= close("thermal energy change", tg["end"] - tg["start"], change, tolerance)
    if "walls" in tc:  # the heat books: what fixed temperatures and sources gave
        ok &= "walls" in tg and close("heat given by walls and bodies", tg["walls"], tc["walls"],
                                      tolerance, max(abs(tc["walls"]), 1e-9 * abs(tc["end"])))
    # The fluid's front: the largest x of a fluid particle (the dam break's surge).
    hg, pg = particles(gpu_dir, last_csv(gpu_dir))
    hc, pc = particles(cpu_dir, last_csv(cpu_dir))
    kind = hg.index("kind")
    front = lambda p: max(r[0] for r in p.values() if r[kind] == 0)
    ok &= close("front (largest fluid x)", front(pg), front(pc), tolerance)
    if "temperature" in hc:  # every particle's temperature, against the range of temperatures
        t = hc.index("temperature")
        span = max(r[t] for r in pc.values()) - min(r[t] for r in pc.values())
        worst = max(abs(g[hg.index("temperature")] - c[t]) for g, c in paired(pg, pc, dims(hc)))
        ok &= close("largest temperature difference", worst, 0.0, tolerance, span)
    if os.path.exists(os.path.join(cpu_dir, "bodies.csv")):
        ok &= compare_bodies(gpu_dir, cpu_dir, tolerance)
    return ok


# bodies.csv's columns by kind: each is compared against the largest value of its kind in the
# cpu run, and at least (the floor) 1 rad for attitudes, 1 rad/s for spins, the largest force
# times 1 cm for torques (a body at rest or turning by round-off has them near zero).
BODY_KINDS = {"x": "position", "y": "position", "z": "position", "vx": "velocity",
              "vy": "velocity", "vz": "velocity", "angle": "attitude", "q0": "attitude",
              "q1": "attitude", "q2": "attitude", "q3": "attitude", "omega": "spin", "wx": "spin",
              "wy": "spin", "wz": "spin", "fx": "force", "fy": "force", "fz": "force",
              "torque": "torque", "tx": "torque", "ty": "torque", "tz": "torque"}


def compare_bodies(gpu_dir, cpu_dir, tolerance):
    """bodies.csv (moving bodies): every row's path, velocities, loads and heat against the cpu
    run's, each column against the largest value of its kind (BODY_KINDS)."""
    def rows(directory):
        with open(os.path.join(directory, "bodies.csv")) as f:
            return [line.strip().split(",") for line in f if line.strip()]
    g, c = rows(gpu_dir), rows(cpu_dir)
    if g[0] != c[0] or len(g) != len(c) or any(a[1] != b[1] for a, b in zip(g[1:], c[1:])):
        print(f"  FAIL bodies.csv: {len(g) - 1} rows against the cpu run's {len(c) - 1}, or other columns or bodies")
        return False
    kind = lambda name: BODY_KINDS.get(name, name)
    largest = {}
    for k, name in enumerate(c[0]):
        if name != "body":
            largest[kind(name)] = max([largest.get(kind(name), 0.0)] + [abs(float(r[k])) for r in c[1:]])
    floor = {"attitude": 1.0, "spin": 1.0, "torque": 1e-2 * largest.get("force", 0.0)}
    worst, where = -1.0, ""
    for k, name in enumerate(c[0]):
        if name == "body":
            continue
        scale = max(largest[kind(name)], floor.get(kind(name), 0.0), 1e-300)
        diff = max(abs(float(a[k]) - float(b[k])) for a, b in zip(g[1:], c[1:]))
        if diff / scale > worst:
            worst, where = diff / scale, name
    return close(f"bodies.csv, {len(c) - 1} rows: largest relative difference (column {where})", worst,
                 0.0, tolerance, 1.0)


# The shipped scenes the CUDA back end runs (scene, end time, spacing, what it adds), and those it
# refuses with the scene key it names.
SHIPPED = [("buoyant_blob_2d.json", "0.05", "0.02", "density by summation"),
           ("dam_break_hot_cold_2d.json", "0.01", "0.02", "bodies, heat"),
           ("falling_film_hot_tubes_2d.json", "0.3", "0.02", "emitters, open top, heat books"),
           ("weir_slope_2d.json", "0.05", "0.04", "a polygon wall, open top"),
           ("dam_break_3d.json", "0.05", "0.08", "3D"),
           ("hot_cold_exchange_3d.json", "0.02", "0.04", "open top, heat books"),
           ("hoses_3d.json", "0.1", "0.04", "emitters"),
           ("hot_water_cold_cup_3d.json", "0.05", "0.04", "a cylinder-difference wall, emitters"),
           ("heat_exchanger_2d.json", "0.5", "0.01", "an inlet and an outlet, heat books"),
           ("hot_pipe_3d.json", "0.1", "0.0014", "an inlet into a pipe, an outlet")]
# The moving bodies' scenes (a last item: --set changes; the flap gate's water column moved up to
# 5 cm before the gate, so that it hits the gate within the short run).
SHIPPED += [("flap_gate_2d.json", "0.1", "0.01", "two free bodies on hinges, heat", "fluids.0.max=[0.74,0.45]"),
            ("floating_box_waves_2d.json", "0.05", "0.02", "a prescribed piston, a free box"),
            ("stirred_tank_2d.json", "0.1", "0.02", "a prescribed turning stirrer"),
            ("hot_ball_drop_3d.json", "0.1", "0.05", "a free ball dropped into water, heat")]
REFUSED = []


def shipped_scenes(a, work, env, quiet):
    """Every shipped scene without plugins: the ones the back end runs against the CPU back end
    (same steps, figures to 1e-6), the others refused with one line naming the key (exit 5)."""
    ok = True
    for name, end, dx, what, *sets in SHIPPED:
        app = a.fluid_sim_3d if name.endswith("_3d.json") else a.fluid_sim
        scene = os.path.join(a.scenes, name)
        print(f"{name} ({what}), t = {end} s, dx = {dx}:")
        g, c = (os.path.join(work, name[:-5] + tag) for tag in ("_cuda", "_cpu"))
        extra = ["--end-time", end, "--set", f"particles.spacing={dx}"] + quiet
        extra += [a for s in sets for a in ("--set", s)]
        run(app, [scene, "--backend", "cuda", "--out", g] + extra, env)
        run(app, [scene, "--backend", "cpu", "--out", c] + extra)
        ok &= compare_runs(g, c, 1e-6, same_steps=True)
    for name, key in REFUSED:
        app = a.fluid_sim_3d if name.endswith("_3d.json") else a.fluid_sim
        p = run(app, [os.path.join(a.scenes, name), "--backend", "cuda", "--out",
                      os.path.join(work, "refused")] + quiet, env, check=False)
        good = p.returncode == 5 and key in p.stderr and len(p.stderr.strip().splitlines()) == 1
        print(f"  {'ok  ' if good else 'FAIL'} {name} refused: exit {p.returncode}: {p.stderr.strip()}")
        ok &= good
    return ok


def parse_args():
    """The command line (see the module's docstring)."""
    ap = argparse.ArgumentParser()
    ap.add_argument("fluid_sim")
    ap.add_argument("fluid_sim_3d")
    ap.add_argument("scenes")
    ap.add_argument("work")
    ap.add_argument("--mode", choices=["host", "gpu"], required=True)
    ap.add_argument("--short", action="store_true", help="--mode gpu: runs a fifth as long")
    return ap.parse_args()


def gpu_missing(a, work, env, quiet, s2):
    """--mode gpu: SKIP (the reason printed) without a CUDA back end or a GPU, else None."""
    version = run(a.fluid_sim, ["--version"]).stdout
    if "back end (--backend cuda): built" not in version:
        print("skipped: no GPU test possible: this build has no CUDA back end (" + version.strip().splitlines()[-1] + ")")
        return SKIP
    probe = run(a.fluid_sim, [s2, "--backend", "cuda", "--end-time", "1e-4", "--out",
                              os.path.join(work, "probe")] + quiet, env, check=False)
    if probe.returncode == 12:
        print("skipped: no GPU: " + probe.stderr.strip())
        return SKIP
    if probe.returncode != 0:
        sys.exit(f"FAILED: the probe run exited {probe.returncode}: {probe.stderr}")
    return None


def dam_breaks(a, work, env, quiet, scenes, host, gpu_time, tolerance):
    """The 2D and 3D dam breaks and the 2D default scene: cuda against cpu; True where all agree."""
    s2, s3, hot_cold = scenes
    ok = True
    # 2D and 3D dam breaks: cuda against cpu. On the host execution the order of operations is
    # the CPU's up to round-off, so the figures agree to many digits and the steps are the same;
    # on the GPU (its own pow and libm) within 1 %.
    cases = [("2D dam break (Martin & Moyce)", a.fluid_sim, s2, "0.05" if host else gpu_time("0.5"), []),
             ("3D dam break", a.fluid_sim_3d, s3, "0.05" if host else gpu_time("0.5"),
              ["--set", "particles.spacing=0.08"] if host else []),
             ("2D default scene (bodies, heat)", a.fluid_sim, hot_cold,
              "0.01" if host else gpu_time("0.2"), [])]
    for name, app, scene, end, extra in cases:
        print(name + ", t = " + end + " s:")
        tag = name.split(" ")[0] + ("_default" if "default" in name else "")
        g, c = os.path.join(work, tag + "_cuda"), os.path.join(work, tag + "_cpu")
        run(app, [scene, "--backend", "cuda", "--end-time", end, "--out", g] + quiet + extra, env)
        run(app, [scene, "--backend", "cpu", "--end-time", end, "--out", c] + quiet + extra)
        ok &= compare_runs(g, c, tolerance, same_steps=host)
    return ok


def two_runs_bitwise(a, work, env, quiet, s2, host, gpu_time):
    """Two cuda runs: bitwise identical (their checkpoints byte for byte); True where they are."""
    print("two cuda runs, bitwise:")
    end = "0.02" if host else gpu_time("0.2")
    dirs = [os.path.join(work, f"repeat{k}") for k in (1, 2)]
    for d in dirs:
        run(a.fluid_sim, [s2, "--backend", "cuda", "--end-time", end, "--checkpoint-every", end,
                          "--out", d] + quiet, env)
    same = filecmp.cmp(os.path.join(dirs[0], "checkpoint_0001.chk"),
                       os.path.join(dirs[1], "checkpoint_0001.chk"), shallow=False)
    print(f"  {'ok  ' if same else 'FAIL'} checkpoint_0001.chk identical")
    return same


def restart_cpu_cuda_cpu(a, work, env, quiet, s2, host, gpu_time, tolerance):
    """Restart CPU -> cuda -> CPU against the CPU all the way; True where they agree."""
    print("restart cpu -> cuda -> cpu:")
    t1, t2, t3 = ("0.01", "0.02", "0.03") if host else tuple(gpu_time(t) for t in ("0.1", "0.2", "0.3"))
    r1, r2, r3, ref = (os.path.join(work, n) for n in ("r_cpu1", "r_cuda", "r_cpu2", "r_ref"))
    run(a.fluid_sim, [s2, "--backend", "cpu", "--end-time", t1, "--checkpoint-every", t1, "--out", r1] + quiet)
    run(a.fluid_sim, ["--restart", os.path.join(r1, "checkpoint_0001.chk"), "--backend", "cuda",
                      "--end-time", t2, "--checkpoint-every", t1, "--out", r2] + quiet, env)
    run(a.fluid_sim, ["--restart", os.path.join(r2, "checkpoint_0002.chk"), "--backend", "cpu",
                      "--end-time", t3, "--out", r3] + quiet)
    run(a.fluid_sim, [s2, "--backend", "cpu", "--end-time", t3, "--out", ref] + quiet)
    return compare_runs(r3, ref, tolerance, same_steps=False)


def open_side_and_refusals(a, work, env, quiet, s2, tolerance):
    """--mode host: water leaving through an open side, and the refusals; True where all pass."""
    ok = True
    # Water leaving through an open side (the dam break's tank shortened to 0.12 m, its far
    # wall opened): the same particles removed.
    print("an open side that water leaves through, t = 0.15 s:")
    g, c = os.path.join(work, "open_cuda"), os.path.join(work, "open_cpu")
    opened = ["--end-time", "0.15", "--set", "boundaries.x_max.type=open", "--set",
              "domain.max=[0.12,0.2286]", "--set", "particles.spacing=0.0057", "--set",
              "probes=[]"] + quiet
    run(a.fluid_sim, [s2, "--backend", "cuda", "--out", g] + opened, env)
    run(a.fluid_sim, [s2, "--backend", "cpu", "--out", c] + opened)
    ok &= compare_runs(g, c, tolerance, same_steps=True)
    removed = summary(g)["removed_particles"], summary(c)["removed_particles"]
    good = removed[0] == removed[1] > 0
    print(f"  {'ok  ' if good else 'FAIL'} removed particles {removed[0]}, the cpu run {removed[1]}")
    ok &= good
    # What the back end does not run: one line naming the scene key, exit 5.
    print("refusals:")
    sym = run(a.fluid_sim, [s2, "--backend", "cuda", "--set", "particles.evaluation=symmetric",
                            "--out", os.path.join(work, "sym")] + quiet, env, check=False)
    good = sym.returncode == 5 and "particles.evaluation" in sym.stderr
    print(f"  {'ok  ' if good else 'FAIL'} symmetric: exit {sym.returncode}: {sym.stderr.strip()}")
    ok &= good
    # Without the test hook, on a build without CUDA or a machine without a GPU: exit 12.
    plain = run(a.fluid_sim, [s2, "--backend", "cuda", "--end-time", "1e-4", "--out",
                              os.path.join(work, "plain")] + quiet,
                {"NUMERICS_TEST_DEVICE_EXECUTION": ""}, check=False)
    good = plain.returncode in (0, 12) and (plain.returncode == 0 or "cuda" in plain.stderr)
    print(f"  {'ok  ' if good else 'FAIL'} without the hook: exit {plain.returncode} "
          f"(0 with a GPU, 12 without): {plain.stderr.strip()}")
    ok &= good
    return ok


def main():
    a = parse_args()
    host = a.mode == "host"
    # The GPU's end times; --short: a fifth of them.
    gpu_time = (lambda t: f"{float(t) / 5:g}") if a.short else (lambda t: t)
    env = {"NUMERICS_TEST_DEVICE_EXECUTION": "host"} if host else {"NUMERICS_TEST_DEVICE_EXECUTION": ""}
    work = os.path.join(a.work, a.mode)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    quiet = ["-q", "--set", "output.images=false", "--set", "output.video=false",
             "--set", 'output.formats=["csv"]', "--set", "output.plots=[]"]
    s2 = os.path.join(a.scenes, "validation", "dam_break_martin_moyce.json")
    s3 = os.path.join(a.scenes, "dam_break_3d.json")
    hot_cold = os.path.join(a.scenes, "dam_break_hot_cold_2d.json")  # fluid_sim's default

    if not host:
        skipped = gpu_missing(a, work, env, quiet, s2)
        if skipped is not None:
            return skipped

    ok = True
    tolerance = 1e-6 if host else 1e-2
    ok &= dam_breaks(a, work, env, quiet, (s2, s3, hot_cold), host, gpu_time, tolerance)
    ok &= two_runs_bitwise(a, work, env, quiet, s2, host, gpu_time)
    ok &= restart_cpu_cuda_cpu(a, work, env, quiet, s2, host, gpu_time, tolerance)
    if host:
        ok &= shipped_scenes(a, work, env, quiet)
        ok &= open_side_and_refusals(a, work, env, quiet, s2, tolerance)
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
