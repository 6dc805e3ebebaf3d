#!/usr/bin/python3
"""PySPH beside the app on Martin & Moyce's surge front: PySPH's weakly-compressible scheme
(WCSPHScheme: Tait, c0 = 10 sqrt(2 g 2a), artificial viscosity alpha = 0.1, delta-SPH) on the
lattice of bench/pysph_dam_break_2d.py, a column a = 1 m wide and 2a high (n^2 = 2) released at
once in a tank 4a long, its front read as validation/cases.py reads the app's (surge_front) and
compared with the tabulated times at which it has not reached the far wall.

    /usr/bin/python3 validation/pysph_martin_moyce.py [--dx 0.025] [--openmp]

Needs Debian's python3-pysph. Prints the relative error at each of those times."""
import glob
import math
import os
import sys
import tempfile

import numpy as np
import pysph_run

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "bench"))
import cases  # noqa: E402
import pysph_dam_break_2d as bench  # noqa: E402
from pysph.solver.utils import load  # noqa: E402

A = 1.0  # the column's width [m] (bench: 1 m x 2 m)
TANK = 4.0  # the tank's length [m]


def main():
    p = pysph_run.arguments(__doc__, 0.025, "spacing [m] (a / 40 by default)")
    args = p.parse_args()
    ref = cases.read_table("martin_moyce1952.csv")
    scale = math.sqrt(2 * bench.G / A)  # T = t sqrt(2 g / a)
    end = (ref["T"][ref["Z"] < TANK / A][-1] + 0.2) / scale
    with tempfile.TemporaryDirectory() as out:
        dt = 0.125 * bench.HDX * args.dx / bench.C0  # the bench's fixed step
        app = bench.DamBreakBench(args.dx, 0, end, pfreq=max(1, round(0.005 / dt)), fname="surge")
        app.setup(["-d", out, "-q"] + (["--openmp"] if args.openmp else []))
        app.solver.solve(show_progress=False)
        ts, zs = [], []
        for f in sorted(glob.glob(os.path.join(out, "surge_*.hdf5")),
                        key=lambda f: int(f.rsplit("_", 1)[1].split(".")[0])):
            data = load(f)
            ts.append(data["solver_data"]["t"] * scale)
            zs.append(cases.surge_front(data["arrays"]["fluid"].x, 2 * bench.HDX * args.dx, args.dx) / A)
    ts, zs = np.array(ts), np.array(zs)
    # Only while the front has not reached the far wall.
    sel = ref["T"] <= ts[zs < TANK / A - 0.1][-1]
    zsim = np.interp(ref["T"][sel], ts, zs)
    print(f"PySPH WCSPH, dx = {args.dx:g} m (a / {A / args.dx:g}), {app.particles[0].get_number_of_particles()} "
          f"fluid particles; Z = z / a against T = t sqrt(2 g / a)")
    for T, Z, z in zip(ref["T"][sel], ref["Z"][sel], zsim):
        print(f"T = {T:.3f}: Z = {z:.3f} against {Z:.3f}, relative error {(z - Z) / Z:+.3f}")


if __name__ == "__main__":
    main()
