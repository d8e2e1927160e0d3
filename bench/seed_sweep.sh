#!/bin/sh
# The search's spread over seeds: `zipopt SCENE --seed S` for each scene and seed, one thread per
# run and JOBS runs at once; prints a row per scene with the answer (s) of each seed, then the
# searches' seconds in all (summary.json wall_s: on one thread, their CPU). docs/search.md's
# "seeds 1 to 5" tables are made this way.
#   bench/seed_sweep.sh [-j JOBS] [-s "SEEDS"] [-o DIR] [-x "ARGS"] path/to/zipopt SCENE.ini...
# -j runs at once (default: the cores), -s the seeds (default "1 2 3 4 5"), -o keeps each run's
# output in DIR/SCENE_SEED/ (default: a temporary folder, removed), -x more arguments for every
# run (for example "--max-evals 90000" or "--algorithm portfolio-de").
set -eu
jobs=$(nproc)
seeds="1 2 3 4 5"
keep=
extra=
while getopts j:s:o:x: opt; do
    case $opt in
    j) jobs=$OPTARG ;;
    s) seeds=$OPTARG ;;
    o) keep=$OPTARG ;;
    x) extra=$OPTARG ;;
    *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
if [ $# -lt 2 ]; then
    echo "usage: bench/seed_sweep.sh [-j JOBS] [-s SEEDS] [-o DIR] [-x ARGS] ZIPOPT SCENE.ini..." >&2
    exit 2
fi
exe=$1
shift
[ -x "$exe" ] || { echo "seed_sweep: $exe is not an executable" >&2; exit 2; }
for scene in "$@"; do
    [ -r "$scene" ] || { echo "seed_sweep: cannot read $scene" >&2; exit 2; }
done
# each run's output is named after its scene's file
same=$(for scene in "$@"; do basename "$scene" .ini; done | sort | uniq -d)
if [ -n "$same" ]; then
    echo "seed_sweep: two scenes share the name $same" >&2
    exit 2
fi
if [ -n "$keep" ]; then
    out=$keep
    mkdir -p "$out"
else
    out=$(mktemp -d)
    trap 'rm -rf "$out"' EXIT
fi
start=$(date +%s)
for scene in "$@"; do
    for seed in $seeds; do
        printf '%s %s\n' "$scene" "$seed"
    done
done | OMP_NUM_THREADS=1 xargs -P "$jobs" -n 2 sh -c '
    out=$1 exe=$2 extra=$3 scene=$4 seed=$5
    dir="$out/$(basename "$scene" .ini)_$seed"
    rm -rf "$dir"
    # exit 3: the search ran and found no survivable schedule; its summary says so.
    # $extra unquoted: its words are separate arguments
    "$exe" "$scene" --seed "$seed" --no-plot --json --out "$dir" $extra >"$dir.log" 2>&1 ||
        [ $? -eq 3 ] || { echo "seed_sweep: $scene seed $seed failed:" >&2; tail -n 3 "$dir.log" >&2; exit 1; }
' _ "$out" "$exe" "$extra" || true
end=$(date +%s)
python3 - "$out" "$seeds" "$((end - start))" "$@" <<'PY'
import json, os, sys
out, seeds, wall, scenes = sys.argv[1], sys.argv[2].split(), sys.argv[3], sys.argv[4:]
spent, failed = 0.0, 0
print("scene" + "".join(f" | seed {s}" for s in seeds))
for scene in scenes:
    name = os.path.basename(scene)[:-4] if scene.endswith(".ini") else os.path.basename(scene)
    row = []
    for s in seeds:
        base = os.path.join(out, f"{name}_{s}")
        try:
            d = json.load(open(os.path.join(base, "summary.json")))
            row.append(f"{d['time']:.5f}" if d.get("found") else "none survives")
            spent += d["wall_s"]
        except (OSError, ValueError, KeyError):
            row.append("failed")
            failed += 1
    print(name + "".join(f" | {r}" for r in row))
print(f"searches {spent:.1f} s in all, {wall} s wall")
sys.exit(1 if failed else 0)
PY
