/* The search: the fastest survivable schedule of parameters within bounds, in rounds of a
   scan that extends in order and local polishes, so a larger budget never gives a worse answer. */
#ifndef ZP_SEARCH_H
#define ZP_SEARCH_H

#include <signal.h>

#include "objective.h"

#define ZP_SEARCH_HIST 256   /* improvements kept in the history */
#define ZP_SEARCH_REACH 1e-4 /* a polish ending this close (relative time) reached the best */
#define ZP_SEARCH_CONV 1e-6  /* a round improving the best less than this (relative) converged */
#define ZP_SEARCH_ENDS 4     /* survivable polish ends kept for a warm restart */
#define ZP_SEARCH_ISLANDS 4  /* islands reported, best first */
#define ZP_SEARCH_UNSEEN 0.5 /* expected unvisited basins below which more budget is unlikely
                                to help */

#define ZP_SEARCH_SCAN -1

/* The strategies the search offers: a global phase, then a local polish. */
typedef struct zp_search_algo {
    const char *name; /* as typed after --algorithm */
    const char *doc;  /* one line for --help */
    int global;       /* nlopt_algorithm of the global phase, or ZP_SEARCH_SCAN: the parallel
                         scan */
    int local;        /* nlopt_algorithm of the polish */
} zp_search_algo;

int zp_search_algo_count(void);
const zp_search_algo *zp_search_algo_get(int i);
int zp_search_algo_find(const char *name); /* -1 if unknown */

/* Best so far, as the progress display and the checkpoint see it. */
typedef struct zp_search_progress {
    const char *phase;   /* "scan" or "polish" */
    int round;           /* 0-based round of scan and polish */
    long evals;          /* simulations so far */
    long budget;         /* simulations the search may spend */
    double wall_s;       /* s since the search began */
    int found;           /* a survivable schedule is known */
    double time;         /* s, its finish time */
    const double *force; /* borrowed, N per section: the best so far */
    int restart;         /* 0: the search; k > 0: the robust search's k-th restart, after its
                            adversary added a k-th scenario (zp_search_opts.restart) */
} zp_search_progress;

typedef struct zp_search_opts {
    int algo;           /* zp_search_algo index */
    long max_evals;     /* simulations the search may spend */
    double max_time;    /* s of wall time the search may spend, 0: no limit (not reproducible) */
    unsigned long seed; /* same seed, same answer, bit for bit */
    int nthreads;       /* workspaces = OpenMP threads; 0: OpenMP's default */
    int full_budget;    /* 1: rounds go on after convergence, until the budget or the rounds
                           run out (a check of the convergence claim) */
    volatile sig_atomic_t *stop; /* borrowed, may be NULL: nonzero stops the search */
    /* called, serialised, when the best improves (improved = 1) and now and then (0) */
    void (*progress)(void *user, const zp_search_progress *p, int improved);
    void *user;
    int restart; /* passed to progress: which restart of the robust search this is, 0 the first */
} zp_search_opts;

typedef struct zp_search_hist {
    long evals;  /* simulations spent, counting the phases and restarts one after another */
    double time; /* s, the best survivable finish time by then */
} zp_search_hist;

typedef struct zp_search_result {
    int found;                     /* a survivable schedule was found */
    double force[ZP_SCHED_MAX_PARAMS]; /* the best parameters (N per section) or closest */
    zp_eval best;
    int base_found;    /* a survivable constant push was found */
    double base_force; /* N, the best constant push */
    zp_eval base;
    double base_p[ZP_SCHED_MAX_PARAMS]; /* its parameters */
    int nends;                          /* distinct survivable polish ends, best first */
    double ends[ZP_SEARCH_ENDS][ZP_SCHED_MAX_PARAMS];
    double ends_time[ZP_SEARCH_ENDS]; /* s, their finish times */
    long evals;              /* simulations spent */
    long nfeasible, nfailed; /* runs that survived, runs the integrator gave up on */
    int nthreads, nstarts;   /* workspaces used, local polishes run */
    double wall_s;
    int interrupted; /* stopped by opts.stop before the end */
    /* convergence evidence */
    int nrounds;      /* rounds of scan and polish completed */
    int nbasins;      /* distinct survivable schedules the polishes ended at */
    int nreached;     /* polishes that ended within ZP_SEARCH_REACH of the best time */
    int converged;    /* a completed round after the first improved the best by < ZP_SEARCH_CONV */
    int budget_out;   /* max_evals ran out before convergence */
    int timed_out;    /* max_time ran out before convergence */
    double last_gain; /* relative improvement of the best in the last completed round */
    int nminima;      /* distinct minima the polishes ended at, survivable or not */
    double unseen;    /* Boender-Rinnooy Kan: expected basins not yet found (INFINITY: too few
                         polishes to say) */
    long help_evals;  /* simulations, about the budget that would let the search converge */
    int nislands;     /* islands of the map (the best near-survivable points, islands.c) */
    int npolished;    /* of them, islands a polish ended in */
    int nshown;       /* survivable islands below, best first */
    double island_time[ZP_SEARCH_ISLANDS]; /* s, each one's fastest survivable point */
    double island_force[ZP_SEARCH_ISLANDS][ZP_SCHED_MAX_PARAMS];
    int island_pts[ZP_SEARCH_ISLANDS];     /* survivable points mapped in it: its size */
    int nhist;
    zp_search_hist hist[ZP_SEARCH_HIST];
} zp_search_result;

/* The default budget for n parameters: ZP_SCENE_EVALS_PER_SECTION simulations each. */
long zp_search_default_budget(int n);

/* Searches the box [lo[k], hi[k]] (one per section, N) for the fastest schedule that keeps
   ob's limit. Creates one workspace per thread from (m, so) before any parallel work. Every
   simulation a smaller max_evals would run is also run with a larger one (same seed), so the
   best is never worse; the answer does not depend on the number of threads. ZP_OK, or
   ZP_ERR_NOMEM / ZP_ERR_INPUT (an NLopt setup failure) with why in err. */
zp_status zp_search_run(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                        const double *hi, const zp_search_opts *o, zp_search_result *res, char *err,
                        size_t errlen);

/* A warm restart after ob's scenario set grew: res holds a search's result for the smaller set
   (zp_search_run's or this one's) and receives this one's. COBYLA (the algorithm's polish) runs
   from the answer, from the distinct survivable polish ends within ZP_SEARCH_WARM_REACH of its
   time and from the fastest point of each island res reports, each with a budget fixed in
   advance, all in parallel; the best constant push is kept while it survives the grown set,
   else polished again from where it was. found = 0: no start was made survivable (the caller
   searches afresh). The answer, its counts (added to the earlier ones) and the ends are the
   warm ones; the evidence of convergence (rounds, polishes, basins, islands, history) stays the
   full search's. Same seed and set, same bits on any thread count. */
#define ZP_SEARCH_WARM_REACH 1e-3
zp_status zp_search_warm(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                         const double *hi, const zp_search_opts *o, zp_search_result *res,
                         char *err, size_t errlen);

#endif
