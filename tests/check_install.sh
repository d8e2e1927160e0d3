#!/bin/sh
# cmake --install into a temporary prefix puts the program, the man page zipopt(1), the bash
# completion and the example scenes in place, and the completion offers what --help documents.
# usage: check_install.sh BUILD_DIR CMAKE
set -u
build=$1
cmake=$2
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
[ "$failures" = 0 ] || exit 1

# the installed program runs an installed scene
"$exe" check "$prefix/share/zipopt/scenes/seed.ini" >/dev/null || fail "zipopt check seed.ini"

# the man page is zipopt(1) and documents every command's options ('-' is '\-' in roff)
grep -q '^\.TH ZIPOPT "*1' "$man" || fail "the man page is not zipopt(1)"
manual=$(sed 's/\\-/-/g' "$man")

# COMPREPLY of the installed completion for the words given (the last is being completed)
offers() {
    PATH="$prefix/bin:$PATH" bash -c 'source "$1"; shift; COMP_WORDS=("$@");
        COMP_CWORD=$(($# - 1)); _zipopt; echo " ${COMPREPLY[*]} "' _ "$comp" "$@"
}

got=$(offers zipopt "")
for c in simulate check landscape sweep bench; do
    case $got in *" $c "*) ;; *) fail "zipopt <TAB> does not offer $c: $got" ;; esac
done
[ "$(offers zipopt sim)" = " simulate " ] || fail "zipopt sim<TAB>: $(offers zipopt sim)"
[ "$(offers zipopt bench "")" = " trade " ] || fail "zipopt bench <TAB>: $(offers zipopt bench "")"

# every option a command's --help names is offered and is in the man page
for cmd in simulate check landscape sweep "bench trade" x.ini; do
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

[ "$failures" = 0 ] || exit 1
echo "check_install: ok"
