#!/usr/bin/env python3
"""`[optimize] objective = slowest` through the command: a trolley with a negligible chain on a
straight slope, pushed by at most 30 N, its mass 80-150 % of 20 kg. The fastest push for every
rider is the largest, and the slowest rider is the heaviest: the search's objective must be
that rider's finish time in closed form, T = sqrt(2 * 200 / x''), (1 + 0.04) x'' = F / m0 +
0.2 g, and its answer 30 N.

usage: check_slowest.py ZIPOPT_EXE SOURCE_DIR"""
import json
import math
import os
import subprocess
import sys
import tempfile

from checklib import check, done

exe = sys.argv[1]
SCENE = """[scene]
name = slowest
[course]
x_start = 0
section = 200 : 100 - 0.2*x
[trolley]
mass = 20
[body]
lengths = 1, 1
masses = 1e-6, 1e-6
damping = 1e-6
[drive]
min = 0
max = 30
[optimize]
objective = slowest
max_evals = 300
[robust]
trolley_mass_range = 80, 150
samples = 4
verify_samples = 50
"""
with tempfile.TemporaryDirectory() as tmp:
    scene = os.path.join(tmp, "slowest.ini")
    with open(scene, "w") as f:
        f.write(SCENE)
    p = subprocess.run([exe, scene, "--no-plot", "--json", "--out", os.path.join(tmp, "o")],
                       capture_output=True, text=True)
    check(p.returncode == 0, "exit %d: %s" % (p.returncode, p.stderr[-300:]))
    d = json.loads(p.stdout)
    want = math.sqrt(2 * 200 / ((30 / (20 * 1.5) + 0.2 * 9.81) / 1.04))
    check(d["objective"] == "slowest" and abs(d["objective_s"] - want) <= 1e-6 * want,
          "objective %s %s s, closed form %s s" % (d.get("objective"), d.get("objective_s"), want))
    check(abs(d["forces"][0] - 30) <= 1e-6, "the answer pushes %s N, not 30" % d["forces"])
done("check_slowest")
