#!/usr/bin/python3
"""Writes docs/validation.md from the results of validation/cases.py (app runs only).

    report.py RESULTS_DIR SUMMARY.json REPORT.md PLOT_DIR

RESULTS_DIR holds CASE@SPACING.json, one per app run (validation/run.sh; not kept in git: the
profiles they hold are most of their size). SUMMARY.json (kept in git) holds every run's figures
without its profile: the runs found in RESULTS_DIR replace their entries there, and the report
is written from it. Per case the report gives the set-up (cases.py's SETUPS), the run, the checks
at documentation resolution (measured error, the issue's gate, pass or MISSED), what the figures
alone do not show and why a missed gate is missed (cases.py's note and miss_note), the
convergence table over the study's spacings and a plot (PLOT_DIR/CASE.png: the app's result
against the reference, and the errors against the spacing; redrawn when the run at documentation
resolution is in RESULTS_DIR, else the stored plot is kept).
"""
import glob
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cases  # noqa: E402


def key(r):
    return (r["case"], f"{r['spacing']:.10g}")


def load(results_dir, summary):
    """Every run: the summary's, replaced by those in results_dir (with their profiles)."""
    runs = {}
    if os.path.exists(summary):
        with open(summary) as f:
            for r in json.load(f):
                runs[key(r)] = r
    for path in glob.glob(os.path.join(results_dir, "*.json")):
        with open(path) as f:
            r = json.load(f)
        runs[key(r)] = r
    by_case = {}
    for r in runs.values():
        by_case.setdefault(r["case"], []).append(r)
    for rs in by_case.values():
        rs.sort(key=lambda r: -r["spacing"])
    return by_case


def write_summary(by_case, summary):
    """One run per line, without its profile, in case and spacing order."""
    lines = [json.dumps({k: v for k, v in r.items() if k != "profile"})
             for name in sorted(by_case) for r in by_case[name]]
    with open(summary, "w") as f:
        f.write("[\n" + ",\n".join(lines) + "\n]\n")


def build_date(build):
    """The commit date of an app build (YYYY-MM-DD), or "" where git does not know it."""
    try:
        out = subprocess.run(["git", "-C", cases.ROOT, "show", "-s", "--format=%cs", build.split("+")[0]],
                             capture_output=True, text=True)
    except OSError:
        return ""
    return out.stdout.strip() if out.returncode == 0 else ""


def build_name(build, form="{build} ({date})"):
    date = build_date(build)
    return form.format(build=build, date=date) if date else build


def close(a, b):
    return abs(a - b) <= 1e-9 * max(abs(a), abs(b))


def plot(name, doc, runs, plot_dir):
    path = os.path.join(plot_dir, f"{name}.png")
    if "profile" not in doc:
        return path  # only the summary's figures: the stored plot stays
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4))
    prof = doc["profile"]
    for s in prof["series"]:
        if s["style"] == "points":
            ax.plot(s["x"], s["y"], ".", ms=3 if len(s["x"]) > 100 else 7, label=s["label"])
        else:
            ax.plot(s["x"], s["y"], "-", label=s["label"])
    ax.set_xlabel(prof["xlabel"])
    ax.set_ylabel(prof["ylabel"])
    ax.set_title(f"{name}, spacing {doc['spacing']:.4g}")
    ax.legend(fontsize=7)
    ok = [r for r in runs if "failed" not in r]
    for i, ch in enumerate(doc["checks"]):
        xs = [r["spacing"] for r in ok]
        ys = [r["checks"][i]["value"] for r in ok]
        line, = bx.loglog(xs, ys, "o-", label=ch["metric"][:60])
        bx.axhline(ch["gate"], color=line.get_color(), ls="--", lw=0.8)
    bx.set_xlabel("particle spacing [m]")
    bx.set_ylabel("error (dashed: the issue's gate)")
    bx.set_title("convergence")
    bx.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def main():
    results_dir, summary, report, plot_dir = sys.argv[1:5]
    os.makedirs(plot_dir, exist_ok=True)
    by_case = load(results_dir, summary)
    write_summary(by_case, summary)
    rel_plot = os.path.relpath(plot_dir, os.path.dirname(os.path.abspath(report)))
    rows, sections, builds = [], [], set()
    passed = missed = absent = 0
    for name, c in cases.CASES.items():
        runs = by_case.get(name, [])
        doc = next((r for r in runs if close(r["spacing"], c["doc"])), None)
        for r in runs:
            builds.add(r.get("app_build", "unknown"))
        if doc is None or "failed" in doc:
            absent += 1
            why = doc["failed"] if doc else c.get("doc_note", "not run")
            rows.append(f"| [{name}](#{name}) | {c['doc']:.4g} | – | – | **no result**: {why} |")
            sections.append(f"## {name}\n\nNo result at documentation resolution (spacing {c['doc']:.4g}): {why}\n")
            continue
        ok = doc["passed"]
        passed += ok
        missed += not ok
        main_ch = max(doc["checks"], key=lambda ch: ch["value"] / ch["gate"])
        rows.append(f"| [{name}](#{name}) | {doc['spacing']:.4g} ({doc['fluid_particles']} particles) | "
                    f"{main_ch['value']:.3g} | {main_ch['gate']:g} | {'pass' if ok else '**MISSED**'} |")
        png = plot(name, doc, runs, plot_dir)
        threads = f"{doc['threads']} thread{'s' if doc['threads'] != 1 else ''}"
        out = [f"## {name}\n", f"{c['setup']}.\n",
               f"Run: `{doc['command']}`: {doc['fluid_particles']} fluid particles, {doc['steps']} steps, "
               f"{doc['wall_seconds']:.0f} s on {threads}, build {build_name(doc['app_build'], '{build} of {date}')}.\n",
               f"| check | measured | gate ({c.get('gates', 'issue {}'.format(c.get('issue', 9)))}) | result |",
               "| --- | --- | --- | --- |"]
        for ch in doc["checks"]:
            metric = ch["metric"].replace("|", "\\|")
            out.append(f"| {metric} | {ch['value']:.4g} | {ch['gate']:g} | {'pass' if ch['passed'] else '**MISSED**'} |")
        out.append(f"\nDetails: {doc['notes']}.\n")
        if not ok and c.get("miss_note"):
            out.append(f"**Why it misses**: {c['miss_note']}.\n")
        if c.get("note"):
            out.append(f"{c['note']}.\n")
        if c.get("doc_note"):
            out.append(f"Resolution: {c['doc_note']}.\n")
        ci = c["ci"]
        bounds = ci[1] or [None] * len(doc["checks"])
        gated = [str(i + 1) for i, b in enumerate(bounds) if b is None]
        asserts = [f"check {i + 1} <= {b:g} (a regression bound)" for i, b in enumerate(bounds) if b is not None]
        if gated:
            asserts.append(f"check{'s' if len(gated) > 1 else ''} {', '.join(gated)} within the gate")
        out.append(f"Convergence (`--set particles.spacing=DX`); CI (`ctest -L validation`) runs {ci[0]:.4g}: "
                   + "; ".join(asserts) + ".\n")
        out.append("| spacing | fluid particles | " + " | ".join(f"check {i + 1}" for i in range(len(doc["checks"]))) + " | wall s |")
        out.append("| --- | --- | " + " | ".join("---" for _ in doc["checks"]) + " | --- |")
        for r in runs:
            if "failed" in r:
                out.append(f"| {r['spacing']:.4g} | run failed: {r['failed']} |")
                continue
            out.append(f"| {r['spacing']:.4g} | {r['fluid_particles']} | " +
                       " | ".join(f"{ch['value']:.4g}" for ch in r["checks"]) + f" | {r['wall_seconds']:.0f} |")
        out.append(f"\n![{name}]({rel_plot}/{os.path.basename(png)})\n")
        sections.append("\n".join(out))
    head = f"""# Validation report

Each case is a scene of `scenes/validation/` run by `fluid_sim` or `fluid_sim_3d` as a user runs
it (the app's defaults; only the spacing changes, `--set particles.spacing=DX`) and compared with
its reference ([reference_solutions.md](reference_solutions.md), `validation/data/`) from the
app's own outputs by `validation/cases.py`; nothing here comes from the C++ API tests. Gates are
those of issue 9, of issue 48 for the cases with geometry and of issue 59 for moving bodies (for the
inlet and outlet cases, each check names where its gate comes from); a
gate is never loosened: a case that misses it says **MISSED**, with the number and what is known
of why. CI checks each case
at a coarser spacing, against the gate or, where a case misses it or comes close, a regression
bound (the error measured there plus 50 %; `validation/cases.py` says when each was measured).

`validation/run.sh` writes this page from every run's figures in `docs/validation/summary.json`.
One case: `/usr/bin/python3 validation/cases.py run CASE --spacing DX --bin build/release/apps`.
Wall times: 2 CPU cores (a KVM guest); app builds {", ".join(build_name(b) for b in sorted(builds)) or "none"}.

**{passed} of {len(cases.CASES)} cases meet their gates** at documentation resolution, {missed} miss them{f", {absent} have no result" if absent else ""}.

| case | documentation spacing | measured (the check furthest from its gate) | its gate | result |
| --- | --- | --- | --- | --- |
"""
    with open(report, "w") as f:
        f.write(head + "\n".join(rows) + "\n\n" + "\n".join(sections))


if __name__ == "__main__":
    main()
