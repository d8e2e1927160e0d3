/* A set of figures made aside (CLI.md "Files", STYLE 3.4): data files and gnuplot scripts are
   written to a hidden folder inside the output folder, gnuplot draws there, and only then is
   every file renamed into the output folder. Nothing partial is left behind. */
#ifndef ZP_GNUPLOT_H
#define ZP_GNUPLOT_H

#include <stddef.h>
#include <stdio.h>

#include "diag.h"

#define ZP_GNUPLOT_MAX_FILES 64

typedef struct zp_gnuplot {
    char dir[1024]; /* the output folder */
    char tmp[1100]; /* the hidden folder the figures are made in */
    int nfile, nscript;
    FILE *f[ZP_GNUPLOT_MAX_FILES];          /* owned until zp_gnuplot_finish/abort */
    char script[ZP_GNUPLOT_MAX_FILES][128]; /* file names inside tmp, for gnuplot to run */
} zp_gnuplot;

/* Creates dir (and parents) and a fresh hidden folder in it. ZP_ERR_IO with why in err. */
zp_status zp_gnuplot_begin(zp_gnuplot *g, const char *dir, char *err, size_t errlen);
/* Opens name for writing in the hidden folder (closed by finish or abort); script = 1 marks it
   as a gnuplot script to run. NULL with why in err. */
FILE *zp_gnuplot_open(zp_gnuplot *g, const char *name, int script, char *err, size_t errlen);
/* 1 when an executable named prog is on PATH. */
int zp_gnuplot_have(const char *prog);
/* Closes the files and runs gnuplot on every script inside the hidden folder (a few at a
   time), then renames every file into the output folder. When gnuplot is not on PATH the data
   and scripts are still moved and *missing is set to 1 (ZP_OK). A write error, a gnuplot error
   or a failed rename moves nothing more: ZP_ERR_IO with the cause (gnuplot's own message) in
   err. The hidden folder is always removed. */
zp_status zp_gnuplot_finish(zp_gnuplot *g, int *missing, char *err, size_t errlen);
/* Removes the hidden folder and everything in it: nothing is written. */
void zp_gnuplot_abort(zp_gnuplot *g);

#endif
