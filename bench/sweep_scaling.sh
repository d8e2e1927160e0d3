#!/usr/bin/env bash
# The scaling of `zipopt sweep` over MPI ranks: a 64-point study of the seed (body.masses
# x0.8..x1.2 by body.damping x0.5..x2, 8 x 8), once in one process without mpirun, then under
# mpirun on each rank count given; prints the wall time, speed-up and parallel efficiency of
# each, and checks that every run's sweep.csv equals the one-process file bit for bit.
#   usage: bench/sweep_scaling.sh [RANKS..]          (default: 2; e.g. 2 4 8 16 on a big machine)
#   env:   ZIPOPT   the binary (default build/zipopt)
#          RUN      search (default) or simulate
#          EVALS    the search's budget per point ([optimize] max_evals; default the seed's 5000)
#          THREADS  OpenMP threads per rank (default 1: each rank on one core)
#          HOSTFILE a hostfile for mpirun (a cluster: one line per node, `node01 slots=16`)
#          MPIRUN_ARGS more mpirun options (default --oversubscribe; as root --allow-run-as-root
#                   is added)
# Writes out/bench/sweep_scaling/scaling.csv (ranks, wall_s, speedup, efficiency).
set -euo pipefail
cd "$(dirname "$0")/.."
zipopt=${ZIPOPT:-build/zipopt}
run=${RUN:-search}
out=out/bench/sweep_scaling
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(2)
mkdir -p "$out"
scene=$out/seed.ini
if [ -n "${EVALS:-}" ]; then
  sed "s/^max_evals *=.*/max_evals = $EVALS/" config/seed.ini >"$scene"
else
  cp config/seed.ini "$scene"
fi
vary=(--vary body.masses=0.8:1.2:8 --vary body.damping=0.5:2:8)
export OMP_NUM_THREADS=${THREADS:-1}
read -r -a mpi <<<"${MPIRUN_ARGS:---oversubscribe}"
[ "$(id -u)" != 0 ] || mpi+=(--allow-run-as-root)
[ -z "${HOSTFILE:-}" ] || mpi+=(--hostfile "$HOSTFILE")

now() { date +%s.%N; }
t0=$(now)
"$zipopt" sweep "$scene" "${vary[@]}" --run "$run" --out "$out/ranks1" >/dev/null
t1=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print b - a }')
echo "ranks,wall_s,speedup,efficiency" >"$out/scaling.csv"
echo "1,$t1,1,1" >>"$out/scaling.csv"
printf '%-6s %10s %8s %11s  %s\n' ranks wall_s speedup efficiency "(64 points, $run, $OMP_NUM_THREADS thread(s) per rank, $(hostname))"
printf '%-6s %10.2f %8.2f %10.0f%%\n' 1 "$t1" 1 100
for n in "${ranks[@]}"; do
  t0=$(now)
  mpirun "${mpi[@]}" -np "$n" "$zipopt" sweep "$scene" "${vary[@]}" --run "$run" \
    --out "$out/ranks$n" >/dev/null
  tn=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print b - a }')
  cmp -s "$out/ranks1/sweep.csv" "$out/ranks$n/sweep.csv" ||
    { echo "ranks $n: sweep.csv differs from the one-process run" >&2; exit 1; }
  awk -v n="$n" -v t1="$t1" -v tn="$tn" 'BEGIN {
    printf "%-6s %10.2f %8.2f %10.0f%%\n", n, tn, t1 / tn, 100 * t1 / tn / n }'
  awk -v n="$n" -v t1="$t1" -v tn="$tn" 'BEGIN { print n "," tn "," t1 / tn "," t1 / tn / n }' \
    >>"$out/scaling.csv"
done
echo "every sweep.csv equals the one-process one bit for bit; table in $out/scaling.csv"
