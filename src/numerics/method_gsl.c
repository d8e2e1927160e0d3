/* Methods "gsl-rk8pd" (explicit Runge-Kutta-Prince-Dormand 8(9)) and "gsl-rk4imp" (implicit
   Gauss-Legendre 4, A-stable) from GSL odeiv2 behind the method interface. GSL steps; this file
   adds what odeiv2 lacks: cubic Hermite dense output and root finding on it. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "method.h"

/* Design note: a root is located by Brent's method on g(Hermite(t)), cheap but only O(h^4)
   accurate, then the state there is "landed" by one GSL step of the same type from the step's
   start, with one Newton correction of the time. Rejected: reporting the interpolated state,
   whose O(h^4) error would cap the 8th-order method at ~1e-6 s on finish times. Both steppers
   are one-step methods, so a landing step leaves no history behind (msbdf would). */

#define NEWTON_MAX 3 /* landing steps after the first: each gains the interpolant's accuracy */

typedef struct gsl_work {
    int n, nroot;
    int *dir;        /* owned, nroot: +1/-1 only that direction of crossing, 0 both */
    int *state_only; /* owned, nroot: 1 where one landing step suffices (no Newton on t) */
    zp_rhs_fn rhs;
    zp_root_fn root;
    void *user; /* borrowed, handed to rhs and root */
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *run;  /* owned: step, control and evolve of the integration */
    gsl_odeiv2_driver *land; /* owned: a second stepper of the same type for root states */
    gsl_root_fsolver *brent; /* owned */
    double t_stop, h;        /* s: end of the run, next step size */
    double rtol, atol; /* the requested tolerances (rtol: how well a root's time need be known) */
    long steps, evals;
    /* the last step [t0, t1] with states and (when computed) rates at both ends */
    double t0, t1;
    double *y0, *y1, *f0, *f1; /* owned, n */
    int have_f0, have_f1;
    /* roots are searched in (tlo, t1]: glo = g at tlo, g1 = g at t1 */
    int pending; /* the step's end has not been reported yet */
    double tlo;
    double *glo, *g1, *gtmp; /* owned, nroot */
    double *ytmp, *yerr;     /* owned, n: scratch */
    double *fj;              /* owned, 2n: the Jacobian's base and perturbed rates */
    int iroot;               /* component Brent is working on */
} gsl_work;

/* the rhs as GSL sees it: >0 (non-finite rates) makes GSL retry with a smaller step */
static int g_rhs(double t, const double y[], double f[], void *p) {
    gsl_work *w = p;
    w->evals++;
    int r = w->rhs(t, y, f, w->user);
    return r == 0 ? GSL_SUCCESS : r > 0 ? GSL_FAILURE : GSL_EBADFUNC;
}

/* forward-difference Jacobian through the rhs, for the implicit stepper's Newton iteration;
   the system is autonomous so df/dt = 0 */
static int g_jac(double t, const double y[], double *dfdy, double dfdt[], void *p) {
    gsl_work *w = p;
    int n = w->n, st = g_rhs(t, y, w->fj, w);
    memcpy(w->ytmp, y, sizeof(double) * n);
    for (int j = 0; j < n && st == GSL_SUCCESS; j++) {
        double d = sqrt(DBL_EPSILON) * fmax(fabs(y[j]), 1.0);
        w->ytmp[j] = y[j] + d;
        st = g_rhs(t, w->ytmp, w->fj + n, w);
        w->ytmp[j] = y[j];
        for (int i = 0; i < n; i++) {
            dfdy[i * n + j] = (w->fj[n + i] - w->fj[i]) / d;
        }
    }
    for (int i = 0; i < n; i++) {
        dfdt[i] = 0;
    }
    return st;
}

static void gsl_free_work(void *work) {
    gsl_work *w = work;
    if (!w) {
        return;
    }
    if (w->run) {
        gsl_odeiv2_driver_free(w->run);
    }
    if (w->land) {
        gsl_odeiv2_driver_free(w->land);
    }
    if (w->brent) {
        gsl_root_fsolver_free(w->brent);
    }
    free(w->dir);
    free(w->state_only);
    free(w->y0);
    free(w->y1);
    free(w->f0);
    free(w->f1);
    free(w->glo);
    free(w->g1);
    free(w->gtmp);
    free(w->ytmp);
    free(w->yerr);
    free(w->fj);
    free(w);
}

static void *gsl_create(const gsl_odeiv2_step_type *type, int n, int nroot, const int *rootdir,
                        zp_rhs_fn rhs, zp_root_fn root, void *user, const zp_method_opts *o) {
    gsl_work *w = calloc(1, sizeof *w);
    if (!w) {
        return NULL;
    }
    w->n = n;
    w->nroot = nroot;
    w->rhs = rhs;
    w->root = root;
    w->user = user;
    w->sys = (gsl_odeiv2_system){g_rhs, g_jac, (size_t)n, w};
    /* the driver's initial step is irrelevant: reset sets h */
    w->rtol = o->rtol;
    w->atol = o->atol;
    w->run = gsl_odeiv2_driver_alloc_y_new(&w->sys, type, 1e-6, o->atol, o->rtol);
    w->land = gsl_odeiv2_driver_alloc_y_new(&w->sys, type, 1e-6, o->atol, o->rtol);
    w->brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    size_t nr = nroot > 0 ? nroot : 1;
    w->dir = calloc(nr, sizeof *w->dir);
    w->state_only = calloc(nr, sizeof *w->state_only);
    w->glo = calloc(nr, sizeof *w->glo);
    w->g1 = calloc(nr, sizeof *w->g1);
    w->gtmp = calloc(nr, sizeof *w->gtmp);
    w->y0 = calloc(n, sizeof(double));
    w->y1 = calloc(n, sizeof(double));
    w->f0 = calloc(n, sizeof(double));
    w->f1 = calloc(n, sizeof(double));
    w->ytmp = calloc(n, sizeof(double));
    w->yerr = calloc(n, sizeof(double));
    w->fj = calloc(2 * (size_t)n, sizeof(double));
    if (!w->run || !w->land || !w->brent || !w->dir || !w->state_only || !w->glo || !w->g1 ||
        !w->gtmp || !w->y0 || !w->y1 || !w->f0 || !w->f1 || !w->ytmp || !w->yerr || !w->fj) {
        gsl_free_work(w);
        return NULL;
    }
    for (int i = 0; i < nroot; i++) {
        w->dir[i] = rootdir ? rootdir[i] : 0;
        w->state_only[i] = o->root_state_only ? o->root_state_only[i] : 0;
    }
    return w;
}

static void *rk8pd_create(int n, int nroot, const int *rootdir, zp_rhs_fn rhs, zp_root_fn root,
                          void *user, const zp_method_opts *o) {
    return gsl_create(gsl_odeiv2_step_rk8pd, n, nroot, rootdir, rhs, root, user, o);
}

static void *rk4imp_create(int n, int nroot, const int *rootdir, zp_rhs_fn rhs, zp_root_fn root,
                           void *user, const zp_method_opts *o) {
    return gsl_create(gsl_odeiv2_step_rk4imp, n, nroot, rootdir, rhs, root, user, o);
}

/* the first step of a run or restart, from the rates at two points (Hairer, Norsett and
   Wanner, Solving ODEs I, II.4): sized so the method's leading error term is about the
   tolerance; 1e-6 s when the rates fail. Two rhs evaluations against the handful of
   rejected-free doublings from a tiny step it replaces. */
static double first_step(gsl_work *w, double t0, const double *y0) {
    double d0 = 0, d1 = 0, d2 = 0, *f0 = w->fj, *f1 = w->fj + w->n;
    if (g_rhs(t0, y0, f0, w)) {
        return 1e-6;
    }
    for (int i = 0; i < w->n; i++) {
        double sc = w->atol + w->rtol * fabs(y0[i]);
        d0 += (y0[i] / sc) * (y0[i] / sc);
        d1 += (f0[i] / sc) * (f0[i] / sc);
    }
    double h0 = d0 < 1e-10 || d1 < 1e-10 ? 1e-6 : 0.01 * sqrt(d0 / d1);
    for (int i = 0; i < w->n; i++) {
        w->ytmp[i] = y0[i] + h0 * f0[i];
    }
    if (g_rhs(t0 + h0, w->ytmp, f1, w)) {
        return 1e-6;
    }
    for (int i = 0; i < w->n; i++) {
        double sc = w->atol + w->rtol * fabs(y0[i]);
        d2 += ((f1[i] - f0[i]) / sc) * ((f1[i] - f0[i]) / sc);
    }
    d1 = sqrt(d1 / w->n);
    d2 = sqrt(d2 / w->n) / h0;
    int order = (int)gsl_odeiv2_step_order(w->run->s);
    double h1 =
        fmax(d1, d2) <= 1e-15 ? fmax(1e-6, h0 * 1e-3) : pow(0.01 / fmax(d1, d2), 1.0 / (order + 1));
    return fmin(100 * h0, h1);
}

static int gsl_reset(void *work, double t0, const double *y0, double t_stop) {
    gsl_work *w = work;
    w->t_stop = t_stop;
    w->t0 = w->t1 = w->tlo = t0;
    memcpy(w->y0, y0, sizeof(double) * w->n);
    memcpy(w->y1, y0, sizeof(double) * w->n);
    w->have_f0 = w->have_f1 = 0;
    w->pending = 0;
    w->steps = w->evals = 0;
    w->h = first_step(w, t0, y0);
    if (gsl_odeiv2_driver_reset(w->run) || gsl_odeiv2_driver_reset(w->land)) {
        return 1;
    }
    /* a g exactly zero at the restart (the boundary just crossed) is masked until it moves */
    return w->nroot > 0 && w->root(t0, y0, w->glo, w->user) != 0;
}

/* rates at one end of the last step, computed once on first need */
static int ensure_rates(gsl_work *w) {
    if (!w->have_f0) {
        if (g_rhs(w->t0, w->y0, w->f0, w)) {
            return 1;
        }
        w->have_f0 = 1;
    }
    if (!w->have_f1) {
        if (g_rhs(w->t1, w->y1, w->f1, w)) {
            return 1;
        }
        w->have_f1 = 1;
    }
    return 0;
}

/* cubic Hermite on [t0, t1]: exact at both ends, O(h^4) inside */
static void hermite(const gsl_work *w, double t, double *y) {
    double h = w->t1 - w->t0, s = h > 0 ? (t - w->t0) / h : 1.0;
    double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    for (int i = 0; i < w->n; i++) {
        y[i] = h00 * w->y0[i] + h01 * w->y1[i] + h * (h10 * w->f0[i] + h11 * w->f1[i]);
    }
}

static int gsl_interpolate(void *work, double t, double *y) {
    gsl_work *w = work;
    double slack = 1e-12 * fmax(1.0, fabs(w->t1));
    if (t < w->t0 - slack || t > w->t1 + slack || ensure_rates(w)) {
        return 1;
    }
    hermite(w, t, y);
    return 0;
}

/* g_i on the interpolant, Brent's function */
static double g_on_hermite(double t, void *p) {
    gsl_work *w = p;
    hermite(w, t, w->ytmp);
    w->root(t, w->ytmp, w->gtmp, w->user);
    return w->gtmp[w->iroot];
}

/* whether g_i crosses zero from glo to g1 in a direction that counts */
static int crosses(const gsl_work *w, int i) {
    double a = w->glo[i], b = w->g1[i];
    if (a == 0) {
        return 0; /* masked: zero at the restart or just after a root */
    }
    return (a < 0 && b >= 0 && w->dir[i] >= 0) || (a > 0 && b <= 0 && w->dir[i] <= 0);
}

/* Brent's bracket [lo, hi] of g_i's root in (tlo, t1]; returns 0 on convergence */
static int bracket_root(gsl_work *w, int i, double *lo, double *hi) {
    gsl_function F = {g_on_hermite, w};
    w->iroot = i;
    *lo = w->tlo;
    *hi = w->t1;
    if (gsl_root_fsolver_set(w->brent, &F, *lo, *hi)) {
        return 1;
    }
    double ttol = 4 * DBL_EPSILON * fmax(fabs(w->t0), fabs(w->t1));
    for (int it = 0; it < 200; it++) {
        if (gsl_root_fsolver_iterate(w->brent)) {
            return 1;
        }
        *lo = gsl_root_fsolver_x_lower(w->brent);
        *hi = gsl_root_fsolver_x_upper(w->brent);
        if (gsl_root_test_interval(*lo, *hi, ttol, 0) == GSL_SUCCESS) {
            return 0;
        }
    }
    return 0; /* the bracket after 200 iterations is still a bracket */
}

/* y at time t by one GSL step from the step's start; falls back to the interpolant */
static void land(gsl_work *w, double t, double *y) {
    memcpy(y, w->y0, sizeof(double) * w->n);
    if (t > w->t0 && gsl_odeiv2_step_apply(w->land->s, w->t0, t - w->t0, y, w->yerr, w->f0, NULL,
                                           &w->sys) == GSL_SUCCESS) {
        return;
    }
    hermite(w, t, y);
}

/* the earliest root in (tlo, t1]: t and y there, roots[] the directions of those that
   crossed; returns 0 if there is none */
static int find_root(gsl_work *w, double *t, double *y, int *roots) {
    double best_hi = INFINITY, best_lo = 0;
    int best = -1;
    for (int i = 0; i < w->nroot; i++) {
        double lo, hi;
        if (crosses(w, i) && !bracket_root(w, i, &lo, &hi) && hi < best_hi) {
            best = i;
            best_lo = lo;
            best_hi = hi;
        }
    }
    if (best < 0) {
        return 0;
    }
    /* every g that has crossed by the end of the earliest bracket is reported with it */
    hermite(w, best_hi, w->ytmp);
    w->root(best_hi, w->ytmp, w->gtmp, w->user);
    for (int i = 0; i < w->nroot; i++) {
        int crossed = i == best || (crosses(w, i) && w->gtmp[i] * w->glo[i] <= 0);
        roots[i] = crossed ? (w->glo[i] < 0 ? 1 : -1) : 0;
    }
    /* the next search starts past this root, on the interpolant it was found on */
    double tr = 0.5 * (best_lo + best_hi);
    w->tlo = best_hi;
    memcpy(w->glo, w->gtmp, sizeof(double) * w->nroot);
    for (int i = 0; i < w->nroot; i++) {
        if (roots[i]) {
            w->glo[i] = 0; /* masked until the step's end: the root is consumed */
        }
    }
    /* land the state, then Newton steps on the time with the interpolant's slope, unless
       only the state is wanted: the time from the interpolant is O(h^4) off, which moves a
       stationary quantity by O(h^8) */
    land(w, tr, y);
    *t = tr;
    if (w->state_only[best]) {
        return 1;
    }
    w->iroot = best;
    double eps = 1e-7 * (w->t1 - w->t0);
    double ta = fmax(tr - eps, w->t0), tb = fmin(tr + eps, w->t1);
    double slope = (g_on_hermite(tb, w) - g_on_hermite(ta, w)) / (tb - ta);
    for (int it = 0; it < NEWTON_MAX && slope != 0; it++) {
        w->root(tr, y, w->gtmp, w->user);
        double tn = fmin(fmax(tr - w->gtmp[best] / slope, w->t0), w->t1);
        /* converged (Newton squares the error): a correction this small is below what the
           integration itself resolves, and landing it would cost a whole step */
        if (!isfinite(tn) || fabs(tn - tr) <= 1e-2 * w->rtol * (w->t1 - w->t0)) {
            break;
        }
        tr = tn;
        land(w, tr, y);
    }
    *t = tr;
    return 1;
}

/* y at t inside the last step by a step of the integrator from its start: the cubic Hermite's
   O(h^4) error would otherwise be read at a load's peak (1e-3 of it at rtol 1e-5) */
static int gsl_land(void *work, double t, double *y) {
    gsl_work *w = work;
    double slack = 1e-12 * fmax(1.0, fabs(w->t1));
    if (t < w->t0 - slack || t > w->t1 + slack || ensure_rates(w)) {
        return 1;
    }
    land(w, fmin(fmax(t, w->t0), w->t1), y);
    return 0;
}

static zp_adv gsl_advance(void *work, double *t, double *y, int *roots, char *err, size_t errlen) {
    gsl_work *w = work;
    if (!w->pending) {
        /* a new step from the end of the last one */
        memcpy(w->y0, w->y1, sizeof(double) * w->n);
        memcpy(w->f0, w->f1, sizeof(double) * w->n);
        w->have_f0 = w->have_f1;
        w->have_f1 = 0;
        w->t0 = w->tlo = w->t1;
        double tt = w->t0;
        int st = gsl_odeiv2_evolve_apply(w->run->e, w->run->c, w->run->s, &w->sys, &tt, w->t_stop,
                                         &w->h, w->y1);
        if (st != GSL_SUCCESS) {
            memcpy(w->y1, w->y0, sizeof(double) * w->n);
            *t = w->t0;
            memcpy(y, w->y0, sizeof(double) * w->n);
            snprintf(err, errlen, "GSL %s step failed (%s) with step size %.3g s",
                     gsl_odeiv2_step_name(w->run->s), gsl_strerror(st), w->h);
            return ZP_ADV_FAIL;
        }
        w->t1 = tt;
        w->steps++;
        /* the step's rates at both ends, when the stepper computed them anyway */
        const gsl_odeiv2_step_type *type = w->run->s->type;
        if (type->can_use_dydt_in && type->gives_exact_dydt_out) {
            memcpy(w->f0, w->run->e->dydt_in, sizeof(double) * w->n);
            memcpy(w->f1, w->run->e->dydt_out, sizeof(double) * w->n);
            w->have_f0 = w->have_f1 = 1;
        }
        w->pending = 1;
        if (w->nroot > 0 && w->root(w->t1, w->y1, w->g1, w->user)) {
            snprintf(err, errlen, "the root functions failed at t = %.9g s", w->t1);
            return ZP_ADV_FAIL;
        }
    }
    int any = 0;
    for (int i = 0; i < w->nroot && !any; i++) {
        any = crosses(w, i);
    }
    if (any && ensure_rates(w) == 0 && find_root(w, t, y, roots)) {
        return ZP_ADV_ROOT;
    }
    /* no (more) roots in this step: report its end */
    w->pending = 0;
    memcpy(w->glo, w->g1, sizeof(double) * w->nroot);
    *t = w->t1;
    memcpy(y, w->y1, sizeof(double) * w->n);
    return w->t1 >= w->t_stop ? ZP_ADV_STOP : ZP_ADV_STEP;
}

static void gsl_stats(void *work, long *steps, long *rhs_evals) {
    gsl_work *w = work;
    *steps = w->steps;
    *rhs_evals = w->evals;
}

const zp_method zp_method_gsl_rk8pd = {
    .name = "gsl-rk8pd",
    .doc = "GSL explicit Runge-Kutta Prince-Dormand 8(9): non-stiff runs at tight tolerances",
    .create = rk8pd_create,
    .reset = gsl_reset,
    .advance = gsl_advance,
    .interpolate = gsl_interpolate,
    .land = gsl_land,
    .stats = gsl_stats,
    .free = gsl_free_work,
};

const zp_method zp_method_gsl_rk4imp = {
    .name = "gsl-rk4imp",
    .doc = "GSL implicit Gauss-Legendre 4 (A-stable), finite-difference Jacobian: stiff runs",
    .create = rk4imp_create,
    .reset = gsl_reset,
    .advance = gsl_advance,
    .interpolate = gsl_interpolate,
    .land = gsl_land,
    .stats = gsl_stats,
    .free = gsl_free_work,
};
