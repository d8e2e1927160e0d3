#!/bin/sh
# Every symbol the libraries export starts with zp_ (STYLE.md 3.3): lists the strays, fails on any.
# AddressSanitizer's ODR indicators (__odr_asan.<symbol>) are instrumentation, not exports.
# A shared library (*.so) exports only the public API, zipopt_ (include/zipopt.h).
status=0
for lib in "$@"; do
    case $lib in
    *.so*) nmflags="-D --defined-only" prefix=zipopt_ ;;
    *) nmflags="-g --defined-only" prefix=zp_ ;;
    esac
    strays=$(nm $nmflags "$lib" | awk 'NF == 3 {print $3}' | grep -v "^$prefix" | grep -v "^__odr_asan\\.$prefix")
    if [ -n "$strays" ]; then
        echo "$lib exports symbols without the $prefix prefix:" $strays
        status=1
    fi
done
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
