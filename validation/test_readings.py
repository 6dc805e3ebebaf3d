#!/usr/bin/python3
"""Checks of the readings validation/cases.py takes from the apps' particle files (run by ctest as
validation.readings; needs Debian's python3-numpy only)."""
import json
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cases  # noqa: E402


def lattice(spacing, jitter, seed=1):
    """Particles on a square lattice over [0, 1]^2, each moved by up to `jitter` spacings."""
    n = int(round(1 / spacing))
    x, y = np.meshgrid((np.arange(n) + 0.5) * spacing, (np.arange(n) + 0.5) * spacing)
    rng = np.random.default_rng(seed)
    x = x.ravel() + rng.uniform(-jitter, jitter, x.size) * spacing
    y = y.ravel() + rng.uniform(-jitter, jitter, y.size) * spacing
    return {"x": x, "y": y}


def shepard(p, field, point, h):
    """What a probe reads: sum_j f_j W_j / sum_j W_j over the kernel support (Wendland C2)."""
    q = np.hypot(p["x"] - point[0], p["y"] - point[1]) / h
    w = np.where(q < 2, (1 - q / 2) ** 4 * (2 * q + 1), 0.0)
    return float(np.sum(w * p[field]) / np.sum(w))


class QuadraticReading(unittest.TestCase):
    def test_reproduces_a_quadratic_field_on_disordered_particles(self):
        p = lattice(0.01, 0.2)
        p["f"] = 1 + 2 * p["x"] - 3 * p["y"] + 0.5 * p["x"] ** 2 + p["x"] * p["y"] - 2 * p["y"] ** 2
        points = [(0.5, 0.5), (0.21, 0.73), (0.02, 0.5), (0.5, 0.98)]  # the last two near an edge
        exact = [1 + 2 * x - 3 * y + 0.5 * x * x + x * y - 2 * y * y for x, y in points]
        np.testing.assert_allclose(cases.quadratic_reading(p, "f", points, 0.015), exact, rtol=1e-10)

    def test_reads_a_boundary_layer_peak_that_the_kernel_average_reads_low(self):
        # v = (x / d) exp(1 - x / d), peak 1 at x = d = 0.066: the shape and width of the upward
        # flow along the hot wall at Ra = 1e5. At 80 x 80 (h = 1.5 dx) the kernel average reads the
        # peak about 1.1 % low (the analysis in cases.quadratic_reading); the quadratic within 0.1 %.
        dx, d = 0.0125, 0.066
        h = 1.5 * dx
        p = lattice(dx, 0.0)
        p["v"] = (p["x"] / d) * np.exp(1 - p["x"] / d)
        line = np.linspace(0.04, 0.1, 61)
        quadratic, _ = cases.peak(line, cases.quadratic_reading(p, "v", [(x, 0.5) for x in line], h))
        averaged, _ = cases.peak(line, np.array([shepard(p, "v", (x, 0.5), h) for x in line]))
        self.assertLess(abs(quadratic - 1), 0.001)
        self.assertLess(averaged, 0.995)


class Peak(unittest.TestCase):
    def test_finds_the_top_of_a_parabola_between_samples(self):
        x = np.linspace(0, 1, 11)
        value, at = cases.peak(x, 3 - 5 * (x - 0.437) ** 2)
        self.assertAlmostEqual(value, 3, places=12)
        self.assertAlmostEqual(at, 0.437, places=12)


class SurgeFront(unittest.TestCase):
    def test_is_the_last_connected_particle_not_the_spray_ahead(self):
        dx, support = 0.01, 0.03
        bulk = (np.arange(50) + 0.5) * dx  # 0.005 to 0.495, spaced dx
        spray = np.array([0.53, 0.9])  # 0.035 and then 0.37 beyond the bulk: both detached
        x = np.concatenate([spray, bulk[::-1]])  # in no particular order
        self.assertAlmostEqual(cases.surge_front(x, support, dx), 0.495 + dx / 2, places=12)

    def test_without_a_gap_is_the_farthest_particle(self):
        self.assertAlmostEqual(cases.surge_front([0.3, 0.1, 0.2], 0.15, 0.1), 0.35, places=12)


class CylinderDrag(unittest.TestCase):
    def test_reads_the_flux_and_adds_the_force_of_the_pressure_the_body_force_replaces(self):
        # A steady run: F_x = 10 N/m; across the section a wake's profile with two maxima,
        # u = U (pi / 2) |sin(2 pi y / H)|, whose mean is U = 0.2; the scene's body force g and
        # cylinder D add rho g pi D^2 / 4.
        with tempfile.TemporaryDirectory() as out:
            with open(os.path.join(cases.SCENES, "cylinder_re20_periodic.json")) as f:
                scene = json.load(f)
            probes = [p for p in scene["probes"] if p["name"].startswith("u")]
            names = ["time", "cylinder.force_x", "cylinder.force_y"]
            names += [p["name"] + ".v" + c for p in probes for c in "xy"]
            rows = []
            for t in np.arange(0, 10.001, 0.5):
                row = [t, 10.0, 0.0]
                for p in probes:
                    y = p["point"][1]
                    row += [0.2 * np.pi / 2 * abs(np.sin(2 * np.pi * y / 0.41)), 0.0]
                rows.append(",".join(f"{v:.17g}" for v in row))
            with open(os.path.join(out, "probes.csv"), "w") as f:
                f.write(",".join(names) + "\n" + "\n".join(rows) + "\n")
            run = cases.Run(scene, out, {"final_time": 10.0}, "", 0)
            checks, notes, _ = cases.cylinder_drag(run)
        displaced = 1000 * scene["gravity"][0] * np.pi * 0.1**2 / 4
        cd = 2 * (10.0 + displaced) / (1000 * 0.2**2 * 0.1)
        self.assertAlmostEqual(checks[0]["value"], abs(cd - 5.5795) / 5.5795, delta=0.005)
        self.assertLess(checks[1]["value"], 0.003)  # Re = 20 within the trapezoidal rule's error
        self.assertIn(f"+ {displaced:.4f} N/m", notes)

if __name__ == "__main__":
    unittest.main()
