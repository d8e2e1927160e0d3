/* The best constant push (every parameter at the same share of its range), found apart from
   the search for the report's baseline. The search's own pushes (49 points and two zooms
   around the best two local minima) miss survivable bands narrower than their spacing: on
   the seed they kept 27.69 N, 15.03 s, where 32.8 to 33.45 N survives with the margin and
   finishes in 14.63 s. */
#ifndef ZP_PUSH_SCAN_H
#define ZP_PUSH_SCAN_H

#include "objective.h"

/* Grid points of the scan: a quarter of the search's budget, within these bounds (on the seed
   1250 points, 0.4 N apart over [0, 500] N). */
#define ZP_PUSH_SCAN_MIN 401
#define ZP_PUSH_SCAN_MAX 2001
#define ZP_PUSH_SCAN_ISLANDS 4 /* the fastest islands whose fast edge is bisected */
#define ZP_PUSH_SCAN_BISECT 12 /* bisections of each, down to 1/4096 of the grid's spacing */

typedef struct zp_push_scan {
    int found;    /* a push survived with the margin and [limits] */
    double share; /* of every parameter's range: p_k = lo_k + share (hi_k - lo_k) */
    double p[ZP_SCHED_MAX_PARAMS];
    zp_eval e;  /* its evaluation */
    int npts;   /* grid points */
    long evals; /* simulations spent */
} zp_push_scan;

/* Grid points for a search budget of max_evals simulations. */
int zp_push_scan_points(long max_evals);

/* The fastest push that survives under ob (nominal, its set's scenarios too when it has one),
   over npts evenly spaced shares of [lo, hi] run with so on nthreads (0: OpenMP's default),
   then each of the ZP_PUSH_SCAN_ISLANDS fastest runs of survivable grid points bisected
   towards the dying neighbour on its faster side. The same bits on any thread count.
   ZP_OK or ZP_ERR_NOMEM. */
zp_status zp_push_scan_run(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                           const double *hi, int npts, int nthreads, zp_push_scan *out);

#endif
