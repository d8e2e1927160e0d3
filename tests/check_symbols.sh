#!/bin/sh
# Every symbol the libraries export starts with zp_ (STYLE.md 3.3): lists the strays, fails on any.
# AddressSanitizer's ODR indicators (__odr_asan.<symbol>) are instrumentation, not exports.
status=0
for lib in "$@"; do
    strays=$(nm -g --defined-only "$lib" | awk 'NF == 3 {print $3}' | grep -v '^zp_' | grep -v '^__odr_asan\.zp_')
    if [ -n "$strays" ]; then
        echo "$lib exports symbols without the zp_ prefix:" $strays
        status=1
    fi
done
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
