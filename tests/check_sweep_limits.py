#!/usr/bin/env python3
"""sweep judges every point by the scene's margin and [limits]: with `--run simulate` on the seed
with an arrival-speed limit, each sweep.csv row's found flag, binding limit and limited
quantities agree with `zipopt simulate` of the same forces (an independent run through another
command): a push that arrives too fast is not "found", and its row names max_arrival_speed.
--force and --schedule fix every point's forces, --max-evals bounds every point's search. A
ride that does not arrive has no arrival speed: neither kept nor broken.

usage: check_sweep_limits.py ZIPOPT_EXE SOURCE_DIR"""
import csv
import json
import os
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]
ARRIVAL = 42.0  # km/h: the seed at 20 N arrives under it, at 25 N over it, at 30 N it dies
with open(os.path.join(src, "config", "seed.ini")) as f:
    seed = f.read()
with tempfile.TemporaryDirectory() as tmp:
    scene = os.path.join(tmp, "limited.ini")
    with open(scene, "w") as f:
        f.write(seed + "\n[limits]\nmax_arrival_speed = %g\n" % ARRIVAL)
    out = os.path.join(tmp, "sw")
    p = subprocess.run([exe, "sweep", scene, "--vary", "drive.forces=0.2:0.3:3", "--run",
                        "simulate", "--out", out], capture_output=True, text=True)
    check(p.returncode == 0, "sweep: exit %d: %s" % (p.returncode, p.stderr[-500:]))
    with open(os.path.join(out, "sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 3, "3 points, got %d" % len(rows))
    seen = set()
    for r in rows:
        forces = [r["F%d_N" % k] for k in (1, 2, 3)]
        q = subprocess.run([exe, "simulate", scene, "--force", ",".join(forces), "--json",
                            "--out", os.path.join(tmp, "sim")], capture_output=True, text=True)
        d = json.loads(q.stdout)
        arrival = d["limits"]["max_arrival_speed"]["reached"]
        if d["outcome"] != "finished":  # never measured: neither kept nor broken
            check(arrival is None and d["limits"]["max_arrival_speed"]["kept"] is None,
                  "F = %s: a ride that did not arrive has no arrival speed: %s"
                  % (forces, d["limits"]["max_arrival_speed"]))
            t = subprocess.run([exe, "simulate", scene, "--force", ",".join(forces), "--out",
                                os.path.join(tmp, "sim")], capture_output=True, text=True)
            check("limit max_arrival_speed: not reached" in t.stdout, "text: %s" % t.stdout)
        arrival = 0 if arrival is None else arrival  # sweep.csv writes 0: did not arrive
        finished = d["outcome"] == "finished"
        margin_kept = max(d["max_rel_angle"]) <= 170
        kept = finished and margin_kept and arrival <= ARRIVAL
        want = ("death" if d["outcome"] == "died" else "t_max" if not finished
                else "margin" if not margin_kept else None if kept else "max_arrival_speed")
        check(r["found"] == ("1" if kept else "0"),
              "F = %s: found %s, simulate says %s" % (forces, r["found"], kept))
        if want:
            check(r["limit"] == want, "F = %s: limit %s, expected %s" % (forces, r["limit"], want))
            seen.add(want)
        check(abs(float(r["arrival_kmh"]) - arrival) <= 1e-9 * max(arrival, 1),
              "F = %s: arrival %s vs simulate %g" % (forces, r["arrival_kmh"], arrival))
        check(float(r["peak_g"]) > 1, "F = %s: peak_g %s" % (forces, r["peak_g"]))
    check("max_arrival_speed" in seen, "a point must break the arrival limit: %s" % seen)

    # --schedule then --force over the scene's forces, --max-evals over its budget
    sched = os.path.join(tmp, "s.ini")
    with open(sched, "w") as f:
        f.write("[drive]\nforces = 25, 25, 25\n")
    for opt in (["--schedule", sched], ["--force", "25,25,25"]):
        o = os.path.join(tmp, "f" + opt[0][2:])
        q = subprocess.run([exe, "sweep", scene, "--vary", "body.damping=1:2:2", "--run",
                            "simulate", "--out", o] + opt, capture_output=True, text=True)
        check(q.returncode == 0, "%s: exit %d: %s" % (opt, q.returncode, q.stderr[-300:]))
        with open(os.path.join(o, "sweep.csv")) as f:
            got = [[r["F%d_N" % k] for k in (1, 2, 3)] for r in csv.DictReader(f)]
        check(got == [["25"] * 3] * 2, "%s: the points ran %s" % (opt, got))
    o = os.path.join(tmp, "evals")
    q = subprocess.run([exe, "sweep", scene, "--vary", "body.damping=1:2:2", "--max-evals", "40",
                        "--no-grid-schedule", "--out", o], capture_output=True, text=True)
    check(q.returncode == 0, "--max-evals: exit %d: %s" % (q.returncode, q.stderr[-300:]))
    with open(os.path.join(o, "sweep.csv")) as f:
        evals = [int(r["evals"]) for r in csv.DictReader(f)]
    check(len(evals) == 2 and all(0 < e <= 40 for e in evals), "--max-evals 40: %s" % evals)
    # the figure's axes in the designer's units: a scaled list names what its factor scales
    o = os.path.join(tmp, "axes")
    q = subprocess.run([exe, "sweep", scene, "--vary", "body.masses=0.8:1.2:2", "--vary",
                        "limits.max_arrival_speed=40:50:2", "--run", "simulate", "--out", o],
                       capture_output=True, text=True)
    with open(os.path.join(o, "sweep.gp")) as f:
        gp = f.read()
    check("set xlabel '[body] masses: factor on 15, 5, 2 kg (the scene)'" in gp and
          "set ylabel '[limits] max_arrival_speed (km/h)'" in gp, "the axes: %s" % gp[:400])
    q = subprocess.run([exe, "sweep", scene, "--vary", "drive.forces=1:2:2", "--force", "1,2,3",
                        "--out", os.path.join(tmp, "no")], capture_output=True, text=True)
    check(q.returncode == 2 and not os.path.exists(os.path.join(tmp, "no")),
          "--force with a varied drive.forces is refused: %d" % q.returncode)

done("check_sweep_limits")
