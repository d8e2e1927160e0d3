#!/bin/sh
# The floors link only downward (README "Design"): no file includes a header from a floor above
# its own. Floors, bottom up: src/numerics, src/core, src/io, optim, src/lib, src/app.
# Within a floor, no include circle: a.c (or a.h) includes b.h while b.c (or b.h) includes a.h,
# or a longer cycle a -> b -> c -> a. A header with no .c of its own (scene.h, a family's
# *_int.h) is read through: what it includes counts as included by the file including it. Such
# a header must not declare the functions of several files: their circle would not show here.
top=${1:-.}
cd "$top" || exit 1
floors="src/numerics src/core src/io optim src/lib src/app"
level() { # the floor index of the folder holding header $1, or -1 if none does
    i=0
    for f in $floors; do
        [ -f "$f/$1" ] && { echo $i; return; }
        i=$((i + 1))
    done
    echo -1
}
includes() { # the quoted includes of the files $@ that exist
    for file in "$@"; do
        [ -f "$file" ] && sed -n 's/^#include "\([^"]*\)".*/\1/p' "$file"
    done
}
uses() { # the files of floor $1 whose headers unit $2 (its .c and .h) includes, one a line
    dir=$1
    seen=" "
    todo="$dir/$2.c $dir/$2.h"
    while [ -n "$todo" ]; do
        next=""
        for h in $(includes $todo); do
            [ -f "$dir/$h" ] || continue
            case "$seen" in *" $h "*) continue ;; esac
            seen="$seen$h "
            if [ -f "$dir/${h%.h}.c" ]; then
                [ "${h%.h}" != "$2" ] && echo "${h%.h}"
            else
                next="$next $dir/$h"
            fi
        done
        todo=$next
    done
}
status=0
i=0
for f in $floors; do
    for src in "$f"/*.c "$f"/*.h; do
        [ -f "$src" ] || continue
        for h in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$src"); do
            l=$(level "$h")
            if [ "$l" -gt "$i" ]; then
                echo "$src includes $h from a floor above its own"
                status=1
            fi
        done
    done
    i=$((i + 1))
    # the graph "a includes b's header"; tsort names each cycle it has to break, a line each
    cycles=$(for c in "$f"/*.c; do
        [ -f "$c" ] || continue
        u=$(basename "$c" .c)
        echo "$u $u"
        for b in $(uses "$f" "$u"); do
            echo "$u $b"
        done
    done | tsort 2>&1 >/dev/null | awk '
        /contains a loop/ { if (l) print l " -> " first; l = ""; next }
        { sub(/^tsort: /, ""); if (l) l = l " -> " $0; else first = l = $0 }
        END { if (l) print l " -> " first }')
    [ -n "$cycles" ] || continue
    status=1
    echo "$cycles" | while read -r cycle; do
        echo "$f: include circle: $cycle"
    done
done
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
