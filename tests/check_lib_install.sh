#!/bin/sh
# The library as a user gets it: `cmake --install` into a temporary prefix, examples/simulate.c
# compiled with the installed zipopt.pc and run against the installed libzipopt.so (the 10 N
# seed run finishes at the program's time, bit for bit; a bad scene exits 2 naming file and
# line), and the installed Python module imported from its documented folder.
# usage: check_lib_install.sh BUILD_DIR CMAKE SOURCE_DIR PYTHON3
build=$1 cmake=$2 src=$(cd "$3" && pwd) py=$4
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }

"$cmake" --install "$build" --prefix "$tmp/p" >/dev/null || bad "cmake --install"
pc=$(find "$tmp/p" -name zipopt.pc | head -n 1)
[ -n "$pc" ] && ok || bad "zipopt.pc not installed"
[ -f "$tmp/p/include/zipopt.h" ] && ok || bad "zipopt.h not installed"
libdir=$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --variable=libdir zipopt)
[ -e "$libdir/libzipopt.so.0" ] && [ -e "$libdir/libzipopt.so" ] && ok || bad "no libzipopt.so.0 in $libdir"

# the example against the installed library, as README says
flags=$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --cflags --libs zipopt) || bad "pkg-config"
${CC:-cc} -std=c11 -Wall -Wextra -Werror "$src/examples/simulate.c" $flags -o "$tmp/simulate" \
    && ok || bad "examples/simulate.c does not build against the installed library"
out=$(LD_LIBRARY_PATH=$libdir "$tmp/simulate" "$src/config/seed.ini" 10,10,10) \
    && ok || bad "examples/simulate failed"
lib_t=$(echo "$out" | sed -n 's/^time: \([^ ]*\) s$/\1/p')
prog_t=$("$build/zipopt" simulate "$src/config/seed.ini" --force 10,10,10 --json --out "$tmp/o" |
    sed -n 's/^ *"time": \([^,]*\),$/\1/p')
awk -v a="$lib_t" -v b="$prog_t" 'BEGIN { exit !(a != "" && a + 0 == b + 0) }' \
    && ok || bad "example's time '$lib_t' is not the program's '$prog_t'"
printf '[scene]\nname = bad\n[body]\nmasses = 1, -2\n' >"$tmp/bad.ini"
LD_LIBRARY_PATH=$libdir "$tmp/simulate" "$tmp/bad.ini" 2>"$tmp/err" >/dev/null
[ $? = 2 ] && grep -q "$tmp/bad.ini:4: \[body\] masses" "$tmp/err" && ok \
    || bad "a bad scene: $(cat "$tmp/err")"

# the Python module from share's documented folder, the library by the system loader
pydir=$(find "$tmp/p" -path '*/zipopt/__init__.py' | head -n 1)
[ -n "$pydir" ] && ok || bad "the Python module is not installed"
if "$py" -c 'import numpy' 2>/dev/null; then
    py_t=$(cd "$tmp" && PYTHONPATH=$(dirname "$(dirname "$pydir")") LD_LIBRARY_PATH=$libdir \
        "$py" -c "import zipopt; print(repr(zipopt.simulate('$src/config/seed.ini', [10, 10, 10]).time))")
    awk -v a="$py_t" -v b="$prog_t" 'BEGIN { exit !(a != "" && a + 0 == b + 0) }' \
        && ok || bad "installed module's time '$py_t' is not the program's '$prog_t'"
else
    echo "skipped the installed module: numpy is missing (apt-get install python3-numpy)"
fi
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
