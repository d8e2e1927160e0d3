#!/bin/sh
# cmake --install into a temporary prefix puts the program, the man page zipopt(1), the bash
# completion and the example scenes in place, and the completion offers what --help documents.
# With SOURCE_DIR and PYTHON3 also the library: examples/simulate.c compiled with the installed
# zipopt.pc against the installed libzipopt.so (the 10 N seed run finishes at the installed
# program's time, bit for bit; a bad scene exits 2 naming file and line), and the installed
# Python module imported from its folder.
# usage: check_install.sh BUILD_DIR CMAKE [SOURCE_DIR PYTHON3]
set -u
build=$1
cmake=$2
src=${3:-}
py=${4:-}
prefix=$(mktemp -d "${TMPDIR:-/tmp}/zp_install_XXXXXX")
trap 'rm -rf "$prefix"' EXIT
failures=0
fail() {
    echo "check_install: $*" >&2
    failures=$((failures + 1))
}

"$cmake" --install "$build" --prefix "$prefix" >/dev/null || fail "cmake --install failed"
exe=$prefix/bin/zipopt
man=$prefix/share/man/man1/zipopt.1
comp=$(find "$prefix/share" -path '*bash-completion/completions/zipopt' -type f)
[ -x "$exe" ] || fail "no program at bin/zipopt"
[ -f "$prefix/share/zipopt/scenes/seed.ini" ] || fail "no example scenes in share/zipopt/scenes"
[ -n "$comp" ] || fail "no completion in share/bash-completion/completions/zipopt"
[ -f "$man" ] || fail "no man page at share/man/man1/zipopt.1"
# the docs the man page and --help send users to are installed beside them
for d in model.md scene-file.md commands.md; do
    [ -f "$prefix/share/doc/zipopt/$d" ] || fail "no share/doc/zipopt/$d"
done
[ "$failures" = 0 ] || exit 1

# the installed program runs an installed scene
"$exe" check "$prefix/share/zipopt/scenes/seed.ini" >/dev/null || fail "zipopt check seed.ini"

# the man page is zipopt(1) and documents every command's options ('-' is '\-' in roff)
grep -q '^\.TH ZIPOPT "*1' "$man" || fail "the man page is not zipopt(1)"
manual=$(sed 's/\\-/-/g' "$man")
case $manual in *"share/doc/zipopt"*) ;; *) fail "the man page does not name share/doc/zipopt" ;; esac

# COMPREPLY of the installed completion for the words given (the last is being completed)
offers() {
    PATH="$prefix/bin:$PATH" bash -c 'source "$1"; shift; COMP_WORDS=("$@");
        COMP_CWORD=$(($# - 1)); _zipopt; echo " ${COMPREPLY[*]} "' _ "$comp" "$@"
}

got=$(offers zipopt "")
for c in simulate check landscape tradeoff sweep bench; do
    case $got in *" $c "*) ;; *) fail "zipopt <TAB> does not offer $c: $got" ;; esac
done
[ "$(offers zipopt sim)" = " simulate " ] || fail "zipopt sim<TAB>: $(offers zipopt sim)"
[ "$(offers zipopt bench "")" = " trade " ] || fail "zipopt bench <TAB>: $(offers zipopt bench "")"

# every option a command's --help names is offered and is in the man page
for cmd in simulate check landscape tradeoff sweep "bench trade" x.ini; do
    # shellcheck disable=SC2086 # cmd is one or two words (x.ini: the search)
    for o in $("$exe" $cmd --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
        # shellcheck disable=SC2086
        case $(offers zipopt $cmd x.ini --) in
        *" $o "*) ;;
        *) fail "zipopt $cmd -- <TAB> does not offer $o" ;;
        esac
        case $manual in *"$o"*) ;; *) fail "the man page does not mention $o" ;; esac
    done
done
case $(offers zipopt x.ini --algorithm "") in
*" scan-cobyla "*) ;;
*) fail "--algorithm <TAB> does not offer scan-cobyla" ;;
esac

# scene files (and folders), not other files
work=$(mktemp -d "${TMPDIR:-/tmp}/zp_comp_XXXXXX")
mkdir "$work/sub" && : >"$work/a.ini" && : >"$work/b.txt"
got=$(cd "$work" && offers zipopt check "")
case $got in *" a.ini "*) ;; *) fail "zipopt check <TAB> does not offer a.ini: $got" ;; esac
case $got in *" sub "*) ;; *) fail "zipopt check <TAB> does not offer the folder sub: $got" ;; esac
case $got in *b.txt*) fail "zipopt check <TAB> offers b.txt: $got" ;; esac
got=$(cd "$work" && offers zipopt simulate a.ini --out "")
[ "$got" = " sub " ] || fail "--out <TAB> offers more than folders: $got"
rm -rf "$work"

# the library as README's pkg-config line builds against it
if [ -n "$src" ]; then
    pc=$(find "$prefix" -name zipopt.pc)
    [ -f "$prefix/include/zipopt.h" ] || fail "no header at include/zipopt.h"
    [ -n "$pc" ] || fail "no zipopt.pc"
    export PKG_CONFIG_PATH="${pc%/zipopt.pc}"
    libdir=$(pkg-config --variable=libdir zipopt)
    [ -e "$libdir/libzipopt.so.0" ] || fail "no libzipopt.so.0 in $libdir"
    # shellcheck disable=SC2046 # pkg-config's flags are words
    ${CC:-cc} -std=c11 -Wall -Wextra -Werror "$src/examples/simulate.c" \
        $(pkg-config --cflags --libs zipopt) -o "$prefix/simulate" ||
        fail "examples/simulate.c does not build against the installed library"
    seed=$prefix/share/zipopt/scenes/seed.ini
    lib_t=$(LD_LIBRARY_PATH=$libdir "$prefix/simulate" "$seed" 10,10,10 |
        sed -n 's/^time: \([^ ]*\) s$/\1/p')
    exe_t=$(cd "$prefix" && "$exe" simulate "$seed" --force 10,10,10 --json --out "$prefix/o" |
        sed -n 's/^ *"time": \([^,]*\),$/\1/p')
    same() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 == b + 0) }'; }
    same "$lib_t" "$exe_t" || fail "examples/simulate's time '$lib_t' is not zipopt's '$exe_t'"
    printf '[scene]\nname = bad\n[body]\nmasses = 1, -2\n' >"$prefix/bad.ini"
    LD_LIBRARY_PATH=$libdir "$prefix/simulate" "$prefix/bad.ini" 2>"$prefix/err" >/dev/null
    rc=$?
    [ $rc = 2 ] && grep -q "bad.ini:4: \[body\] masses" "$prefix/err" ||
        fail "examples/simulate on a bad scene: exit $rc, $(cat "$prefix/err")"
    # the Python module from its documented folder, the library by the system loader
    init=$(find "$prefix" -path '*/python*/zipopt/__init__.py')
    [ -n "$init" ] || fail "no Python module in lib/python3.X/dist-packages"
    if [ -n "$init" ] && "$py" -c 'import numpy' 2>/dev/null; then
        py_t=$(cd "$prefix" && PYTHONPATH=${init%/zipopt/__init__.py} LD_LIBRARY_PATH=$libdir \
            "$py" -c "import zipopt; print(repr(zipopt.simulate('$seed', [10, 10, 10]).time))")
        same "$py_t" "$exe_t" || fail "the installed module's time '$py_t' is not zipopt's '$exe_t'"
        # the module alone finds its library and scenes in its own prefix, from any folder,
        # and the installed notebook example runs there
        py_t=$(cd / && env -u LD_LIBRARY_PATH -u ZIPOPT_LIB PYTHONPATH=${init%/zipopt/__init__.py} \
            "$py" -c "import zipopt; print(repr(zipopt.simulate(zipopt.example_scene('seed.ini'), [10, 10, 10]).time))")
        same "$py_t" "$exe_t" || fail "the module without LD_LIBRARY_PATH: '$py_t', not '$exe_t'"
        nb=$prefix/share/zipopt/examples/notebook.py
        mkdir -p "$prefix/nb"
        (cd "$prefix/nb" && env -u LD_LIBRARY_PATH -u ZIPOPT_LIB PYTHONPATH=${init%/zipopt/__init__.py} \
            ZIPOPT_EVALS=60 MPLBACKEND=Agg "$py" "$nb" >"$prefix/nb/log" 2>&1) ||
            fail "the installed notebook example: $(tail -3 "$prefix/nb/log")"
    elif [ -n "$init" ]; then
        echo "check_install: numpy is missing (apt-get install python3-numpy): module not run"
    fi
fi

[ "$failures" = 0 ] || exit 1
echo "check_install: ok"
