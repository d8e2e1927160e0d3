/* Every local maximum of every load history inside an interval [a, b] of a run, from its values
   at a, the midpoint and b and its rates at both ends (one-sided differences on the dense
   output), so a maximum anywhere in the interval is bracketed, not only one near the middle. */
#include "peaks.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a maximum is located to this share of its bracket (Brent's method): near a smooth top the
   value then moves by ~1e-12 of the history's change across the bracket, far below any limit's
   slack */
#define PEAK_SHARE 1e-6
#define PEAK_ITER 60
/* the one-sided differences at the ends step this share of the interval inside */
#define END_STEP 1e-3

zp_peaks *zp_peaks_create(int nq) {
    zp_peaks *p = calloc(1, sizeof *p);
    if (!p) {
        return NULL;
    }
    p->nq = nq;
    p->brent = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!p->brent) {
        free(p);
        return NULL;
    }
    zp_peaks_reset(p);
    return p;
}

void zp_peaks_free(zp_peaks *p) {
    if (p) {
        gsl_min_fminimizer_free(p->brent);
        free(p);
    }
}

static void take(zp_peaks *p, double t, const double *v) {
    for (int q = 0; q < p->nq; q++) {
        if (v[q] > p->best[q]) {
            p->best_t[q] = t;
        }
        p->best[q] = fmax(p->best[q], v[q]);
    }
}

void zp_peaks_reset(zp_peaks *p) {
    for (int q = 0; q < p->nq; q++) {
        p->best[q] = -INFINITY;
        p->best_t[q] = NAN;
        p->gap[q] = 0;
    }
}

void zp_peaks_restart(zp_peaks *p, double t, const double *v) {
    p->t = t;
    memcpy(p->v, v, sizeof *v * p->nq);
    for (int q = 0; q < p->nq; q++) {
        p->slope[q] = NAN;
    }
    take(p, t, v);
}

/* every history at t on the dense output (0: done), seen by the bests */
static int eval(zp_peaks *p, double t, double *v) {
    if (p->f(t, 0, v, p->user)) {
        return 1;
    }
    take(p, t, v);
    return 0;
}

/* minus history p->q at t */
static double minus_value(double t, void *vp) {
    zp_peaks *p = vp;
    return eval(p, t, p->vtmp) ? 0 : -p->vtmp[p->q];
}

/* the maximum of history q bracketed by lo < mid < hi (its value at mid above both ends),
   refined unless even a generous bound on it stays below the history's best: the top of a
   smooth history lies within its curvature term `bend` of the best sample */
static void refine(zp_peaks *p, int q, double lo, double vlo, double mid, double vmid, double hi,
                   double vhi, double bend) {
    if (!(vmid > vlo && vmid > vhi) || vmid + bend + 2 * p->gap[q] < p->best[q]) {
        return;
    }
    p->q = q;
    gsl_function F = {minus_value, p};
    if (gsl_min_fminimizer_set_with_values(p->brent, &F, mid, -vmid, lo, -vlo, hi, -vhi)) {
        return;
    }
    for (int it = 0; it < PEAK_ITER; it++) {
        if (gsl_min_fminimizer_iterate(p->brent)) {
            return;
        }
        double a = gsl_min_fminimizer_x_lower(p->brent), b = gsl_min_fminimizer_x_upper(p->brent);
        /* GSL's Brent step stalls at about sqrt(eps) |t|: no narrower bracket comes */
        double tol = fmax(PEAK_SHARE * (hi - lo), 4 * GSL_SQRT_DBL_EPSILON * fabs(b));
        if (gsl_min_test_interval(a, b, tol, 0) == GSL_SUCCESS) {
            break;
        }
    }
    /* the top read again from a state as accurate as the steps: the dense output's own error
       there, kept per history, widens the bound that skips later maxima */
    double t = gsl_min_fminimizer_x_minimum(p->brent), v[ZP_PEAKS_MAX];
    if (eval(p, t, p->vtmp) == 0 && p->f(t, 1, v, p->user) == 0) {
        take(p, t, v);
        p->gap[q] = fmax(p->gap[q], fabs(v[q] - p->vtmp[q]));
    }
}

void zp_peaks_interval(zp_peaks *p, double b, const double *vb, zp_peaks_fn f, void *user) {
    double a = p->t, m = 0.5 * (a + b), d = END_STEP * (b - a);
    double vm[ZP_PEAKS_MAX], vd[ZP_PEAKS_MAX], vc[ZP_PEAKS_MAX], bend[ZP_PEAKS_MAX];
    p->f = f;
    p->user = user;
    take(p, b, vb);
    int have_m = b > a && m > a && m < b && eval(p, m, vm) == 0;
    /* which histories may hold a maximum above their best near either end; the one-sided
       differences there are paid only for them */
    int want_d = 0, want_c = 0;
    for (int q = 0; have_m && q < p->nq; q++) {
        /* ~8x what the sampled top can miss for a smooth history (second difference) */
        bend[q] = fabs(p->v[q] - 2 * vm[q] + vb[q]);
        double reach = bend[q] + 2 * p->gap[q];
        want_d |= vb[q] >= vm[q] && vb[q] + reach >= p->best[q];
        want_c |= p->v[q] >= vm[q] && !(p->slope[q] <= 0) && p->v[q] + reach >= p->best[q];
    }
    int have_d = want_d && b - d > m && b - d < b && eval(p, b - d, vd) == 0;
    int have_c = want_c && a + d > a && a + d < m && eval(p, a + d, vc) == 0;
    for (int q = 0; have_m && q < p->nq; q++) {
        /* a maximum around the midpoint */
        refine(p, q, a, p->v[q], m, vm[q], b, vb[q], bend[q]);
        /* one between the midpoint and b: the history falls into b */
        if (have_d && vb[q] >= vm[q]) {
            refine(p, q, m, vm[q], b - d, vd[q], b, vb[q], bend[q]);
        }
        /* one between a and the midpoint: the history rises out of a (its rate there from the
           interval before, or after a restart from a difference inside this one) */
        if (have_c && p->v[q] >= vm[q] && !(p->slope[q] <= 0)) {
            refine(p, q, a, p->v[q], a + d, vc[q], m, vm[q], bend[q]);
        }
    }
    /* the rates at b for the next interval: unknown where not differenced */
    for (int q = 0; q < p->nq; q++) {
        p->slope[q] = have_d ? (vb[q] - vd[q]) / d : NAN;
    }
    p->t = b;
    memcpy(p->v, vb, sizeof *vb * p->nq);
}
