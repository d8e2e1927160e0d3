/* One leg of the search: a sequential run of simulations on one thread's workspace (a local
   polish, or a global algorithm that cannot run in parallel) over the variables a strategy
   sees, with a budget fixed before any leg of its batch starts, its own best and its
   improvements. Legs run in parallel; their counts, improvements and ends are folded into the
   state in their serial order, so a smaller budget cuts the same legs short and nothing depends
   on which thread ran which. */
#ifndef ZP_LEG_H
#define ZP_LEG_H

#include "search_state.h"

/* an improvement of a leg, `at` of its simulations in */
typedef struct zp_leg_imp {
    long at;
    zp_eval e;
} zp_leg_imp;

/* where a leg started and the best it reached */
typedef struct zp_leg_rec {
    double start[ZP_SCHED_MAX_PARAMS];
    double end[ZP_SCHED_MAX_PARAMS];
    zp_eval e;
    long n; /* simulations it spent */
    int at; /* archive index of its end, -1: not in the archive */
} zp_leg_rec;

typedef struct zp_leg {
    /* the problem as a strategy sees it */
    int nx; /* variables: the parameters, or 1 (one share of the box for every parameter) */
    double lo[ZP_SCHED_MAX_PARAMS], hi[ZP_SCHED_MAX_PARAMS]; /* the variables' bounds */
    double x0[ZP_SCHED_MAX_PARAMS];                          /* the start */
    const double *step; /* first steps per variable, NULL: the strategy's own */
    double xtol;        /* the variables' resolution: a polish may stop once they settle to it */
    long budget;        /* simulations it may spend */
    void *user;         /* the job's own, for the strategy that runs it */
    zp_search_state *S;
    /* set by a strategy that could not run the leg */
    int refused;
    char why[256];
    /* kept by zp_leg_eval */
    zp_sim *sim;
    zp_result *r;
    int diag;    /* the one variable is a share of the box */
    int archive; /* every point evaluated joins the archive */
    long n;      /* simulations so far */
    int have;    /* the last point evaluated: key, e (and its constraint's parts) */
    double key[ZP_SCHED_MAX_PARAMS];
    zp_eval e;
    int nparts; /* set by a strategy that holds the constraint's parts apart, before any run */
    double parts[ZP_OBJECTIVE_PARTS_MAX];
    double bar; /* s: the search's best time when the leg's batch began; only faster
                   improvements can be the search's, so only those are recorded */
    double bestf[ZP_SCHED_MAX_PARAMS]; /* the best so far, parameters */
    zp_eval best;
    /* its improvements that may be the search's, for the history: owned, freed by whoever
       ran the leg once folded */
    int nimp, imp_cap;
    zp_leg_imp *imp;
} zp_leg;

/* The evaluation at the leg's variables x (nx), simulated once for whatever the strategy asks
   of it there; NULL when the leg must stop: its budget is spent or the search stopped. */
const zp_eval *zp_leg_eval(zp_leg *leg, const double *x);

/* what a strategy is told for a point once its leg must stop (zp_leg_eval gave NULL): worse than
   the runs it ranks, so it moves nowhere near there */
double zp_leg_spent_score(const zp_leg *leg);

/* the parameters f (S->n) of the leg's variables x, inside the box */
void zp_leg_params(const zp_leg *leg, const double *x, double *f);
/* runs a strategy spent beside zp_leg_eval's (a sensitivity run, charged as the plain runs it
   costs) into the leg's count, as many as its budget holds: 0, or -1 when they did not all fit
   or the search stopped (the leg must stop) */
int zp_leg_charge(zp_leg *leg, long runs);

/* runs leg to its end on the calling thread; how: what the caller passed with it */
typedef void (*zp_leg_run)(const void *how, zp_leg *leg);

typedef struct zp_leg_job {
    const double *x0;   /* start, parameters */
    const double *step; /* first steps per variable, NULL: the strategy's own */
    int diag;           /* one variable: the same share of the box for every parameter */
    int archive;        /* every point it evaluates joins the archive (a leg run alone) */
    long cap;           /* simulations it may spend */
    void *user;         /* passed on to the leg */
    zp_leg_rec *out;    /* the record filled, may be NULL */
} zp_leg_job;

/* run(how, leg) for each job's leg, in parallel, with budgets fixed in order from what is
   left of S's; then each leg's improvements and simulations into S and its record out, in
   order. ZP_OK, ZP_ERR_NOMEM or ZP_ERR_INPUT (a leg refused: the last one's why in err). */
zp_status zp_leg_batch(zp_search_state *S, zp_leg_run run, const void *how, const zp_leg_job *jobs,
                       int njob, char *err, size_t errlen);

/* A polish inside a running leg (a global strategy's own, on the leg's workspace): run(how)
   from x0 (parameters) with first steps `step`, of at most cap simulations of what the leg
   has left. Its simulations and the improvements on the leg's best are the leg's, in order,
   so a smaller budget still cuts the same runs short; what it came to into out. 0, or -1 when
   the leg had nothing left to spend (out untouched). */
int zp_leg_polish_within(zp_leg *leg, zp_leg_run run, const void *how, const double *x0,
                         const double *step, long cap, zp_leg_rec *out);

#endif
