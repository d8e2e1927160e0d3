/* The search's NLopt adapter (search_int.h): one simulation per point for the objective and
   the constraint together, budgets counted in simulations, local polishes in parallel with
   budgets fixed in order, and the sequential NLopt global algorithms. */
#include <math.h>
#include <nlopt.h>
#include <stdlib.h>
#include <string.h>

#include "search_int.h"

#define XTOL 1e-3      /* N: the polish stops when the parameters settle to this */
#define FTOL 1e-6      /* s: ... or the finish time to this */
#define MAX_IMP 64     /* improvements recorded per run, for the history */
#define DIAG_XTOL 1e-6 /* share of the box: XTOL for the one-variable polish */

/* one NLopt run: its evaluations, its own best and its improvements */
typedef struct run_ctx {
    zp_search *S;
    zp_sim *sim;
    zp_result *r;
    nlopt_opt opt;
    int alg;        /* nlopt_algorithm */
    int diag;       /* one variable: the same share of the box for every parameter */
    int penalty;    /* minimise the penalised score; else the time under the constraint */
    int to_archive; /* keep every point for the polish (sequential runs only) */
    long budget, n;
    double key[ZP_SCHED_MAX_PARAMS]; /* NLopt's point of the cached evaluation */
    int have;
    zp_eval e;
    double bestf[ZP_SCHED_MAX_PARAMS];
    zp_eval best;
    int nimp;
    long imp_at[MAX_IMP];
    zp_eval imp[MAX_IMP];
    nlopt_result status;
} run_ctx;

static int takes_constraint(int alg) {
    return alg == NLOPT_LN_COBYLA || alg == NLOPT_GN_ISRES;
}

/* the parameters of NLopt's point x, inside the box */
static void to_params(const zp_search *S, int diag, const double *x, double *f) {
    for (int k = 0; k < S->n; k++) {
        double v = diag ? S->lo[k] + (S->hi[k] - S->lo[k]) * x[0] : x[k];
        f[k] = fmin(fmax(v, S->lo[k]), S->hi[k]);
    }
}

/* the run's evaluation at x, simulated once for the objective and the constraint together */
static const zp_eval *run_at(run_ctx *c, const double *x) {
    zp_search *S = c->S;
    int nx = c->diag ? 1 : S->n;
    if (c->have && !memcmp(x, c->key, sizeof *x * nx)) {
        return &c->e;
    }
    if (c->n >= c->budget || zp_search_stopped(S)) {
        /* NLopt stops at its next check; until then it sees a point worse than any run */
        nlopt_force_stop(c->opt);
        c->have = 0;
        c->e.obj = c->e.score = 3 * S->ob->t_max;
        c->e.cons = 360;
        return &c->e;
    }
    double f[ZP_SCHED_MAX_PARAMS];
    to_params(S, c->diag, x, f);
    zp_search_eval(S, c->sim, c->r, f, &c->e);
    memcpy(c->key, x, sizeof *x * nx);
    c->have = 1;
    c->n++;
    if (c->n == 1 || zp_search_ahead(&c->e, f, &c->best, c->bestf, S->n)) {
        c->best = c->e;
        memcpy(c->bestf, f, sizeof *f * S->n);
        if (zp_objective_feasible(&c->e) && c->nimp < MAX_IMP) {
            c->imp_at[c->nimp] = c->n;
            c->imp[c->nimp++] = c->e;
        }
    }
    if (c->to_archive) {
        zp_archive_add(S, f, &c->e);
    }
    return &c->e;
}

static double nl_obj(unsigned n, const double *x, double *grad, void *data) {
    run_ctx *c = data;
    (void)n;
    (void)grad;
    const zp_eval *e = run_at(c, x);
    return c->penalty ? e->score : e->obj;
}

static double nl_cons(unsigned n, const double *x, double *grad, void *data) {
    (void)n;
    (void)grad;
    return run_at(data, x)->cons;
}

/* bounds, objective, constraint, tolerances and steps of opt */
static nlopt_result setup(run_ctx *c, nlopt_opt opt, int nx, const double *step) {
    zp_search *S = c->S;
    double lb[ZP_SCHED_MAX_PARAMS], ub[ZP_SCHED_MAX_PARAMS];
    for (int k = 0; k < nx; k++) {
        lb[k] = c->diag ? 0 : S->lo[k];
        ub[k] = c->diag ? 1 : S->hi[k];
    }
    nlopt_result st = nlopt_set_lower_bounds(opt, lb);
    if (st > 0) {
        st = nlopt_set_upper_bounds(opt, ub);
    }
    if (st > 0) {
        st = nlopt_set_min_objective(opt, nl_obj, c);
    }
    if (st > 0 && !c->penalty) {
        st = nlopt_add_inequality_constraint(opt, nl_cons, c, 0);
    }
    if (st > 0 && c->alg == NLOPT_G_MLSL_LDS) {
        nlopt_opt loc = nlopt_create(NLOPT_LN_BOBYQA, nx);
        st = loc ? nlopt_set_xtol_abs1(loc, XTOL) : NLOPT_OUT_OF_MEMORY;
        if (st > 0) {
            st = nlopt_set_local_optimizer(opt, loc);
        }
        nlopt_destroy(loc);
    }
    if (st > 0) {
        st = nlopt_set_xtol_abs1(opt, c->diag ? DIAG_XTOL : XTOL);
    }
    if (st > 0) {
        st = nlopt_set_ftol_abs(opt, FTOL);
    }
    if (st > 0 && step) {
        st = nlopt_set_initial_step(opt, step);
    }
    if (st > 0) {
        /* NLopt counts calls, not simulations; our own count stops the run */
        st = nlopt_set_maxeval(opt, (int)fmin(4 * c->budget + 10, 1e9));
    }
    return st;
}

/* one NLopt optimisation from x0 (NLopt's variables) with initial steps (NULL: NLopt's) */
static void run_nlopt(run_ctx *c, int alg, const double *x0, const double *step) {
    int nx = c->diag ? 1 : c->S->n;
    c->alg = alg;
    c->penalty = !takes_constraint(alg);
    nlopt_opt opt = nlopt_create((nlopt_algorithm)alg, nx);
    c->status = NLOPT_OUT_OF_MEMORY;
    if (!opt) {
        return;
    }
    c->opt = opt;
    double x[ZP_SCHED_MAX_PARAMS], fbest;
    memcpy(x, x0, sizeof *x * nx);
    nlopt_result st = setup(c, opt, nx, step);
    if (st > 0) {
        st = nlopt_optimize(opt, x, &fbest);
    }
    c->status = st;
    nlopt_destroy(opt);
}

/* the run's improvements into the serial history, and its simulations into the count */
static void run_done(zp_search *S, const run_ctx *c) {
    for (int j = 0; j < c->nimp; j++) {
        zp_search_record(S, S->spent + c->imp_at[j], &c->imp[j]);
    }
    S->spent += c->n;
}

static int nlopt_failed(const run_ctx *c, char *err, size_t errlen) {
    if (c->status == NLOPT_INVALID_ARGS || c->status == NLOPT_OUT_OF_MEMORY) {
        snprintf(err, errlen, "NLopt %s refused the search: %s",
                 nlopt_algorithm_name((nlopt_algorithm)c->alg), nlopt_result_to_string(c->status));
        return 1;
    }
    return 0;
}

typedef struct polish_batch {
    zp_search *S;
    int alg;
    const zp_polish_job *jobs;
    run_ctx *c;
} polish_batch;

static void polish_job(void *user, int i, zp_sim *s, zp_result *r) {
    polish_batch *b = user;
    const zp_polish_job *j = &b->jobs[i];
    run_ctx *c = &b->c[i];
    long budget = c->budget;
    *c = (run_ctx){.S = b->S, .sim = s, .r = r, .diag = j->diag, .budget = budget};
    if (budget > 0) {
        double x0 = 0;
        if (j->diag) {
            int k = 0; /* the start's share of the box, read off a parameter with a range */
            while (k + 1 < b->S->n && b->S->hi[k] == b->S->lo[k]) {
                k++;
            }
            x0 = b->S->hi[k] > b->S->lo[k] ? (j->x0[k] - b->S->lo[k]) / (b->S->hi[k] - b->S->lo[k])
                                           : 0;
        }
        run_nlopt(c, b->alg, j->diag ? &x0 : j->x0, j->step);
    }
}

zp_status zp_polish_batch(zp_search *S, int alg, const zp_polish_job *jobs, int njob, char *err,
                          size_t errlen) {
    polish_batch b = {S, alg, jobs, calloc(njob ? njob : 1, sizeof *b.c)};
    if (!b.c) {
        snprintf(err, errlen, "out of memory for the polish");
        return ZP_ERR_NOMEM;
    }
    /* budgets fixed in order before any runs: a smaller budget cuts the same runs short */
    long left = S->o->max_evals - S->spent;
    for (int i = 0; i < njob; i++) {
        b.c[i].budget = left < jobs[i].cap ? (left > 0 ? left : 0) : jobs[i].cap;
        S->exhausted |= left <= jobs[i].cap;
        left -= b.c[i].budget;
    }
    zp_pool_map(S->pool, njob, polish_job, &b, NULL, NULL);
    zp_status st = ZP_OK;
    for (int i = 0; i < njob; i++) {
        const run_ctx *c = &b.c[i];
        if (c->budget > 0 && nlopt_failed(c, err, errlen)) {
            st = ZP_ERR_INPUT;
        }
        run_done(S, c);
        zp_polish_rec *o = jobs[i].out;
        memcpy(o->start, jobs[i].x0, sizeof *o->start * S->n);
        memcpy(o->end, c->n > 0 ? c->bestf : jobs[i].x0, sizeof *o->end * S->n);
        o->e = c->best;
        o->n = c->n;
        o->at = -1;
    }
    free(b.c);
    return st;
}

typedef struct global_ctx {
    run_ctx *c;
    int alg;
    const double *x0;
} global_ctx;

static void global_job(void *user, int i, zp_sim *s, zp_result *r) {
    global_ctx *g = user;
    (void)i;
    g->c->sim = s;
    g->c->r = r;
    run_nlopt(g->c, g->alg, g->x0, NULL);
}

zp_status zp_polish_global(zp_search *S, int alg, long budget, char *err, size_t errlen) {
    long left = S->o->max_evals - S->spent;
    S->exhausted |= left <= budget;
    run_ctx c = {.S = S, .to_archive = 1, .budget = left < budget ? left : budget};
    double mid[ZP_SCHED_MAX_PARAMS];
    for (int k = 0; k < S->n; k++) {
        mid[k] = 0.5 * (S->lo[k] + S->hi[k]);
    }
    nlopt_srand(S->o->seed);
    global_ctx g = {&c, alg, mid};
    if (c.budget > 0 && !zp_search_stopped(S)) {
        zp_pool_map(S->pool, 1, global_job, &g, NULL, NULL);
    }
    run_done(S, &c);
    return c.budget > 0 && nlopt_failed(&c, err, errlen) ? ZP_ERR_INPUT : ZP_OK;
}
