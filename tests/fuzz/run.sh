#!/usr/bin/env bash
# Fuzzes the scene parser and expression reader (libFuzzer + ASan/UBSan, clang) for a fixed
# budget of executions from a seed corpus of config/*.ini. Usage: tests/fuzz/run.sh [RUNS]
# (default 1000000). A crash leaves crash-* in build-fuzz/; turn each into a case of
# tests/test_fuzz_regress.c.
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-1000000}
CC=clang cmake -S . -B build-fuzz -DZIPOPT_FUZZ=ON -DZIPOPT_SANITIZE=ON -DZIPOPT_BUILD_TESTS=OFF \
  -DZIPOPT_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j2 --target fuzz_scene >/dev/null
corpus=build-fuzz/corpus
mkdir -p "$corpus"
cp config/*.ini "$corpus"/
cd build-fuzz
# leaks are checked once at exit (libmatheval's own suppressed): per input they cut the speed 50-fold
LSAN_OPTIONS=suppressions=../tests/lsan.supp ./fuzz_scene -runs="$runs" -max_len=4096 -detect_leaks=0 \
  -seed=1 -print_final_stats=1 corpus
