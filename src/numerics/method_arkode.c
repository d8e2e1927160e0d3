/* Method "arkode-verner" (explicit Runge-Kutta, Verner 8(5,6): 8 stages, order 6) from
   SUNDIALS ARKODE's ERKStep, with ARKODE's dense output and its root finding on it. */
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>

#include "method.h"
#include "nvec_fast.h"

/* Design note: roots are located by ARKODE on its Hermite interpolant and the run restarts
   from the interpolated state; no step is spent landing on them (gsl-rk8pd lands each one
   with extra GSL steps, having no dense output of its order). Verner's 6th-order pair over
   the 8th-order Fehlberg 13 table: the quintic Hermite interpolant (degree 5, the most
   ARKODE offers) is O(h^6), so it keeps pace with a 6th-order step but would cap an
   8th-order one, whose long steps then need restarts from a less accurate state. */

/* the first step of each restart, as a share of the first step the same restart took in the
   previous run: a similar schedule needs a similar step, and the share leaves room for the
   controller to grow rather than be rejected */
#define WARM_SHARE 0.5
#define WARM_MAX 16 /* restarts of a run remembered (start, kinks, breaks, rest) */

typedef struct arkode_work {
    SUNContext ctx;
    void *mem;
    N_Vector y;
    int n;
    zp_rhs_fn rhs;
    zp_root_fn root;
    void *user;           /* borrowed, handed to rhs and root */
    char last_error[256]; /* ARKODE's last message, for the failure report */
    /* warm starts: the first step each restart took in the last run (0: none yet) */
    double warm[WARM_MAX], warm_next[WARM_MAX]; /* s */
    int restart;         /* restarts of this run so far */
    int first_pending;   /* the current restart's first step is still to be recorded */
    double t_prev_reset; /* s: time of the last reset, to tell a new run from a restart */
} arkode_work;

static int ark_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *data) {
    arkode_work *w = data;
    return w->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), w->user);
}

static int ark_root(sunrealtype t, N_Vector y, sunrealtype *g, void *data) {
    arkode_work *w = data;
    return w->root(t, N_VGetArrayPointer(y), g, w->user);
}

/* ARKODE's messages are kept for the failure report instead of going to stderr */
static void ark_error(int code, const char *module, const char *function, char *msg,
                      void *data) {
    arkode_work *w = data;
    snprintf(w->last_error, sizeof w->last_error, "%s (%s, code %d)", msg, function, code);
    (void)module;
}

static void arkode_free(void *work) {
    arkode_work *w = work;
    if (!w) {
        return;
    }
    ERKStepFree(&w->mem);
    N_VDestroy(w->y);
    SUNContext_Free(&w->ctx);
    free(w);
}

static void *verner_create(int n, int nroot, const int *rootdir, zp_rhs_fn rhs, zp_root_fn root,
                           void *user, const zp_method_opts *o) {
    arkode_work *w = calloc(1, sizeof *w);
    if (!w || SUNContext_Create(NULL, &w->ctx)) {
        free(w);
        return NULL;
    }
    w->n = n;
    w->rhs = rhs;
    w->root = root;
    w->user = user;
    w->y = N_VNew_Serial(n, w->ctx);
    if (!w->y) {
        arkode_free(w);
        return NULL;
    }
    N_VConst(0.0, w->y);
    zp_nvec_fast_install(w->y);
    w->mem = ERKStepCreate(ark_rhs, 0.0, w->y, w->ctx);
    int bad = !w->mem || ERKStepSetUserData(w->mem, w) ||
              ERKStepSetErrHandlerFn(w->mem, ark_error, w) ||
              ERKStepSetTableNum(w->mem, getenv("ZT")?atoi(getenv("ZT")):ARKODE_VERNER_8_5_6) ||
              (getenv("ZI") && ERKStepSetInterpolantType(w->mem, atoi(getenv("ZI")))) || ERKStepSetInterpolantDegree(w->mem, getenv("ZD")?atoi(getenv("ZD")):ARK_INTERP_MAX_DEGREE) ||
              ERKStepSStolerances(w->mem, o->rtol, o->atol) ||
              ERKStepSetMaxNumSteps(w->mem, o->max_steps) ||
              (nroot > 0 && ERKStepRootInit(w->mem, nroot, ark_root)) ||
              (nroot > 0 && rootdir && ERKStepSetRootDirection(w->mem, (int *)rootdir)) ||
              (nroot > 0 && ERKStepSetNoInactiveRootWarn(w->mem));
    if (bad) {
        arkode_free(w);
        return NULL;
    }
    return w;
}

static int arkode_reset(void *work, double t0, const double *y0, double t_stop) {
    arkode_work *w = work;
    memcpy(N_VGetArrayPointer(w->y), y0, sizeof(double) * w->n);
    w->last_error[0] = '\0';
    /* a run starts at t = 0; every later reset is a restart within it */
    if (t0 == 0 || t0 < w->t_prev_reset) {
        memcpy(w->warm, w->warm_next, sizeof w->warm);
        memset(w->warm_next, 0, sizeof w->warm_next);
        w->restart = 0;
    } else {
        w->restart++;
    }
    w->t_prev_reset = t0;
    w->first_pending = w->restart < WARM_MAX;
    double h0 = getenv("ZCOLD") ? 0 : w->restart < WARM_MAX ? WARM_SHARE * w->warm[w->restart] : 0;
    return ERKStepReInit(w->mem, ark_rhs, t0, w->y) || ERKStepSetInitStep(w->mem, h0) ||
           ERKStepSetStopTime(w->mem, t_stop);
}

static zp_adv arkode_advance(void *work, double *t, double *y, int *roots, char *err,
                             size_t errlen) {
    arkode_work *w = work;
    sunrealtype tret = 0;
    /* tout only bounds the first step's size guess: always far away, so that the steps do not
       depend on output requests (the stop time ends the run) */
    int flag = ERKStepEvolve(w->mem, 1e300, w->y, &tret, ARK_ONE_STEP);
    *t = tret;
    memcpy(y, N_VGetArrayPointer(w->y), sizeof(double) * w->n);
    if (w->first_pending && flag >= 0) {
        sunrealtype h = 0;
        ERKStepGetActualInitStep(w->mem, &h);
        w->warm_next[w->restart] = h;
        w->first_pending = 0;
    }
    switch (flag) {
    case ARK_ROOT_RETURN:
        ERKStepGetRootInfo(w->mem, roots);
        return ZP_ADV_ROOT;
    case ARK_TSTOP_RETURN:
        return ZP_ADV_STOP;
    case ARK_SUCCESS:
        return ZP_ADV_STEP;
    default:
        snprintf(err, errlen, "ARKODE ERKStep failed: %s",
                 w->last_error[0] ? w->last_error : ERKStepGetReturnFlagName(flag));
        return ZP_ADV_FAIL;
    }
}

static int arkode_interpolate(void *work, double t, double *y) {
    arkode_work *w = work;
    N_Vector v = N_VMake_Serial(w->n, y, w->ctx);
    int bad = !v || ERKStepGetDky(w->mem, t, 0, v);
    N_VDestroy(v);
    return bad;
}

static void arkode_stats(void *work, long *steps, long *rhs_evals) {
    arkode_work *w = work;
    long nst = 0, nfe = 0;
    ERKStepGetNumSteps(w->mem, &nst);
    ERKStepGetNumRhsEvals(w->mem, &nfe);
    *steps = nst;
    *rhs_evals = nfe;
}

const zp_method zp_method_arkode_verner = {
    .name = "arkode-verner",
    .doc = "ARKODE explicit Runge-Kutta Verner 6(5), quintic dense output: non-stiff searches",
    .create = verner_create,
    .reset = arkode_reset,
    .advance = arkode_advance,
    .interpolate = arkode_interpolate,
    .stats = arkode_stats,
    .free = arkode_free,
};
