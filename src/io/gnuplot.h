/* The one gnuplot runner: draws scripts inside a transaction's private folder (out_file.h),
   so the figures are committed with the rest of the command's files or not at all. */
#ifndef ZP_GNUPLOT_H
#define ZP_GNUPLOT_H

#include <stddef.h>

#include "out_file.h"

/* 1 when an executable named prog is on PATH. */
int zp_gnuplot_have(const char *prog);
/* Closes the transaction's open files, then runs gnuplot on each of the n scripts (names in
   the private folder) a few at a time, each in its own process group (a Ctrl-C at the
   terminal is the transaction's to handle, not gnuplot's). When gnuplot is not on PATH,
   *missing = 1 and ZP_OK. A write error or a failing script: ZP_ERR_IO with the cause
   (gnuplot's own message) in err; the caller then aborts the transaction. */
zp_status zp_gnuplot_run(zp_tx *t, const char *const *scripts, int n, int *missing, char *err,
                         size_t errlen);

#endif
