#!/usr/bin/env python3
"""Per scene: zipopt's default search, zipopt at 10x the default budget, and the peer (SciPy's
differential evolution with its polish, bench/peer_de.py): answer, simulations, wall time, and
whether the default is within 0.1 % of the best of the three (docs/search.md, "Against a peer").

    /usr/bin/python3 bench/compare_peer.py [--build build] [--algorithm NAME] [--peer-evals N]
                                           [--skip-10x] [--skip-peer] SCENE.ini..

The zipopt runs use the command line (--no-plot --json, into a temporary folder); the peer runs
through the Python module of the same build. One line per run as it ends, then the table.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def zipopt(build, scene, extra, tmp):
    t0 = time.perf_counter()
    out = subprocess.run([os.path.join(build, "zipopt"), scene, "--no-plot", "--json",
                          "--out", tmp] + extra, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if out.returncode not in (0, 3):
        sys.exit(f"zipopt failed on {scene}: {out.stderr.strip()}")
    d = json.loads(out.stdout)
    return {"time": d["time"] if d["found"] else None, "sims": d["evaluations"], "wall_s": wall,
            "sentence": d["convergence"]["sentence"]}


def default_budget(build, scene):
    """The search's budget: the scene's max_evals, else 5000 simulations per section."""
    out = subprocess.run([os.path.join(build, "zipopt"), "check", scene, "--json"],
                         capture_output=True, text=True, check=True)
    d = json.loads(out.stdout)
    given = any(line.split("=")[0].strip() == "max_evals" for line in open(scene))
    return int(d["max_evals"]) if given else 5000 * len(d["sections"])


def peer(build, scene, evals):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"),
               ZIPOPT_LIB=os.path.join(build, "src", "lib", "libzipopt.so"))
    cmd = [sys.executable, os.path.join(HERE, "peer_de.py"), scene, "--json"]
    if evals:
        cmd += ["--evals", str(evals)]
    out = subprocess.run(cmd, capture_output=True, text=True, env=env, check=True)
    d = json.loads(out.stdout)
    return {"time": d["time"], "sims": d["sims"], "wall_s": d["wall_s"]}


def fmt(r):
    if r is None:
        return "-"
    t = f"{r['time']:.5f}" if r["time"] is not None else "none"
    return f"{t} s, {r['sims']} sims, {r['wall_s']:.1f} s"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--algorithm", default=None,
                    help="zipopt's --algorithm for its runs (default: zipopt's default)")
    ap.add_argument("--peer-evals", type=int, default=0,
                    help="the peer's simulations (default: zipopt's default budget)")
    ap.add_argument("--skip-10x", action="store_true")
    ap.add_argument("--skip-peer", action="store_true")
    a = ap.parse_args()
    alg = ["--algorithm", a.algorithm] if a.algorithm else []
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene in a.scenes:
            row = {"scene": os.path.basename(scene)}
            row["default"] = zipopt(a.build, scene, alg, tmp)
            print(row["scene"], "default", fmt(row["default"]), flush=True)
            row["10x"] = None
            if not a.skip_10x:
                budget = 10 * default_budget(a.build, scene)
                row["10x"] = zipopt(a.build, scene, alg + ["--max-evals", str(budget)], tmp)
                print(row["scene"], "10x", fmt(row["10x"]), flush=True)
            row["peer"] = None if a.skip_peer else peer(a.build, scene, a.peer_evals)
            if row["peer"]:
                print(row["scene"], "peer", fmt(row["peer"]), flush=True)
            rows.append(row)
    print("\n| scene | zipopt default | zipopt 10x | peer (SciPy DE + polish) | default within "
          "0.1 % of the best |\n|---|---|---|---|---|")
    for row in rows:
        times = [r["time"] for r in (row["default"], row["10x"], row["peer"])
                 if r and r["time"] is not None]
        best = min(times) if times else None
        d = row["default"]["time"]
        ok = "yes" if d is not None and best is not None and d <= best * 1.001 else "NO"
        print(f"| {row['scene']} | {fmt(row['default'])} | {fmt(row['10x'])} | "
              f"{fmt(row['peer'])} | {ok} |")


if __name__ == "__main__":
    main()
