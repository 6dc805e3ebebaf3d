#!/usr/bin/env python3
"""The GPU check of a bundle made by bench/gpu_bundle.sh: what to run on a machine with an NVIDIA
GPU, its driver, the CUDA toolkit (for compute-sanitizer only) and Python 3 (standard library
only), in about 5 minutes on an H100. Run through the bundle's check.sh, which sets the paths:

  check.sh [--host] [--debug] [--work DIR] [--only NAMES]

Parts, each with a budget of time (the seconds are the most it waits for a part):
  gpu         nvidia-smi's line: the GPU, its driver and memory                            10 s
  step test   gpu_cuda_step_test: the device step's CUDA execution against its host
              execution (every array of one evaluation, 40 steps, two GPU runs bitwise)    120 s
  memcheck    compute-sanitizer --tool memcheck on 20 steps of the 2D dam break with
              --backend cuda and NUMERICS_CUDA_DEBUG=1 (every kernel synchronised and
              checked, named on failure); passes on "ERROR SUMMARY: 0 errors"; "not
              found" (a skip, not a failure) where compute-sanitizer is absent            120 s
  apps        app_backend.py --short: the apps with --backend cuda against the CPU back
              end (2D and 3D dam breaks and the 2D default scene within 1 %, two GPU runs
              bitwise, a restart cpu -> cuda -> cpu)                                      150 s
  1e5, 1e6, 1e7  the 3D dam break at about 1e5, 1e6 and 1e7 fluid particles on the GPU: ns
              per particle-step of the time loop (two runs to two end times, the difference
              of the wall times over the difference of the particle-steps: set-up and outputs
              left out) and the GPU memory per particle (summary.json's
              device_bytes_per_particle), both per particle, walls included   60, 90, 200 s
Prints one table (check, result, figure, seconds) at the end; exits 1 when any check failed
(a GPU test skipped for want of a GPU is a failure here), 0 otherwise.

--host: everything that runs without a GPU, on the host execution (NUMERICS_TEST_DEVICE_EXECUTION
  =host: the same functors the kernels run, in loops on one CPU thread): the apps' comparison in
  its host mode and the sizes 1e5 and 1e6 with fewer steps; the step test, memcheck and 1e7 are
  skipped. It tests the bundle itself (its libraries, scenes and scripts), not the GPU; its
  figures are no GPU figures.
--debug: every run on the GPU with NUMERICS_CUDA_DEBUG=1 (slower: the timings are then no
  figures to quote).
"""
import argparse
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP = 77

# The 3D dam break's spacing for about 1e5, 1e6 and 1e7 fluid particles (bench/gpu_scaling.sh;
# with the walls 2.0e5, 1.5e6 and about 1.2e7 particles), the steps (about) of the shorter run
# and the steps the longer one adds, on the GPU and on the host execution (None: not run
# there), and the most seconds both runs may take. At 1e7 most of a run is its set-up on the CPU
# (the particles made on one thread), so few steps.
SIZES = [("1e5", 0.01293, (5, 200), (2, 20), 60),
         ("1e6", 0.006, (5, 60), (1, 4), 90),
         ("1e7", 0.002785, (3, 15), None, 200)]
QUIET = ["-q", "--set", "output.images=false", "--set", "output.video=false",
         "--set", "output.formats=[]", "--set", "output.plots=[]", "--set", "probes=[]"]


# ---- what the table is made of (tested by tests/device/gpu_check_test.py) ----

PASS, FAIL, SKIPPED, INFO = "pass", "FAIL", "skip", "info"


class Row:
    def __init__(self, check, result, figure, seconds=None):
        self.check, self.result, self.figure, self.seconds = check, result, figure, seconds


def table(rows):
    """The rows as one Markdown table: check, result, figure, seconds."""
    lines = ["| check | result | figure | seconds |", "| --- | --- | --- | --- |"]
    for r in rows:
        s = "" if r.seconds is None else f"{r.seconds:.1f}"
        figure = str(r.figure).replace("|", "/").replace("\n", " ")
        lines.append(f"| {r.check} | {r.result} | {figure} | {s} |")
    return "\n".join(lines)


def exit_code(rows):
    return 1 if any(r.result == FAIL for r in rows) else 0


def sanitizer_errors(text):
    """compute-sanitizer's error count from its "ERROR SUMMARY: N errors" line, or None."""
    for line in reversed(text.splitlines()):
        if "ERROR SUMMARY:" in line:
            words = line.split("ERROR SUMMARY:")[1].split()
            try:
                return int(words[0])
            except (IndexError, ValueError):
                return None
    return None


def count_checks(text):
    """The lines of a test's output that say "ok" and "FAIL" (the tests' own format)."""
    lines = [l.strip() for l in text.splitlines()]
    return sum(l.startswith("ok ") for l in lines), sum(l.startswith("FAIL") for l in lines)


def judged(name, rc, text, gpu):
    """A test program's row from its exit code and output: 0 and PASSED pass; 77 (skipped, no
    GPU or no CUDA back end) fails where a GPU was asked for; anything else fails."""
    ok, failed = count_checks(text)
    if rc == SKIP:
        reason = next((l.strip() for l in text.splitlines() if l.strip().startswith("skipped")),
                      "skipped")
        return Row(name, FAIL if gpu else SKIPPED, reason)
    passed = rc == 0 and "PASSED" in text and failed == 0
    figure = f"{ok} ok, {failed} failed"
    if rc != 0 and not failed:
        tail = [l for l in text.strip().splitlines() if l.strip()]
        figure += f", exit {rc}" + (": " + tail[-1][:160] if tail else "")
    return Row(name, PASS if passed else FAIL, figure)


def per_particle_step(first, second):
    """ns per particle-step and device bytes per particle from two summaries of one case run to
    two end times: the difference of the wall times over the difference of the particle-steps.
    Raises ValueError where they give no figure."""
    for s in (first, second):
        if s.get("status") != "completed":
            raise ValueError(f"run {s.get('status')}: {s.get('message', '')}")
    n = second["particles"]
    if first["particles"] != n:
        raise ValueError("the two runs have different particles")
    steps = second["steps"] - first["steps"]
    if steps <= 0:
        raise ValueError(f"no more steps in the longer run ({first['steps']}, {second['steps']})")
    ns = (second["wall_seconds"] - first["wall_seconds"]) / (steps * n) * 1e9
    if ns <= 0:
        raise ValueError(f"the longer run took no longer ({first['wall_seconds']:.3f} s, "
                         f"{second['wall_seconds']:.3f} s): too few steps timed")
    if "device_bytes_per_particle" not in second:
        raise ValueError("summary.json has no device_bytes_per_particle (not --backend cuda?)")
    return n, steps, ns, second["device_bytes_per_particle"]


def scaling_figure(n, steps, ns, bytes_per_particle, fluid=None):
    of = f"{fluid:,} fluid of " if fluid is not None else ""
    return (f"{of}{n:,} particles, {steps} steps: {ns:.2f} ns per particle-step, "
            f"{bytes_per_particle:.0f} B per particle")


def first_end_time(scene, dx, steps):
    """An end time of about `steps` steps: the leapfrog's step is about cfl h / c0
    (bench/gpu_scaling.sh's estimate)."""
    h = scene["particles"].get("h_over_spacing", 1.5) * dx
    cfl = scene.get("time", {}).get("cfl", 0.25)
    c0 = 10 * math.sqrt(2 * 9.81 * 0.6)
    return steps * cfl * h / c0


# ---- running ----

def run(cmd, env=None, timeout=None):
    """(exit code, stdout and stderr together, seconds); 124 when past the timeout, when the
    command and everything it started (its process group) is killed."""
    start = time.monotonic()
    try:
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             env=env, start_new_session=True)
    except OSError as e:
        return 127, str(e), time.monotonic() - start
    try:
        out, _ = p.communicate(timeout=timeout)
        return p.returncode, out, time.monotonic() - start
    except subprocess.TimeoutExpired:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, _ = p.communicate()
        return 124, (out or "") + f"\n(stopped after {timeout:.0f} s)", time.monotonic() - start


def say(text):
    print(text, flush=True)


def check_gpu(a, env):
    smi = shutil.which("nvidia-smi", path=env.get("PATH"))
    if not smi:
        return Row("gpu", SKIPPED if a.host else FAIL, "nvidia-smi not found")
    rc, out, s = run([smi, "--query-gpu=name,driver_version,memory.total",
                      "--format=csv,noheader"], env, 10)
    line = out.strip().splitlines()[0] if out.strip() else f"exit {rc}"
    if rc != 0:
        return Row("gpu", SKIPPED if a.host else FAIL, "nvidia-smi: " + line, s)
    return Row("gpu", INFO, line, s)


def check_step_test(a, env):
    rc, out, s = run([os.path.join(a.bin, "gpu_cuda_step_test")], env, 120)
    say(out)
    row = judged("step test (gpu_cuda_step_test)", rc, out, gpu=True)
    row.seconds = s
    return row


def check_memcheck(a, env):
    sanitizer = shutil.which("compute-sanitizer", path=env.get("PATH"))
    for d in (os.environ.get("CUDA_HOME"), "/usr/local/cuda"):
        if not sanitizer and d and os.path.exists(os.path.join(d, "bin", "compute-sanitizer")):
            sanitizer = os.path.join(d, "bin", "compute-sanitizer")
    if not sanitizer:
        return Row("memcheck (compute-sanitizer)", SKIPPED,
                   "compute-sanitizer not found (on PATH, $CUDA_HOME/bin, /usr/local/cuda/bin)")
    scene = os.path.join(a.scenes, "validation", "dam_break_martin_moyce.json")
    out_dir = os.path.join(a.work, "memcheck")
    debug_env = dict(env, NUMERICS_CUDA_DEBUG="1")
    cmd = [sanitizer, "--tool", "memcheck", "--error-exitcode", "3",
           os.path.join(a.bin, "fluid_sim"), scene, "--backend", "cuda",  # 3,236 particles, 20 steps
           "--end-time", "0.001", "--out", out_dir] + QUIET
    rc, out, s = run(cmd, debug_env, 120)
    say(out)
    errors = sanitizer_errors(out)
    ok = rc == 0 and errors == 0
    figure = f"{errors} errors" if errors is not None else "no ERROR SUMMARY line"
    figure += f" (NUMERICS_CUDA_DEBUG=1), exit {rc}"
    return Row("memcheck (compute-sanitizer)", PASS if ok else FAIL, figure, s)


def check_apps(a, env):
    mode = "host" if a.host else "gpu"
    cmd = [sys.executable, os.path.join(HERE, "app_backend.py"),
           os.path.join(a.bin, "fluid_sim"), os.path.join(a.bin, "fluid_sim_3d"), a.scenes,
           os.path.join(a.work, "apps"), "--mode", mode, "--short"]
    rc, out, s = run(cmd, env, 150 if not a.host else 600)
    say(out)
    row = judged(f"apps: cuda against cpu ({mode})", rc, out, gpu=not a.host)
    row.seconds = s
    return row


def check_size(a, env, name, dx, steps, budget):
    scene_file = os.path.join(a.scenes, "dam_break_3d.json")
    with open(scene_file) as f:
        scene = json.load(f)
    t1 = first_end_time(scene, dx, steps[0])
    app = os.path.join(a.bin, "fluid_sim_3d")
    args = [scene_file, "--backend", "cuda", "--set", f"particles.spacing={dx}"] + QUIET
    summaries, seconds = [], 0.0
    timeout = 600 if a.host else budget
    t = t1
    for k in range(2):
        out_dir = os.path.join(a.work, "size_" + name, str(k))
        rc, out, s = run([app] + args + ["--end-time", f"{t:.6g}", "--out", out_dir], env,
                         max(1.0, timeout - seconds))
        seconds += s
        if rc != 0:
            tail = out.strip().splitlines()[-1][:200] if out.strip() else ""
            return Row(f"{name} particles", FAIL, f"exit {rc}: {tail}", seconds)
        with open(os.path.join(out_dir, "summary.json")) as f:
            summaries.append(json.load(f))
        if k == 0:  # the second run: about steps[1] more, at the first run's mean step
            done = summaries[0]["steps"]
            dt = summaries[0]["final_time"] / max(done, 1)
            t = summaries[0]["final_time"] + steps[1] * dt
    try:
        figures = per_particle_step(*summaries)
    except ValueError as e:
        return Row(f"{name} particles", FAIL, str(e), seconds)
    return Row(f"{name} particles", INFO,
               scaling_figure(*figures, fluid=summaries[1].get("fluid_particles")), seconds)


def parse_args(argv):
    """The command line (see the module's docstring), with the work folder made."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--host", action="store_true",
                    help="no GPU: the host execution, what runs without one")
    ap.add_argument("--debug", action="store_true", help="NUMERICS_CUDA_DEBUG=1 for every run")
    ap.add_argument("--work", default=None, help="where the runs write (default: a new folder in $TMPDIR)")
    ap.add_argument("--only", default="", help="comma-separated parts: gpu,step,memcheck,apps,1e5,1e6,1e7")
    ap.add_argument("--bin", default=os.path.join(HERE, "bin"))
    ap.add_argument("--scenes", default=os.path.join(HERE, "scenes"))
    a = ap.parse_args(argv)
    if a.work is None:
        import tempfile
        a.work = tempfile.mkdtemp(prefix="numerics_gpu_check_")
    os.makedirs(a.work, exist_ok=True)
    return a


def run_env(a):
    """The environment of every run (--host: the host execution; --debug: NUMERICS_CUDA_DEBUG=1)."""
    env = dict(os.environ)
    env["NUMERICS_TEST_DEVICE_EXECUTION"] = "host" if a.host else ""
    if a.debug:
        env["NUMERICS_CUDA_DEBUG"] = "1"
    env.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    return env


def main(argv=None):
    a = parse_args(argv)
    only = set(x for x in a.only.split(",") if x)
    wanted = lambda part: not only or part in only

    env = run_env(a)
    start = time.monotonic()
    mode = "host execution (--host: no GPU figures)" if a.host else "GPU"
    say(f"gpu_check: {mode}{', debug mode' if a.debug else ''}; runs in {a.work}")
    rc, version, _ = run([os.path.join(a.bin, "fluid_sim"), "--version"], env, 30)
    say(version.strip())
    rows = []
    if rc != 0:
        rows.append(Row("fluid_sim --version", FAIL, f"exit {rc}: {version.strip()[-200:]}"))
    elif "back end (--backend cuda): built" not in version:
        rows.append(Row("fluid_sim --version", FAIL, "built without the CUDA back end"))

    def part(name, key, fn, *args, host_skip=None):
        if not wanted(key):
            return
        if a.host and host_skip:
            rows.append(Row(name, SKIPPED, host_skip))
            return
        say(f"== {name}")
        try:
            row = fn(a, env, *args)
        except Exception as e:  # a part that broke is a failed check, and the rest still runs
            row = Row(name, FAIL, f"{type(e).__name__}: {e}")
        say(f"   {row.result}: {row.figure}")
        rows.append(row)

    part("gpu", "gpu", check_gpu)
    part("step test (gpu_cuda_step_test)", "step", check_step_test, host_skip="needs a GPU (--host)")
    part("memcheck (compute-sanitizer)", "memcheck", check_memcheck, host_skip="needs a GPU (--host)")
    part("apps: cuda against cpu", "apps", check_apps)
    for name, dx, gpu_steps, host_steps, budget in SIZES:
        steps = host_steps if a.host else gpu_steps
        part(f"{name} particles", name, check_size, name, dx, steps or (0, 0), budget,
             host_skip=None if host_steps else "too large for the host execution (--host)")
    total = time.monotonic() - start
    rows.append(Row("all", FAIL if exit_code(rows) else PASS,
                    f"{sum(r.result == FAIL for r in rows)} failed of {len(rows)}", total))
    say("")
    say(table(rows))
    return exit_code(rows)


if __name__ == "__main__":
    sys.exit(main())
