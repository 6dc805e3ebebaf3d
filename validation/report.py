#!/usr/bin/python3
"""Writes docs/validation.md from the results of validation/cases.py (app runs only).

    report.py RESULTS_DIR SUMMARY.json REPORT.md PLOT_DIR

RESULTS_DIR holds CASE@SPACING.json, one per app run (validation/run.sh; not kept in git: the
profiles they hold are most of their size). SUMMARY.json (kept in git) holds every run's figures
without its profile: the runs found in RESULTS_DIR replace their entries there, and the report
is written from it (an empty RESULTS_DIR rewrites the report from the summary alone). Per case
the report gives the set-up (cases.py's SETUPS), the run, the checks at documentation resolution
(measured error, the gate, pass or MISSED), the run's details where cases.py asks for them
("details"), why a missed gate is missed (miss_note), what the figures alone do not show (note)
and a plot (PLOT_DIR/CASE.png: the app's result against the reference, and the errors against
the spacing; redrawn when the run at documentation resolution is in RESULTS_DIR, else the stored
plot is kept). PLOT_DIR/convergence.md holds each case's convergence table over the study's
spacings and what CI asserts.
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


def ci_line(c, n_checks):
    """What CI (ctest -L validation) asserts for a case, or why the case is not in it."""
    if c.get("not_in_ci"):
        return f"not in CI: {c['not_in_ci']}"
    spacing, bounds = c["ci"]
    bounds = bounds or [None] * n_checks
    gated = [str(i + 1) for i, b in enumerate(bounds) if b is None]
    if len(gated) == n_checks:
        return f"CI at {spacing:.4g}: the gate"
    bound = [f"check {i + 1} <= {b:g}" for i, b in enumerate(bounds) if b is not None]
    text = f"CI at {spacing:.4g}: " + ", ".join(bound) + f" (regression bound{'s' if len(bound) > 1 else ''})"
    if gated:
        text += f", check{'s' if len(gated) > 1 else ''} {', '.join(gated)} the gate"
    return text


def case_section(name, c, doc, runs, rel_plot, png):
    """The report's section of a case with a result at documentation resolution."""
    run = [f"{doc['steps']} steps"]
    if doc["threads"] != 2:
        run.append(f"{doc['threads']} thread{'s' if doc['threads'] != 1 else ''}")
    if c.get("shared_cores"):
        run.append("cores shared with other work")
    run.append(f"build {doc['app_build']}")
    out = [f"## {name}\n", f"{c['setup']}. Run: `{doc['command']}` ({', '.join(run)}).\n",
           f"Checks (gate: {c.get('gates', 'issue {}'.format(c.get('issue', 9)))}; convergence and CI: "
           f"[{name}]({rel_plot}/convergence.md#{name})):\n"]
    for i, ch in enumerate(doc["checks"]):
        out.append(f"{i + 1}. {ch['metric']}: {ch['value']:.4g}, gate {ch['gate']:g}, "
                   f"{'pass' if ch['passed'] else '**MISSED**'}")
    out.append("")
    if c.get("details"):
        out.append(f"Details: {doc['notes']}.\n")
    if not doc["passed"] and c.get("miss_note"):
        out.append(f"**Why it misses**: {c['miss_note']}\n")
    if c.get("note"):
        out.append(f"{c['note']}\n")
    if c.get("doc_note"):
        out.append(f"Resolution: {c['doc_note']}.\n")
    out.append(f"![{name}]({rel_plot}/{os.path.basename(png)})\n")
    return "\n".join(out)


def convergence_section(name, c, doc, runs):
    """A case's convergence table (the documentation resolution in bold) and what CI asserts."""
    out = [f"## {name}\n", f"{ci_line(c, len(doc['checks']))}.\n",
           "| spacing | particles | " + " | ".join(f"check {i + 1}" for i in range(len(doc["checks"]))) + " | wall s |",
           "|" + "---|" * (len(doc["checks"]) + 3)]
    for r in runs:
        if "failed" in r:
            out.append(f"| {r['spacing']:.4g} | run failed: {r['failed']} |")
            continue
        sp = f"{r['spacing']:.4g}"
        out.append(f"| {f'**{sp}**' if r is doc else sp} | {r['fluid_particles']} | " +
                   " | ".join(f"{ch['value']:.4g}" for ch in r["checks"]) + f" | {r['wall_seconds']:.0f} |")
    return "\n".join(out) + "\n"


CONVERGENCE_HEAD = """# Validation: convergence and CI

Each case of [the validation report](../validation.md): its checks (numbered as there) at every
spacing of its study, the documentation resolution in bold, and what CI (`ctest -L validation`)
asserts at its coarser spacing: the issue's gate or, where the case misses it or comes close, a
regression bound (the error measured there plus 50 %).

"""


def report_head(span, passed, missed, absent):
    """The report's introduction and the head of its table of cases."""
    return f"""# Validation report

Each case is a scene of `scenes/validation/` run by `fluid_sim` or `fluid_sim_3d` with the app's
defaults (only the spacing changes, `--set particles.spacing=DX`; a case that sets one more key
shows it in its command) and compared with its reference
([reference_solutions.md](reference_solutions.md), `validation/data/`) from the app's own outputs
by `validation/cases.py`. A gate is never loosened: a case that misses it says **MISSED**.

- One case: `/usr/bin/python3 validation/cases.py run CASE --spacing DX --bin build/release/apps`.
- Every case with its convergence study, and this page: `validation/run.sh` (the figures of every
  run are kept in `docs/validation/summary.json`).
- CI (`ctest -L validation`) runs each case at a coarser spacing against its gate or, where the
  case misses it or comes close, a regression bound (the error measured there plus 50 %).

Wall times: 2 threads on 2 CPU cores (a KVM guest) unless a run says otherwise.
App builds of {span}; each case's run names its build.
Each case's convergence study is in [validation/convergence.md](validation/convergence.md).

**{passed} of {len(cases.CASES)} cases meet their gates** at documentation resolution, {missed} miss them{f", {absent} have no result" if absent else ""}.

| case | documentation spacing | measured (the check furthest from its gate) | its gate | result |
|---|---|---|---|---|
"""


def main():
    results_dir, summary, report, plot_dir = sys.argv[1:5]
    os.makedirs(plot_dir, exist_ok=True)
    by_case = load(results_dir, summary)
    write_summary(by_case, summary)
    rel_plot = os.path.relpath(plot_dir, os.path.dirname(os.path.abspath(report)))
    rows, sections, tables, dates = [], [], [], set()
    passed = missed = absent = 0
    for name, c in cases.CASES.items():
        runs = by_case.get(name, [])
        doc = next((r for r in runs if close(r["spacing"], c["doc"])), None)
        for r in runs:
            date = build_date(r.get("app_build", "unknown"))
            if date:
                dates.add(date)
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
        sections.append(case_section(name, c, doc, runs, rel_plot, png))
        tables.append(convergence_section(name, c, doc, runs))
    span = (f"{min(dates)} to {max(dates)}" if len(dates) > 1 else min(dates) if dates else "dates unknown")
    head = report_head(span, passed, missed, absent)
    with open(report, "w") as f:
        f.write(head + "\n".join(rows) + "\n\n" + "\n".join(sections))
    with open(os.path.join(plot_dir, "convergence.md"), "w") as f:
        f.write(CONVERGENCE_HEAD + "\n".join(tables))


if __name__ == "__main__":
    main()
