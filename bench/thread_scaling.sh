#!/usr/bin/env bash
# The search's scaling over OpenMP threads: each study below at every thread count given,
# wall and CPU time (median of REPS runs), speed-up and parallel efficiency against one
# thread, and a check that every thread count gives the same answer (forces and time, bit for
# bit in summary.json).
#   usage: bench/thread_scaling.sh [THREADS..]   (default: 1 2; e.g. 1 2 4 8 16 on a big machine)
#   env:   ZIPOPT  the binary (default: zipopt on PATH, else build/zipopt)
#          REPS    runs per point (default 3; the robust and human studies REPS_LONG, default 1)
#          ONLY    the studies to run, by name (default all)
# Writes out/bench/thread_scaling/scaling.csv (study, threads, wall_s, cpu_s, speedup,
# efficiency, and for the searches search_s, search_speedup: the search phase alone, summary.json
# wall_s, without the verification and the outputs). Timed with bash's `time` (no /usr/bin/time needed).
set -euo pipefail
cd "$(dirname "$0")/.."
zipopt=${ZIPOPT:-$(command -v zipopt || echo build/zipopt)}
reps=${REPS:-3}
out=out/bench/thread_scaling
threads=("$@")
[ ${#threads[@]} -gt 0 ] || threads=(1 2)
mkdir -p "$out"
# study name | command after the binary (the robust one is the seed at +/-5 % force error,
# 64 scenarios; human.ini's budget is cut so that one thread stays affordable: the search
# cuts its work at the budget in its serial order, so every thread count runs the same work)
studies=(
  "seed|config/seed.ini --no-plot"
  "seed_figures|config/seed.ini"
  "multi8|config/multi8.ini --no-plot"
  "human_1000|config/human.ini --no-plot --max-evals 1000"
  "seed_pm5_robust|config/seed_pm5.ini --no-plot"
  "landscape|landscape config/seed.ini --slice 1,2"
)

# one run: "wall cpu" (s; cpu counts every thread)
timed() {
  local TIMEFORMAT='%R %U %S'
  # exit 3 (no survivable schedule) is an answer; a machine without gnuplot still times the
  # work (the landscape then exits 1 with its data written)
  { time "$@" >/dev/null 2>"$out/stderr.txt"; } 2>"$out/time.txt" ||
    [ $? -eq 3 ] || grep -q "gnuplot is not installed" "$out/stderr.txt" ||
    { cat "$out/stderr.txt" >&2; return 1; }
  awk '{ print $1, $2 + $3 }' "$out/time.txt"
}
# the answer a run wrote: the forces and time of summary.json, or the landscape's CSV
answer() {
  if [ -f "$1/summary.json" ]; then
    grep -E '^  "(forces|time)"' "$1/summary.json"
  else
    cat "$1"/landscape*.csv
  fi
}

# the median of the numbers on stdin
median() { sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
# the search phase's wall time of a run (summary.json wall_s), or nan for the landscape
search_s() { sed -n 's/^  "wall_s": \([0-9.e+-]*\),*$/\1/p' "$1/summary.json" 2>/dev/null | grep . || echo nan; }

echo "study,threads,wall_s,cpu_s,speedup,efficiency,search_s,search_speedup" >"$out/scaling.csv"
printf '%-16s %7s %8s %8s %8s %10s %9s %8s\n' study threads wall_s cpu_s speedup efficiency \
  search_s speedup
for s in "${studies[@]}"; do
  name=${s%%|*}
  [ -z "${ONLY:-}" ] || [[ " $ONLY " == *" $name "* ]] || continue
  read -r -a args <<<"${s#*|}"
  n=$reps
  case $name in seed_pm5_robust | human_*) n=${REPS_LONG:-1} ;; esac
  w1= s1=
  for t in "${threads[@]}"; do
    walls=() cpus=() searches=()
    for ((i = 0; i < n; i++)); do
      rm -rf "$out/run"
      read -r w c < <(OMP_NUM_THREADS=$t timed "$zipopt" "${args[@]}" --out "$out/run")
      walls+=("$w") cpus+=("$c") searches+=("$(search_s "$out/run")")
    done
    w=$(printf '%s\n' "${walls[@]}" | median)
    c=$(printf '%s\n' "${cpus[@]}" | median)
    sw=$(printf '%s\n' "${searches[@]}" | median)
    answer "$out/run" >"$out/answer_$t.txt"
    cmp -s "$out/answer_$t.txt" "$out/answer_${threads[0]}.txt" ||
      { echo "$name: $t threads give another answer than ${threads[0]}" >&2; exit 1; }
    w1=${w1:-$(awk -v w="$w" -v t="$t" 'BEGIN { print w * t }')}
    s1=${s1:-$(awk -v w="$sw" -v t="$t" 'BEGIN { print w * t }')}
    awk -v s="$name" -v t="$t" -v w="$w" -v c="$c" -v w1="$w1" -v sw="$sw" -v s1="$s1" 'BEGIN {
      sp = sw == "nan" ? "nan" : sprintf("%.2f", s1 / sw)
      ss = sw == "nan" ? "nan" : sprintf("%.3f", sw)
      printf "%-16s %7d %8.3f %8.3f %8.2f %9.0f%% %9s %8s\n", s, t, w, c, w1 / w, 100 * w1 / w / t,
        ss, sp
      print s "," t "," w "," c "," w1 / w "," w1 / w / t "," sw "," sp >> "'"$out/scaling.csv"'" }'
  done
done
echo "every thread count gave the same answer; speed-up against the first count's wall time"
echo "times its threads; table in $out/scaling.csv"
