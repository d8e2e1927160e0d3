/* Damped Newton for the cable's equilibria: quadratic convergence from a good start, the step
   halved where the start is poor; the callers' continuation handles what halving cannot. */
#include "cable_newton.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <string.h>

#define MAX_STEPS 60
#define MIN_DAMPING 0x1p-30 /* a step halved this far makes no progress: give up */
/* a full step this small (scaled) leaves an error of its square: one more step, then done */
#define POLISH_STEP 1e-8
/* a step this small (scaled) is round-off: the residual need not decrease any more */
#define ROUND_OFF_STEP 1e-13
#define CONTINUE_TRIES 400
#define ROOT_ITER 200
#define MIN_CONTINUE_STEP 0x1p-20

static double scaled_norm(int n, const double *r, const double *rscale) {
    double sum = 0;
    for (int i = 0; i < n; i++) {
        sum += (r[i] / rscale[i]) * (r[i] / rscale[i]);
    }
    return sqrt(sum);
}

int zp_cable_newton_linear(int n, const double *jac, const double *b, double *x) {
    double lu[ZP_CABLE_NEWTON_MAX * ZP_CABLE_NEWTON_MAX], rhs[ZP_CABLE_NEWTON_MAX];
    size_t perm_data[ZP_CABLE_NEWTON_MAX];
    memcpy(lu, jac, sizeof *lu * (size_t)(n * n));
    memcpy(rhs, b, sizeof *b * (size_t)n);
    gsl_matrix_view m = gsl_matrix_view_array(lu, (size_t)n, (size_t)n);
    gsl_vector_view bv = gsl_vector_view_array(rhs, (size_t)n);
    gsl_vector_view xv = gsl_vector_view_array(x, (size_t)n);
    gsl_permutation perm = {(size_t)n, perm_data};
    int sign;
    if (gsl_linalg_LU_decomp(&m.matrix, &perm, &sign)) {
        return -1;
    }
    /* checked here: GSL's solve reports a singular matrix through its (aborting) handler */
    for (int i = 0; i < n; i++) {
        double p = lu[i * n + i];
        if (p == 0 || !isfinite(p)) {
            return -1;
        }
    }
    return gsl_linalg_LU_solve(&m.matrix, &perm, &bv.vector, &xv.vector) ? -1 : 0;
}

/* dz = -jac^-1 r */
static int newton_step(int n, const double *jac, const double *r, double *dz) {
    double minus_r[ZP_CABLE_NEWTON_MAX];
    for (int i = 0; i < n; i++) {
        minus_r[i] = -r[i];
    }
    return zp_cable_newton_linear(n, jac, minus_r, dz);
}

int zp_cable_newton_solve(int n, zp_cable_newton_fn fn, void *ctx, double *z, const double *zscale,
                          const double *rscale) {
    double r[ZP_CABLE_NEWTON_MAX], jac[ZP_CABLE_NEWTON_MAX * ZP_CABLE_NEWTON_MAX];
    double dz[ZP_CABLE_NEWTON_MAX], trial[ZP_CABLE_NEWTON_MAX];
    double rt[ZP_CABLE_NEWTON_MAX], jt[ZP_CABLE_NEWTON_MAX * ZP_CABLE_NEWTON_MAX];
    if (fn(z, r, jac, ctx)) {
        return -1;
    }
    double norm = scaled_norm(n, r, rscale);
    for (int step = 0; step < MAX_STEPS; step++) {
        if (newton_step(n, jac, r, dz)) {
            return -1;
        }
        double size = 0;
        for (int i = 0; i < n; i++) {
            size = fmax(size, fabs(dz[i]) / zscale[i]);
        }
        if (!isfinite(size)) {
            return -1;
        }
        double damping = 1, tnorm;
        for (;; damping *= 0.5) {
            if (damping < MIN_DAMPING) {
                return -1;
            }
            for (int i = 0; i < n; i++) {
                trial[i] = z[i] + damping * dz[i];
            }
            if (fn(trial, rt, jt, ctx) == 0) {
                tnorm = scaled_norm(n, rt, rscale);
                if (tnorm < norm || damping * size < ROUND_OFF_STEP) {
                    break;
                }
            }
        }
        memcpy(z, trial, sizeof *z * (size_t)n);
        memcpy(r, rt, sizeof *r * (size_t)n);
        memcpy(jac, jt, sizeof *jac * (size_t)(n * n));
        norm = tnorm;
        if (damping == 1 && size < POLISH_STEP) {
            if (newton_step(n, jac, r, dz)) {
                return -1;
            }
            for (int i = 0; i < n; i++) {
                z[i] += dz[i];
            }
            return 0;
        }
    }
    return -1;
}

int zp_cable_newton_continue(int n, zp_cable_newton_fn fn, void *ctx, double *lambda, double *z,
                             const double *zscale, const double *rscale) {
    double at = 0, step = 1, prev_step = 0;
    double z_at[ZP_CABLE_NEWTON_MAX], z_prev[ZP_CABLE_NEWTON_MAX];
    memcpy(z_at, z, sizeof *z * (size_t)n);
    for (int tries = 0; tries < CONTINUE_TRIES; tries++) {
        step = fmin(step, 1 - at);
        *lambda = at + step;
        /* the secant through the last two solutions predicts the next */
        for (int i = 0; i < n; i++) {
            z[i] = z_at[i] + (prev_step > 0 ? (z_at[i] - z_prev[i]) * step / prev_step : 0);
        }
        if (zp_cable_newton_solve(n, fn, ctx, z, zscale, rscale) == 0) {
            if (*lambda == 1) {
                return 0;
            }
            memcpy(z_prev, z_at, sizeof *z * (size_t)n);
            memcpy(z_at, z, sizeof *z * (size_t)n);
            at = *lambda;
            prev_step = step;
            step *= 2;
        } else if ((step *= 0.5) < MIN_CONTINUE_STEP) {
            return -1;
        }
    }
    return -1;
}

double zp_cable_newton_root(double (*f)(double, void *), void *ctx, double lo, double hi) {
    double flo = f(lo, ctx), fhi = f(hi, ctx);
    if (!(isfinite(flo) && isfinite(fhi) && (flo <= 0) != (fhi <= 0))) {
        return NAN;
    }
    gsl_function fn = {f, ctx};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double root = NAN;
    if (s && gsl_root_fsolver_set(s, &fn, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < ROOT_ITER; it++) {
            if (gsl_root_fsolver_iterate(s)) {
                root = NAN;
                break;
            }
            root = gsl_root_fsolver_root(s);
            double a = gsl_root_fsolver_x_lower(s), b = gsl_root_fsolver_x_upper(s);
            if (gsl_root_test_interval(a, b, 0, 4 * DBL_EPSILON) == GSL_SUCCESS) {
                break;
            }
        }
    }
    gsl_root_fsolver_free(s);
    return root;
}
