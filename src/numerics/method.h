/* The integrator interface: advance an ODE with root finding to an output time. CVODE (Adams,
   BDF) and GSL odeiv2 (rk8pd, rk4imp) implement it; the simulator sees nothing else. */
#ifndef ZP_METHOD_H
#define ZP_METHOD_H

#include <stddef.h>

typedef int (*zp_rhs_fn)(double t, const double *y, double *ydot, void *user);
typedef int (*zp_root_fn)(double t, const double *y, double *g, void *user);

typedef struct zp_method_opts {
    double rtol, atol;
    long max_steps; /* per advance call; the simulator also bounds the run */
    /* NULL, or per root 1 where only the state at the root is wanted, not its time to the
       integration's resolution (g is the rate of what is recorded, which is stationary
       there): a method that lands its roots by a step may skip refining such a time */
    const int *root_state_only;
    /* components [0, npos) are positions whose rates are components [npos, 2 npos), so the
       rates of those are their accelerations: a method may interpolate positions from
       values, rates and accelerations at both ends of a step. 0: no such structure */
    int npos;
} zp_method_opts;

/* What one advance did. */
typedef enum {
    ZP_ADV_STEP, /* took a step; t is its end */
    ZP_ADV_ROOT, /* a root of g lies in the step; t is the root */
    ZP_ADV_STOP, /* reached t_stop */
    ZP_ADV_FAIL
} zp_adv;

typedef struct zp_method {
    const char *name; /* as typed in [solver] method */
    const char *doc;  /* one line for --help */
    /* rootdir[i]: +1/-1 reports only increasing/decreasing crossings of g_i, 0 both. */
    void *(*create)(int n, int nroot, const int *rootdir, zp_rhs_fn rhs, zp_root_fn root,
                    void *user, const zp_method_opts *o);
    /* Restart at (t0, y0), integrating no further than t_stop. 0 on success. */
    int (*reset)(void *w, double t0, const double *y0, double t_stop);
    /* One internal step (the step sequence never depends on what is output). On ZP_ADV_ROOT
       roots[i] = +1/-1 for each g_i that crossed (its direction), 0 otherwise. On ZP_ADV_FAIL
       err holds the reason. */
    zp_adv (*advance)(void *w, double *t, double *y, int *roots, char *err, size_t errlen);
    /* Dense output: y at a time t inside the last step. 0 on success. */
    int (*interpolate)(void *w, double t, double *y);
    /* NULL where the dense output is as accurate as the steps; else y at a time t inside the
       last step to the steps' own accuracy (a step from its start), for the few values that
       must not carry a low-order interpolant's error. 0 on success. */
    int (*land)(void *w, double t, double *y);
    /* Steps and rhs evaluations since the last reset. */
    void (*stats)(void *w, long *steps, long *rhs_evals);
    void (*free)(void *w);
    /* Steps the error test rejected since the last reset (each cost a step's evaluations and
       was taken again shorter); NULL where a method does not count them. */
    void (*rejections)(void *w, long *rejected);
} zp_method;

/* ZP_METHOD_<ID> for every line of methods.def */
typedef enum {
#define ZP_METHOD(id, obj) ZP_METHOD_##id,
#include "methods.def"
#undef ZP_METHOD
    ZP_METHOD_COUNT
} zp_method_id;

const zp_method *zp_method_get(int id);
/* On the dense output of w's last step: the first time in [ta, tb] at which component comp of
   y crosses level, found by Brent's method on the interpolant, with y there; comp must lie
   below level at ta and not below it at tb. 0 on success; on failure (the interpolant does
   not bracket the crossing) *t is the end nearer to it and y is unset. */
int zp_method_dense_crossing(const zp_method *meth, void *w, int comp, double level, double ta,
                             double tb, double *t, double *y);
int zp_method_find(const char *name); /* -1 if unknown */

#endif
