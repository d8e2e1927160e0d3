/* What a search is asked and what it gives back: its options, the progress it reports and its
   result. Plain types shared by the entry points (search.h) and the search's state
   (search_state.h), which sits below them. */
#ifndef ZP_SEARCH_TYPES_H
#define ZP_SEARCH_TYPES_H

#include <signal.h>

#include "objective.h"

#define ZP_SEARCH_HIST 1024  /* improvements kept in the history, thinned by half when full */
#define ZP_SEARCH_REACH 1e-4 /* a polish ending this close (relative time) reached the best */
#define ZP_SEARCH_CONV 1e-6  /* a round improving the best less than this (relative) converged */
#define ZP_SEARCH_ENDS 4     /* survivable polish ends kept for a warm restart */
#define ZP_SEARCH_ISLANDS 4  /* islands reported, best first */
#define ZP_SEARCH_UNSEEN                                                                           \
    0.5 /* expected unvisited basins below which more budget is unlikely                           \
           to help */

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
    int found;                         /* a survivable schedule was found */
    double force[ZP_SCHED_MAX_PARAMS]; /* the best parameters (N per section) or closest */
    zp_eval best;
    int base_found;    /* a survivable constant push was found */
    double base_force; /* N, the best constant push */
    zp_eval base;
    double base_p[ZP_SCHED_MAX_PARAMS]; /* its parameters */
    int nends;                          /* distinct survivable polish ends, best first */
    double ends[ZP_SEARCH_ENDS][ZP_SCHED_MAX_PARAMS];
    double ends_time[ZP_SEARCH_ENDS]; /* s, their finish times */
    long evals;                       /* simulations spent */
    long nfeasible, nfailed;          /* runs that survived, runs the integrator gave up on */
    int nthreads, nstarts;            /* workspaces used, local polishes run */
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
    int npops;        /* populations the global strategy evolves beside the polishes (0: none) */
    double pops_best; /* s, the fastest survivable run of those populations (INFINITY: none) */
    long nwindows;    /* window searches of a population's best schedule, the rest held */
    long npinned;     /* bang-bang searches from the map's best (pinned.h) */
    int nislands;     /* islands of the map (the best near-survivable points, islands.c) */
    int npolished;    /* of them, islands a polish ended in */
    int nshown;       /* survivable islands below, best first */
    double island_time[ZP_SEARCH_ISLANDS]; /* s, each one's fastest survivable point */
    double island_force[ZP_SEARCH_ISLANDS][ZP_SCHED_MAX_PARAMS];
    int island_pts[ZP_SEARCH_ISLANDS]; /* survivable points mapped in it: its size */
    int nhist;
    int hist_halvings; /* times the full history kept only the later of each pair */
    zp_search_hist hist[ZP_SEARCH_HIST];
} zp_search_result;

#endif
