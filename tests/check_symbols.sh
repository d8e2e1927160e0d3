#!/bin/sh
# What the libraries export (STYLE.md 3.3), checked on the built archives and objects:
# - a shared library (*.so) exports only the public API, zipopt_ (include/zipopt.h);
# - in a static floor (*.a) every export starts with zp_ and carries its file's name: file
#   sim_rhs.c exports zp_sim_rhs*, so a name says where it lives (as REBOUND's checker does);
#   a build without MPI's stand-in X_none.c exports X's names;
# - with --unused DIR: no export that no other object under DIR (the libraries, the program,
#   the tests and benchmarks) calls: such a function belongs static in its file.
# AddressSanitizer's ODR indicators (__odr_asan.<symbol>) are instrumentation, not exports.
status=0
fail() {
    echo "$@"
    status=1
}

# exports used by no other object, each kept for a reason a reader can check
keep_unused="zp_sim_rhs" # named by bench/run_bench.py's callgrind share of the equations

unused_dir=
libs=
while [ $# -gt 0 ]; do
    case $1 in
    --unused) unused_dir=$2; shift ;;
    *) libs="$libs $1" ;;
    esac
    shift
done

for lib in $libs; do
    case $lib in
    *.so*)
        strays=$(nm -D --defined-only "$lib" | awk 'NF == 3 {print $3}' | grep -v '^zipopt_')
        [ -z "$strays" ] || fail "$lib exports symbols without the zipopt_ prefix:" $strays
        ;;
    *)
        # member:symbol for every defined global; the member's stem is the file's name
        strays=$(nm -A -g --defined-only "$lib" | awk 'NF == 3 {
                n = split($1, p, ":"); m = p[n - 1]; sub(/\.c\.o$/, "", m); sub(/_none$/, "", m); s = $3
                if (s ~ /^__odr_asan\./) next
                if (index(s, "zp_" m) != 1) print m ".c:" s }')
        [ -z "$strays" ] || fail "$lib: exports that do not carry their file's name (zp_<file>):" $strays
        ;;
    esac
done

if [ -n "$unused_dir" ]; then
    objs=$(find "$unused_dir" -name '*.o' ! -path '*zipopt_shared*')
    # a stand-in (X_none.c) mirrors X's interface, whose callers may be built only with MPI
    defined=$(for lib in $libs; do
        case $lib in *.a) nm -A -g --defined-only "$lib" | awk 'NF == 3 && $1 !~ /_none\.c\.o:/ {print $3}' ;; esac
    done | grep -v '^__odr_asan\.' | sort -u)
    used=$(nm -u $objs 2>/dev/null | awk '{print $NF}' | sort -u)
    dead=$(printf '%s\n' "$defined" | while read -r s; do
        printf '%s\n' "$used" | grep -qx "$s" || printf '%s\n' " $keep_unused " | grep -q " $s " || echo "$s"
    done)
    [ -z "$dead" ] || fail "exported but called from no other file (make them static):" $dead
fi

[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
