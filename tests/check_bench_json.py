#!/usr/bin/env python3
"""`zipopt bench trade --json` (docs/commands.md: one JSON object on stdout): the documented keys; each
run's time error recomputed from its time and the reference's; the fastest configurations
found again by a brute-force loop over the runs; nothing but the object on stdout."""
import json
import math
import subprocess
import sys
import tempfile

exe = sys.argv[1]
failed = []


def check(ok, what):
    if not ok:
        failed.append(what)


with tempfile.TemporaryDirectory() as out:
    p = subprocess.run([exe, "bench", "trade", "--repeats", "1", "--json", "--out", out],
                       capture_output=True, text=True)
    check(p.returncode == 0, "exit status %d: %s" % (p.returncode, p.stderr[-500:]))
    d = json.loads(p.stdout)  # one object, nothing else on stdout
    check("wrote in" in p.stderr, "the files written are said on stderr")

for k in ["study", "scene", "repeats", "reference_rtol", "atol_per_rtol", "cases", "fastest"]:
    check(k in d, "key " + k)
check(d["study"] == "trade" and d["scene"] == "seed" and d["repeats"] == 1, "echoed inputs")
names = [c["name"] for c in d["cases"]]
check(names == ["survive", "die", "stiff"], "cases " + str(names))
methods = set()
for c in d["cases"]:
    ref = c["reference"]
    check(ref["outcome"] in ("finished", "died") and len(ref["methods"]) == 2, "reference")
    check(all(math.isfinite(ref["agreement"][k]) for k in ["time", "impulse", "angle", "x",
                                                           "speed"]), "agreement")
    rtols = sorted({r["rtol"] for r in c["runs"]}, reverse=True)
    check(len(rtols) == 10 and rtols[0] == 1e-3 and rtols[-1] == 1e-12, "rtol sweep")
    for r in c["runs"]:
        methods.add(r["method"])
        check(r["atol"] == r["rtol"] * d["atol_per_rtol"], "atol")
        e = r["error"]["time"]
        if r["outcome"] == ref["outcome"] and e is not None:
            check(e == abs(r["time"] - ref["time"]), "time error of %s %g" % (r["method"],
                                                                              r["rtol"]))
        elif r["outcome"] != ref["outcome"]:
            check(e is None, "a wrong outcome has no error")
        check(r["rhs_evals"] > 0 and r["steps"] > 0 and r["wall_s"] > 0, "cost")
check(len(methods) == 4, "every method")


def brute(target, cases):
    """the configuration of least total wall whose worst time error is within target"""
    best = None
    for m in sorted(methods):
        for tol in sorted({r["rtol"] for r in cases[0]["runs"]}, reverse=True):
            runs = [next(r for r in c["runs"] if r["method"] == m and r["rtol"] == tol)
                    for c in cases]
            errs = [r["error"]["time"] for r in runs]
            if any(x is None for x in errs) or max(errs) > target:
                continue
            wall = sum(r["wall_s"] for r in runs)
            if best is None or wall < best[2]:
                best = (m, tol, wall)
    return best


check([f["time_error"] for f in d["fastest"]] == [1e-3, 1e-6, 1e-9], "targets")
for f in d["fastest"]:
    for key, cases in [(c["name"], [c]) for c in d["cases"]] + [("all", d["cases"])]:
        b = brute(f["time_error"], cases)
        got = f[key]
        check((b is None) == (got is None), "fastest %s %g" % (key, f["time_error"]))
        if b and got:
            check(got["method"] == b[0] and got["rtol"] == b[1] and
                  math.isclose(got["wall_s"], b[2], rel_tol=1e-9),
                  "fastest %s %g: %s vs %s" % (key, f["time_error"], got, b))

for f in failed:
    print("FAILED:", f)
print("%d failed" % len(failed))
sys.exit(1 if failed else 0)
