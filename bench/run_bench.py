#!/usr/bin/python3
"""Benchmark of the inner simulator: the C simulator (build/zipopt simulate) against the
straightforward SciPy implementation (bench/scipy_zipline.py) on the seed scene at a
constant 10 N per section.  Run with Debian's /usr/bin/python3 (it has scipy):

    /usr/bin/python3 bench/run_bench.py [--zipopt build/zipopt] [--repeat 21]

It
  1. computes the accuracy reference T_ref with SciPy DOP853 at rtol 1e-12, atol 1e-14
     (converged to ~1e-12 s: see the table in bench/README or the report);
  2. runs the C simulator for each rtol in --c-rtols (atol = rtol/100), --repeat times, and
     takes the median in-process wall time (stats.wall_s), steps, rhs evaluations, |T - T_ref|;
  3. runs SciPy for each rtol in --py-rtols, --py-repeat times (median wall time);
  4. compares the cheapest C setting with |dT| <= --target against the cheapest SciPy one;
  5. measures with valgrind --tool=callgrind the share of one C run's instructions spent
     inside the equations of motion (inclusive cost of zp_sim_rhs / total, and / zp_sim_run);
  6. prints a table and writes out/bench/bench_sim.csv.
"""

import argparse
import csv
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import scipy_zipline as sz  # noqa: E402

FORCES = [10.0, 10.0, 10.0]
# SciPy DOP853, rtol 1e-12 / atol 1e-14 (1e-11..3e-14 all within 1.3e-12; RK45 and LSODA at
# 1e-12 within 4e-12): the finish time of the seed scene at 10 N per section.
T_REF_KNOWN = 21.105089547266


def scene_text(seed_text, rtol, atol):
    """The seed scene with its [solver] rtol/atol lines replaced."""
    out, section = [], None
    for line in seed_text.splitlines():
        m = re.match(r"\s*\[(\w+)\]", line)
        if m:
            section = m.group(1)
        key = line.split("=")[0].strip() if "=" in line else None
        if section == "solver" and key == "rtol":
            line = f"rtol = {rtol:g}"
        elif section == "solver" and key == "atol":
            line = f"atol = {atol:g}"
        out.append(line)
    return "\n".join(out) + "\n"


def write_scene(tmpdir, seed_text, rtol, atol):
    path = os.path.join(tmpdir, f"bench_rtol{rtol:g}.ini")
    with open(path, "w") as fh:
        fh.write(scene_text(seed_text, rtol, atol))
    return path


def c_cmd(zipopt, scene, tmpdir):
    return [zipopt, "simulate", scene, "--force", ",".join(f"{f:g}" for f in FORCES), "--json",
            "--out", os.path.join(tmpdir, "out")]


def run_c(zipopt, scene, tmpdir):
    p = subprocess.run(c_cmd(zipopt, scene, tmpdir), capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{zipopt} exited {p.returncode}: {p.stderr.strip()}")
    return json.loads(p.stdout)


def run_py(rtol, atol):
    model = sz.Model(sz.seed_course())
    return sz.simulate(model, FORCES, rtol=rtol, atol=atol)


def summarize(runs, t_ref):
    first = runs[0]
    times = {r["time"] for r in runs}
    return {
        "outcome": first["outcome"],
        "time": first["time"],
        "dT": abs(first["time"] - t_ref),
        "deterministic": len(times) == 1,
        "steps": first["stats"]["steps"],
        "rhs_evals": first["stats"]["rhs_evals"],
        "wall_s": statistics.median(r["stats"]["wall_s"] for r in runs),
        "wall_min": min(r["stats"]["wall_s"] for r in runs),
        "kinks": first.get("kinks", []),
    }


def callgrind_share(zipopt, scene, tmpdir):
    """Inclusive instruction share of zp_sim_rhs in one C run (valgrind callgrind)."""
    outfile = os.path.join(tmpdir, "callgrind.out")
    cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={outfile}"] + c_cmd(zipopt, scene, tmpdir)
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"callgrind run failed: {p.stderr[-2000:]}")
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", "--auto=no", outfile],
                         capture_output=True, text=True, check=True).stdout
    num = r"^\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+"
    total = rhs = run = None
    for line in ann.splitlines():
        if re.match(num + r"PROGRAM TOTALS", line):
            total = int(re.match(num, line).group(1).replace(",", ""))
        elif re.match(num + r"\S*:zp_sim_rhs \[", line):
            rhs = int(re.match(num, line).group(1).replace(",", ""))
        elif re.match(num + r"\S*:zp_sim_run \[", line):
            run = int(re.match(num, line).group(1).replace(",", ""))
    if total is None or rhs is None:
        raise RuntimeError("callgrind_annotate output has no PROGRAM TOTALS or zp_sim_rhs line")
    return {"total_ir": total, "rhs_ir": rhs, "run_ir": run, "share_total": rhs / total,
            "share_run": rhs / run if run else None}


def cheapest(rows, target):
    ok = [r for r in rows if r["outcome"] == "finished" and r["dT"] <= target]
    return min(ok, key=lambda r: r["wall_s"]) if ok else None


def main():
    ap = argparse.ArgumentParser(description="C simulator vs SciPy benchmark on the seed scene at 10 N")
    ap.add_argument("--zipopt", default=os.path.join(ROOT, "build", "zipopt"))
    ap.add_argument("--scene", default=os.path.join(ROOT, "config", "seed.ini"))
    ap.add_argument("--repeat", type=int, default=21, help="C runs per tolerance")
    ap.add_argument("--py-repeat", type=int, default=5, help="SciPy runs per tolerance")
    ap.add_argument("--c-rtols", default="1e-6,1e-8,1e-10")
    ap.add_argument("--py-rtols", default="1e-5,1e-6,1e-7,1e-8")
    ap.add_argument("--target", type=float, default=1e-6, help="s: matched accuracy |T - T_ref|")
    ap.add_argument("--csv", default=os.path.join(ROOT, "out", "bench", "bench_sim.csv"))
    ap.add_argument("--no-c", action="store_true", help="SciPy part only (no C binary yet)")
    ap.add_argument("--no-callgrind", action="store_true")
    args = ap.parse_args()
    c_rtols = [float(v) for v in args.c_rtols.split(",")]
    py_rtols = [float(v) for v in args.py_rtols.split(",")]

    # 1. reference
    ref = run_py(1e-12, 1e-14)
    t_ref = ref["time"]
    print(f"T_ref = {t_ref:.12f} s  (SciPy DOP853 rtol 1e-12 atol 1e-14, {ref['outcome']}; "
          f"stored value {T_REF_KNOWN:.12f}, diff {t_ref - T_REF_KNOWN:+.1e})")
    if ref["outcome"] != "finished" or abs(t_ref - T_REF_KNOWN) > 1e-10:
        print("warning: the reference does not reproduce the stored value", file=sys.stderr)

    rows = []
    with tempfile.TemporaryDirectory(prefix="zipbench") as tmpdir:
        seed_text = open(args.scene).read()
        # 2. C
        c_rows = []
        if not args.no_c:
            if not os.access(args.zipopt, os.X_OK):
                sys.exit(f"no C simulator at {args.zipopt} (use --no-c for the SciPy part only)")
            for rtol in c_rtols:
                scene = write_scene(tmpdir, seed_text, rtol, rtol / 100)
                runs = [run_c(args.zipopt, scene, tmpdir) for _ in range(args.repeat)]
                row = {"impl": "C", "rtol": rtol, "atol": rtol / 100, "runs": len(runs)}
                row.update(summarize(runs, t_ref))
                c_rows.append(row)
                print(f"  C     rtol {rtol:g}: {row['outcome']} T {row['time']:.12f} "
                      f"|dT| {row['dT']:.2e} wall {row['wall_s'] * 1e3:.3f} ms", flush=True)
        # 3. SciPy
        py_rows = []
        for rtol in py_rtols:
            runs = [run_py(rtol, rtol / 100) for _ in range(args.py_repeat)]
            row = {"impl": "SciPy", "rtol": rtol, "atol": rtol / 100, "runs": len(runs)}
            row.update(summarize(runs, t_ref))
            py_rows.append(row)
            print(f"  SciPy rtol {rtol:g}: {row['outcome']} T {row['time']:.12f} "
                  f"|dT| {row['dT']:.2e} wall {row['wall_s'] * 1e3:.1f} ms", flush=True)
        rows = c_rows + py_rows
        # 5. callgrind
        cg = None
        if c_rows and not args.no_callgrind:
            rtol = c_rows[0]["rtol"]
            best_c = cheapest(c_rows, args.target)
            if best_c:
                rtol = best_c["rtol"]
            scene = write_scene(tmpdir, seed_text, rtol, rtol / 100)
            cg = callgrind_share(args.zipopt, scene, tmpdir)
            cg["rtol"] = rtol

    # 6. table and CSV
    print()
    hdr = f"{'impl':6} {'rtol':>7} {'atol':>7} {'outcome':9} {'T (s)':>17} {'|T-Tref| (s)':>12} " \
          f"{'steps':>6} {'rhs':>6} {'wall med (ms)':>13} {'wall min (ms)':>13} {'runs':>4}"
    print(hdr)
    print("-" * len(hdr))
    for r in rows:
        print(f"{r['impl']:6} {r['rtol']:7.0e} {r['atol']:7.0e} {r['outcome']:9} {r['time']:17.12f} "
              f"{r['dT']:12.2e} {r['steps']:6d} {r['rhs_evals']:6d} {r['wall_s'] * 1e3:13.4f} "
              f"{r['wall_min'] * 1e3:13.4f} {r['runs']:4d}")
    for r in rows:
        if not r["deterministic"]:
            print(f"note: {r['impl']} rtol {r['rtol']:g} gave different T across repeats")

    best_c = cheapest(c_rows, args.target)
    best_py = cheapest(py_rows, args.target)
    ratio = None
    print()
    if best_py:
        print(f"cheapest SciPy with |dT| <= {args.target:g} s: rtol {best_py['rtol']:g} "
              f"({best_py['wall_s'] * 1e3:.1f} ms, |dT| {best_py['dT']:.1e} s)")
    else:
        print(f"no SciPy setting met |dT| <= {args.target:g} s")
    if best_c:
        print(f"cheapest C     with |dT| <= {args.target:g} s: rtol {best_c['rtol']:g} "
              f"({best_c['wall_s'] * 1e3:.3f} ms, |dT| {best_c['dT']:.1e} s)")
    elif c_rows:
        print(f"no C setting met |dT| <= {args.target:g} s")
    if best_c and best_py:
        ratio = best_c["wall_s"] / best_py["wall_s"]
        print(f"speed ratio C/SciPy wall time at matched accuracy: {ratio:.4g} "
              f"(C is {1 / ratio:.0f}x faster)")
    if cg:
        print(f"callgrind (C, rtol {cg['rtol']:g}): zp_sim_rhs inclusive {cg['rhs_ir']:,} Ir of "
              f"{cg['total_ir']:,} total = {100 * cg['share_total']:.1f}%"
              + (f"; of zp_sim_run ({cg['run_ir']:,} Ir) {100 * cg['share_run']:.1f}%" if cg["run_ir"] else ""))

    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    cols = ["impl", "rtol", "atol", "outcome", "time", "dT", "steps", "rhs_evals", "wall_s", "wall_min",
            "runs", "t_ref", "matched_best", "speed_ratio_c_over_scipy", "rhs_share_total", "rhs_share_run"]
    tmp = args.csv + ".tmp"
    with open(tmp, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            rec = dict(r)
            rec["rtol"], rec["atol"] = f"{r['rtol']:g}", f"{r['atol']:g}"
            rec["dT"], rec["wall_s"], rec["wall_min"] = f"{r['dT']:.3e}", f"{r['wall_s']:.6g}", f"{r['wall_min']:.6g}"
            rec["t_ref"] = f"{t_ref:.12f}"
            rec["time"] = f"{r['time']:.12f}"
            rec["matched_best"] = int(r is best_c or r is best_py)
            rec["speed_ratio_c_over_scipy"] = f"{ratio:.6g}" if ratio and rec["matched_best"] else ""
            is_cg = cg and r["impl"] == "C" and r["rtol"] == cg["rtol"]
            rec["rhs_share_total"] = f"{cg['share_total']:.4f}" if is_cg else ""
            rec["rhs_share_run"] = f"{cg['share_run']:.4f}" if is_cg and cg["share_run"] else ""
            w.writerow(rec)
    os.replace(tmp, args.csv)
    print(f"wrote {os.path.relpath(args.csv, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
