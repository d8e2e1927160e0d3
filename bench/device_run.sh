#!/usr/bin/env bash
# The scaling benchmarks on a many-core machine from a bundle (bench/device_bundle.sh): the
# search over 1..16 threads (bench/thread_scaling.sh), the sweep over 1..16 MPI ranks
# (bench/sweep_scaling.sh), and the simulator against SciPy (bench/run_bench.py) when that
# machine's python3 has numpy, scipy and sympy. Results go to DEST (default out/bench).
#   usage: bench/device_run.sh [BUNDLE [DEST]]   (default out/device)
set -uo pipefail
cd "$(dirname "$0")/.."
bundle=${1:-out/device}
dest=${2:-out/bench}
# shellcheck source=/dev/null
. "$bundle/env.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$dest"
{
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
  lscpu 2>/dev/null | grep -E '^(Thread|Core|Socket|NUMA node\(s\))'
  command -v gnuplot >/dev/null || echo "no gnuplot there: the figures' cost is not measured"
  zipopt --version
  bench/thread_scaling.sh 1 2 4 8 16
  THREADS=1 bench/sweep_scaling.sh 1 2 4 8 16
  python3 bench/run_bench.py --bench-sim "$bundle/bin/bench_sim" --repeat 11 --no-callgrind
} 2>&1 | tee "$dest/device_run.log"
cp out/bench/thread_scaling/scaling.csv "$dest/thread_scaling.csv" 2>/dev/null
cp out/bench/sweep_scaling/scaling.csv "$dest/sweep_scaling.csv" 2>/dev/null
cp out/bench/bench_sim.csv "$dest/bench_sim.csv" 2>/dev/null
true
