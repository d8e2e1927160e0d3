#!/bin/sh
# check_layers.sh on small made-up trees: it must fail on an include from a floor above and on
# an include circle (two files, three, and one through a header with no .c of its own) in any
# floor, optim's too, and pass a tree whose includes only go down.
check=$(dirname "$0")/check_layers.sh
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
# tree NAME FILE=INCLUDES..: a fresh tree of empty files, each including the headers listed
# after it (comma-separated)
tree() {
    dir="$tmp/$1"
    shift
    mkdir -p "$dir/src/numerics" "$dir/src/core" "$dir/src/io" "$dir/optim" "$dir/src/lib" \
        "$dir/src/app"
    for spec in "$@"; do
        file=${spec%%=*}
        : >"$dir/$file"
        for h in $(echo "${spec#*=}" | tr ',' ' '); do
            echo "#include \"$h\"" >>"$dir/$file"
        done
    done
}
# expect NAME STATUS PATTERN: check_layers.sh on tree NAME exits STATUS, its output matching
# PATTERN (grep -E)
expect() {
    out=$(sh "$check" "$tmp/$1")
    got=$?
    if [ "$got" = "$2" ] && echo "$out" | grep -Eq "$3"; then
        pass=$((pass + 1))
    else
        echo "FAIL $1: status $got (expected $2), output:"
        echo "$out"
        fail=$((fail + 1))
    fi
}
tree down src/core/a.c=a.h,b.h src/core/a.h=b.h src/core/b.c=b.h,c.h src/core/b.h= \
    src/core/c.h= src/io/w.c=a.h
expect down 0 "^1 passed"
tree up src/core/a.c=w.h src/core/a.h= src/io/w.c= src/io/w.h=
expect up 1 "src/core/a.c includes w.h from a floor above its own"
tree two src/core/a.c=a.h,b.h src/core/a.h= src/core/b.c=b.h src/core/b.h=a.h
expect two 1 "src/core: include circle: (a -> b -> a|b -> a -> b)"
tree three src/io/a.c=b.h src/io/a.h= src/io/b.c=c.h src/io/b.h= src/io/c.c= src/io/c.h=a.h
expect three 1 "src/io: include circle: .*a.*b.*c|src/io: include circle: .*c.*a.*b"
tree through src/core/a.c=b.h src/core/a.h= src/core/b.c=b_int.h src/core/b.h= \
    src/core/b_int.h=a.h
expect through 1 "src/core: include circle"
tree optim optim/a.c=b.h optim/a.h= optim/b.c=a.h optim/b.h=
expect optim 1 "optim: include circle"
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
