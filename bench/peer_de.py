#!/usr/bin/env python3
"""An independent peer for the search: SciPy's differential evolution (with its polish) over the
Python module, on the same box, margin and [limits]-free scenes as zipopt's search.

    PYTHONPATH=python ZIPOPT_LIB=build/src/lib/libzipopt.so \\
        /usr/bin/python3 bench/peer_de.py SCENE.ini [--evals N] [--seed S] [--json]

The peer ranks its runs with zipopt's own search integrator ([optimize]: gsl-rk8pd at rtol 1e-5,
written into a copy of the scene's text), minimises the finish time plus the same penalty as
zipopt's score (a run that dies scores by how far it got), and answers with the fastest schedule
it ran that keeps the margin; that schedule is then rerun with the scene's own [solver] and must
keep the margin there too. It shares no code with the search: only the simulator.
"""

import argparse
import json
import math
import re
import sys
import time

import numpy as np
from scipy.optimize import differential_evolution

import zipopt

SLACK_DEG = 1e-3  # deg kept inside the margin, as zipopt's objective does


def ini_values(text):
    """{(section, key): value text} of the last occurrence, comments dropped; course ends."""
    vals, ends, sec = {}, [], ""
    for raw in text.splitlines():
        line = re.split(r"\s[;#]", raw, maxsplit=1)[0].strip()
        if not line or line[0] in ";#":
            continue
        m = re.match(r"\[(\w+)\]", line)
        if m:
            sec = m.group(1)
            continue
        key, _, val = line.partition("=")
        key, val = key.strip(), val.strip()
        if sec == "course" and key == "section":
            ends.append(float(val.split(":", 1)[0]))
        vals[(sec, key)] = val
    return vals, ends


def ranking_text(text):
    """The scene with [solver] set to the search's ranking integrator and no trajectory rows."""
    out, sec = [], ""
    for raw in text.splitlines():
        m = re.match(r"\s*\[(\w+)\]", raw)
        if m:
            sec = m.group(1)
        elif sec == "solver" and re.match(r"\s*(method|rtol|atol|accuracy|output_dt)\s*=", raw):
            continue
        out.append(raw)
        if m and sec == "solver":
            out += ["method = gsl-rk8pd", "rtol = 1e-5", "atol = 1e-7", "output_dt = 1e6"]
    if not any(re.match(r"\s*\[solver\]", r) for r in text.splitlines()):
        out += ["[solver]", "method = gsl-rk8pd", "rtol = 1e-5", "atol = 1e-7",
                "output_dt = 1e6"]
    return "\n".join(out) + "\n"


class Problem:
    def __init__(self, path):
        text = open(path).read()
        vals, ends = ini_values(text)
        self.x0 = float(vals.get(("course", "x_start"), "0"))
        self.x1 = ends[-1]
        self.t_max = float(vals.get(("solver", "t_max"), "120"))
        death = float(vals.get(("body", "death_angle"), "180"))
        self.limit_deg = death - float(vals.get(("optimize", "margin"), "10"))
        self.phi_max_deg = death
        self.path = path
        self.fast = zipopt.Scene(ranking_text(text), text=True, name=path)
        self.exact = zipopt.Scene(path)
        self.n = self.fast.params  # the schedule's: a profile has knots per section
        self.lo, self.hi = self.fast.bounds
        self.restart()

    def judge(self, scene, x):
        scene.forces = x
        r = scene.simulate()
        angle = math.degrees(max(r.max_angles))
        return r, angle

    def verify(self, x):
        """x rerun with the scene's own [solver]: (keeps the margin there, the run, its angle)."""
        r, angle = self.judge(self.exact, x)
        return r.outcome == "finished" and angle <= self.limit_deg, r, angle

    def restart(self):
        """Forget the simulations counted and the best survivor kept, for a new search."""
        self.sims = 0
        self.best = (math.inf, None)

    def score(self, x):
        """zipopt's penalised score of x, from one ranking run; the best survivor kept."""
        r, angle = self.judge(self.fast, x)
        self.sims += 1
        progress = min(max((r.x - self.x0) / (self.x1 - self.x0), 0.0), 1.0)
        behind = 1 - progress
        if r.outcome == "finished":
            obj = r.time
            cons = angle - self.limit_deg + SLACK_DEG
        else:
            obj = self.t_max * (1 + behind)
            cons = angle - self.limit_deg + SLACK_DEG
            if r.outcome == "died":
                cons = self.phi_max_deg - self.limit_deg + 180 * behind
        if not math.isfinite(obj) or not math.isfinite(cons):
            return 3 * self.t_max
        if r.outcome == "finished" and cons <= 0 and r.time < self.best[0]:
            self.best = (r.time, np.array(x, dtype=float))
        return obj + max(cons, 0.0) * self.t_max / 180


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--evals", type=int, default=0,
                    help="simulations for the evolution (default 5000 per parameter)")
    ap.add_argument("--popsize", type=int, default=15, help="members per parameter (SciPy's)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    p = Problem(a.scene)
    budget = a.evals or 5000 * p.n
    members = a.popsize * p.n
    t0 = time.perf_counter()
    res = differential_evolution(p.score, list(zip(p.lo, p.hi)), popsize=a.popsize,
                                 maxiter=max(budget // members - 1, 1), tol=0, seed=a.seed,
                                 polish=True, init="sobol" if members & (members - 1) == 0
                                 else "latinhypercube")
    wall = time.perf_counter() - t0
    out = {"scene": a.scene, "peer": "scipy differential_evolution + polish",
           "sims": p.sims, "wall_s": wall, "found": False, "time": None, "forces": None,
           "de_message": res.message}
    if p.best[1] is not None:
        ok, r, angle = p.verify(p.best[1])
        out.update(found=ok, time=r.time if ok else None, forces=list(p.best[1]),
                   ranking_time=p.best[0], margin_deg=p.phi_max_deg - angle)
    if a.json:
        json.dump(out, sys.stdout)
        print()
    else:
        t = f"{out['time']:.6f} s" if out["found"] else "none survivable"
        print(f"{a.scene}: {t} after {p.sims} simulations in {wall:.1f} s "
              f"({out['forces']})")


if __name__ == "__main__":
    main()
