#!/usr/bin/python3
"""Writes the validation report from the results of the validation tests.

    report.py RESULTS_DIR REPORT.md PLOT_DIR

RESULTS_DIR holds, per case, <case>.json ({"case", "resolution", "error", "tolerance",
"passed", "notes"}) and <case>_profile.csv (coordinate, numeric, analytic[, time]). The report
is a table of every case and one plot per case of the numeric result against the analytic one
(PNG, in PLOT_DIR, linked from the report).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# What each case checks, for the report (cases not listed get their notes only).
DESCRIPTIONS = {
    "heat_slabs_equal": "Two slabs, equal materials: erf profile (validation.md 5), temperature vs x at t = 0.01.",
    "heat_slabs_k2": "Two slabs, k_R = 2 k_L: interface at T_c = 0.414214 and erf profiles (validation.md 5).",
    "heat_slabs_equal_wendland": "Two slabs, equal materials, Wendland C2 kernel at h = 2 dx.",
    "heat_pulse_2d": "Gaussian pulse in 2D, periodic box; line of particles through the centre.",
    "heat_pulse_3d": "Gaussian pulse in 3D, periodic box; line of particles through the centre.",
    "heat_conservation": "Total heat sum m c T with adiabatic walls, two materials (x = 0: symmetric, 1: asymmetric evaluation; y: relative drift).",
    "heat_fixed_body": "Disc held at 90 degC in water at 20 degC: water temperature vs distance; error = energy-balance mismatch.",
    "heat_buoyancy_blob": "Warm blob in cold water: mean vertical velocity vs time against the Boussinesq estimate beta dT g (1 + phi) / 2.",
}

LABELS = {
    "heat_buoyancy_blob": ("time [s]", "blob velocity [m/s]"),
    "heat_conservation": ("evaluation mode", "relative heat drift"),
    "heat_fixed_body": ("distance from the centre", "temperature [degC]"),
    "heat_pulse_2d": ("x", "T"),
    "heat_slabs_equal": ("x", "T"),
    "heat_slabs_k2": ("x", "T"),
    "heat_slabs_equal_wendland": ("x", "T"),
    "heat_pulse_3d": ("x", "T"),
}


def read_profile(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return None
    cols = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    return cols


def plot_case(name, profile, plot_dir):
    fig, ax = plt.subplots(figsize=(6, 4))
    x, num, ana = profile["coordinate"], profile["numeric"], profile["analytic"]
    times = profile.get("time")
    order = np.argsort(x, kind="stable")
    if times is not None and len(np.unique(times)) > 1 and name != "heat_buoyancy_blob":
        for n, t in enumerate(np.unique(times)):
            sel = times == t
            o = np.argsort(x[sel])
            color = f"C{n % 10}"
            ax.plot(x[sel][o], ana[sel][o], "-", lw=1, color=color, label=f"analytic t = {t:g}")
            ax.plot(x[sel][o], num[sel][o], "o", ms=3, color=color, label=f"numeric t = {t:g}")
    else:
        ax.plot(x[order], ana[order], "-", lw=1.5, label="analytic / reference")
        ax.plot(x[order], num[order], "o", ms=3, label="numeric")
    xl, yl = LABELS.get(name, ("coordinate", "value"))
    ax.set_xlabel(xl)
    ax.set_ylabel(yl)
    ax.set_title(name)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(plot_dir, name + ".png")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    results, report, plot_dir = sys.argv[1:]
    os.makedirs(plot_dir, exist_ok=True)
    cases = []
    for fname in sorted(os.listdir(results)):
        if not fname.endswith(".json"):
            continue
        with open(os.path.join(results, fname)) as f:
            c = json.load(f)
        prof = os.path.join(results, c["case"] + "_profile.csv")
        c["plot"] = None
        if os.path.exists(prof):
            p = read_profile(prof)
            if p is not None:
                c["plot"] = plot_case(c["case"], p, plot_dir)
        cases.append(c)

    rel = os.path.relpath(plot_dir, os.path.dirname(os.path.abspath(report)) or ".")
    lines = [
        "# Validation report",
        "",
        "Every case of the ctest label `validation`, run at documentation resolution by",
        "`validation/run.sh` (`NUMERICS_VALIDATION_FULL=1`). Analytic solutions and gates come",
        "from [reference_solutions.md](reference_solutions.md); each test states where its tolerance comes from. Errors",
        "are relative to the scale named in the notes (temperature jump, u_max, V0...).",
        "",
        f"{sum(c['passed'] for c in cases)} of {len(cases)} cases pass.",
        "",
        "| case | resolution | error | tolerance | passed |",
        "| --- | --- | --- | --- | --- |",
    ]
    for c in cases:
        lines.append(
            f"| [{c['case']}](#{c['case']}) | {c['resolution']} | {c['error']:.3g} | "
            f"{c['tolerance']:.3g} | {'yes' if c['passed'] else '**no**'} |"
        )
    lines.append("")
    for c in cases:
        lines += [f"## {c['case']}", ""]
        if c["case"] in DESCRIPTIONS:
            lines += [DESCRIPTIONS[c["case"]], ""]
        lines += [
            f"Resolution {c['resolution']}; error {c['error']:.4g} "
            f"(tolerance {c['tolerance']:.3g}): {'passed' if c['passed'] else 'FAILED'}.",
            "",
        ]
        if c.get("notes"):
            lines += [c["notes"], ""]
        if c["plot"]:
            lines += [f"![{c['case']}]({rel}/{os.path.basename(c['plot'])})", ""]
    with open(report, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
