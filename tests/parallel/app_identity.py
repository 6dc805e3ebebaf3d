#!/usr/bin/python3
"""Runs an app on one process and under mpiexec on several, and checks the runs agree bitwise.

  app_identity.py same MPIEXEC FLAGS APP NPS SCENE [ARGS...]
      every output (.vtu, .csv, .pvd) byte for byte equal to the single-process run's, and
      summary.json equal but for timing and process figures, for each process count in NPS
      (comma-separated);
  app_identity.py restart MPIEXEC FLAGS APP SCENE [ARGS...]
      a run on 4 processes writes a checkpoint half-way; restarted on 2 and on 1 processes it
      ends with outputs byte for byte those of the uninterrupted single-process run;
  app_identity.py errors MPIEXEC FLAGS APP SCENE
      under 4 processes, a malformed scene (exit code 4), an unwritable output directory (7) and
      a run that goes unstable (9, summary.json "unstable"): each one error line.

FLAGS is one argument, split at spaces (e.g. "--oversubscribe --allow-run-as-root").
"""
import json
import os
import subprocess
import sys
import tempfile

# Keys of summary.json that depend on the machine, the time taken or the processes (the first
# process's neighbour lists are rebuilt as its own particles move).
VARYING = {"wall_seconds", "particle_steps_per_second", "processes", "decomposition", "threads",
           "video", "probe_plot", "paraview_script", "outputs_directory", "scene",
           "neighbour_list_builds"}


def run(cmd, expect=0):
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if expect is not None and done.returncode != expect:
        sys.exit(f"FAIL: {' '.join(cmd)} exited with {done.returncode}, expected {expect}:\n"
                 f"{done.stderr[-3000:]}")
    return done


def compare(reference, other, label):
    """Every output file of `reference` equal in `other`; the summaries equal but for VARYING."""
    failures = []
    outputs = sorted(f for f in os.listdir(reference) if f.endswith((".vtu", ".csv", ".pvd")))
    if not outputs:
        sys.exit(f"FAIL: no outputs in {reference}")
    for name in outputs:
        with open(os.path.join(reference, name), "rb") as a:
            path = os.path.join(other, name)
            if not os.path.exists(path):
                failures.append(f"{label}: {name} missing")
                continue
            with open(path, "rb") as b:
                if a.read() != b.read():
                    failures.append(f"{label}: {name} differs")
    with open(os.path.join(reference, "summary.json")) as a, \
            open(os.path.join(other, "summary.json")) as b:
        sa, sb = json.load(a), json.load(b)
    # The walls' heat books are given on one process only (each process sums its own).
    for summary in (sa, sb):
        summary.get("conservation", {}).get("thermal_energy", {}).pop("walls", None)
    for key in sorted(set(sa) | set(sb)):
        if key not in VARYING and sa.get(key) != sb.get(key):
            failures.append(f"{label}: summary.json {key}: {sa.get(key)} against {sb.get(key)}")
    return failures


def mpi(mpiexec, flags, np, app):
    return [mpiexec, "-n", str(np)] + flags.split() + [app]


def same(mpiexec, flags, app, nps, scene_args, work):
    run([app] + scene_args + ["-q", "--out", f"{work}/single"])
    failures = []
    for np in nps:
        out = f"{work}/np{np}"
        run(mpi(mpiexec, flags, np, app) + scene_args + ["-q", "--out", out])
        failures += compare(f"{work}/single", out, f"{np} processes")
        with open(f"{out}/summary.json") as f:
            if json.load(f)["processes"] != np:
                failures.append(f"{np} processes: summary.json processes is not {np}")
    return failures


def restart(mpiexec, flags, app, scene_args, work):
    end = float(scene_args[scene_args.index("--end-time") + 1])
    run([app] + scene_args + ["-q", "--out", f"{work}/single"])
    run(mpi(mpiexec, flags, 4, app) + scene_args +
        ["-q", "--out", f"{work}/np4", "--checkpoint-every", str(end / 2)])
    checkpoint = f"{work}/np4/checkpoint_0001.chk"
    failures = []
    for np in (2, 1):
        out = f"{work}/restart{np}"
        run(mpi(mpiexec, flags, np, app) +
            ["--restart", checkpoint, "--end-time", str(end), "-q", "--out", out])
        # The restarted run writes the outputs after the checkpoint: those must match.
        written = [name for name in sorted(os.listdir(out)) if name.endswith(".vtu")]
        if not written:
            failures.append(f"restart on {np} processes: no outputs")
        for name in written:
            with open(f"{work}/single/{name}", "rb") as a, open(f"{out}/{name}", "rb") as b:
                if a.read() != b.read():
                    failures.append(f"restart on {np} processes: {name} differs")
    return failures


def errors(mpiexec, flags, app, scene, work, faulty_plugin=None):
    """Under 4 processes: each error ends the run with its exit code and one line. With the
    test's faulty plugin: a plugin term that fails on every process in the same step."""
    bad = f"{work}/bad.json"
    with open(bad, "w") as f:
        f.write('{"dimension": 2, "particles": {"spacing": 0.02,}}\n')
    blocker = f"{work}/a_file"
    open(blocker, "w").close()
    quick = ["--set", "particles.spacing=0.02", "--threads", "1", "-q",
             "--set", "output.images=false"]
    cases = [("bad scene", [bad], 4),
             ("unwritable output", [scene] + quick + ["--out", f"{blocker}/out"], 7),
             # A sound speed of 2 m/s: the falling water passes it at t = 0.15 s.
             ("unstable run", [scene] + quick + ["--set", "materials.water.sound_speed=2",
                                                 "--end-time", "0.5", "--out", f"{work}/u"], 9)]
    if faulty_plugin:
        plugins = json.dumps([{"library": faulty_plugin,
                               "terms": [{"term": "throws_in_step", "after": 0.01}]}])
        cases.append(("plugin failing on every process",
                      [scene] + quick + ["--set", f"plugins={plugins}", "--end-time", "0.05",
                                         "--out", f"{work}/p"], 10))
    failures = []
    for name, args, code in cases:
        done = run(mpi(mpiexec, flags, 4, app) + args, expect=None)
        ours = [line for line in done.stderr.splitlines()
                if line.startswith(os.path.basename(app))]
        if done.returncode != code:
            failures.append(f"{name}: exit code {done.returncode}, expected {code}")
        if len(ours) != 1:
            failures.append(f"{name}: {len(ours)} error lines, expected 1:\n{done.stderr}")
    with open(f"{work}/u/summary.json") as f:
        if json.load(f)["status"] != "unstable":
            failures.append("unstable run: summary.json does not say unstable")
    if faulty_plugin:
        with open(f"{work}/p/summary.json") as f:
            if json.load(f)["status"] != "failed":
                failures.append("plugin failure: summary.json does not say failed")
    return failures


def main():
    mode, mpiexec, flags, app = sys.argv[1:5]
    with tempfile.TemporaryDirectory() as work:
        if mode == "same":
            nps = [int(n) for n in sys.argv[5].split(",")]
            failures = same(mpiexec, flags, app, nps, sys.argv[6:], work)
        elif mode == "restart":
            failures = restart(mpiexec, flags, app, sys.argv[5:], work)
        else:
            failures = errors(mpiexec, flags, app, sys.argv[5], work, *sys.argv[6:7])
    for f in failures:
        print("FAIL:", f)
    print("PASS" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
