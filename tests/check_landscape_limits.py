#!/usr/bin/env python3
"""The landscape judges every push by the scene's margin and [limits], as the search does: on the
seed with an arrival-speed and a felt-g limit, each landscape.csv row's `kept` and `binding` follow
from what `zipopt simulate` of the same push reaches (an independent run through another
command), the printed "fastest" is the fastest push that keeps them all, and the fastest
finishing push is named with what it breaks.

usage: check_landscape_limits.py ZIPOPT_EXE SOURCE_DIR"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]
ARRIVAL, G, MARGIN = 42.0, 12.5, 10.0  # km/h, g, deg: the seed's constant pushes straddle them
with open(os.path.join(src, "config", "seed.ini")) as f:
    seed = f.read()
with tempfile.TemporaryDirectory() as tmp:
    scene = os.path.join(tmp, "limited.ini")
    with open(scene, "w") as f:
        f.write(seed + "\n[limits]\nmax_arrival_speed = %g\nmax_g = %g\n" % (ARRIVAL, G))
    out = os.path.join(tmp, "land")
    p = subprocess.run([exe, "landscape", scene, "--force-range", "5:35:13", "--out", out],
                       capture_output=True, text=True)
    check(p.returncode == 0, "landscape: exit %d: %s" % (p.returncode, p.stderr[-500:]))
    with open(os.path.join(out, "landscape.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 13, "13 pushes, got %d" % len(rows))
    check("max_arrival_speed_reached_km_h" in rows[0] and "max_g_reached_g" in rows[0],
          "columns for the limits set: %s" % list(rows[0]))
    kept_rows = []
    for r in rows:
        force = float(r["force"])
        q = subprocess.run([exe, "simulate", scene, "--force", "%s,%s,%s" % ((r["force"],) * 3),
                            "--json", "--out", os.path.join(tmp, "sim")],
                           capture_output=True, text=True)
        d = json.loads(q.stdout)
        finished = d["outcome"] == "finished"
        angle = max(d["max_rel_angle"])
        arrival = d["limits"]["max_arrival_speed"]["reached"]
        g = d["limits"]["max_g"]["reached"]
        want = []
        if not finished:
            want.append(d["outcome"])
        elif angle > 180 - MARGIN:
            want.append("margin")
        else:
            over = [(v / lim, name) for v, lim, name in
                    ((arrival, ARRIVAL, "max_arrival_speed"), (g, G, "max_g")) if v > lim]
            if over:
                want.append(max(over)[1])
        binding = want[0] if want else ""
        check(r["outcome"] == d["outcome"], "%g N: outcome %s vs %s" % (force, r["outcome"],
                                                                         d["outcome"]))
        check(r["binding"] == binding and r["kept"] == ("0" if want else "1"),
              "%g N: kept %s binding %r, simulate says %r" % (force, r["kept"], r["binding"],
                                                             binding))
        if finished:
            check(abs(float(r["max_arrival_speed_reached_km_h"]) - arrival) <= 1e-6 * arrival,
                  "%g N: arrival %s vs %g" % (force, r["max_arrival_speed_reached_km_h"], arrival))
        if not want:
            kept_rows.append((float(r["time"]), force))
    finishing = [(float(r["time"]), float(r["force"]), r["binding"]) for r in rows
                 if r["outcome"] == "finished"]
    check(kept_rows and finishing and min(finishing) != min(kept_rows),
          "the case must have a fastest finishing push that breaks a limit: %s / %s"
          % (kept_rows, finishing))
    if kept_rows:
        m = re.search(r"^fastest: ([0-9.e+-]+) N, finished in", p.stdout, re.M)
        check(m and float(m.group(1)) == min(kept_rows)[1],
              "fastest printed %s, the fastest kept push is %g N" % (m and m.group(1),
                                                                      min(kept_rows)[1]))
    if finishing:
        t, force, why = min(finishing)
        check(("fastest finishing push: %g N, %.3f s, breaks %s" % (force, t, why)) in p.stdout
              or (kept_rows and min(kept_rows)[1] == force),
              "the fastest finishing push is named with what it breaks: %s" % p.stdout)

done("check_landscape_limits")
