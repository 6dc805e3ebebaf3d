"""What the validation/pysph_*.py scripts share: their common options and solving a PySPH
application without output."""
import argparse
import tempfile


def arguments(doc, dx, dx_help):
    """The command line of a script whose docstring is `doc`: --dx (default dx, help dx_help) and
    --openmp; the script adds its own options."""
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    ap.add_argument("--dx", type=float, default=dx, help=dx_help)
    ap.add_argument("--openmp", action="store_true", help="PySPH's OpenMP threads (OMP_NUM_THREADS)")
    return ap


def solve_quietly(app, openmp, prepare=None):
    """Sets up and solves the PySPH Application `app` without particle files, its log in a
    temporary folder, on OpenMP threads if `openmp`; prepare(app) runs between the two."""
    with tempfile.TemporaryDirectory() as out:  # PySPH writes its log there
        app.setup(["-d", out, "--disable-output", "-q"] + (["--openmp"] if openmp else []))
        if prepare:
            prepare(app)
        app.solver.solve(show_progress=False)
