/* Methods "cvode-adams" (non-stiff: Adams-Moulton, fixed-point iteration) and "cvode-bdf"
   (stiff: BDF, Newton with a dense direct solver), with CVODE's own root finding. */
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "method.h"
#include "nvec_fast.h"

typedef struct cvode_work {
    SUNContext ctx;
    void *mem;
    N_Vector y;
    SUNMatrix A;               /* BDF only */
    SUNLinearSolver ls;        /* BDF only */
    SUNNonlinearSolver nls;    /* Adams only */
    int n, nroot;
    double t_stop; /* s, where the run ends at the latest */
    zp_rhs_fn rhs;
    zp_root_fn root;
    void *user;                /* borrowed, handed to rhs and root */
    char last_error[256];      /* CVODE's last message, for the failure report */
} cvode_work;

static int cv_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *data) {
    cvode_work *w = data;
    return w->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), w->user);
}

static int cv_root(sunrealtype t, N_Vector y, sunrealtype *g, void *data) {
    cvode_work *w = data;
    return w->root(t, N_VGetArrayPointer(y), g, w->user);
}

/* CVODE's messages are kept for the failure report instead of going to stderr */
static void cv_error(int code, const char *module, const char *function, char *msg, void *data) {
    cvode_work *w = data;
    snprintf(w->last_error, sizeof w->last_error, "%s (%s, code %d)", msg, function, code);
    (void)module;
}

static void cvode_free(void *work) {
    cvode_work *w = work;
    if (!w) {
        return;
    }
    CVodeFree(&w->mem);
    SUNLinSolFree(w->ls);
    SUNMatDestroy(w->A);
    SUNNonlinSolFree(w->nls);
    N_VDestroy(w->y);
    SUNContext_Free(&w->ctx);
    free(w);
}

static void *cvode_create(int lmm, int n, int nroot, const int *rootdir, zp_rhs_fn rhs,
                          zp_root_fn root, void *user,
                          const zp_method_opts *o) {
    cvode_work *w = calloc(1, sizeof *w);
    if (!w || SUNContext_Create(NULL, &w->ctx)) {
        free(w);
        return NULL;
    }
    w->n = n;
    w->nroot = nroot;
    w->rhs = rhs;
    w->root = root;
    w->user = user;
    w->y = N_VNew_Serial(n, w->ctx);
    w->mem = CVodeCreate(lmm, w->ctx);
    if (!w->y || !w->mem) {
        cvode_free(w);
        return NULL;
    }
    N_VConst(0.0, w->y);
    zp_nvec_fast_install(w->y);
    int bad = CVodeInit(w->mem, cv_rhs, 0.0, w->y) || CVodeSetUserData(w->mem, w) ||
              CVodeSetErrHandlerFn(w->mem, cv_error, w) ||
              CVodeSStolerances(w->mem, o->rtol, o->atol) ||
              CVodeSetMaxNumSteps(w->mem, o->max_steps) ||
              (nroot > 0 && CVodeRootInit(w->mem, nroot, cv_root)) ||
              (nroot > 0 && rootdir && CVodeSetRootDirection(w->mem, (int *)rootdir));
    if (!bad && lmm == CV_BDF) {
        w->A = SUNDenseMatrix(n, n, w->ctx);
        w->ls = w->A ? SUNLinSol_Dense(w->y, w->A, w->ctx) : NULL;
        bad = !w->ls || CVodeSetLinearSolver(w->mem, w->ls, w->A);
    } else if (!bad) {
        /* non-stiff: fixed-point iteration needs no Jacobian */
        w->nls = SUNNonlinSol_FixedPoint(w->y, 0, w->ctx);
        bad = !w->nls || CVodeSetNonlinearSolver(w->mem, w->nls);
    }
    if (bad) {
        cvode_free(w);
        return NULL;
    }
    return w;
}

static void *adams_create(int n, int nroot, const int *rootdir, zp_rhs_fn rhs,
                          zp_root_fn root, void *user,
                          const zp_method_opts *o) {
    return cvode_create(CV_ADAMS, n, nroot, rootdir, rhs, root, user, o);
}

static void *bdf_create(int n, int nroot, const int *rootdir, zp_rhs_fn rhs,
                          zp_root_fn root, void *user,
                        const zp_method_opts *o) {
    return cvode_create(CV_BDF, n, nroot, rootdir, rhs, root, user, o);
}

static int cvode_reset(void *work, double t0, const double *y0, double t_stop) {
    cvode_work *w = work;
    memcpy(N_VGetArrayPointer(w->y), y0, sizeof(double) * w->n);
    w->last_error[0] = '\0';
    w->t_stop = t_stop;
    return CVodeReInit(w->mem, t0, w->y) || CVodeSetStopTime(w->mem, t_stop);
}

static zp_adv cvode_advance(void *work, double *t, double *y, int *roots, char *err,
                            size_t errlen) {
    cvode_work *w = work;
    sunrealtype tret = 0;
    /* tout only bounds the first step's size guess: always the far end, so that the steps
       do not depend on output requests */
    int flag = CVode(w->mem, w->t_stop, w->y, &tret, CV_ONE_STEP);
    *t = tret;
    memcpy(y, N_VGetArrayPointer(w->y), sizeof(double) * w->n);
    switch (flag) {
    case CV_ROOT_RETURN:
        CVodeGetRootInfo(w->mem, roots);
        return ZP_ADV_ROOT;
    case CV_TSTOP_RETURN:
        return ZP_ADV_STOP;
    case CV_SUCCESS:
        return ZP_ADV_STEP;
    default:
        snprintf(err, errlen, "CVode failed: %s",
                 w->last_error[0] ? w->last_error : CVodeGetReturnFlagName(flag));
        return ZP_ADV_FAIL;
    }
}

static int cvode_interpolate(void *work, double t, double *y) {
    cvode_work *w = work;
    N_Vector v = N_VMake_Serial(w->n, y, w->ctx);
    int bad = !v || CVodeGetDky(w->mem, t, 0, v);
    N_VDestroy(v);
    return bad;
}

static void cvode_stats(void *work, long *steps, long *rhs_evals) {
    cvode_work *w = work;
    long nst = 0, nfe = 0, nfels = 0;
    CVodeGetNumSteps(w->mem, &nst);
    CVodeGetNumRhsEvals(w->mem, &nfe);
    if (w->ls) {
        CVodeGetNumLinRhsEvals(w->mem, &nfels); /* difference-quotient Jacobians */
    }
    *steps = nst;
    *rhs_evals = nfe + nfels;
}

static void cvode_rejections(void *work, long *rejected) {
    cvode_work *w = work;
    *rejected = 0;
    CVodeGetNumErrTestFails(w->mem, rejected);
}

const zp_method zp_method_cvode_adams = {
    .name = "cvode-adams",
    .doc = "CVODE Adams-Moulton orders 1-12, fixed-point iteration: non-stiff runs (default)",
    .create = adams_create,
    .reset = cvode_reset,
    .advance = cvode_advance,
    .interpolate = cvode_interpolate,
    .stats = cvode_stats,
    .free = cvode_free,
    .rejections = cvode_rejections,
};

const zp_method zp_method_cvode_bdf = {
    .name = "cvode-bdf",
    .doc = "CVODE BDF orders 1-5, Newton with dense LU: stiff runs (heavy damping)",
    .create = bdf_create,
    .reset = cvode_reset,
    .advance = cvode_advance,
    .interpolate = cvode_interpolate,
    .stats = cvode_stats,
    .free = cvode_free,
    .rejections = cvode_rejections,
};
