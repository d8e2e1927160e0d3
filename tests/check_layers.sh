#!/bin/sh
# The floors link only downward (README "Design"): no file includes a header from a floor above
# its own. Floors, bottom up: src/numerics, src/core, src/io, optim, src/lib, src/app.
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
done
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
