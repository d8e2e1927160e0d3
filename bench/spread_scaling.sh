#!/usr/bin/env bash
# `zipopt landscape` spread over MPI ranks: the seed's landscape with a slice (201 constant
# pushes and a 101 x 101 slice of sections 1 and 2: 10402 runs), once in one process without
# mpirun, then under mpirun on each rank count given, REPEAT times each, interleaved; prints the
# median wall and CPU time of each and checks that every run's CSV files equal the one-process
# files bit for bit.
#   usage: bench/spread_scaling.sh [RANKS..]   (default: 2; e.g. 2 4 8 16 on a big machine)
#   env:   ZIPOPT   the binary (default build/zipopt)
#          THREADS  OpenMP threads per process (default 1: each rank on one core)
#          REPEAT   runs of each (default 3)
#          MPIRUN_ARGS more mpirun options (default --oversubscribe; as root --allow-run-as-root
#                   is added)
set -euo pipefail
cd "$(dirname "$0")/.."
zipopt=${ZIPOPT:-build/zipopt}
out=out/bench/spread_scaling
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(2)
repeat=${REPEAT:-3}
mkdir -p "$out"
args=(landscape config/seed.ini --slice 1,2 --range 0:500:101)
export OMP_NUM_THREADS=${THREADS:-1}
read -r -a mpi <<<"${MPIRUN_ARGS:---oversubscribe}"
[ "$(id -u)" != 0 ] || mpi+=(--allow-run-as-root)

# one run: "wall_s cpu_s" (the CPU seconds of every process it started)
timed() {
  /usr/bin/time -f "%e %U %S" -o "$out/time.txt" "$@" >/dev/null
  awk '{ print $1, $2 + $3 }' "$out/time.txt"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
same() { # the run in folder $1 wrote the reference's CSV files
  for f in landscape.csv landscape_slice.csv; do
    cmp -s "$out/plain/$f" "$1/$f" || { echo "$1/$f differs from the one-process run" >&2; exit 1; }
  done
}

configs=(plain "${ranks[@]}")
for ((i = 0; i < repeat; i++)); do
  for c in "${configs[@]}"; do
    if [ "$c" = plain ]; then
      timed "$zipopt" "${args[@]}" --out "$out/plain" >>"$out/t_plain.txt"
    else
      timed mpirun "${mpi[@]}" -np "$c" "$zipopt" "${args[@]}" --out "$out/ranks$c" \
        >>"$out/t_$c.txt"
      same "$out/ranks$c"
    fi
  done
done
printf '%-7s %9s %9s  %s\n' ranks wall_s cpu_s \
  "(10402 runs, $OMP_NUM_THREADS thread(s) per process, medians of $repeat, $(hostname))"
for c in "${configs[@]}"; do
  printf '%-7s %9.2f %9.2f\n' "$c" "$(cut -d' ' -f1 "$out/t_$c.txt" | median)" \
    "$(cut -d' ' -f2 "$out/t_$c.txt" | median)"
  rm -f "$out/t_$c.txt"
done
echo "every landscape.csv and landscape_slice.csv equals the one-process one bit for bit"
