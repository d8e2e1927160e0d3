#!/usr/bin/env python3
"""The search follows the edge where two constraints meet: on the seed under max_g 12 and 90 km/h
(bench/scenes/seed_limits.ini) the fastest schedules lie where the margin and the arrival speed
bind together, and the search reaches them (<= 12.62 s, where it stopped at 12.685 s while COBYLA
saw the largest of the two as one constraint). Its answer, rerun by `zipopt simulate` with the
scene's [solver] (an independent run through another command), keeps the margin and both limits;
the same answer on 1 and 2 threads. The budget is half the default's: a larger budget runs every
simulation a smaller one does, so the default's answer is at least as fast.

usage: check_limits_edge.py ZIPOPT_EXE SOURCE_DIR"""
import json
import os
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]
scene = os.path.join(src, "bench", "scenes", "seed_limits.ini")
TARGET, MARGIN, DEATH, MAX_G, MAX_ARRIVAL = 12.62, 10.0, 180.0, 12.0, 90.0  # s, deg, deg, g, km/h


def search(out, threads):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    p = subprocess.run([exe, scene, "--max-evals", "2500", "--no-plot", "--json", "--out", out],
                       capture_output=True, text=True, env=env)
    check(p.returncode == 0, "search on %d threads: exit %d: %s" % (threads, p.returncode,
                                                                    p.stderr[-500:]))
    return json.loads(p.stdout) if p.returncode == 0 else None


with tempfile.TemporaryDirectory() as tmp:
    two = search(os.path.join(tmp, "two"), 2)
    one = search(os.path.join(tmp, "one"), 1)
    if two and one:
        check(two["found"] and two["verified"], "the answer is found and verified")
        check(two["time"] <= TARGET, "the answer %.6f s is not <= %g s" % (two["time"], TARGET))
        check(one["forces"] == two["forces"] and one["time"] == two["time"],
              "1 and 2 threads differ: %s, %s" % (one["forces"], two["forces"]))
        sched = os.path.join(tmp, "two", "schedule.ini")
        p = subprocess.run([exe, "simulate", scene, "--schedule", sched, "--json", "--out",
                            os.path.join(tmp, "sim")], capture_output=True, text=True)
        check(p.returncode == 0, "simulate: exit %d: %s" % (p.returncode, p.stderr[-500:]))
        if p.returncode == 0:
            run = json.loads(p.stdout)
            lim = run["limits"]
            check(run["outcome"] == "finished", "the rerun %s" % run["outcome"])
            check(run["time"] <= TARGET, "the rerun takes %.6f s" % run["time"])
            check(abs(run["time"] - two["time"]) < 1e-6,
                  "the rerun %.9f s, the search's answer %.9f s" % (run["time"], two["time"]))
            angle = max(abs(a) for a in run["max_rel_angle"])
            check(angle <= DEATH - MARGIN, "the rerun's largest angle %.4f deg breaks the "
                  "margin" % angle)
            check(lim["max_g"]["limit"] == MAX_G and lim["max_g"]["reached"] <= MAX_G,
                  "max_g: %s" % lim["max_g"])
            check(lim["max_arrival_speed"]["limit"] == MAX_ARRIVAL and
                  lim["max_arrival_speed"]["reached"] <= MAX_ARRIVAL,
                  "max_arrival_speed: %s" % lim["max_arrival_speed"])
            check(lim["max_g"]["kept"] and lim["max_arrival_speed"]["kept"], "kept: %s" % lim)
            print("answer %.6f s at %s: %.4f deg, %.4f g, %.4f km/h" % (
                run["time"], two["forces"], angle, lim["max_g"]["reached"],
                lim["max_arrival_speed"]["reached"]))
done("check_limits_edge")
