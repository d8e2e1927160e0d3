/* The warm restart (search.h): short polishes from what a search found, after the set it is
   held to grew. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "polishes.h"
#include "search.h"
#include "strategy.h"

/* design note: after the adversary adds a scenario the answer breaks by a hair, so the best of
   the grown set lies next to it (or next to another end nearly as fast): short polishes from
   there, with small first steps, find it at a fraction of a full search's cost */
#define WARM_BUDGET 60  /* simulations per warm polish */
#define WARM_STEP 0.002 /* its first step, share of the box */

#define WARM_ENDS ZP_POLISHES_ROUND /* starts from the answer and its good ends */
#define WARM_STARTS (WARM_ENDS + ZP_SEARCH_ISLANDS)

/* x may start a warm polish: distinct from the n starts before it */
static int warm_new(const zp_search_state *S, const double *x, const double **xs, int n) {
    for (int i = 0; i < n; i++) {
        if (!zp_search_state_distinct(S, x, xs[i])) {
            return 0;
        }
    }
    return 1;
}

/* the warm polishes' starts: the answer, the good ends distinct from it, then the fastest
   point of each of the best islands of the map (the grown set may break the answer's island
   where a slower one still holds) */
static int warm_starts(const zp_search_state *S, const zp_search_result *prev, const double **x) {
    int n = 0;
    x[n++] = prev->force;
    for (int i = 0; i < prev->nends && n < WARM_ENDS; i++) {
        if (warm_new(S, prev->ends[i], x, n) &&
            prev->ends_time[i] <= prev->best.time * (1 + ZP_SEARCH_WARM_REACH)) {
            x[n++] = prev->ends[i];
        }
    }
    for (int i = 0; i < prev->nshown && n < WARM_STARTS; i++) {
        if (warm_new(S, prev->island_force[i], x, n)) {
            x[n++] = prev->island_force[i];
        }
    }
    return n;
}

/* the previous best constant push kept when it survives the grown set, else polished again */
static int warm_base(zp_search_state *S, const zp_search_result *prev, zp_leg_job *job,
                     double *step) {
    if (!prev->base_found) {
        return 0;
    }
    zp_eval e;
    zp_pool_eval(S->pool, S->ob, 1, prev->base_p, &e, NULL, NULL);
    S->spent++; /* counted in res->evals after the polishes (the first counted sets the best) */
    if (zp_objective_feasible(&e)) {
        zp_search_state_base(S, prev->base_p, &e);
        return 0;
    }
    *step = ZP_POLISHES_PUSH_STEP;
    *job =
        (zp_leg_job){.x0 = prev->base_p, .step = step, .diag = 1, .cap = ZP_POLISHES_PUSH_BUDGET};
    return 1;
}

static zp_status warm(zp_search_state *S, const zp_search_result *prev, char *err, size_t errlen) {
    zp_leg_rec rec[WARM_STARTS + 1];
    zp_leg_job jobs[WARM_STARTS + 1];
    double step[ZP_SCHED_MAX_PARAMS], diag_step;
    for (int k = 0; k < S->n; k++) {
        step[k] = WARM_STEP * (S->hi[k] - S->lo[k]);
    }
    S->phase = "polish";
    int nj = warm_base(S, prev, &jobs[0], &diag_step);
    const double *x[WARM_STARTS];
    int nstart = warm_starts(S, prev, x);
    for (int i = 0; i < nstart; i++) {
        jobs[nj++] = (zp_leg_job){.x0 = x[i], .step = step, .cap = WARM_BUDGET};
    }
    for (int i = 0; i < nj; i++) {
        jobs[i].out = &rec[i];
    }
    const zp_strategy *local = zp_search_algo_get(S->o->algo)->local;
    zp_status st = zp_leg_batch(S, local->polish, local, jobs, nj, err, errlen);
    int base = nj > nstart;
    S->res->evals += prev->base_found;
    if (base && rec[0].n > 0 && zp_objective_feasible(&rec[0].e)) {
        zp_search_state_base(S, rec[0].end, &rec[0].e);
    }
    zp_polishes_ends(&(zp_polishes){.rec = rec + base, .n = nstart}, S);
    return st;
}

/* the evidence of convergence stays the full search's: its polishes, what they reached */
static void keep_evidence(zp_search_result *res, const zp_search_result *prev) {
    res->nrounds = prev->nrounds;
    res->nbasins = prev->nbasins;
    res->nreached = prev->nreached;
    res->converged = prev->converged;
    res->last_gain = prev->last_gain;
    res->nminima = prev->nminima;
    res->unseen = prev->unseen;
    res->help_evals = prev->help_evals;
    res->npops = prev->npops;
    res->pops_best = prev->pops_best;
    res->nwindows = prev->nwindows;
    res->npinned = prev->npinned;
    res->nislands = prev->nislands;
    res->npolished = prev->npolished;
    res->nshown = prev->nshown;
    memcpy(res->island_time, prev->island_time, sizeof res->island_time);
    memcpy(res->island_force, prev->island_force, sizeof res->island_force);
    memcpy(res->island_pts, prev->island_pts, sizeof res->island_pts);
    res->nhist = prev->nhist;
    res->hist_halvings = prev->hist_halvings;
    memcpy(res->hist, prev->hist, sizeof *res->hist * prev->nhist);
}

zp_status zp_search_warm(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                         const double *hi, const zp_search_opts *o, zp_search_result *res,
                         char *err, size_t errlen) {
    zp_search_result *prev = malloc(sizeof *prev);
    if (!prev) {
        snprintf(err, errlen, "out of memory for the warm restart");
        return ZP_ERR_NOMEM;
    }
    *prev = *res;
    zp_search_state S;
    zp_search_state_begin(&S, ob, lo, hi, o, res);
    zp_status st = zp_search_state_start(&S, so, err, errlen);
    if (st == ZP_OK) {
        st = warm(&S, prev, err, errlen);
    }
    keep_evidence(res, prev);
    zp_search_state_end(&S);
    res->budget_out = prev->budget_out;
    res->timed_out = prev->timed_out;
    res->nstarts = prev->nstarts;
    res->evals += prev->evals;
    res->nfeasible += prev->nfeasible;
    res->nfailed += prev->nfailed;
    res->wall_s += prev->wall_s;
    free(prev);
    return st;
}
