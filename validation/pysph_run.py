"""What the validation/pysph_*.py scripts share: solving a PySPH application without output."""
import tempfile


def solve_quietly(app, openmp, prepare=None):
    """Sets up and solves the PySPH Application `app` without particle files, its log in a
    temporary folder, on OpenMP threads if `openmp`; prepare(app) runs between the two."""
    with tempfile.TemporaryDirectory() as out:  # PySPH writes its log there
        app.setup(["-d", out, "--disable-output", "-q"] + (["--openmp"] if openmp else []))
        if prepare:
            prepare(app)
        app.solver.solve(show_progress=False)
