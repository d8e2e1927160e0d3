#!/usr/bin/env python3
"""Every command on a cable scene (docs/model.md "A cable that sags"), a small one with short
budgets: simulate in both formulations (they agree), with [physics] drag, wind and rolling (each
changes the ride and the energy audit closes); the search with [limits] max_cable_tension keeps
it (simulate of the answer reaches at most the limit, the same number the search reports) and,
set below what the line carries, no schedule keeps it (exit 3, the limit named); the robust
search reports the population's highest anchor tension, at least the nominal rider's; tradeoff;
sweep over cable.tension, cable.length and cable.ea (the axis in N and m, each point's anchor
tension the one simulate gives); landscape; and the scene rules (kink_radius with [cable],
max_cable_tension without it: exit 2 naming file, line and key, nothing written).

usage: check_cable_commands.py ZIPOPT_EXE SOURCE_DIR"""
import csv
import json
import re
import os
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]

# an 80 m line, 10 m drop, strung to 6 kN: a ride of about 10 s
SCENE = """[scene]
name = small_cable
[cable]
start = 0, 12
end = 80, 2
{cable}
weight = 3
ea = {ea}
x_start = 1.5
sections = 30, 55, 76
[trolley]
mass = 5
[body]
lengths = 0.5, 0.9
masses = 40, 25
damping = 1, 2
death_angle = 180
[drive]
direction = horizontal
forces = 0, 0, 0
min = 0
max = 150
[solver]
rtol = 1e-9
atol = 1e-11
t_max = 60
{solver}
[optimize]
margin = 10
max_evals = 120
seed = 1
"""


def scene(tmp, name, extra="", cable="tension = 6000", solver="", ea="3e6"):
    path = os.path.join(tmp, name + ".ini")
    with open(path, "w") as f:
        f.write(SCENE.format(cable=cable, solver=solver, ea=ea) + extra)
    return path


def run(args):
    return subprocess.run([exe] + args, capture_output=True, text=True)


def simulate(tmp, path, more=()):
    p = run(["simulate", path, "--json", "--out", os.path.join(tmp, "sim")] + list(more))
    check(p.returncode == 0, "simulate %s: exit %d: %s" % (path, p.returncode, p.stderr[-300:]))
    return json.loads(p.stdout) if p.returncode == 0 else None


def closes(d, what):
    e = d["energy"]
    scale = abs(e["initial"]) + abs(e["final"]) + abs(e["cable_potential"]["initial"])
    check(abs(e["residual"]) <= 1e-7 * scale, "%s: energy residual %g J of %g J"
          % (what, e["residual"], scale))


with tempfile.TemporaryDirectory() as tmp:
    base = scene(tmp, "base")
    lag = simulate(tmp, base)
    ne = simulate(tmp, scene(tmp, "ne", solver="formulation = newton-euler"))
    check(lag["outcome"] == "finished" and ne["outcome"] == "finished", "both finish")
    check(abs(lag["time"] - ne["time"]) <= 1e-8, "lagrange %.12f s, newton-euler %.12f s"
          % (lag["time"], ne["time"]))
    check(lag["kinks"] == [], "a cable has no kinks")
    closes(lag, "lagrange")

    # [physics]: drag slows the ride, a head wind more, rolling takes its work too
    drag = simulate(tmp, scene(tmp, "drag", "[physics]\ndrag_area = 0.02, 0.3, 0.2\n"))
    wind = simulate(tmp, scene(tmp, "wind", "[physics]\ndrag_area = 0.02, 0.3, 0.2\nwind = -3\n"))
    roll = simulate(tmp, scene(tmp, "roll", "[physics]\nrolling = 0.01\n"))
    check(drag["time"] > lag["time"] and wind["time"] > drag["time"],
          "drag %.4f s > bare %.4f s, head wind %.4f s > drag" % (drag["time"], lag["time"],
                                                                 wind["time"]))
    check(drag["energy"]["drag_work"] > 0 and wind["energy"]["drag_work"] > 0, "drag works")
    check(roll["time"] > lag["time"] and roll["energy"]["friction_work"] > 0,
          "rolling %.4f s > bare %.4f s, its work %g J" % (roll["time"], lag["time"],
                                                          roll["energy"]["friction_work"]))
    for d, what in ((drag, "drag"), (wind, "wind"), (roll, "rolling")):
        closes(d, what)

    # max_cable_tension kept: the answer's anchor tension, by simulate, at most the limit
    nominal = lag["cable"]["anchor_tension_max"]
    limit = round(nominal * 1.05)
    lim = scene(tmp, "lim", "[limits]\nmax_cable_tension = %d\nmax_arrival_speed = 55\n" % limit)
    out = os.path.join(tmp, "search")
    p = run([lim, "--json", "--no-plot", "--out", out])
    check(p.returncode == 0, "search: exit %d: %s" % (p.returncode, p.stderr[-300:]))
    s = json.loads(p.stdout)
    reached = s["limits"]["max_cable_tension"]["reached"]
    check(s["limits"]["max_cable_tension"]["kept"] and reached <= limit,
          "the search keeps max_cable_tension: %g N of %d N" % (reached, limit))
    check(s["cable"]["anchor_tension_max"] == reached, "summary.json's cable and limit agree")
    d = simulate(tmp, lim, ["--schedule", os.path.join(out, "schedule.ini")])
    check(d["cable"]["anchor_tension_max"] <= limit and
          d["limits"]["max_cable_tension"]["reached"] == d["cable"]["anchor_tension_max"] and
          d["limits"]["max_cable_tension"]["kept"] is True,
          "simulate of the answer: anchor tension %g N, limit %d N"
          % (d["cable"]["anchor_tension_max"], limit))
    check(abs(d["time"] - s["time"]) <= 1e-9, "simulate of the answer: %.12f s, search %.12f s"
          % (d["time"], s["time"]))
    for key in ("lowest_x", "lowest_y", "sag_mid", "anchor_a_tension_max",
                "anchor_b_tension_max", "trolley_tension_max"):
        check(key in s["cable"], "summary.json cable.%s" % key)
    with open(os.path.join(out, "report.md")) as f:
        md = f.read()
    check("## The cable" in md and "| max_cable_tension |" in md, "report.md: cable, limit")

    # set below what the nominal rider puts on the anchors: nothing keeps it
    low = scene(tmp, "low", "[limits]\nmax_cable_tension = %d\n" % round(nominal * 0.95))
    p = run([low, "--json", "--no-plot", "--out", os.path.join(tmp, "low")])
    check(p.returncode == 3, "a low max_cable_tension binds: exit %d" % p.returncode)
    if p.returncode == 3:
        s = json.loads(p.stdout)
        check(not s["found"] and s["limits"]["max_cable_tension"]["kept"] is False,
              "the closest candidate breaks max_cable_tension")
        with open(os.path.join(tmp, "low", "report.md")) as f:
            md = f.read()
        # the anchors' load is set by where the rider is, not by the drive: the report says no
        # budget helps, naming the tension every finishing ride reaches (the nominal's, +/- 1 N)
        said = re.search(r"loads an anchor to (\d+) N, .*a larger budget cannot help", md)
        check(said is not None and abs(int(said.group(1)) - nominal) <= 1,
              "report.md: no schedule can keep it, at the nominal rider's %g N" % nominal)

    # the robust search: the population on their own paths; the heaviest loads the anchors most
    rob = scene(tmp, "rob", "[limits]\nmax_cable_tension = %d\n[robust]\nforce_error = 5\n"
                "mass_range = 80, 130\nsamples = 6\nverify_samples = 60\n" % round(nominal * 1.3))
    p = run([rob, "--json", "--no-plot", "--out", os.path.join(tmp, "rob")])
    check(p.returncode == 0, "robust search: exit %d: %s" % (p.returncode, p.stderr[-300:]))
    s = json.loads(p.stdout)
    pop = s["cable"]["population_anchor_tension_max"]
    check(pop is not None and pop["value"] > s["cable"]["anchor_tension_max"],
          "population's highest anchor tension %s above the nominal rider's %g N"
          % (pop, s["cable"]["anchor_tension_max"]))
    check(s["robust"]["verify"]["limits_kept"] == 60, "every fresh rider keeps the limit")

    p = run(["tradeoff", rob, "--levels", "5", "--max-evals", "40", "--json", "--out",
             os.path.join(tmp, "trade")])
    check(p.returncode == 0, "tradeoff: exit %d: %s" % (p.returncode, p.stderr[-300:]))
    if p.returncode == 0:
        lv = json.loads(p.stdout)["levels"]
        check(len(lv) == 2 and all(level["found"] for level in lv), "tradeoff: two levels found")

    # sweeps over the cable: the axis in the key's unit, each point's tension simulate's
    length = scene(tmp, "length", cable="length = 80.8")
    for path, vary, unit in ((base, "cable.tension=4000:8000:3", "(N)"),
                             (length, "cable.length=80.7:81.1:3", "(m)"),
                             (base, "cable.ea=1e6:5e6:3", "(N)")):
        out = os.path.join(tmp, "sweep_" + vary.split("=")[0])
        p = run(["sweep", path, "--vary", vary, "--run", "simulate", "--out", out])
        check(p.returncode == 0, "sweep %s: exit %d: %s" % (vary, p.returncode, p.stderr[-300:]))
        if p.returncode:
            continue
        with open(os.path.join(out, "sweep.csv")) as f:
            rows = list(csv.DictReader(f))
        check(len(rows) == 3 and all(r["outcome"] == "finished" for r in rows),
              "sweep %s: 3 finished rows" % vary)
        key = vary.split("=")[0]
        with open(os.path.join(out, "sweep.gp")) as f:
            check(unit in f.read(), "sweep %s: the axis in %s" % (vary, unit))
        r = rows[-1]
        one = scene(tmp, "point",
                    cable="length = " + r[key] if key == "cable.length" else
                    "tension = " + (r[key] if key == "cable.tension" else "6000"),
                    ea=r[key] if key == "cable.ea" else "3e6")
        d = simulate(tmp, one)
        check(float(r["anchor_tension_N"]) == d["cable"]["anchor_tension_max"] and
              float(r["time_s"]) == d["time"],
              "sweep %s at %s: anchor tension %s, time %s; simulate %r, %r"
              % (key, r[key], r["anchor_tension_N"], r["time_s"],
                 d["cable"]["anchor_tension_max"], d["time"]))
    tensions = []
    with open(os.path.join(tmp, "sweep_cable.tension", "sweep.csv")) as f:
        tensions = [float(r["anchor_tension_N"]) for r in csv.DictReader(f)]
    check(tensions == sorted(tensions), "a tighter line pulls harder on its anchors: %s"
          % tensions)

    p = run(["landscape", base, "--force-range", "0:150:7", "--json", "--out",
             os.path.join(tmp, "land")])
    check(p.returncode == 0, "landscape: exit %d: %s" % (p.returncode, p.stderr[-300:]))
    if p.returncode == 0:
        d = json.loads(p.stdout)
        check(d["runs"] == 7 and d["windows"] == [[0, 150]], "landscape: every push finishes")

    # the landscape judges the limit as the search does: below the line's tension, no push
    p = run(["landscape", low, "--force-range", "0:150:4", "--json", "--out",
             os.path.join(tmp, "land_low")])
    check(p.returncode == 0 and json.loads(p.stdout)["fastest"] is None and
          json.loads(p.stdout)["fastest_finish"]["breaks"] == "max_cable_tension",
          "landscape with a low max_cable_tension: %s" % p.stdout[-300:])
    with open(os.path.join(tmp, "land_low", "landscape.csv")) as f:
        rows = list(csv.DictReader(f))
    check(all(abs(float(r["max_cable_tension_reached_N"]) - nominal) <= 1e-8 * nominal
              for r in rows),
          "landscape: each finishing push reaches the nominal rider's anchor tension %r" % nominal)

    # check --json: the cable's equilibria per rider, the course at the boundaries its path
    p = run(["check", rob, "--json"])
    check(p.returncode == 0, "check --json: exit %d: %s" % (p.returncode, p.stderr[-300:]))
    d = json.loads(p.stdout)
    cab = d["cable"]
    check([r["rider"] for r in cab["riders"]] == ["nominal", "lightest", "heaviest"],
          "check --json: three riders")
    nom = cab["riders"][0]
    check(max(nom["anchor_a_tension_max"], nom["anchor_b_tension_max"]) ==
          lag["cable"]["anchor_tension_max"],
          "check's nominal anchor tension over the ride is simulate's (the same x)")
    loads = [r["load"] for r in cab["riders"]]
    sags = [r["sag_mid"] for r in cab["riders"]]
    check(loads[1] < loads[0] < loads[2] and sags[1] < sags[0] < sags[2] and
          cab["unloaded"]["sag_mid"] < sags[1], "heavier riders sag more: %s" % sags)
    check(all(sec["f"] is None for sec in d["sections"]) and
          all(not b["kink"] and b["slope_left"] == b["slope_right"] and 2 < b["y"] < 12
              for b in d["boundaries"]), "check --json: the course is the cable's path")

    # check --plot: the figure of the paths, written whole; none for a scene without a cable
    out = os.path.join(tmp, "fig")
    p = run(["check", rob, "--plot", "--out", out])
    check(p.returncode == 0 and sorted(os.listdir(out)) == ["cable.dat", "cable.gp", "cable.png"],
          "check --plot: exit %d, %s" % (p.returncode, os.listdir(out) if p.returncode == 0
                                         else p.stderr))
    with open(os.path.join(out, "cable.dat")) as f:
        rows = [line.split() for line in f if not line.startswith("#")]
    check(len(rows) == 401 and all(len(r) == 5 for r in rows), "cable.dat: 401 x, 4 paths")
    check(all(float(r[4]) <= float(r[2]) <= float(r[3]) <= float(r[1]) + 1e-12
              for r in rows), "the heaviest rides lowest, the rope alone highest")
    out = os.path.join(tmp, "nofig")
    p = run(["check", os.path.join(src, "config", "seed.ini"), "--plot", "--out", out])
    check(p.returncode == 2 and not os.path.exists(out), "check --plot without [cable]: exit %d"
          % p.returncode)

    # the scene rules: exit 2, file, line and key named, nothing written
    path = scene(tmp, "kink", "[physics]\nkink_radius = 2\n")
    with open(path) as f:
        line = f.read().count("\n")  # the last line
    out = os.path.join(tmp, "never")
    p = run(["simulate", path, "--out", out])
    check(p.returncode == 2 and ("%s:%d: [physics] kink_radius" % (path, line)) in p.stderr and
          not os.path.exists(out), "kink_radius with [cable]: exit %d: %s"
          % (p.returncode, p.stderr))
    with open(os.path.join(src, "config", "seed.ini")) as f:
        seed = f.read()
    path = os.path.join(tmp, "nocable.ini")
    with open(path, "w") as f:
        f.write(seed + "\n[limits]\nmax_cable_tension = 1000\n")
    nline = (seed + "\n[limits]\nmax_cable_tension = 1000\n").count("\n")
    p = run(["simulate", path, "--out", os.path.join(tmp, "never")])
    check(p.returncode == 2 and
          ("%s:%d: [limits] max_cable_tension" % (path, nline)) in p.stderr and
          not os.path.exists(os.path.join(tmp, "never")),
          "max_cable_tension without [cable]: exit %d: %s" % (p.returncode, p.stderr))
done("check_cable_commands")
