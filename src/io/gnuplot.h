/* The one gnuplot runner: draws scripts inside a transaction's private folder (out_file.h),
   so the figures are committed with the rest of the command's files or not at all. */
#ifndef ZP_GNUPLOT_H
#define ZP_GNUPLOT_H

#include <stddef.h>

#include "tx.h"

#include <sys/types.h>

#define ZP_GNUPLOT_MAX_SCRIPTS 16
#define ZP_GNUPLOT_MAX_PROC 8
/* the line each process prints to its log before a script (the one that failed is the last) */
#define ZP_GNUPLOT_MARK "zipopt: drawing "

/* Scripts being drawn: one gnuplot process per core (at most ZP_GNUPLOT_MAX_PROC), process g
   drawing scripts g, g + nproc, ... in a fresh session each. */
typedef struct zp_gnuplot_job {
    const char *script[ZP_GNUPLOT_MAX_SCRIPTS]; /* borrowed names in the private folder */
    int n, nproc, running;
    pid_t pid[ZP_GNUPLOT_MAX_PROC];
    int missing; /* 1: gnuplot is not on PATH; nothing runs */
} zp_gnuplot_job;

/* The cores this process may run on (its CPU affinity), at least 1. */
int zp_gnuplot_cores(void);
/* 1 when an executable named prog is on PATH. */
int zp_gnuplot_have(const char *prog);
/* Closes the transaction's open files, then starts gnuplot on the n scripts (names in the
   private folder, kept by the caller until the wait) in nproc processes (0: one per core of
   zp_gnuplot_cores), each in its own process group (a Ctrl-C at the terminal is the transaction's
   to handle, not gnuplot's) and registered with the transaction (its abort ends them). When gnuplot
   is not on PATH, j->missing = 1 and ZP_OK. A write error or a failed start: ZP_ERR_IO with why in
   err; the caller then aborts the transaction. */
zp_status zp_gnuplot_start(zp_tx *t, const char *const *scripts, int n, int nproc,
                           zp_gnuplot_job *j, char *err, size_t errlen);
/* Waits for j's processes, then checks that every image a script names (`set output
   'NAME'`) is whole (zp_gnuplot_whole): gnuplot ends with 0 when the disk fills under one.
   A failing script or an image not whole: ZP_ERR_IO with the script's name and its part of
   the log (gnuplot's own message), or the image's name, in err; the caller then aborts the
   transaction. */
zp_status zp_gnuplot_wait(zp_tx *t, zp_gnuplot_job *j, char *err, size_t errlen);
/* 1 when the file name in the folder dirfd is a whole image by its extension: a PNG ending
   in its IEND chunk, a GIF in its trailer, an SVG in its closing tag, an MP4 whose boxes
   fill it exactly; another extension: not empty. 0 when missing, cut short or not a file. */
int zp_gnuplot_whole(int dirfd, const char *name);
/* Both: *missing = 1 when gnuplot is not on PATH. */
zp_status zp_gnuplot_run(zp_tx *t, const char *const *scripts, int n, int *missing, char *err,
                         size_t errlen);

#endif
