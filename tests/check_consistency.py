#!/usr/bin/env python3
"""Every number of the search's report is the one the other surfaces give for its answer, on a
designer's line (config/tower.ini: four stretches off a 40 m tower, drag, rolling, rounded
kinks, a 45-120 kg population, felt g and arrival limits) and on that line with an eddy brake
over its landing zone (config/tower_brake.ini): report.md and report.html state summary.json's
finish time (and the brake work simulate gives); `simulate --schedule schedule.ini` gives that
time and those limit values bit for bit; the sweep at the scene itself (--schedule, one point;
through the brake's eddy key on the braked line), the landscape's slice cell at the answer's
forces and the Python module give the same run.

usage: check_consistency.py ZIPOPT_EXE SOURCE_DIR"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]


def run(*args):
    p = subprocess.run([exe, *args], capture_output=True, text=True)
    check(p.returncode in (0, 3), "%s: exit %d: %s" % (args[:2], p.returncode, p.stderr[-300:]))
    return p


def brake_eddy():
    """config/tower_brake.ini's [brake] eddy, for the one-point sweep through it"""
    text = open(os.path.join(src, "config", "tower_brake.ini")).read()
    return re.search(r"\[brake\][^[]*?\neddy *= *([0-9.]+)", text).group(1)


def consistent(name, vary):
    """the surfaces of scene config/NAME.ini agree; vary: the sweep's one-point --vary"""
    with open(os.path.join(src, "config", name + ".ini")) as f:
        tower = f.read()
    with tempfile.TemporaryDirectory() as tmp:
        scene = os.path.join(tmp, name + ".ini")
        with open(scene, "w") as f:  # a smaller verification: the test checks agreement, not odds
            f.write(tower.replace("samples = 16\n", "samples = 4\nverify_samples = 100\n"))
        out = os.path.join(tmp, "search")
        run(scene, "--max-evals", "300", "--out", out)
        summary = json.load(open(os.path.join(out, "summary.json")))
        sched = os.path.join(out, "schedule.ini")
        t = summary["time"]

        # report.md and report.html state the summary's finish time and forces
        md = open(os.path.join(out, "report.md")).read()
        html = open(os.path.join(out, "report.html")).read()
        check("Finish time: **%.4f s**" % t in md, "report.md's finish time")
        check("Finish time: <strong>%.4f s</strong>" % t in html, "report.html's finish time")
        for k, force in enumerate(summary["forces"]):
            check("| %d |" % (k + 1) in md and "%.4f |" % force in md, "force %d in report.md" % k)

        # simulate of the written schedule: the same run
        sim = json.loads(run("simulate", scene, "--schedule", sched, "--json", "--out",
                             os.path.join(tmp, "sim")).stdout)
        check(sim["time"] == t, "simulate %r, summary %r" % (sim["time"], t))
        if "brake_work" in sim["energy"]:
            work = "Brake work (energy taken out): %.0f J." % sim["energy"]["brake_work"]
            check(work in md and work in html, "report.md/html's brake work: %s" % work)
            # the arrival is judged as braked: no "calls for a brake" on a line that has one
            landed = "Arrival at %.1f km/h after the brake zone" % (sim["speed"] * 3.6)
            check(landed in md and "calls for a brake" not in md,
                  "report.md judges the arrival after the brake zone: %s" % landed)
        for key, lim in summary["limits"].items():
            if isinstance(lim, dict) and "reached" in lim:
                check(sim["limits"][key]["reached"] == lim["reached"],
                      "%s: simulate %s, summary %s" % (key, sim["limits"][key], lim))

        # the sweep at the scene itself: one point, the schedule laid over it
        sw = os.path.join(tmp, "sweep")
        run("sweep", scene, "--vary", vary, "--run", "simulate",
            "--schedule", sched, "--out", sw)
        row = list(csv.DictReader(open(os.path.join(sw, "sweep.csv"))))[0]
        check(float(row["time_s"]) == t and float(row["arrival_kmh"]) ==
              sim["limits"]["max_arrival_speed"]["reached"] and
              float(row["peak_g"]) == sim["limits"]["max_g"]["reached"] and row["found"] == "1",
              "sweep row %s against simulate" % row)

        # the landscape's slice through the answer: its cell at (F1, F2) is the same run
        f1, f2 = summary["forces"][0], summary["forces"][1]
        land = os.path.join(tmp, "land")
        run("landscape", scene, "--schedule", sched, "--force-range", "0:10:2", "--slice", "1,2",
            "--range", "%.17g:%.17g:2,%.17g:%.17g:2" % (f1, f1 + 1, f2, f2 + 1), "--out", land)
        cells = list(csv.DictReader(open(os.path.join(land, "landscape_slice.csv"))))
        near = lambda a, b: abs(a - b) <= 5e-9 * abs(b)  # the CSV keeps 9 digits
        cell = [c for c in cells if near(float(c["f1"]), f1) and near(float(c["f2"]), f2)]
        check(len(cell) == 1 and near(float(cell[0]["time"]), t) and cell[0]["kept"] == "1",
              "landscape cell %s against %r" % (cell, t))

        # the Python module over the library (ZIPOPT_LIB: the built one; a sanitizer build's
        # library cannot load into python3, and that build leaves it unset)
        lib = os.environ.get("ZIPOPT_LIB")
        if not lib:
            print("check_consistency: no ZIPOPT_LIB, the Python module is not checked")
            return
        env = dict(os.environ, PYTHONPATH=os.path.join(src, "python"))
        code = ("import json, zipopt; r = zipopt.simulate(%r, schedule=%r); "
                "print(json.dumps([r.time, r.peak_g, r.arrival_kmh, r.w_brake]))" % (scene, sched))
        py = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True,
                            env=env)
        check(py.returncode == 0, "python: %s" % py.stderr[-300:])
        if py.returncode == 0:
            pt, pg, pa, pb = json.loads(py.stdout)
            check(pt == t and pg == sim["limits"]["max_g"]["reached"] and
                  pa == sim["limits"]["max_arrival_speed"]["reached"] and
                  pb == sim["energy"].get("brake_work", 0),
                  "python %s against simulate" % py.stdout)


consistent("tower", "physics.rolling=0.01:0.01:1")
consistent("tower_brake", "brake.eddy=%s:%s:1" % ((brake_eddy(),) * 2))
done("check_consistency")
