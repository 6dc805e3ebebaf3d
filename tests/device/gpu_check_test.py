#!/usr/bin/env python3
"""The GPU check's own logic (bench/gpu_bundle/gpu_check.py), without a GPU (label device): the
figures from two stored summary.json files of one case run to two end times (from the bundle's
check on the host execution), the judgement of a test program's output and exit code,
compute-sanitizer's error count, and the table and exit code.

  gpu_check_test.py GPU_CHECK_PY DATA_DIR
"""
import copy
import importlib.util
import json
import os
import sys
import unittest

spec = importlib.util.spec_from_file_location("gpu_check", sys.argv[1])
gc = importlib.util.module_from_spec(spec)
spec.loader.exec_module(gc)
DATA = sys.argv[2]


def load(name):
    with open(os.path.join(DATA, name)) as f:
        return json.load(f)


class Figures(unittest.TestCase):
    def setUp(self):
        self.a, self.b = load("gpu_check_summary_short.json"), load("gpu_check_summary_long.json")

    def test_per_particle_step(self):
        n, steps, ns, per = gc.per_particle_step(self.a, self.b)
        self.assertEqual(n, self.b["particles"])
        self.assertEqual(steps, self.b["steps"] - self.a["steps"])
        self.assertGreater(steps, 0)
        expected = (self.b["wall_seconds"] - self.a["wall_seconds"]) / (steps * n) * 1e9
        self.assertAlmostEqual(ns, expected, places=9)
        self.assertEqual(per, self.b["device_bytes_per_particle"])
        text = gc.scaling_figure(n, steps, ns, per)
        self.assertIn(f"{n:,} particles", text)
        self.assertIn(f"{ns:.2f} ns per particle-step", text)
        fluid = self.b["fluid_particles"]
        self.assertIn(f"{fluid:,} fluid of {n:,} particles",
                      gc.scaling_figure(n, steps, ns, per, fluid=fluid))

    def test_refusals(self):
        with self.assertRaises(ValueError):  # the same run twice: no steps between them
            gc.per_particle_step(self.b, self.b)
        unstable = copy.deepcopy(self.b)
        unstable["status"] = "unstable"
        with self.assertRaises(ValueError):
            gc.per_particle_step(self.a, unstable)
        cpu = copy.deepcopy(self.b)
        del cpu["device_bytes_per_particle"]
        with self.assertRaises(ValueError):
            gc.per_particle_step(self.a, cpu)
        other = copy.deepcopy(self.b)
        other["particles"] += 1
        with self.assertRaises(ValueError):
            gc.per_particle_step(self.a, other)

    def test_end_time(self):
        scene = {"particles": {"spacing": 0.04, "h_over_spacing": 1.3}, "time": {"cfl": 0.25}}
        t = gc.first_end_time(scene, 0.006, 10)
        self.assertAlmostEqual(t, 10 * 0.25 * 1.3 * 0.006 / (10 * (2 * 9.81 * 0.6) ** 0.5))


class Judgement(unittest.TestCase):
    def test_sanitizer(self):
        self.assertEqual(gc.sanitizer_errors("========= COMPUTE-SANITIZER\nrun\n"
                                             "========= ERROR SUMMARY: 0 errors\n"), 0)
        self.assertEqual(gc.sanitizer_errors("========= Invalid __global__ read of size 8\n"
                                             "========= ERROR SUMMARY: 12 errors\n"), 12)
        self.assertIsNone(gc.sanitizer_errors("fluid_sim: error: no GPU\n"))

    def test_program(self):
        out = "2D dam break:\n  ok   positions: 0 particles differ\n  ok   pressure: x\nPASSED\n"
        row = gc.judged("t", 0, out, gpu=True)
        self.assertEqual((row.result, row.figure), (gc.PASS, "2 ok, 0 failed"))
        bad = out.replace("ok   pressure", "FAIL pressure").replace("PASSED", "FAILED")
        self.assertEqual(gc.judged("t", 1, bad, gpu=True).result, gc.FAIL)
        # A FAIL line fails even where the program said PASSED and exited 0.
        self.assertEqual(gc.judged("t", 0, out.replace("ok   pressure", "FAIL pressure"),
                                   gpu=True).result, gc.FAIL)
        crashed = gc.judged("t", 134, "terminate called after ...\n", gpu=True)
        self.assertEqual(crashed.result, gc.FAIL)
        self.assertIn("exit 134", crashed.figure)
        skipped = "skipped: no GPU: no CUDA GPU found\n"
        self.assertEqual(gc.judged("t", 77, skipped, gpu=True).result, gc.FAIL)
        self.assertEqual(gc.judged("t", 77, skipped, gpu=False).result, gc.SKIPPED)
        self.assertIn("no CUDA GPU found", gc.judged("t", 77, skipped, gpu=True).figure)


class Table(unittest.TestCase):
    def test_table_and_exit(self):
        rows = [gc.Row("gpu", gc.INFO, "NVIDIA H100 | 580", 0.1), gc.Row("step", gc.PASS, "9 ok"),
                gc.Row("memcheck", gc.SKIPPED, "compute-sanitizer not found")]
        lines = gc.table(rows).splitlines()
        self.assertEqual(lines[0], "| check | result | figure | seconds |")
        self.assertEqual(len(lines), 2 + len(rows))
        self.assertEqual(lines[2], "| gpu | info | NVIDIA H100 / 580 | 0.1 |")  # no stray column
        self.assertTrue(all(l.count("|") == 5 for l in lines))
        self.assertEqual(gc.exit_code(rows), 0)
        self.assertEqual(gc.exit_code(rows + [gc.Row("1e7", gc.FAIL, "exit 12")]), 1)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
