#!/bin/sh
# Benchmark of the search end to end: `zipopt SCENE.ini` with its default strategy and budget;
# prints the wall time, the simulations, the simulations per second and the convergence.
#   bench/bench_search.sh [path/to/zipopt] [scene.ini]
set -eu
exe=${1:-build/zipopt}
scene=${2:-config/seed.ini}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
start=$(date +%s.%N)
"$exe" "$scene" --out "$out" >/dev/null || [ $? -eq 3 ]
end=$(date +%s.%N)
python3 - "$out/summary.json" "$start" "$end" "$(nproc)" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
wall = float(sys.argv[3]) - float(sys.argv[2])
c = d["convergence"]
print(f"scene {d['scene']}: best {d['time']:.4f} s with forces {d['forces']}")
print(f"end to end {wall:.2f} s on {sys.argv[4]} cores; search {d['wall_s']:.2f} s, "
      f"{d['evaluations']} simulations, {d['evaluations'] / d['wall_s']:.0f} simulations/s")
print(f"{c['rounds']} rounds: {c['sentence']}")
PY
