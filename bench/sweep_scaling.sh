#!/usr/bin/env bash
# The scaling of `zipopt sweep` over MPI ranks: a 64-point study of the seed (body.masses
# x0.8..x1.2 by body.damping x0.5..x2, 8 x 8; SIDE x SIDE points), once in one process without mpirun, then under
# mpirun on each rank count given; prints the wall and CPU time, speed-up and parallel
# efficiency of each (against the first count), and checks that every run's sweep.csv and
# summary.json (the grid schedule in it) equal the one-process files bit for bit.
#   usage: bench/sweep_scaling.sh [RANKS..]   (default: 1 2; e.g. 1 2 4 8 16 on a big machine)
#   env:   ZIPOPT   the binary (default: zipopt on PATH, else build/zipopt)
#          RUN      search (default) or simulate
#          EVALS    the search's budget per point ([optimize] max_evals; default the seed's 5000)
#          THREADS  OpenMP threads per rank (default 1: each rank on one core)
#          GRID     0: without the grid schedule (--no-grid-schedule); default with it, one
#                   item of about 7 points' cost that bounds the wall time at 16 ranks
#          SIDE     values per key (default 8: 64 points)
#          HOSTFILE a hostfile for mpirun (a cluster: one line per node, `node01 slots=16`)
#          MPIRUN_ARGS more mpirun options (default --oversubscribe; as root --allow-run-as-root
#                   is added)
# Writes out/bench/sweep_scaling/scaling.csv (ranks, wall_s, cpu_s, speedup, efficiency).
set -euo pipefail
cd "$(dirname "$0")/.."
zipopt=${ZIPOPT:-$(command -v zipopt || echo build/zipopt)}
run=${RUN:-search}
out=out/bench/sweep_scaling
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(1 2)
mkdir -p "$out"
scene=$out/seed.ini
if [ -n "${EVALS:-}" ]; then
  sed "s/^max_evals *=.*/max_evals = $EVALS/" config/seed.ini >"$scene"
else
  cp config/seed.ini "$scene"
fi
side=${SIDE:-8} # values per key: side^2 points
vary=(--vary body.masses=0.8:1.2:$side --vary body.damping=0.5:2:$side)
[ "${GRID:-1}" != 0 ] || vary+=(--no-grid-schedule)
export OMP_NUM_THREADS=${THREADS:-1}
read -r -a mpi <<<"${MPIRUN_ARGS:---oversubscribe}"
[ "$(id -u)" != 0 ] || mpi+=(--allow-run-as-root)
[ -z "${HOSTFILE:-}" ] || mpi+=(--hostfile "$HOSTFILE")

# one study: "wall_s cpu_s" (the CPU seconds of every process it started)
timed() {
  local TIMEFORMAT='%R %U %S'
  { time "$@" >/dev/null; } 2>"$out/time.txt"
  awk 'END { print $1, $2 + $3 }' "$out/time.txt"
}
# the reference: one process, no mpirun; every MPI run must give its sweep.csv bit for bit
read -r w0 c0 < <(timed "$zipopt" sweep "$scene" "${vary[@]}" --run "$run" --out "$out/plain")
echo "ranks,wall_s,cpu_s,speedup,efficiency" >"$out/scaling.csv"
printf '%-7s %9s %9s %8s %11s  %s\n' ranks wall_s cpu_s speedup efficiency \
  "($((side * side)) points, $run, $OMP_NUM_THREADS thread(s) per rank, $(hostname))"
printf '%-7s %9.2f %9.2f\n' "plain" "$w0" "$c0"
w1=
for n in "${ranks[@]}"; do
  read -r wn cn < <(timed mpirun "${mpi[@]}" -np "$n" "$zipopt" sweep "$scene" "${vary[@]}" \
    --run "$run" --out "$out/ranks$n")
  for f in sweep.csv summary.json; do
    cmp -s "$out/plain/$f" "$out/ranks$n/$f" ||
      { echo "ranks $n: $f differs from the one-process run" >&2; exit 1; }
  done
  w1=${w1:-$(awk -v w="$wn" -v n="$n" 'BEGIN { print w * n }')} # the first count's rank-seconds
  awk -v n="$n" -v w1="$w1" -v w="$wn" -v c="$cn" 'BEGIN {
    printf "%-7s %9.2f %9.2f %8.2f %10.0f%%\n", n, w, c, w1 / w, 100 * w1 / w / n
    print n "," w "," c "," w1 / w "," w1 / w / n >> "'"$out/scaling.csv"'" }'
done
echo "every sweep.csv and summary.json equal the one-process ones bit for bit; speed-up against the first rank"
echo "count's wall time times its ranks; table in $out/scaling.csv"
