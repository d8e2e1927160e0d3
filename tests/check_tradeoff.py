#!/usr/bin/env python3
"""tradeoff: each level keeps the fastest answer any level (or the schedule given) found that
survives its own scenarios, so a cost is never negative; a schedule given with --force that the
level's own small search cannot reach is adopted at the 0 % level with the time `simulate`
gives it; Ctrl-C during a later level writes the finished levels, marked incomplete (exit 1).

usage: check_tradeoff.py ZIPOPT_EXE SOURCE_DIR"""
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile

from checklib import check, done
import time

exe, src = sys.argv[1], sys.argv[2]
seed = os.path.join(src, "config", "seed.ini")
# the seed's nominal optimum: a 40-simulation search does not find it, the given schedule is it
GIVEN = "59.5891457,500,500"
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "t")
    p = subprocess.run([exe, "tradeoff", seed, "--levels", "1", "--max-evals", "40", "--force",
                        GIVEN, "--json", "--out", out], capture_output=True, text=True)
    check(p.returncode == 0, "tradeoff: exit %d: %s" % (p.returncode, p.stderr[-500:]))
    d = json.loads(p.stdout)
    lv = d["levels"]
    check(d["complete"] is True and len(lv) == 2, "two levels, complete")
    sim = subprocess.run([exe, "simulate", seed, "--force", GIVEN, "--json", "--out",
                          os.path.join(tmp, "s")], capture_output=True, text=True)
    t_given = json.loads(sim.stdout)["time"]
    check(lv[0]["found"] and abs(lv[0]["time"] - t_given) < 1e-5,
          "the 0 %% level holds the given schedule: %s s against simulate's %s s"
          % (lv[0]["time"], t_given))
    check(lv[0]["from_level_pct"] is None, "the 0 % level's answer is the given one")
    for level in lv:
        if level["found"]:
            check(level["cost"] >= 0, "+/-%g %%: cost %g s is negative"
                  % (level["force_error_pct"], level["cost"]))
    with open(os.path.join(out, "tradeoff.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 2 and rows[0]["from_level_pct"] == "", "tradeoff.csv: %s" % rows)

    # Ctrl-C once the 0 % level is done: that level is written, marked incomplete
    out2 = os.path.join(tmp, "i")
    with open(os.path.join(tmp, "err"), "w+") as err:
        proc = subprocess.Popen([exe, "tradeoff", seed, "--levels", "5", "--out", out2],
                                stdout=subprocess.PIPE, stderr=err, text=True)
        deadline = time.time() + 120
        while time.time() < deadline and proc.poll() is None:
            err.seek(0)
            if "tradeoff: +/-0 %" in err.read():
                break
            time.sleep(0.05)
        proc.send_signal(signal.SIGINT)
        stdout, _ = proc.communicate(timeout=120)
        err.seek(0)
        said = err.read()
    if proc.returncode == 0 and "+/-5 %" in stdout:
        print("note: the +/-5 % level finished before the signal; nothing to check")
    else:
        check(proc.returncode == 1, "interrupted tradeoff: exit %d: %s" % (proc.returncode, said))
        check("marked incomplete" in said, "says what it wrote: %s" % said)
        with open(os.path.join(out2, "report.md")) as f:
            check("**Incomplete**" in f.read(), "report.md marked incomplete")
        with open(os.path.join(out2, "tradeoff.csv")) as f:
            rows = list(csv.DictReader(f))
        check([r["force_error_pct"] for r in rows] == ["0"], "only the finished level: %s" % rows)

done("check_tradeoff")
