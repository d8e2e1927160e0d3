/* The state of one search, in the manner of GSL's gsl_multimin_fminimizer: the box, the budget
   counted in the serial order, the one entry point through which every simulation runs, the
   archive of the points evaluated and the progress reported. The scan, the legs, the islands
   and the strategies build on it; it knows none of them. */
#ifndef ZP_SEARCH_STATE_H
#define ZP_SEARCH_STATE_H

#include <time.h>

#include "pool.h"
#include "search_types.h"

#define ZP_DISTINCT 0.02 /* points differ by this share of the box in some parameter */

/* every point scanned (and each polish's end), in the serial order: where the polish starts
   come from */
typedef struct zp_archive {
    int n, cap;
    double *f;  /* owned, cap x n parameters */
    zp_eval *e; /* owned, cap */
} zp_archive;

typedef struct zp_search_state {
    const zp_objective *ob;
    const zp_search_opts *o;
    const zp_sim_opts *so; /* borrowed: the runs' options, for a strategy's runs of its own */
    int n;                 /* parameters */
    const double *lo, *hi; /* borrowed, n */
    zp_pool *pool;         /* owned */
    zp_search_result *res;
    zp_archive a;
    long spent;        /* simulations in the serial order: what the budget counts */
    int exhausted;     /* some unit of work was cut short by the budget */
    double running;    /* s, the best time in the serial history */
    int round;         /* 0-based, reported with the progress */
    const char *phase; /* "scan" or "polish", reported with the progress */
    struct timespec t0;
    double last_report; /* s */
} zp_search_state;

/* S over res (zeroed), its clock started; nothing allocated yet */
void zp_search_state_begin(zp_search_state *S, const zp_objective *ob, const double *lo,
                           const double *hi, const zp_search_opts *o, zp_search_result *res);
/* the workspaces, one per thread (and their helpers with a scenario set): ZP_OK, or
   ZP_ERR_NOMEM with why in err */
zp_status zp_search_state_start(zp_search_state *S, const zp_sim_opts *so, char *err,
                                size_t errlen);
/* how the search ended into res, and S freed */
void zp_search_state_end(zp_search_state *S);

/* stopped by the caller or by max_time: nothing more is run */
int zp_search_state_stopped(const zp_search_state *S);
/* stopped, or the budget is spent */
int zp_search_state_halted(const zp_search_state *S);
/* a total order (feasible, score, then the parameters), so the best does not depend on which
   thread finished first */
int zp_search_state_ahead(const zp_eval *a, const double *fa, const zp_eval *b, const double *fb,
                          int n);
/* archive indices idx[n] sorted best first by that order (ties: the lower index); 0, or -1 when
   out of memory (idx unchanged) */
int zp_search_state_rank(const zp_search_state *S, int *idx, int n);
/* a and b differ by more than ZP_DISTINCT of the box in some parameter: S's box, or the box
   [lo, hi] of n parameters */
int zp_search_state_distinct(const zp_search_state *S, const double *a, const double *b);
int zp_search_state_apart(int n, const double *lo, const double *hi, const double *a,
                          const double *b);

/* one simulation of parameters f from any thread (s, r: its workspace), with the constraint's
   parts when parts is not NULL (zp_objective_parts_count): the shared counts and the best so far */
void zp_search_state_eval(zp_search_state *S, zp_sim *s, zp_result *r, const double *f, zp_eval *e,
                          double *parts);
/* npt points (rows of n parameters) in parallel, cut at the budget in their serial order, into
   the archive; how many ran */
int zp_search_state_batch(zp_search_state *S, const double *pts, int npt);
/* an improvement of the serial history, `at` simulations into the search */
void zp_search_state_record(zp_search_state *S, long at, const zp_eval *e);

/* the result's baseline: the constant push f, evaluated e */
void zp_search_state_base(zp_search_state *S, const double *f, const zp_eval *e);

/* the parameters of archive point i */
const double *zp_search_state_point(const zp_search_state *S, int i);
/* index of the point added to the archive, -1 when out of memory */
int zp_search_state_add(zp_search_state *S, const double *f, const zp_eval *e);

#endif
