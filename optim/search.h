/* The search (issue 4 items 2, 3, 6): the fastest survivable schedule of per-section forces
   within [drive] min, max, by a global phase and a local polish from several starts. */
#ifndef ZP_SEARCH_H
#define ZP_SEARCH_H

#include <signal.h>

#include "objective.h"

#define ZP_SEARCH_HIST 256 /* improvements kept in the history */

/* The strategies the search offers: a global phase, then a local polish. */
typedef struct zp_search_algo {
    const char *name; /* as typed after --algorithm */
    const char *doc;  /* one line for --help */
    int global;       /* nlopt_algorithm of the global phase, or -1: the parallel scan */
    int local;        /* nlopt_algorithm of the polish */
} zp_search_algo;

int zp_search_algo_count(void);
const zp_search_algo *zp_search_algo_get(int i);
int zp_search_algo_find(const char *name); /* -1 if unknown */

/* Best so far, as the progress display and the checkpoint see it. */
typedef struct zp_search_progress {
    long evals;        /* simulations so far */
    double wall_s;     /* s since the search began */
    int found;         /* a survivable schedule is known */
    double time;       /* s, its finish time */
    const double *force; /* borrowed, N per section: the best so far */
} zp_search_progress;

typedef struct zp_search_opts {
    int algo;           /* zp_search_algo index */
    long max_evals;     /* simulations the search may spend */
    unsigned long seed; /* same seed, same answer, bit for bit */
    int nthreads;       /* workspaces = OpenMP threads; 0: OpenMP's default */
    volatile sig_atomic_t *stop; /* borrowed, may be NULL: nonzero stops the search */
    /* called, serialised, when the best improves (improved = 1) and now and then (0) */
    void (*progress)(void *user, const zp_search_progress *p, int improved);
    void *user;
} zp_search_opts;

typedef struct zp_search_hist {
    long evals;  /* simulations spent, counting the phases and restarts one after another */
    double time; /* s, the best survivable finish time by then */
} zp_search_hist;

typedef struct zp_search_result {
    int found;                       /* a survivable schedule was found */
    double force[ZP_MAX_SECTIONS];   /* N, the best schedule (or the best-scoring one) */
    zp_eval best;
    int base_found;                  /* a survivable constant push was found */
    double base_force;               /* N, the best constant push */
    zp_eval base;
    long evals;                      /* simulations spent */
    long nfeasible, nfailed;         /* runs that survived, runs the integrator gave up on */
    int nthreads, nstarts;           /* workspaces used, local polishes run */
    double wall_s;
    int interrupted;                 /* stopped by opts.stop before the end */
    int nhist;
    zp_search_hist hist[ZP_SEARCH_HIST];
} zp_search_result;

/* Searches [lo, hi]^nsec (N) for the fastest schedule that keeps ob's limit. Creates one
   workspace per thread from (m, so) before any parallel work. ZP_OK, or ZP_ERR_NOMEM /
   ZP_ERR_INPUT (an NLopt setup failure) with why in err. */
zp_status zp_search_run(const zp_objective *ob, const zp_sim_opts *so, double lo, double hi,
                        const zp_search_opts *o, zp_search_result *res, char *err,
                        size_t errlen);

#endif
