/* The search's scans that every round runs whatever its strategies: the constant pushes as a
   line, and per-parameter lines through a point, each with zooms around its best local minima;
   every batch run in parallel and cut at the budget in its serial order. */
#ifndef ZP_SCAN_H
#define ZP_SCAN_H

#include "search_state.h"

/* what the lines of one search remember */
typedef struct zp_scan {
    double step[ZP_SCHED_MAX_PARAMS]; /* first polish step per parameter: the lines narrow it to
                                         a share of the survivable width they saw */
    double *lined; /* owned: the lines scanned, nlined rows of their origin's n parameters then
                      the parameter varied */
    int nlined, linecap;
} zp_scan;

/* sc with first polish steps of share of each parameter's range, no line scanned yet */
void zp_scan_init(zp_scan *sc, const zp_search_state *S, double share);
void zp_scan_free(zp_scan *sc);
/* the constant pushes as a line with zooms; the archive index of the hardest push (every
   parameter at its upper bound), -1 when the budget cut it */
int zp_scan_diag(zp_search_state *S);
/* per-parameter lines through origin, with zooms, repeated while a pass improves; a line
   scanned already is not repeated */
void zp_scan_lines(zp_search_state *S, zp_scan *sc, const double *origin, const zp_eval *origin_e);

#endif
