#!/usr/bin/env python3
"""The search's diagnosis of an answer that fails fresh scenarios agrees with the verification's
own tally (summary.json robust.verify): as many broken as not kept, each counted once by what
breaks and once per half of each range; report.md says where it fails; an answer that keeps
every fresh scenario gets no diagnosis.

usage: check_diagnosis.py ZIPOPT_EXE SOURCE_DIR"""
import json
import os
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]
with open(os.path.join(src, "config", "seed.ini")) as f:
    seed = f.read().replace("max_evals = 5000", "max_evals = 300")
# held to one scenario only, checked on 200: a wide population the answer cannot keep
WEAK = ("\n[limits]\nmax_g = 13\n[robust]\nforce_error = 8\nmass_range = 30, 300\nsamples = 1\n"
        "verify_samples = 200\n")
with tempfile.TemporaryDirectory() as tmp:
    for name, extra, fails in (("weak", WEAK, True),
                               ("kept", "\n[robust]\nforce_error = 1\nsamples = 8\n"
                                "verify_samples = 50\n", False)):
        scene = os.path.join(tmp, name + ".ini")
        with open(scene, "w") as f:
            f.write(seed + extra)
        out = os.path.join(tmp, name)
        p = subprocess.run([exe, scene, "--no-plot", "--out", out], capture_output=True,
                           text=True)
        check(p.returncode in (0, 3), "%s: exit %d: %s" % (name, p.returncode, p.stderr[-400:]))
        with open(os.path.join(out, "summary.json")) as f:
            rb = json.load(f)["robust"]
        v = rb["verify"]
        with open(os.path.join(out, "report.md")) as f:
            md = f.read()
        if not fails:
            check(v["all_kept"] == v["samples"] and "diagnosis" not in rb
                  and "Where it fails" not in md, "%s: no diagnosis when all are kept" % name)
            continue
        d = rb.get("diagnosis")
        check(d is not None and "### Where it fails" in md, "%s: a diagnosis" % name)
        if not d:
            continue
        check(d["samples"] == v["samples"] and d["broken"] == v["samples"] - v["all_kept"],
              "%s: broken %d, the verification kept %d of %d" % (name, d["broken"],
                                                                 v["all_kept"], v["samples"]))
        check(sum(d["by"].values()) == d["broken"] and d["broken"] > 0, "by: %s" % d["by"])
        check(d["by"].get("died", 0) + d["by"].get("stalled", 0) == v["samples"] - v["survived"],
              "died and stalled: %s, survived %d" % (d["by"], v["survived"]))
        names = [r["range"] for r in d["ranges"]]
        check(names == ["force error", "rider mass"], "the ranges varied: %s" % names)
        for r in d["ranges"]:
            check(r["lower"]["scenarios"] + r["upper"]["scenarios"] == d["samples"]
                  and r["lower"]["broken"] + r["upper"]["broken"] == d["broken"],
                  "%s halves: %s" % (r["range"], r))
        check(d["ranges"][1]["edges"] == [30, 165, 300], "mass edges %s" % d["ranges"][1])

done("check_diagnosis")
