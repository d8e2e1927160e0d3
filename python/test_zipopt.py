"""The Python module over libzipopt.so: the seed scene at 10 N finishes at the very time
`zipopt simulate --json` prints (bit for bit: the same library code), the energy audit closes,
the trajectory's columns keep their definitions, the audit books drag and friction work, a
schedule file gives the program's bits, a bad scene raises with its file and line,
and a search keeps its budget and stops when its progress function asks; the schedule's
parameters are what `zipopt check --json` says of [drive] forces (one per section, labelled by
section, N, within min and max), and a search answers with that many. Misuse raises
ValueError instead of crashing, hanging or being misread (each case in a child interpreter,
so a crash or a hang fails that case alone): a closed Scene, one closed inside a progress
function, a scene loaded or searched from inside one, NUL bytes in text, names and paths,
and whole numbers past a C long. The drive's figures and the gradient (time, margin and every
[limits] value's derivatives) are the program's bits.

Run by ctest with PYTHONPATH (the module), ZIPOPT_LIB (the built library), ZIPOPT_EXE (the
program) and ZIPOPT_SOURCE_DIR (the scenes) set.
"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import zipopt

SRC = os.environ.get("ZIPOPT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))
SEED = os.path.join(SRC, "config", "seed.ini")
K_RTOL = 300.0  # closed forms and audits are met to a few hundred times the requested rtol


class DriveAndGradient(unittest.TestCase):
    def test_equal_the_program(self):
        # the drive's figures (a capped drive) and every derivative are the program's bits
        cases = [(os.path.join(SRC, "config", "seed_power.ini"), [60, 500, 500]),
                 (os.path.join(SRC, "tests", "scenes", "gradient_limits.ini"), None)]
        for path, forces in cases:
            with tempfile.TemporaryDirectory() as out:
                extra = ["--force", ",".join(map(str, forces))] if forces else []
                js = subprocess.run([os.environ["ZIPOPT_EXE"], "simulate", path, *extra,
                                     "--gradient", "--json", "--out", out],
                                    check=True, capture_output=True, text=True).stdout
            prog = json.loads(js)
            with zipopt.Scene(path, forces=forces) as s:
                r = s.simulate()
                g = s.gradient()
            self.assertEqual(r.drive_peak_power, prog["drive"]["peak_power"])
            self.assertEqual(r.drive_energy, prog["drive"]["energy"])
            self.assertEqual(r.drive_time_at_cap, prog["drive"]["time_at_cap"])
            pg = prog["gradient"]
            self.assertEqual(list(g["time"]), pg["time"])
            self.assertEqual(list(g["margin_angle"]), pg["margin_angle"])
            self.assertEqual(g["smooth"], pg["smooth"])
            self.assertEqual(set(g["limits"]), {k for k, v in pg["limits"].items() if v})
            for k, v in g["limits"].items():
                self.assertEqual(list(v), pg["limits"][k])
                self.assertEqual(g["limits_smooth"][k], k not in pg["limits_not_smooth"])
        self.assertGreater(r.drive_peak_power, 0)


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

    def test_schedule_file_equals_the_program(self):
        # the schedule.ini `zipopt simulate --schedule` reads gives the program's bits here too
        with tempfile.TemporaryDirectory() as out:
            sched = os.path.join(out, "schedule.ini")
            with open(sched, "w") as f:
                f.write("[drive]\nforces = 12.5, 30, 7\n")
            js = subprocess.run([os.environ["ZIPOPT_EXE"], "simulate", SEED, "--schedule",
                                 sched, "--json", "--out", out],
                                check=True, capture_output=True, text=True).stdout
            r = zipopt.simulate(SEED, schedule=sched)
            with zipopt.Scene(SEED) as s:
                s.load_schedule(sched)
                self.assertEqual(list(s.forces), [12.5, 30, 7])
                with open(sched, "w") as f:
                    f.write("[drive]\nforces = 1, 2\n")
                with self.assertRaises(zipopt.ZipoptError) as e:
                    s.load_schedule(sched)
                self.assertIn("schedule.ini:2: [drive] forces", str(e.exception))
                self.assertEqual(list(s.forces), [12.5, 30, 7])
        self.assertEqual(r.time, json.loads(js)["time"])

    def test_search_numbers_equal_the_program(self):
        # the robust search through the module: its convergence and verification numbers are
        # those the command's summary.json reports for the same scene, budget and seed
        scene = os.path.join(SRC, "config", "seed_robust.ini")
        best = zipopt.search(scene, max_evals=300, seed=3)
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([os.environ["ZIPOPT_EXE"], scene, "--max-evals", "300", "--seed", "3",
                            "--no-plot", "--out", out], capture_output=True, text=True)
            with open(os.path.join(out, "summary.json")) as f:
                prog = json.load(f)
        conv, rb = prog["convergence"], prog["robust"]
        n = best.numbers
        self.assertEqual(list(best.forces), prog["forces"])
        for key in ("rounds", "polishes", "basins", "reached_best"):
            self.assertEqual(n[key], conv[key], key)
        self.assertEqual(bool(n["converged"]), conv["converged"])
        self.assertEqual(bool(n["budget_ran_out"]), conv["budget_ran_out"])
        self.assertEqual(n["scenarios"], rb["scenarios"])
        for key in ("samples", "survived", "margin_kept", "limits_kept", "all_kept", "lower_95"):
            self.assertEqual(n["verify_" + key] if key != "lower_95" else n[key],
                             rb["verify"][key], key)
        self.assertEqual(n["worst_margin_deg"], rb["worst_margin_deg"])
        for key in ("fastest_s", "slowest_s", "arrival_low_kmh", "arrival_high_kmh"):
            self.assertEqual(n[key], rb["spread"][key]["value"], key)
        self.assertEqual(n["headroom"], rb["headroom"]["factor"])
        ranges = {r["range"]: r["factor"] for r in rb["headroom"]["ranges"]}
        self.assertTrue(ranges)
        for name, factor in ranges.items():
            self.assertEqual(n["headroom_" + name.replace(" ", "_")], factor, name)

    def test_loads_and_limits_equal_the_program(self):
        # every quantity [limits] judge, as `zipopt simulate --json` reports it, bit for bit
        scene = os.path.join(SRC, "config", "seed_robust.ini")
        for forces in ([14.81, 88.55, 241.68], [100, 100, 100]):
            r = zipopt.simulate(scene, forces=forces)
            with tempfile.TemporaryDirectory() as out:
                js = subprocess.run([os.environ["ZIPOPT_EXE"], "simulate", scene, "--force",
                                     ",".join(map(str, forces)), "--json", "--out", out],
                                    check=True, capture_output=True, text=True).stdout
            prog = json.loads(js)
            self.assertEqual(r.peak_g, max(prog["loads"]["acc_peak_g"]))
            self.assertEqual(r.peak_joint_force, max(prog["loads"]["joint_peak"]))
            self.assertEqual(r.normal_min, prog["loads"]["normal_min"])
            self.assertEqual(r.normal_max, prog["loads"]["normal_max"])
            self.assertEqual(r.peak_g, prog["limits"]["max_g"]["reached"])
            self.assertEqual(r.rejected_steps, prog["stats"]["rejected_steps"])
            arrival = prog["limits"]["max_arrival_speed"]["reached"]
            if prog["outcome"] == "finished":
                self.assertEqual(r.arrival_kmh, arrival)
                self.assertAlmostEqual(r.arrival_kmh, 3.6 * prog["speed"], places=9)
            else:  # did not arrive: no arrival speed
                self.assertTrue(np.isnan(r.arrival_kmh) and arrival is None)

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
        # seed_real: drag and rolling take out ~23 kJ, booked by the audit (docs/model.md)
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


class Params(unittest.TestCase):
    def test_params_are_the_scene_drive(self):
        js = subprocess.run([os.environ["ZIPOPT_EXE"], "check", SEED, "--json"],
                            check=True, capture_output=True, text=True).stdout
        prog = json.loads(js)
        with zipopt.Scene(SEED) as s:
            self.assertEqual(s.params, len(prog["forces"]))
            self.assertEqual(s.params, s.sections)
            self.assertEqual(s.param_labels, [f"section {k + 1}" for k in range(s.sections)])
            self.assertEqual(s.param_unit, "N")
            lo, hi = s.bounds
            self.assertEqual(list(lo), [prog["force_min"]] * s.params)
            self.assertEqual(list(hi), [prog["force_max"]] * s.params)
            self.assertEqual(len(s.search(max_evals=30, seed=1).forces), s.params)


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


# each snippet prints "ok" when every misuse raised ValueError
MISUSE = {
    "closed": """
s = zipopt.Scene(SEED)
s.close()
for use in (lambda: s.simulate(), lambda: s.forces, lambda: s.name, lambda: s.sections,
            lambda: s.search(max_evals=10), lambda: setattr(s, "forces", [1, 2, 3])):
    try:
        use()
        raise SystemExit("a closed Scene was used")
    except ValueError:
        pass
s.close()  # twice is fine
print("ok")
""",
    "closed_in_progress": """
s = zipopt.Scene(SEED)
def progress(*args):
    s.close()
try:
    s.search(max_evals=200, seed=1, progress=progress)
    raise SystemExit("closed while searched")
except ValueError:
    pass
print("ok" if s.simulate().outcome else "no run")
""",
    "load_in_progress": """
def load(*args):
    zipopt.Scene(SEED)
def search(*args):
    zipopt.search(SEED, max_evals=10)
for progress in (load, search):
    try:
        zipopt.search(SEED, max_evals=200, seed=1, progress=progress)
        raise SystemExit("re-entered the library")
    except ValueError:
        pass
other = zipopt.Scene(SEED)
ran = []
zipopt.search(SEED, max_evals=100, seed=1, progress=lambda *a: ran.append(other.simulate().time))
print("ok" if ran else "the other scene did not run")
""",
    "nul": r"""
text = open(SEED).read()
for make in (lambda: zipopt.Scene(text.replace("forces = ", "forces = 10\0"), text=True),
             lambda: zipopt.Scene(text, text=True, name="a\0b"),
             lambda: zipopt.Scene(SEED + "\0.ini"),
             lambda: zipopt.Scene(os.fsencode(SEED) + b"\0x")):
    try:
        make()
        raise SystemExit("a NUL byte passed")
    except ValueError:
        pass
print("ok")
""",
    "wide_ints": """
for kw in ({"max_evals": 2**64 + 30}, {"seed": 2**63}, {"max_evals": -2**70}, {"seed": 1.5}):
    try:
        zipopt.search(SEED, **kw)
        raise SystemExit(f"{kw} accepted")
    except ValueError:
        pass
print("ok")
""",
}


class Misuse(unittest.TestCase):
    def run_case(self, name):
        code = f"import os, zipopt\nSEED = {SEED!r}\n" + MISUSE[name]
        try:
            p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                               timeout=60)
        except subprocess.TimeoutExpired:
            self.fail(f"{name}: hung for 60 s")
        self.assertEqual((p.returncode, p.stdout.strip()), (0, "ok"), f"{name}: {p.stderr}")

    def test_closed(self):
        self.run_case("closed")

    def test_closed_in_progress(self):
        self.run_case("closed_in_progress")

    def test_load_in_progress(self):
        self.run_case("load_in_progress")

    def test_nul(self):
        self.run_case("nul")

    def test_wide_ints(self):
        self.run_case("wide_ints")


if __name__ == "__main__":
    unittest.main(verbosity=1)
