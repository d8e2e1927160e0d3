/* Methods "gsl-rk8pd" (explicit Runge-Kutta-Prince-Dormand 8(9)) and "gsl-rk4imp" (implicit
   Gauss-Legendre 4, A-stable) from GSL odeiv2 behind the method interface. GSL steps; this file
   adds what odeiv2 lacks: Hermite dense output and root finding on it. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "method.h"

/* Design note: a root is located by Brent's method on g(interpolant(t)). The interpolant is
   a Hermite one from the step's ends: quintic for positions, whose accelerations the rates
   give for free, cubic for velocities and work. Where only the state at a root is wanted (the
   angle extrema: the angle is stationary there) it is the interpolant's, O(h^6) in the
   angle. Elsewhere (section ends, death) the state is "landed" by one GSL step of the same
   type from the step's start, with Newton corrections of the time. Rejected: landing the
   extrema too (a step each: ~30 % of a run's evaluations on the seed, for largest angles at
   most ~1e-3 deg closer), and restarting after a kink from an interpolated state, whose
   O(h^4) velocities put the seed's finish time 5e-5..8e-4 s off at rtol 1e-7..1e-5 (landed:
   7e-9..2e-7 s) for 60-70 evaluations fewer. Both steppers are one-step methods, so a
   landing step leaves no history behind (msbdf would). */

#define NEWTON_MAX 3 /* landing steps after the first: each gains the interpolant's accuracy */
#define FIRST_STEP_PROBES 3 /* estimates of the first step, each probing 100x further */

typedef struct gsl_work {
    int n, nroot;
    int *dir;        /* owned, nroot: +1/-1 only that direction of crossing, 0 both */
    int *state_only; /* owned, nroot: 1 where one landing step suffices (no Newton on t) */
    zp_rhs_fn rhs;
    zp_root_fn root;
    void *user; /* borrowed, handed to rhs and root */
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *run;      /* owned: step and evolve of the integration (not its control) */
    gsl_odeiv2_control *control; /* owned: step_control_type */
    gsl_odeiv2_driver *land;     /* owned: a second stepper of the same type for root states */
    gsl_root_fsolver *brent;     /* owned */
    double t_stop, h;            /* s: end of the run, next step size */
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
    int npos;                /* positions first: zp_method_opts.npos */
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

/* Step size control: GSL's standard one (accept at error <= 1.1, shrink by at most 5x, grow
   by at most 5x below 0.5, safety 0.9), except that the tolerance of a component scales with
   the larger of its magnitudes at the step's two ends, as in Hairer's codes and SciPy.
   Design note: GSL scales with the end alone, so a joint angle or rate that ends a step near
   zero gets a tolerance near atol; most of the seed's rejected steps were such ends, and the
   steps around them were cut short too. Seed at 10 N, rtol 1e-5: 104 steps and 31 rejected
   became 97 and 28, 1826 evaluations 1696. */
typedef struct step_control {
    double atol, rtol;
    const double *y_start; /* borrowed, n: the step's start (gsl_work.y0) */
} step_control;

static void *control_alloc(void) {
    return calloc(1, sizeof(step_control));
}

static int control_init(void *p, double eps_abs, double eps_rel, double a_y, double a_dydt) {
    step_control *c = p;
    c->atol = eps_abs;
    c->rtol = eps_rel;
    (void)a_y;
    (void)a_dydt;
    return GSL_SUCCESS;
}

static int control_hadjust(void *p, size_t dim, unsigned int ord, const double y[],
                           const double yerr[], const double yp[], double *h) {
    const step_control *c = p;
    double rmax = DBL_MIN;
    for (size_t i = 0; i < dim; i++) {
        double scale = fmax(fabs(y[i]), fabs(c->y_start[i]));
        rmax = fmax(rmax, fabs(yerr[i]) / (c->atol + c->rtol * scale));
    }
    (void)yp;
    if (!(rmax <= 1.1)) {
        /* shrink, a share S more than the scaling suggests, and at most 5x */
        *h *= fmax(0.9 / pow(rmax, 1.0 / ord), 0.2);
        return GSL_ODEIV_HADJ_DEC;
    }
    if (rmax < 0.5) {
        *h *= fmin(fmax(0.9 / pow(rmax, 1.0 / (ord + 1.0)), 1.0), 5.0);
        return GSL_ODEIV_HADJ_INC;
    }
    return GSL_ODEIV_HADJ_NIL;
}

/* the error level of one component at its end value, as GSL's standard control has it */
static int control_errlevel(void *p, const double y, const double dydt, const double h,
                            const size_t ind, double *errlev) {
    const step_control *c = p;
    *errlev = c->atol + c->rtol * fabs(y);
    (void)dydt;
    (void)h;
    (void)ind;
    return GSL_SUCCESS;
}

static const gsl_odeiv2_control_type step_control_type = {
    "zp_both_ends", control_alloc, control_init, control_hadjust, control_errlevel, NULL, free,
};

static void gsl_free_work(void *work) {
    gsl_work *w = work;
    if (!w) {
        return;
    }
    if (w->run) {
        gsl_odeiv2_driver_free(w->run);
    }
    if (w->control) {
        gsl_odeiv2_control_free(w->control);
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
    w->npos = o->npos;
    w->sys = (gsl_odeiv2_system){g_rhs, g_jac, (size_t)n, w};
    /* the driver's initial step is irrelevant: reset sets h */
    w->rtol = o->rtol;
    w->atol = o->atol;
    w->run = gsl_odeiv2_driver_alloc_y_new(&w->sys, type, 1e-6, o->atol, o->rtol);
    w->land = gsl_odeiv2_driver_alloc_y_new(&w->sys, type, 1e-6, o->atol, o->rtol);
    w->brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    w->control = gsl_odeiv2_control_alloc(&step_control_type);
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
    if (!w->run || !w->land || !w->brent || !w->control || !w->dir || !w->state_only || !w->glo ||
        !w->g1 || !w->gtmp || !w->y0 || !w->y1 || !w->f0 || !w->f1 || !w->ytmp || !w->yerr ||
        !w->fj) {
        gsl_free_work(w);
        return NULL;
    }
    for (int i = 0; i < nroot; i++) {
        w->dir[i] = rootdir ? rootdir[i] : 0;
        w->state_only[i] = o->root_state_only ? o->root_state_only[i] : 0;
    }
    if (gsl_odeiv2_control_init(w->control, o->atol, o->rtol, 1, 0)) {
        gsl_free_work(w);
        return NULL;
    }
    ((step_control *)w->control->state)->y_start = w->y0;
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
   tolerance; 1e-6 s when the rates fail. Where the estimate is capped at 100x the probe
   step (a probe of 1e-6 s when y0 or its rates are all but zero, as at a start from rest),
   it is made again with the capped step as the probe, up to FIRST_STEP_PROBES times: one rhs
   evaluation each, against the steps of 13 evaluations that would grow from the tiny one
   (the seed's start: 4 steps). */
static double first_step(gsl_work *w, double t0, const double *y0) {
    double d0 = 0, d1 = 0, *f0 = w->fj, *f1 = w->fj + w->n;
    if (g_rhs(t0, y0, f0, w)) {
        return 1e-6;
    }
    for (int i = 0; i < w->n; i++) {
        double sc = w->atol + w->rtol * fabs(y0[i]);
        d0 += (y0[i] / sc) * (y0[i] / sc);
        d1 += (f0[i] / sc) * (f0[i] / sc);
    }
    double h0 = d0 < 1e-10 || d1 < 1e-10 ? 1e-6 : 0.01 * sqrt(d0 / d1);
    d1 = sqrt(d1 / w->n);
    int order = (int)gsl_odeiv2_step_order(w->run->s);
    for (int probe = 0;; probe++) {
        double d2 = 0;
        for (int i = 0; i < w->n; i++) {
            w->ytmp[i] = y0[i] + h0 * f0[i];
        }
        if (g_rhs(t0 + h0, w->ytmp, f1, w)) {
            return probe ? h0 : 1e-6; /* h0: the last good probe's answer, its cap */
        }
        for (int i = 0; i < w->n; i++) {
            double sc = w->atol + w->rtol * fabs(y0[i]);
            d2 += ((f1[i] - f0[i]) / sc) * ((f1[i] - f0[i]) / sc);
        }
        d2 = sqrt(d2 / w->n) / h0;
        double h1 = fmax(d1, d2) <= 1e-15 ? fmax(1e-6, h0 * 1e-3)
                                          : pow(0.01 / fmax(d1, d2), 1.0 / (order + 1));
        if (h1 <= 100 * h0 || probe + 1 == FIRST_STEP_PROBES) {
            return fmin(100 * h0, h1);
        }
        h0 *= 100;
    }
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

/* Hermite on [t0, t1], exact at both ends: quintic for the positions (values, rates and
   accelerations at both ends: O(h^6) inside), cubic for the rest (O(h^4)) */
static void interpolant(const gsl_work *w, double t, double *y) {
    double h = w->t1 - w->t0, s = h > 0 ? (t - w->t0) / h : 1.0, r = 1 - s;
    double h00 = (1 + 2 * s) * r * r, h10 = s * r * r;
    double h01 = s * s * (3 - 2 * s), h11 = -s * s * r;
    for (int i = w->npos; i < w->n; i++) {
        y[i] = h00 * w->y0[i] + h01 * w->y1[i] + h * (h10 * w->f0[i] + h11 * w->f1[i]);
    }
    /* the quintic basis in the symmetric form (s, r = 1 - s) */
    double s3 = s * s * s, r3 = r * r * r;
    double q00 = r3 * (1 + 3 * s + 6 * s * s), q01 = s3 * (1 + 3 * r + 6 * r * r);
    double q10 = s * r3 * (1 + 3 * s), q11 = -r * s3 * (1 + 3 * r);
    double q20 = 0.5 * s * s * r3, q21 = 0.5 * r * r * s3;
    const double *a0 = w->f0 + w->npos, *a1 = w->f1 + w->npos;
    for (int i = 0; i < w->npos; i++) {
        y[i] = q00 * w->y0[i] + q01 * w->y1[i] + h * (q10 * w->f0[i] + q11 * w->f1[i]) +
               h * h * (q20 * a0[i] + q21 * a1[i]);
    }
}

static int gsl_interpolate(void *work, double t, double *y) {
    gsl_work *w = work;
    double slack = 1e-12 * fmax(1.0, fabs(w->t1));
    if (t < w->t0 - slack || t > w->t1 + slack || ensure_rates(w)) {
        return 1;
    }
    interpolant(w, t, y);
    return 0;
}

/* g_i on the interpolant, Brent's function */
static double g_on_interpolant(double t, void *p) {
    gsl_work *w = p;
    interpolant(w, t, w->ytmp);
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
    gsl_function F = {g_on_interpolant, w};
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
    interpolant(w, t, y);
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
    interpolant(w, best_hi, w->ytmp);
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
    /* only states wanted (extrema: what is recorded is stationary there): the interpolant's,
       whose positions are quintic; else land the state, then Newton steps on the time with
       the interpolant's slope */
    *t = tr;
    int state_only = 1;
    for (int i = 0; i < w->nroot; i++) {
        state_only = state_only && (!roots[i] || w->state_only[i]);
    }
    if (state_only) {
        interpolant(w, tr, y);
        return 1;
    }
    land(w, tr, y);
    if (w->state_only[best]) {
        return 1;
    }
    w->iroot = best;
    double eps = 1e-7 * (w->t1 - w->t0);
    double ta = fmax(tr - eps, w->t0), tb = fmin(tr + eps, w->t1);
    double slope = (g_on_interpolant(tb, w) - g_on_interpolant(ta, w)) / (tb - ta);
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
        int st = gsl_odeiv2_evolve_apply(w->run->e, w->control, w->run->s, &w->sys, &tt, w->t_stop,
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

static void gsl_rejections(void *work, long *rejected) {
    gsl_work *w = work;
    *rejected = (long)w->run->e->failed_steps;
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
    .rejections = gsl_rejections,
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
    .rejections = gsl_rejections,
};
