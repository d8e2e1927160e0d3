#!/usr/bin/python3
"""Benchmark of the inner simulator: the C simulator (build/bench_sim: zp_sim_run alone, no
trajectory or output) against the straightforward SciPy implementation
(bench/scipy_zipline.py) on the seed scene at a constant 10 N per section.  Run with Debian's
/usr/bin/python3 (it has scipy):

    /usr/bin/python3 bench/run_bench.py [--bench-sim build/bench_sim] [--repeat 21]

It
  1. computes the accuracy reference T_ref with SciPy DOP853 at rtol 1e-12, atol 1e-14
     (converged to ~1e-12 s: see the table in bench/README or the report);
  2. runs the C simulator for each method in --methods and rtol in --c-rtols (atol = rtol/100),
     --repeat times in one process, and takes the median wall time of zp_sim_run, steps,
     rhs evaluations, |T - T_ref|;
  3. runs SciPy for each rtol in --py-rtols, --py-repeat times (median wall time): the naive peer
     (bench/scipy_zipline.py, numpy rhs) and the strong one (bench/scipy_sympy.py: sympy-derived,
     cse, lambdify); then `zipopt simulate --json` (--cli-method at its cheapest rtol meeting
     --target) interleaved one for one with the strong peer at its cheapest, medians of
     stats.wall_s and of the peer's wall time;
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
import scipy_sympy as ss  # noqa: E402
import scipy_zipline as sz  # noqa: E402

FORCES = [10.0, 10.0, 10.0]
# SciPy DOP853, rtol 1e-12 / atol 1e-14 (1e-11..3e-14 all within 1.3e-12; RK45 and LSODA at
# 1e-12 within 4e-12): the finish time of the seed scene at 10 N per section.
T_REF_KNOWN = 21.105089547266


def c_cmd(bench_sim, method, rtols, repeat):
    return [bench_sim, "--repeat", str(repeat), "--method", method, "--force", f"{FORCES[0]:g}"] + \
        [f"{r:g}" for r in rtols]


def run_c(bench_sim, method, rtols, repeat):
    """One bench_sim process: a JSON line per tolerance."""
    p = subprocess.run(c_cmd(bench_sim, method, rtols, repeat), capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{bench_sim} exited {p.returncode}: {p.stderr.strip()}")
    return [json.loads(line) for line in p.stdout.splitlines()]


def run_py(rtol, atol):
    model = sz.Model(sz.seed_course())
    return sz.simulate(model, FORCES, rtol=rtol, atol=atol)


_STRONG = []


def run_py_strong(rtol, atol):
    """The strong peer (bench/scipy_sympy.py); its derivation is done once, as a user would."""
    if not _STRONG:
        _STRONG.append(ss.SympyModel(sz.seed_course()))
    return sz.simulate(_STRONG[0], FORCES, rtol=rtol, atol=atol)


def run_cli(zipopt, method, rtol, outdir):
    """`zipopt simulate --json` on the seed at FORCES with [solver] method and rtol: the run as
    users make it (trajectory rows at the scene's output_dt, load peaks, error estimate);
    stats.wall_s is the simulator's own measured segment."""
    text = open(os.path.join(ROOT, "config", "seed.ini")).read()
    text = re.sub(r"(?m)^method = .*$", f"method = {method}", text)
    text = re.sub(r"(?m)^rtol = .*$", f"rtol = {rtol:g}", text)
    text = re.sub(r"(?m)^atol = .*$", f"atol = {rtol / 100:g}", text)
    ini = os.path.join(outdir, "seed_bench.ini")
    with open(ini, "w") as fh:
        fh.write(text)
    p = subprocess.run([zipopt, "simulate", ini, "--force", ",".join(f"{f:g}" for f in FORCES),
                        "--json", "--out", os.path.join(outdir, "sim")], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{zipopt} simulate exited {p.returncode}: {p.stderr.strip()}")
    return json.loads(p.stdout)


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


def callgrind_share(bench_sim, method, rtol):
    """Inclusive instruction share of zp_sim_rhs in one C run (valgrind callgrind)."""
    outfile = os.path.join(tempfile.mkdtemp(prefix="zipbench"), "callgrind.out")
    cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={outfile}"] + \
        c_cmd(bench_sim, method, [rtol], 1)
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
    ap.add_argument("--bench-sim", default=os.path.join(ROOT, "build", "bench_sim"))
    ap.add_argument("--methods", default="cvode-adams,cvode-bdf,gsl-rk8pd",
                    help="C methods to time (those the build lacks are skipped)")
    ap.add_argument("--repeat", type=int, default=21, help="C runs per tolerance")
    ap.add_argument("--py-repeat", type=int, default=5, help="SciPy runs per tolerance")
    ap.add_argument("--c-rtols", default="1e-5,1e-6,1e-7,1e-8,1e-10")
    ap.add_argument("--py-rtols", default="1e-5,1e-6,1e-7,1e-8")
    ap.add_argument("--zipopt", default=os.path.join(ROOT, "build", "zipopt"))
    ap.add_argument("--cli-method", default="gsl-rk8pd", help="method of the `zipopt simulate` runs")
    ap.add_argument("--cli-repeat", type=int, default=21,
                    help="`zipopt simulate` runs, interleaved one for one with the strong peer's")
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

    # 2. C
    c_rows = []
    if not args.no_c:
        if not os.access(args.bench_sim, os.X_OK):
            sys.exit(f"no C benchmark at {args.bench_sim} (build it; or --no-c for SciPy only)")
        for method in args.methods.split(","):
            try:
                lines = run_c(args.bench_sim, method, c_rtols, args.repeat)
            except RuntimeError as e:
                print(f"  C     {method}: skipped ({e})")
                continue
            for d in lines:
                row = {"impl": f"C {method}", "rtol": d["rtol"], "atol": d["atol"], "runs": args.repeat,
                       "outcome": d["outcome"], "time": d["time"], "dT": abs(d["time"] - t_ref),
                       "deterministic": True, "steps": d["steps"], "rhs_evals": d["rhs_evals"],
                       "wall_s": d["wall_median_s"], "wall_min": d["wall_min_s"]}
                c_rows.append(row)
                print(f"  C     {method} rtol {row['rtol']:g}: {row['outcome']} T {row['time']:.12f} "
                      f"|dT| {row['dT']:.2e} wall {row['wall_s'] * 1e3:.3f} ms", flush=True)
    # 3. SciPy, the naive peer and (3b) the strong one, at each rtol (a few runs each, to find
    # the cheapest rtol meeting the target)
    def peer_rows(impl, runner):
        rows = []
        for rtol in py_rtols:
            runs = [runner(rtol, rtol / 100) for _ in range(args.py_repeat)]
            row = {"impl": impl, "rtol": rtol, "atol": rtol / 100, "runs": len(runs)}
            row.update(summarize(runs, t_ref))
            rows.append(row)
            print(f"  {impl} rtol {rtol:g}: {row['outcome']} T {row['time']:.12f} "
                  f"|dT| {row['dT']:.2e} wall {row['wall_s'] * 1e3:.1f} ms", flush=True)
        return rows

    py_rows = peer_rows("SciPy", run_py)
    strong_rows = peer_rows("SciPy sympy", run_py_strong)
    # 3c. `zipopt simulate` at the cheapest C rtol of --cli-method meeting the target against
    # the strong peer at its cheapest: interleaved, one run each in turn, medians
    cli_row = None
    best_cli = cheapest([r for r in c_rows if r["impl"] == f"C {args.cli_method}"], args.target)
    best_strong = cheapest(strong_rows, args.target)
    if best_cli and best_strong and os.access(args.zipopt, os.X_OK):
        outdir = tempfile.mkdtemp(prefix="zipbench")
        cli_walls, strong_walls, d = [], [], None
        for _ in range(args.cli_repeat):
            d = run_cli(args.zipopt, args.cli_method, best_cli["rtol"], outdir)
            cli_walls.append(d["stats"]["wall_s"])
            strong_walls.append(run_py_strong(best_strong["rtol"], best_strong["rtol"] / 100)
                                ["stats"]["wall_s"])
        cli_row = {"impl": f"zipopt simulate {args.cli_method}", "rtol": best_cli["rtol"],
                   "atol": best_cli["rtol"] / 100, "runs": args.cli_repeat,
                   "outcome": d["outcome"], "time": d["time"], "dT": abs(d["time"] - t_ref),
                   "deterministic": True, "steps": d["stats"]["steps"],
                   "rhs_evals": d["stats"]["rhs_evals"], "wall_s": statistics.median(cli_walls),
                   "wall_min": min(cli_walls)}
        best_strong = dict(best_strong, wall_s=statistics.median(strong_walls),
                           wall_min=min(strong_walls), runs=args.cli_repeat)
        strong_rows[strong_rows.index(next(r for r in strong_rows if r["rtol"] == best_strong["rtol"]))] = best_strong
        print(f"  zipopt simulate {args.cli_method} rtol {best_cli['rtol']:g}: median stats.wall_s "
              f"{cli_row['wall_s'] * 1e3:.3f} ms; SciPy sympy rtol {best_strong['rtol']:g} in the "
              f"same loop: {best_strong['wall_s'] * 1e3:.1f} ms", flush=True)
    rows = c_rows + py_rows + strong_rows + ([cli_row] if cli_row else [])
    # 5. callgrind on each method's cheapest setting that meets the target
    cgs = []
    for impl in dict.fromkeys(r["impl"] for r in c_rows):
        best_m = cheapest([r for r in c_rows if r["impl"] == impl], args.target)
        if best_m and not args.no_callgrind:
            cg = callgrind_share(args.bench_sim, impl[2:], best_m["rtol"])
            cg.update(rtol=best_m["rtol"], impl=impl)
            cgs.append(cg)

    # 6. table and CSV
    print()
    hdr = f"{'impl':17} {'rtol':>7} {'atol':>7} {'outcome':9} {'T (s)':>17} {'|T-Tref| (s)':>12} " \
          f"{'steps':>6} {'rhs':>6} {'wall med (ms)':>13} {'wall min (ms)':>13} {'runs':>4}"
    print(hdr)
    print("-" * len(hdr))
    for r in rows:
        print(f"{r['impl']:17} {r['rtol']:7.0e} {r['atol']:7.0e} {r['outcome']:9} {r['time']:17.12f} "
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
        print(f"cheapest C     with |dT| <= {args.target:g} s: {best_c['impl'][2:]} rtol {best_c['rtol']:g} "
              f"({best_c['wall_s'] * 1e3:.3f} ms, |dT| {best_c['dT']:.1e} s)")
    elif c_rows:
        print(f"no C setting met |dT| <= {args.target:g} s")
    if best_c and best_py:
        ratio = best_c["wall_s"] / best_py["wall_s"]
        print(f"speed ratio C/SciPy wall time at matched accuracy: {ratio:.4g} "
              f"(C is {1 / ratio:.0f}x faster)")
    strong_ratio = None
    if cli_row and best_strong:
        strong_ratio = best_strong["wall_s"] / cli_row["wall_s"]
        print(f"`zipopt simulate --json` ({cli_row['impl'][16:]} rtol {cli_row['rtol']:g}, "
              f"|dT| {cli_row['dT']:.1e} s, stats.wall_s {cli_row['wall_s'] * 1e3:.3f} ms) against the "
              f"strong SciPy peer (sympy + cse + lambdify, DOP853 rtol {best_strong['rtol']:g}, "
              f"|dT| {best_strong['dT']:.1e} s, {best_strong['wall_s'] * 1e3:.1f} ms): "
              f"{strong_ratio:.0f}x faster")
    if best_c and best_py:
        print(f"against the naive SciPy peer (numpy rhs): {best_py['wall_s'] / best_c['wall_s']:.0f}x "
              f"(bench_sim, in-process)")
    for cg in cgs:
        print(f"callgrind ({cg['impl']}, rtol {cg['rtol']:g}): zp_sim_rhs inclusive {cg['rhs_ir']:,} Ir of "
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
            if strong_ratio and (r is cli_row or r is best_strong):
                rec["matched_best"] = 1
                rec["speed_ratio_c_over_scipy"] = f"{1 / strong_ratio:.6g}"
            cg = next((c for c in cgs if r["impl"] == c["impl"] and r["rtol"] == c["rtol"]), None)
            is_cg = cg is not None
            rec["rhs_share_total"] = f"{cg['share_total']:.4f}" if is_cg else ""
            rec["rhs_share_run"] = f"{cg['share_run']:.4f}" if is_cg and cg["share_run"] else ""
            w.writerow(rec)
    os.replace(tmp, args.csv)
    print(f"wrote {os.path.relpath(args.csv, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
