"""The Python module over libzipopt.so: the seed scene at 10 N finishes at the very time
`zipopt simulate --json` prints (bit for bit: the same library code), the energy audit closes,
the trajectory's columns keep their definitions, the audit books drag and friction work, a bad scene raises with its file and line,
and a search keeps its budget and stops when its progress function asks.

Run by ctest with PYTHONPATH (the module), ZIPOPT_LIB (the built library), ZIPOPT_EXE (the
program) and ZIPOPT_SOURCE_DIR (the scenes) set.
"""

import json
import os
import subprocess
import tempfile
import unittest

import numpy as np

import zipopt

SRC = os.environ.get("ZIPOPT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))
SEED = os.path.join(SRC, "config", "seed.ini")
K_RTOL = 300.0  # closed forms and audits are met to a few hundred times the requested rtol


class Simulate(unittest.TestCase):
    def test_time_equals_the_program(self):
        r = zipopt.simulate(SEED, forces=[10, 10, 10])
        with tempfile.TemporaryDirectory() as out:
            js = subprocess.run([os.environ["ZIPOPT_EXE"], "simulate", SEED, "--force",
                                 "10,10,10", "--json", "--out", out],
                                check=True, capture_output=True, text=True).stdout
        prog = json.loads(js)
        self.assertEqual(r.outcome, prog["outcome"])
        self.assertEqual(r.time, prog["time"])  # bit for bit: JSON keeps 17 digits
        self.assertEqual(r.x, prog["x"])
        self.assertEqual(r.kinks, len(prog["kinks"]))

    def test_energy_and_trajectory(self):
        r = zipopt.simulate(SEED, forces=[10, 10, 10])
        tr = r.trajectory
        scale = max(r.e_initial, r.w_drive)
        self.assertLess(abs(r.energy_residual), K_RTOL * 1e-8 * scale)
        self.assertEqual(tr["t"][-1], r.time)
        self.assertEqual(tr["x"][-1], r.x)
        np.testing.assert_array_equal(tr["phi2"], tr["theta2"] - tr["theta1"])
        # kinetic + potential - (drive work - damper work - impulse loss) stays E(0)
        book = tr["kinetic"] + tr["potential"] - tr["drive_work"] + tr["damper_work"] \
            + tr["impulse_loss"]
        self.assertLess(np.max(np.abs(book - book[0])), K_RTOL * 1e-8 * scale)
        self.assertTrue(np.all(np.diff(tr["t"]) > 0))
        self.assertEqual(len(r.max_angles), 3)
        self.assertEqual(list(r.crossings["x"]), [60.0, 100.0])

    def test_energy_audit_with_drag_and_friction(self):
        # seed_real: drag and rolling take out ~23 kJ, booked by the audit (MODEL.md)
        r = zipopt.simulate(os.path.join(SRC, "config", "seed_real.ini"), forces=[80, 500, 500])
        self.assertEqual(r.outcome, "finished")
        self.assertGreater(r.w_drag, 1e4)
        self.assertGreater(r.w_fric, 0)
        audit = r.e_final - r.e_initial - r.w_drive + r.w_damp + r.e_impulse + r.w_drag \
            + r.w_fric
        self.assertLess(abs(r.energy_residual - audit), 1e-9 * r.w_drag)
        self.assertLess(abs(audit), K_RTOL * 1e-8 * r.w_drag)

    def test_scene_object_reuse(self):
        with zipopt.Scene(SEED, forces=[10, 10, 10]) as s:
            a = s.simulate()
            s.forces = [40, 40, 40]
            b = s.simulate()
            s.forces = [10, 10, 10]
            c = s.simulate()
        self.assertNotEqual(a.time, b.time)
        self.assertEqual(a.time, c.time)
        np.testing.assert_array_equal(a.trajectory["y"], c.trajectory["y"])


class Errors(unittest.TestCase):
    def test_bad_scene_names_file_line_key(self):
        with tempfile.NamedTemporaryFile("w", suffix=".ini", delete=False) as f:
            f.write("[scene]\nname = bad\n[body]\nmasses = 1, -2\n")
        try:
            with self.assertRaises(zipopt.ZipoptError) as e:
                zipopt.simulate(f.name)
            self.assertIn(f"{f.name}:4:", str(e.exception))
            self.assertIn("masses", str(e.exception))
        finally:
            os.unlink(f.name)

    def test_bad_forces(self):
        with self.assertRaises(zipopt.ZipoptError) as e:
            zipopt.simulate(SEED, forces=[10, 10])
        self.assertIn("3", str(e.exception))


class Search(unittest.TestCase):
    def test_budget_and_reproducible(self):
        a = zipopt.search(SEED, max_evals=60, seed=3)
        b = zipopt.search(SEED, max_evals=60, seed=3)
        self.assertLessEqual(a.evals, 60)
        np.testing.assert_array_equal(a.forces, b.forces)
        self.assertEqual(len(a.forces), 3)

    def test_progress_stops(self):
        calls = []

        def progress(evals, wall_s, found, time, forces, improved):
            calls.append(evals)
            return True

        s = zipopt.search(SEED, max_evals=400, seed=3, progress=progress)
        self.assertTrue(s.interrupted)
        self.assertGreaterEqual(len(calls), 1)
        self.assertLess(s.evals, 400)

    def test_progress_exception_raised(self):
        def progress(*args):
            raise KeyError("from progress")

        with self.assertRaises(KeyError):
            zipopt.search(SEED, max_evals=400, seed=3, progress=progress)


if __name__ == "__main__":
    unittest.main(verbosity=1)
