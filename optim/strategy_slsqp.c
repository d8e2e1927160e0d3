/* A gradient polish (strategies.def): NLopt's SLSQP on the finish time under the survival
   constraints, the margin and each [limits] value the scene sets, all with their exact
   gradients from a sensitivity run (sens.h) beside the plain run the leg counts at each point.
   The sensitivity run is charged to the budget as the plain runs its work amounts to, so the
   search's simulation counts stay comparable with the derivative-free polishes. Only the
   nominal scene has gradients: robust scenarios and per-joint death angles are refused. */
#include <math.h>
#include <nlopt.h>
#include <stdio.h>
#include <string.h>

#include "sens.h"
#include "strategy.h"

#define FTOL 1e-6 /* s: the polish stops when the finish time settles to this */
#define DEG (180.0 / M_PI)
/* deg: SLSQP meets the constraint from outside (its last steps end ~1e-4 deg past it), so it
   is held this far inside, which costs ~1e-7 of the time; a survivable end is the leg's best */
#define CONS_SHIFT 1e-3

struct grad_run;

/* NLopt's handle on one [limits] constraint */
typedef struct limit_cons {
    struct grad_run *c;
    int id; /* zp_limit_id */
} limit_cons;

/* one SLSQP run over a leg; NLopt sees the variables in units of the box (x / scale), where
   its first guess of the curvature (the identity) is the same for every parameter */
typedef struct grad_run {
    zp_leg *leg;
    nlopt_opt opt;
    double scale[ZP_SCHED_MAX_PARAMS];
    int nlim; /* the [limits] set, each a constraint */
    limit_cons lim[ZP_LIMIT_COUNT];
    /* the last point differentiated (NLopt asks for the objective and each constraint apart) */
    int have;
    double key[ZP_SCHED_MAX_PARAMS];
    double dobj[ZP_SCHED_MAX_PARAMS], dcons[ZP_SCHED_MAX_PARAMS];
    double dlim[ZP_LIMIT_COUNT][ZP_SCHED_MAX_PARAMS]; /* by zp_limit_id */
} grad_run;

/* design note: a sensitivity run is charged as the plain runs its work amounts to, counted
   not estimated: the plain rate evaluations it made (its integrator's, each parameter's
   stencil, its events') over those of the plain run at the same point, rounded up.
   Deterministic, so the same bits on any number of threads; bench/polish_compare sets it
   against the measured wall time (docs/search.md) */
static long sens_charge(const zp_sens_result *sr, const zp_result *plain) {
    long base = plain->rhs_evals > 0 ? plain->rhs_evals : 1;
    return 1 + (sr->rates - 1) / base;
}

/* 0 when the sensitivity run sr has a smooth gradient of every constraint the polish holds */
static int smooth_everywhere(const grad_run *c, const zp_sens_result *sr) {
    if (!sr->smooth || sr->outcome != ZP_OUTCOME_FINISHED) {
        return -1;
    }
    for (int l = 0; l < c->nlim; l++) {
        int i = c->lim[l].id;
        if (!sr->limits.has[i] || sr->limits.why_not[i][0]) {
            return -1; /* a limit's peak at a tie or a switch: no gradient to follow */
        }
    }
    return 0;
}

/* the gradients at the leg's point x, whose plain run (leg->r) finished, into c per NLopt
   variable; -1 where the run cannot be differentiated there or the budget had no room for it */
static int differentiate(grad_run *c, const double *x) {
    zp_leg *leg = c->leg;
    const zp_search_state *S = leg->S;
    const zp_objective *ob = S->ob;
    double f[ZP_SCHED_MAX_PARAMS];
    zp_leg_params(leg, x, f);
    zp_schedule sched = zp_objective_schedule(ob, f);
    zp_sens_result sr;
    int ok = zp_sens_run(ob->m, S->so, &sched, c->nlim ? &ob->lim : NULL, &sr) == ZP_OK;
    if (zp_leg_charge(leg, sens_charge(&sr, leg->r)) || !ok || smooth_everywhere(c, &sr)) {
        return -1;
    }
    double per_unit[ZP_LIMIT_COUNT];
    for (int l = 0; l < c->nlim; l++) {
        int i = c->lim[l].id;
        zp_objective_limit_cons(ob, i, sr.limits.value[i], &per_unit[i]);
    }
    for (int j = 0; j < leg->nx; j++) {
        /* d parameter k / d variable j: the identity, or the box's width along the pushes */
        double dfk[ZP_SCHED_MAX_PARAMS], dt = 0, dm = 0;
        for (int k = 0; k < S->n; k++) {
            dfk[k] = leg->diag ? S->hi[k] - S->lo[k] : k == j;
            dt += sr.dtime[k] * dfk[k];
            dm += sr.dmargin[k] * dfk[k];
        }
        c->dobj[j] = dt * c->scale[j];
        c->dcons[j] = dm * DEG * c->scale[j];
        for (int l = 0; l < c->nlim; l++) {
            int i = c->lim[l].id;
            double dv = 0;
            for (int k = 0; k < S->n; k++) {
                dv += sr.limits.d[i][k] * dfk[k];
            }
            c->dlim[i][j] = dv * per_unit[i] * c->scale[j];
        }
    }
    return 0;
}

/* the leg's evaluation at NLopt's point u, with the gradients when grad is asked; NULL: the
   polish stops (budget, stop, or a run it cannot differentiate) */
static const zp_eval *grad_eval(grad_run *c, const double *u, int grad) {
    zp_leg *leg = c->leg;
    double x[ZP_SCHED_MAX_PARAMS];
    for (int j = 0; j < leg->nx; j++) {
        x[j] = u[j] * c->scale[j];
    }
    const zp_eval *e = zp_leg_eval(leg, x);
    int fresh = !c->have || memcmp(x, c->key, sizeof *x * leg->nx);
    if (e && grad && fresh) {
        /* a run that does not finish has no time to differentiate: its objective jumps past
           t_max, which SLSQP's line search refuses, so its gradient is never followed */
        memset(c->dobj, 0, sizeof c->dobj);
        memset(c->dcons, 0, sizeof c->dcons);
        memset(c->dlim, 0, sizeof c->dlim);
        if (!e->failed && e->outcome == ZP_OUTCOME_FINISHED && differentiate(c, x)) {
            e = NULL;
        }
        memcpy(c->key, x, sizeof *x * leg->nx);
        c->have = 1;
    }
    if (!e) {
        nlopt_force_stop(c->opt);
    }
    return e;
}

static double grad_obj(unsigned n, const double *u, double *grad, void *data) {
    grad_run *c = data;
    const zp_eval *e = grad_eval(c, u, grad != NULL);
    if (grad) {
        memcpy(grad, c->dobj, sizeof *grad * n);
    }
    return e ? e->obj : zp_leg_spent_score(c->leg);
}

/* the survival constraint of a finished run holds the margin alone beside the limits' own;
   one that did not finish breaks them all (its value, cons, has no gradient) */
static double grad_cons(unsigned n, const double *u, double *grad, void *data) {
    grad_run *c = data;
    const zp_eval *e = grad_eval(c, u, grad != NULL);
    if (grad) {
        memcpy(grad, c->dcons, sizeof *grad * n);
    }
    if (!e) {
        return 360;
    }
    int finished = !e->failed && e->outcome == ZP_OUTCOME_FINISHED;
    return (finished ? zp_objective_margin_cons(c->leg->S->ob, e) : e->cons) + CONS_SHIFT;
}

/* [limits] value id's constraint, on the margin's scale (objective.h) */
static double limit_cons_at(unsigned n, const double *u, double *grad, void *data) {
    const limit_cons *lc = data;
    grad_run *c = lc->c;
    const zp_eval *e = grad_eval(c, u, grad != NULL);
    if (grad) {
        memcpy(grad, c->dlim[lc->id], sizeof *grad * n);
    }
    if (!e) {
        return 360;
    }
    if (e->failed || e->outcome != ZP_OUTCOME_FINISHED) {
        return e->cons + CONS_SHIFT;
    }
    /* the leg's last run is the one at u: zp_leg_eval just ran it or had it */
    const zp_objective *ob = c->leg->S->ob;
    double v[ZP_LIMIT_COUNT], per_unit;
    zp_limits_reached(ob->m, c->leg->r, v);
    return zp_objective_limit_cons(ob, lc->id, v[lc->id], &per_unit) + CONS_SHIFT;
}

/* why the scene's constraints have no gradient here; NULL: they all do */
static const char *refusal(const zp_objective *ob) {
    if (zp_objective_nscenarios(ob) > 0) {
        return "robust scenarios have no gradients yet";
    }
    for (int i = 0; i < ob->m->nlink; i++) {
        if (ob->m->phi_max_j[i] != ob->m->phi_max) {
            return "per-joint death angles: the margin's gradient is of the raw angle";
        }
    }
    return NULL;
}

static nlopt_result setup(grad_run *c, nlopt_opt opt) {
    const zp_leg *leg = c->leg;
    double lo[ZP_SCHED_MAX_PARAMS], hi[ZP_SCHED_MAX_PARAMS];
    for (int j = 0; j < leg->nx; j++) {
        lo[j] = leg->lo[j] / c->scale[j];
        hi[j] = leg->hi[j] / c->scale[j];
    }
    nlopt_result st = nlopt_set_lower_bounds(opt, lo);
    if (st > 0) {
        st = nlopt_set_upper_bounds(opt, hi);
    }
    if (st > 0) {
        st = nlopt_set_min_objective(opt, grad_obj, c);
    }
    if (st > 0) {
        st = nlopt_add_inequality_constraint(opt, grad_cons, c, 0);
    }
    for (int l = 0; l < c->nlim && st > 0; l++) {
        st = nlopt_add_inequality_constraint(opt, limit_cons_at, &c->lim[l], 0);
    }
    double xtol[ZP_SCHED_MAX_PARAMS];
    for (int j = 0; j < leg->nx; j++) {
        xtol[j] = leg->xtol / c->scale[j];
    }
    if (st > 0) {
        st = nlopt_set_xtol_abs(opt, xtol);
    }
    if (st > 0) {
        st = nlopt_set_ftol_abs(opt, FTOL);
    }
    if (st > 0) {
        st = nlopt_set_maxeval(opt, (int)fmin(4 * leg->budget + 10, 1e9));
    }
    return st;
}

static void polish(const void *how, zp_leg *leg) {
    const zp_strategy *self = how;
    const char *no = refusal(leg->S->ob);
    if (no) {
        leg->refused = 1;
        snprintf(leg->why, sizeof leg->why, "%s refuses the scene: %s", self->name, no);
        return;
    }
    grad_run c = {.leg = leg};
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (leg->S->ob->lim.max[i] > 0) {
            c.lim[c.nlim++] = (limit_cons){&c, i};
        }
    }
    double u[ZP_SCHED_MAX_PARAMS], fbest;
    for (int j = 0; j < leg->nx; j++) {
        c.scale[j] = leg->hi[j] > leg->lo[j] ? leg->hi[j] - leg->lo[j] : 1;
        u[j] = leg->x0[j] / c.scale[j];
    }
    nlopt_result st = NLOPT_OUT_OF_MEMORY;
    c.opt = nlopt_create((nlopt_algorithm)self->variant, leg->nx);
    if (c.opt) {
        st = setup(&c, c.opt);
        if (st > 0) {
            st = nlopt_optimize(c.opt, u, &fbest);
        }
        nlopt_destroy(c.opt);
    }
    if (st == NLOPT_INVALID_ARGS || st == NLOPT_OUT_OF_MEMORY) {
        leg->refused = 1;
        snprintf(leg->why, sizeof leg->why, "NLopt's %s refused the search: %s", self->name,
                 nlopt_result_to_string(st));
    }
}

const zp_strategy zp_strategy_slsqp = {
    .name = "SLSQP", .phase = ZP_STRATEGY_LOCAL, .variant = NLOPT_LD_SLSQP, .polish = polish};
