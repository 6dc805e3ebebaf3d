#!/usr/bin/python3
"""Plots the time series a run of fluid_sim or fluid_sim_3d writes (probes.csv, bodies.csv, or
any CSV whose first column is the time in seconds) with matplotlib: a panel per quantity, a line
per probe or body, round ticks, units and a legend.

    plot_series.py probes.csv -o probes.png [-o probes.svg] [--title TEXT]

The columns after `time` are either `<series>.<field>` (probes.csv: `wall.pressure`, `floor.vx`),
a line per series, or, when there is a `body` column, one row per body and time (bodies.csv:
time, body, x, y, ...), a line per body. Each -o's extension gives its format (png, svg, pdf).
Exit codes: 0 drawn; 2 bad arguments or an unreadable CSV; 3 matplotlib is not installed; each
with one line on stderr. The apps run it after a run (docs/scenes.md, output.plots).
"""
import argparse
import csv
import math
import os
import sys

# Field name -> (quantity, component); a quantity's panel gathers its components.
COMPONENTS = {"vx": ("velocity", "vx"), "vy": ("velocity", "vy"), "vz": ("velocity", "vz"),
              "force_x": ("force", "x"), "force_y": ("force", "y"), "force_z": ("force", "z"),
              "x": ("position", "x"), "y": ("position", "y"), "z": ("position", "z")}
UNITS = {"pressure": "Pa", "temperature": "°C", "velocity": "m/s", "density": "kg/m³",
         "force": "N; in 2D N/m", "position": "m", "angle": "rad", "angular_velocity": "rad/s"}
FORMATS = ("png", "svg", "pdf")


class BadInput(Exception):
    """A bad argument or CSV: its message is the one line printed."""


def read_csv(path):
    """(header, rows) of a CSV whose first column is `time`; values that are not numbers are
    kept as text (a body's name)."""
    try:
        with open(path, newline="") as f:
            table = list(csv.reader(f))
    except OSError as e:
        raise BadInput(f"{path}: cannot read it ({e.strerror})")
    if not table or not table[0] or table[0][0] != "time":
        raise BadInput(f"{path}: expected a header whose first column is \"time\"")
    header, rows = table[0], [r for r in table[1:] if r]
    for k, row in enumerate(rows):
        if len(row) != len(header):
            raise BadInput(f"{path}: row {k + 2} has {len(row)} values, the header {len(header)}")
    return header, rows


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def split_field(field):
    """(quantity, component or "") of a column's field."""
    return COMPONENTS.get(field, (field, ""))


def add_line(panels, quantity, label, times, values):
    panels.setdefault(quantity, []).append((label, times, values))


def series_of_wide(header, rows):
    """{quantity: [(label, times, values)]} of `<series>.<field>` columns."""
    times = [number(r[0]) for r in rows]
    panels = {}
    for c, name in enumerate(header[1:], start=1):
        series, _, field = name.rpartition(".")
        quantity, component = split_field(field)
        label = " ".join(p for p in (series, component) if p)
        add_line(panels, quantity, label or name, times, [number(r[c]) for r in rows])
    return panels


def series_of_long(header, rows, key):
    """{quantity: [(label, times, values)]} with a line per value of column `key` (a body)."""
    k = header.index(key)
    panels = {}
    for who in dict.fromkeys(r[k] for r in rows):
        mine = [r for r in rows if r[k] == who]
        times = [number(r[0]) for r in mine]
        for c, field in enumerate(header):
            if c in (0, k):
                continue
            quantity, component = split_field(field)
            label = f"{key} {who}" + (f" {component}" if component else "")
            add_line(panels, quantity, label, times, [number(r[c]) for r in mine])
    return panels


def panels_of(header, rows):
    """The panels of a table: a line per body where there is a `body` column, else per column."""
    if "body" in header:
        return series_of_long(header, rows, "body")
    return series_of_wide(header, rows)


def axis_label(quantity):
    unit = UNITS.get(quantity)
    name = quantity.replace("_", " ")
    return f"{name} [{unit}]" if unit else name


def draw(panels, outputs, title):
    """One figure, a panel per quantity sharing the time axis, saved to every output."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = max(1, len(panels))
    fig, axes = plt.subplots(n, 1, sharex=True, figsize=(8, 1.2 + 2.4 * n), squeeze=False)
    for ax, (quantity, lines) in zip(axes[:, 0], panels.items()):
        for label, times, values in lines:
            ax.plot(times, values, label=label, linewidth=1.2)
        ax.set_ylabel(axis_label(quantity))
        ax.ticklabel_format(axis="y", useOffset=False, style="sci", scilimits=(-3, 5))
        ax.grid(True, alpha=0.3)
        # Many probes (a profile across a channel): the legend in columns, smaller.
        ax.legend(loc="best", fontsize="small" if len(lines) <= 8 else "x-small",
                  ncol=math.ceil(len(lines) / 12))
    axes[-1, 0].set_xlabel("time [s]")
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    for path in outputs:
        fig.savefig(path, dpi=120)
    plt.close(fig)


def arguments(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("csv", help="a CSV whose first column is time [s]")
    p.add_argument("-o", "--output", action="append", required=True,
                   help="picture to write (.png, .svg or .pdf); may be given several times")
    p.add_argument("--title", default="", help="the figure's title")
    a = p.parse_args(argv)
    for path in a.output:
        if os.path.splitext(path)[1].lower().lstrip(".") not in FORMATS:
            raise BadInput(f"{path}: expected a picture ending in .png, .svg or .pdf")
    return a


def main(argv):
    try:
        a = arguments(argv)
        header, rows = read_csv(a.csv)
        try:
            import matplotlib  # noqa: F401 (only whether it is there)
        except ImportError:
            print(f"plot_series.py: matplotlib is not installed for {sys.executable} "
                  "(Debian: apt-get install python3-matplotlib)", file=sys.stderr)
            return 3
        draw(panels_of(header, rows), a.output, a.title)
    except BadInput as e:
        print(f"plot_series.py: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
