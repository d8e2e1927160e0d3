#!/usr/bin/env python3
"""CMA-ES over windows of neighbouring parameters of a schedule, the rest held: is an answer a
local optimum of a search around it?

    PYTHONPATH=python:bench ZIPOPT_LIB=build/src/lib/libzipopt.so \\
        /usr/bin/python3 bench/local_window.py SCENE.ini SUMMARY.json [--width 7] [--stride 3]
        [--sigma 0.05] [--members 35] [--evals 4025] [--seed 1] [--drawn]

SUMMARY.json is a search's summary (its "forces"). For each window (starting every --stride
parameters, the last ending at the last parameter) CMA-ES (Debian's python3-cmaes) starts at the
schedule with a first step of --sigma of the box (--drawn: at the window's centre, the step
--sigma over the whole window), ranks its runs as bench/peer_de.py does (zipopt's ranking
integrator and penalised score) and keeps the fastest survivor. Each window's fastest is rerun
with the scene's own [solver] and must keep the margin there. docs/search.md ("Local windows
from the answers") holds what it measured.
"""

import argparse
import json

import numpy as np
from cmaes import CMA

from peer_de import Problem


def window_search(p, x0, first, width, a):
    """The fastest survivor of CMA-ES over x0's parameters first..first+width-1 (or None)."""
    lo, hi = np.array(p.lo), np.array(p.hi)
    free = np.arange(first, first + width)
    span = hi[free] - lo[free]
    z0 = np.full(width, 0.5) if a.drawn else (x0[free] - lo[free]) / span
    cma = CMA(mean=z0, sigma=a.sigma, bounds=np.array([[0.0, 1.0]] * width), seed=a.seed,
              population_size=a.members)
    p.restart()

    def full(z):
        x = x0.copy()
        x[free] = lo[free] + z * span
        return x

    while p.sims < a.evals:
        asked = [cma.ask() for _ in range(cma.population_size)]
        cma.tell([(z, p.score(full(z))) for z in asked])
    if p.best[1] is None:
        return None
    ok, r, angle = p.verify(p.best[1])
    return (r.time, p.phi_max_deg - angle, p.best[1]) if ok else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("summary", help="a search's summary.json (its forces are the start)")
    ap.add_argument("--width", type=int, default=7, help="parameters a window frees")
    ap.add_argument("--stride", type=int, default=3, help="parameters between window starts")
    ap.add_argument("--sigma", type=float, default=0.05, help="first step, share of the box")
    ap.add_argument("--members", type=int, default=35)
    ap.add_argument("--evals", type=int, default=4025, help="simulations per window")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--drawn", action="store_true",
                    help="start at the window's centre, not at the schedule")
    a = ap.parse_args()
    p = Problem(a.scene)
    with open(a.summary) as f:
        x0 = np.array(json.load(f)["forces"], dtype=float)
    if len(x0) != p.n:
        ap.error(f"{a.summary}: {len(x0)} forces, the scene has {p.n} parameters")
    width = min(a.width, p.n)
    firsts = sorted({min(s, p.n - width) for s in range(0, p.n - width + a.stride, a.stride)})
    _, r, angle = p.verify(x0)
    print(f"start: {r.time:.6f} s ({r.outcome}, margin {p.phi_max_deg - angle:.3f} deg)")
    for first in firsts:
        got = window_search(p, x0, first, width, a)
        where = f"parameters {first + 1}-{first + width}"
        if got is None:
            print(f"{where}: none survivable with the scene's [solver]")
        else:
            t, margin, x = got
            print(f"{where}: {t:.6f} s, margin {margin:.3f} deg: "
                  + ",".join(repr(float(v)) for v in x))


if __name__ == "__main__":
    main()
