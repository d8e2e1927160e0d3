/* The search's parts shared between its files, not part of its interface: the state of one
   run (search.c), the scan that extends in order (scan.c) and the NLopt polish (polish.c). */
#ifndef ZP_SEARCH_INT_H
#define ZP_SEARCH_INT_H

#include <gsl/gsl_qrng.h>
#include <time.h>

#include "pool.h"
#include "search.h"

#define ZP_DISTINCT 0.02 /* points differ by this share of the box in some parameter */

/* every scanned point, in the serial order: where the polish starts come from */
typedef struct zp_archive {
    int n, cap;
    double *f;  /* owned, cap x n parameters */
    zp_eval *e; /* owned, cap */
} zp_archive;

/* one local polish: where it started and the best it reached */
typedef struct zp_polish_rec {
    double start[ZP_SCHED_MAX_PARAMS];
    double end[ZP_SCHED_MAX_PARAMS];
    zp_eval e;
    long n; /* simulations it spent */
    int at; /* archive index of its end, -1: not in the archive */
} zp_polish_rec;


typedef struct zp_search {
    const zp_objective *ob;
    const zp_search_opts *o;
    int n;                 /* parameters */
    const double *lo, *hi; /* borrowed, n */
    zp_pool *pool;         /* owned */
    zp_search_result *res;
    zp_archive a;
    long spent;                    /* simulations in the serial order: what the budget counts */
    int exhausted;                 /* some unit of work was cut short by the budget */
    double running;                /* s, the best time in the serial history */
    double step[ZP_SCHED_MAX_PARAMS];  /* first polish step per parameter: the survivable width */
    gsl_qrng *q;                   /* owned: the low-discrepancy sequence, extended in order */
    double shift[ZP_SCHED_MAX_PARAMS]; /* its seeded shift, share of the box */
    zp_polish_rec *pol;            /* owned, the polishes run, in order */
    int npol, polcap;
    double *lined; /* owned: origins of the lines scanned, nlined x n */
    int *lined_k;  /* owned: their parameter */
    int nlined, linecap;
    int bdiag;     /* archive index of the best constant push, -1: none yet */
    int diag_from; /* ... the last one polished, -1: none */
    int round;
    long round_cost; /* simulations of the costliest completed round */
    const char *phase;
    struct timespec t0;
    double last_report; /* s */
} zp_search;

double zp_search_since(const zp_search *S);
/* stopped by the caller or by max_time: nothing more is run */
int zp_search_stopped(const zp_search *S);
/* stopped, or the budget is spent */
int zp_search_halted(const zp_search *S);
/* a total order (feasible, score, then the parameters), so the best does not depend on which
   thread finished first */
int zp_search_ahead(const zp_eval *a, const double *fa, const zp_eval *b, const double *fb, int n);
/* one simulation from any thread: the shared counts and the best so far */
void zp_search_eval(zp_search *S, zp_sim *s, zp_result *r, const double *f, zp_eval *e);
/* an improvement of the serial history, `at` simulations into the search */
void zp_search_record(zp_search *S, long at, const zp_eval *e);
/* the progress callback, now and then or on an improvement */
void zp_search_report(zp_search *S, int improved);

/* scan.c: points in parallel, truncated at the budget in the serial order */
int zp_scan_batch(zp_search *S, const double *pts, int npt);
/* the constant pushes as a line with zooms; the archive index of the hardest push (every
   parameter at its upper bound), -1 when the budget cut it */
int zp_scan_diag(zp_search *S);
/* the next count points of the shifted low-discrepancy sequence */
int zp_scan_lds(zp_search *S, int count);
/* per-parameter lines through origin, with zooms, repeated while a pass improves */
void zp_scan_lines(zp_search *S, const double *origin, const zp_eval *origin_e);
const double *zp_archive_f(const zp_search *S, int i);
/* index of the point added, -1 when out of memory */
int zp_archive_add(zp_search *S, const double *f, const zp_eval *e);

/* islands.c: the near-survivable points of the archive (the NEAR_MAX best of those that finish
   within a few degrees of the margin), grouped into islands: a point joins the island of the
   nearest better point within MLSL's critical distance that no other mapped point separates
   from it. Islands come best first, each headed by its best point. */
typedef struct zp_island {
    int head; /* archive index of its best point */
    int npts; /* near points in it */
    int nfeas; /* of them, survivable */
} zp_island;
typedef struct zp_islands {
    int n;          /* islands */
    int nnear;      /* near points mapped */
    int *pt;        /* owned, nnear: their archive indices, best first */
    int *of;        /* owned, nnear: the island of each */
    zp_island *isl; /* owned, n */
} zp_islands;
/* 0, or -1 when out of memory (m empty) */
int zp_islands_map(const zp_search *S, zp_islands *m);
void zp_islands_free(zp_islands *m);

/* polish.c: local polishes from the starts, in parallel, with budgets fixed in order;
   diag: a one-variable polish of the constant push. ZP_OK or ZP_ERR_INPUT (NLopt refused). */
typedef struct zp_polish_job {
    const double *x0;   /* start, parameters */
    const double *step; /* first steps per variable */
    int diag;           /* one variable: the same share of the box for every parameter */
    long cap;           /* simulations it may spend */
    zp_polish_rec *out; /* the record filled */
} zp_polish_job;
zp_status zp_polish_batch(zp_search *S, int alg, const zp_polish_job *jobs, int njob, char *err,
                          size_t errlen);
/* an NLopt global algorithm for budget simulations, its points kept in the archive */
zp_status zp_polish_global(zp_search *S, int alg, long budget, char *err, size_t errlen);

#endif
