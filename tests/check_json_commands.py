#!/usr/bin/env python3
"""--json on the search, tradeoff, check and --version (one JSON object on stdout): the
search's object is its summary.json; tradeoff's levels match its tradeoff.csv row by row;
check shows the [limits], [robust] and [physics] values the scene file gives."""
import csv
import json
import os
import subprocess
import sys
import tempfile

exe, src = sys.argv[1], sys.argv[2]
failed = []


def check(ok, what):
    if not ok:
        failed.append(what)


def run(*args):
    p = subprocess.run([exe, *args], capture_output=True, text=True)
    check(p.returncode == 0, "%s: exit %d: %s" % (args, p.returncode, p.stderr[-400:]))
    return json.loads(p.stdout), p.stderr  # one object, nothing else on stdout


v, _ = run("--version", "--json")
check(v["name"] == "zipopt" and v["version"].count(".") == 2, "version " + str(v))
straight = os.path.join(src, "config", "straight.ini")
with tempfile.TemporaryDirectory() as out:
    d, err = run(straight, "--json", "--no-plot", "--out", os.path.join(out, "s"))
    with open(os.path.join(out, "s", "summary.json")) as f:
        check(d == json.load(f), "the search's --json is its summary.json")
    check("wrote in" in err, "files said on stderr")
    for k in ["found", "forces", "time", "margin_deg"]:
        check(k in d, "search key " + k)
    t, _ = run("tradeoff", straight, "--levels", "0,2", "--json", "--out",
               os.path.join(out, "t"))
    with open(os.path.join(out, "t", "tradeoff.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == len(t["levels"]) == 2, "two levels")
    for r, lv in zip(rows, t["levels"]):
        check(float(r["force_error_pct"]) == lv["force_error_pct"], "level")
        check(int(r["found"]) == lv["found"], "found")
        check(abs(float(r["time_s"]) - lv["time"]) <= 1e-8 * lv["time"], "time")
        check(int(r["verify_kept"]) == lv["verify"]["all_kept"], "verify")
        check(abs(float(r["force_1_N"]) - lv["forces"][0]) <= 1e-8 * abs(lv["forces"][0]),
              "force")

# check --json: the optional sections as written in the file (the file is the expectation)
with open(os.path.join(src, "config", "straight.ini")) as f:
    base = f.read()
with tempfile.TemporaryDirectory() as out:
    scene = os.path.join(out, "opt.ini")
    with open(scene, "w") as f:
        f.write(base + "\n[limits]\nmax_g = 7.5\nmax_kink_dv = 3\n[robust]\nforce_error = 2\n"
                "mass_range = 80, 120\n[physics]\nwind = -2.5\nrolling = 0.01\n")
    c, _ = run("check", scene, "--json")
    check(c.get("limits") == {"max_g": 7.5, "max_kink_dv": 3}, "check limits " + str(c.get("limits")))
    r = c.get("robust", {})
    check(r.get("force_error") == 2 and r.get("mass_range") == [80, 120]
          and r.get("samples") == 64 and r.get("damping_range") == [100, 100],
          "check robust (given and defaults) " + str(r))
    check(c.get("physics") == {"wind": -2.5, "rolling": 0.01}, "check physics " + str(c.get("physics")))
    plain, _ = run("check", straight, "--json")
    check(plain.get("limits") == {} and plain.get("robust") == {} and plain.get("physics") == {},
          "a scene without them shows empty sections")
    text = subprocess.run([exe, "check", scene], capture_output=True, text=True).stdout
    check("limits: max_g = 7.5; max_kink_dv = 3" in text, "check's text names the limits")

for f in failed:
    print("FAILED:", f)
print("%d failed" % len(failed))
sys.exit(1 if failed else 0)
