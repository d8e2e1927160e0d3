/* NLopt's algorithms as the search's strategies (strategies.def): its local ones polish a leg;
   its global ones are sequential, so each runs as one leg of its own in the first round, its
   points kept in the archive, and later rounds extend the scan's sequence. The objective and
   the constraint at a point come from one simulation (zp_leg_eval). */
#include <math.h>
#include <nlopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "strategy.h"

#define FTOL 1e-6            /* s: a polish stops when the finish time settles to this */
#define GLOBAL_PER_PARAM 500 /* simulations of a global algorithm per parameter */

/* one NLopt optimisation over a leg */
typedef struct nl_run {
    zp_leg *leg;
    nlopt_opt opt;
    int alg;     /* nlopt_algorithm */
    int penalty; /* minimise the penalised score; else the time under the constraint */
} nl_run;

static int takes_constraint(int alg) {
    return alg == NLOPT_LN_COBYLA || alg == NLOPT_GN_ISRES;
}

/* the leg's evaluation at x; NULL: NLopt stops at its next check and until then sees a point
   worse than any run */
static const zp_eval *nl_eval(nl_run *c, const double *x) {
    const zp_eval *e = zp_leg_eval(c->leg, x);
    if (!e) {
        nlopt_force_stop(c->opt);
    }
    return e;
}

static double nl_obj(unsigned n, const double *x, double *grad, void *data) {
    nl_run *c = data;
    (void)n;
    (void)grad;
    const zp_eval *e = nl_eval(c, x);
    return !e ? zp_leg_spent_score(c->leg) : c->penalty ? e->score : e->obj;
}

static double nl_cons(unsigned n, const double *x, double *grad, void *data) {
    (void)n;
    (void)grad;
    const zp_eval *e = nl_eval(data, x);
    return e ? e->cons : 360;
}

/* COBYLA holds the constraint's parts apart (zp_objective_parts_count); each a point's, of its one
   evaluation */
static void nl_parts(unsigned m, double *result, unsigned n, const double *x, double *grad,
                     void *data) {
    (void)n;
    (void)grad;
    nl_run *c = data;
    if (nl_eval(c, x)) {
        memcpy(result, c->leg->parts, sizeof *result * m);
        return;
    }
    for (unsigned k = 0; k < m; k++) { /* no run: NLopt is stopping (nl_eval) */
        result[k] = 360;
    }
}

/* bounds, objective, constraint, tolerances and steps of opt */
static nlopt_result setup(nl_run *c, nlopt_opt opt) {
    const zp_leg *leg = c->leg;
    nlopt_result st = nlopt_set_lower_bounds(opt, leg->lo);
    if (st > 0) {
        st = nlopt_set_upper_bounds(opt, leg->hi);
    }
    if (st > 0) {
        st = nlopt_set_min_objective(opt, nl_obj, c);
    }
    int parts = c->alg == NLOPT_LN_COBYLA ? zp_objective_parts_count(leg->S->ob) : 1;
    if (st > 0 && !c->penalty && parts > 1) {
        const double tol[ZP_OBJECTIVE_PARTS_MAX] = {0};
        c->leg->nparts = parts;
        st = nlopt_add_inequality_mconstraint(opt, (unsigned)parts, nl_parts, c, tol);
    } else if (st > 0 && !c->penalty) {
        st = nlopt_add_inequality_constraint(opt, nl_cons, c, 0);
    }
    if (st > 0 && c->alg == NLOPT_G_MLSL_LDS) {
        nlopt_opt loc = nlopt_create(NLOPT_LN_BOBYQA, leg->nx);
        st = loc ? nlopt_set_xtol_abs1(loc, leg->xtol) : NLOPT_OUT_OF_MEMORY;
        if (st > 0) {
            st = nlopt_set_local_optimizer(opt, loc);
        }
        nlopt_destroy(loc);
    }
    if (st > 0) {
        st = nlopt_set_xtol_abs1(opt, leg->xtol);
    }
    if (st > 0) {
        st = nlopt_set_ftol_abs(opt, FTOL);
    }
    if (st > 0 && leg->step) {
        st = nlopt_set_initial_step(opt, leg->step);
    }
    if (st > 0) {
        /* NLopt counts calls, not simulations; the leg's own count stops the run */
        st = nlopt_set_maxeval(opt, (int)fmin(4 * leg->budget + 10, 1e9));
    }
    return st;
}

/* the algorithm of the strategy `how` over the leg from its start; a refusal into the leg */
static void polish(const void *how, zp_leg *leg) {
    const zp_strategy *self = how;
    int alg = self->variant;
    nl_run c = {.leg = leg, .alg = alg, .penalty = !takes_constraint(alg)};
    nlopt_opt opt = nlopt_create((nlopt_algorithm)alg, leg->nx);
    nlopt_result st = NLOPT_OUT_OF_MEMORY;
    if (opt) {
        c.opt = opt;
        double x[ZP_SCHED_MAX_PARAMS], fbest;
        for (int k = 0; k < leg->nx; k++) {
            x[k] = leg->x0[k];
        }
        st = setup(&c, opt);
        if (st > 0) {
            st = nlopt_optimize(opt, x, &fbest);
        }
        nlopt_destroy(opt);
    }
    if (st == NLOPT_INVALID_ARGS || st == NLOPT_OUT_OF_MEMORY) {
        leg->refused = 1;
        snprintf(leg->why, sizeof leg->why, "NLopt's %s refused the search: %s", self->name,
                 nlopt_result_to_string(st));
    }
}

static void global_leg(const void *how, zp_leg *leg) {
    /* NLopt's random numbers are per thread (an unseeded one seeds itself from the clock):
       seeded on the thread that runs the leg */
    nlopt_srand(leg->S->o->seed);
    polish(how, leg);
}

/* a global algorithm's state: which one, and the scan's sequence for the later rounds */
typedef struct global {
    const zp_strategy *self;
    void *scan;
} global;

static void global_free(void *state) {
    global *g = state;
    if (g) {
        zp_strategy_scan.free(g->scan);
    }
    free(g);
}

static void *global_create(const zp_strategy *self, const zp_search_state *S) {
    global *g = malloc(sizeof *g);
    if (g) {
        *g = (global){self, zp_strategy_scan.create(&zp_strategy_scan, S)};
    }
    if (!g || !g->scan) {
        global_free(g);
        return NULL;
    }
    return g;
}

static zp_status global_explore(void *state, zp_search_state *S, int round, char *err,
                                size_t errlen) {
    global *g = state;
    if (round > 0) {
        return zp_strategy_scan.explore(g->scan, S, round, err, errlen);
    }
    double mid[ZP_SCHED_MAX_PARAMS];
    for (int k = 0; k < S->n; k++) {
        mid[k] = 0.5 * (S->lo[k] + S->hi[k]);
    }
    zp_leg_job job = {.x0 = mid, .archive = 1, .cap = GLOBAL_PER_PARAM * (long)S->n};
    return zp_leg_batch(S, global_leg, g->self, &job, 1, err, errlen);
}

#define NL_LOCAL(alg, title)                                                                       \
    { .name = title, .phase = ZP_STRATEGY_LOCAL, .variant = alg, .polish = polish }
#define NL_GLOBAL(alg, title)                                                                      \
    {                                                                                              \
        .name = title, .phase = ZP_STRATEGY_GLOBAL, .variant = alg, .create = global_create,       \
        .free = global_free, .explore = global_explore                                             \
    }
const zp_strategy zp_strategy_nlopt_cobyla = NL_LOCAL(NLOPT_LN_COBYLA, "COBYLA");
const zp_strategy zp_strategy_nlopt_bobyqa = NL_LOCAL(NLOPT_LN_BOBYQA, "BOBYQA");
const zp_strategy zp_strategy_nlopt_sbplx = NL_LOCAL(NLOPT_LN_SBPLX, "Sbplx");
const zp_strategy zp_strategy_nlopt_direct = NL_GLOBAL(NLOPT_GN_DIRECT_L, "DIRECT-L");
const zp_strategy zp_strategy_nlopt_crs2 = NL_GLOBAL(NLOPT_GN_CRS2_LM, "CRS2");
const zp_strategy zp_strategy_nlopt_isres = NL_GLOBAL(NLOPT_GN_ISRES, "ISRES");
const zp_strategy zp_strategy_nlopt_mlsl = NL_GLOBAL(NLOPT_G_MLSL_LDS, "MLSL");
