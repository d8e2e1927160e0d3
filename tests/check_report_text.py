#!/usr/bin/env python3
"""report.md fits the scene it reports: its kink table lists exactly the crossings of the
boundaries `zipopt check --json` calls kinks (the best run's crossings from `zipopt simulate`
of the same schedule), section ends where the slopes agree are counted apart; the robustness
table says it counts the limits when the scene has [limits] (the seed with max_g) and is drawn
at the scene's own force error and twice it (2 % and 5 % without one); the gain
over the scene's own [drive] forces says what those break.

usage: check_report_text.py ZIPOPT_EXE SOURCE_DIR"""
import json
import os
import re
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(src, "config", "seed.ini")) as f:
        limited = os.path.join(tmp, "limited.ini")
        with open(limited, "w") as g:
            g.write(f.read().replace("forces = 100, 100, 100", "forces = 20, 20, 20") +
                    "\n[limits]\nmax_g = 11.5\n")
        held = os.path.join(tmp, "held.ini")
        with open(held, "w") as g:
            f.seek(0)
            g.write(f.read() + "\n[robust]\nforce_error = 3\nsamples = 4\nverify_samples = 20\n")
    for name, limits in (("multi6", False), ("limited", True), ("held", False)):
        scene = {"limited": limited, "held": held}.get(name) or \
            os.path.join(src, "config", name + ".ini")
        out = os.path.join(tmp, name)
        p = subprocess.run([exe, scene, "--max-evals", "150", "--no-plot", "--out", out],
                           capture_output=True, text=True)
        check(p.returncode in (0, 3), "%s: exit %d: %s" % (name, p.returncode, p.stderr[-300:]))
        with open(os.path.join(out, "report.md")) as f:
            md = f.read()
        # the schedule the report is about, rerun through simulate; the boundaries from check
        forces = ",".join("%.17g" % x for x in json.load(open(os.path.join(out, "summary.json")))
                          ["forces"])
        run = json.loads(subprocess.run([exe, "simulate", scene, "--force", forces, "--json",
                                         "--out", os.path.join(tmp, "s")],
                                        capture_output=True, text=True).stdout)
        chk = json.loads(subprocess.run([exe, "check", scene, "--json"], capture_output=True,
                                        text=True).stdout)
        kinks = [b["x"] for b in chk["boundaries"] if b["kink"]]
        crossed = [k["x"] for k in run["kinks"]]
        want = sum(1 for x in crossed if any(abs(x - b) < 1e-9 for b in kinks))
        section = md[md.index("## Kink impulses"):md.index("## Loads")]
        rows = re.findall(r"^\| [0-9.]+ \| [0-9.e+-]+ \| \d+ -> \d+ \|", section, re.M)
        check(len(rows) == want, "%s: %d kink rows, %d kink crossings" % (name, len(rows), want))
        smooth = len(crossed) - want
        if smooth:
            check("%d crossing%s of section ends where the slopes agree" %
                  (smooth, "" if smooth == 1 else "s") in section, "%s: %s" % (name, section))
        else:
            check("slopes agree" not in section, "%s: %s" % (name, section))
        check(("margin and every limit kept |" in md) == limits,
              "%s: the robustness table's header" % name)
        # the robustness table at the scene's level (and twice it), else at 2 % and 5 %
        levels = re.findall(r"^\| (\d+) % \| \d+ \|", md, re.M)
        want_levels = ["3", "6"] if name == "held" else ["2", "5"]
        check(levels == want_levels, "%s: robustness levels %s, want %s" % (name, levels,
                                                                          want_levels))
        if limits:  # the scene's own 20 N finishes over max_g: the comparison says so
            own = json.loads(subprocess.run([exe, "simulate", scene, "--json", "--out",
                                             os.path.join(tmp, "o")], capture_output=True,
                                            text=True).stdout)
            summary = json.load(open(os.path.join(out, "summary.json")))
            broken = own["outcome"] == "finished" and not own["limits"]["max_g"]["kept"]
            check(broken and summary["scene_forces"]["breaks"] == "max_g"
                  and "the scene's own [drive] forces (20, 20, 20 N: " in md and
                  "breaks max_g)" in md, "%s: the scene's forces: %s" % (name,
                                                                         summary["scene_forces"]))
    check(len(kinks) == 2, "the seed has two kinks: %s" % kinks)

done("check_report_text")
