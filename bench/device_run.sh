#!/usr/bin/env bash
# The scaling benchmarks on a many-core machine from a bundle (bench/device_bundle.sh): the
# search over 1..16 threads (bench/thread_scaling.sh), the sweep over 1..16 MPI ranks
# (bench/sweep_scaling.sh: the 64 points alone, GRID=0, at EVALS simulations per point, default
# 2500). Results go to DEST (default out/bench).
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
  GRID=0 EVALS=${EVALS:-2500} THREADS=1 bench/sweep_scaling.sh 1 2 4 8 16
} 2>&1 | tee "$dest/device_run.log"
cp out/bench/thread_scaling/scaling.csv "$dest/thread_scaling.csv" 2>/dev/null
cp out/bench/sweep_scaling/scaling.csv "$dest/sweep_scaling.csv" 2>/dev/null
true
