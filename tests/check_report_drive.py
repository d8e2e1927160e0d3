#!/usr/bin/env python3
"""The report's drive: on seed_profile at its default budget the search's report says what the
profile gains over the best constant-per-section schedule of the same scene, and that is true:
the same search over one force per section (the seed with the profile's budget and seed) finds
the constant optimum 9.0459 s (the seed's, known from 10x and the brute force), the profile
faster than that (the issue's floor), both rerun through simulate and the stated times and gain
equal to the reruns'; report.md's
drive table shows the answer's peak power, energy and time at the cap as `zipopt simulate
--json` gives them, and links drive.png, which is drawn; the seed (a constant kind) searches no
constant schedule beside its own.

usage: check_report_drive.py ZIPOPT_EXE SOURCE_DIR"""
import json
import os
import re
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]


def search(scene, out, *extra):
    p = subprocess.run([exe, scene, "--out", out, *extra], capture_output=True, text=True)
    check(p.returncode == 0, "%s: exit %d: %s" % (scene, p.returncode, p.stderr[-300:]))
    return p.stdout


def simulate(scene, forces, out):
    return json.loads(subprocess.run([exe, "simulate", scene, "--force",
                                      ",".join("%.17g" % x for x in forces), "--json", "--out",
                                      out], capture_output=True, text=True).stdout)


with tempfile.TemporaryDirectory() as tmp:
    profile = os.path.join(src, "config", "seed_profile.ini")
    out = os.path.join(tmp, "profile")
    text = search(profile, out)
    md = open(os.path.join(out, "report.md")).read()
    summary = json.load(open(os.path.join(out, "summary.json")))
    run = simulate(profile, summary["forces"], os.path.join(tmp, "s"))
    check(run["outcome"] == "finished" and run["time"] < 9.0459 - 1e-3,
          "the profile's answer: %.6f s, not faster than the constant optimum" % run["time"])
    gain = re.search(r"^- over the best constant-per-section schedule of the same scene \(the "
                     r"same search, budget and seed over one force per section: ([0-9., ]+) N, "
                     r"([0-9.]+) s; this profile ([0-9.]+) s\): ([0-9.]+) s faster", md, re.M)
    check(gain is not None, "report.md states the profile's gain:\n" + md[:2000])
    check("profile gain: %.4f s against 9.0459 s" % run["time"] in text,
          "the text summary:\n" + text)
    if gain:
        forces = [float(x) for x in gain.group(1).split(",")]
        const = simulate(os.path.join(src, "config", "seed.ini"), forces, os.path.join(tmp, "c"))
        check(const["outcome"] == "finished" and abs(const["time"] - 9.0459) < 5e-5,
              "the constant schedule %s reruns to %s at %.6f s" % (forces, const["outcome"],
                                                                  const["time"]))
        check(gain.group(2) == "9.0459" and gain.group(3) == "%.4f" % run["time"] and
              abs(float(gain.group(4)) - (const["time"] - run["time"])) < 1.5e-3,
              "the times: %s" % (gain.groups(),))
    # the drive table against the program's run of the answer (the search's answer profile)
    row = re.search(r"^\| ([0-9]+) W \| ([0-9.]+) kJ \| (.*) \|$", md, re.M)
    check(row is not None, "report.md's drive table")
    if row:
        check(int(row.group(1)) == round(run["drive"]["peak_power"]) and
              abs(float(row.group(2)) - run["drive"]["energy"] / 1000) < 6e-4 and
              row.group(3) == "no cap", "drive table %s against %s" % (row.groups(),
                                                                        run["drive"]))
    check("![the drive against distance and speed](drive.png)" in md and
          os.path.getsize(os.path.join(out, "drive.png")) > 1000, "drive.png, linked and drawn")
    # a constant kind: no second search, no line for it
    seed_out = os.path.join(tmp, "seed")
    text = search(os.path.join(src, "config", "seed.ini"), seed_out, "--max-evals", "150",
                  "--no-plot")
    md = open(os.path.join(seed_out, "report.md")).read()
    check("constant-per-section" not in md and "profile gain" not in text,
          "the seed reports no profile's gain")
    check("## Drive" in md, "the seed's report has its drive table")
done("check_report_drive")
