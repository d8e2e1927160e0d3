/* Accuracy on request: the work-precision table as data, the pick from it, and the run that
   checks the pick against its error estimate and tightens until the request is met. */
#include "accuracy.h"

#include <math.h>
#include <stdio.h>

#include "method.h"
#include "scene.h"

/* docs/trade.md, seed scene, one machine: for each method and rtol (atol = rtol / 100) the
   finish/death time error in s and the median wall time in ms. Non-stiff: the worse of the
   survive (10 N) and die (100 N) cases' errors, survive's time; stiff: 100 N with joint
   damping 1e4 N m s/rad. Update it with `zipopt bench trade` when a method changes. */
typedef struct {
    int method;
    double rtol;
    double err, ms;             /* non-stiff */
    double stiff_err, stiff_ms; /* stiff */
} trade_row;

#define A ZP_METHOD_CVODE_ADAMS
#define B ZP_METHOD_CVODE_BDF
#define R8 ZP_METHOD_GSL_RK8PD
#define R4 ZP_METHOD_GSL_RK4IMP
static const trade_row trade[] = {
    {A, 1e-3, 3.0e-3, 1.10, 8.0e-4, 95.7},     {A, 1e-4, 1.4e-3, 1.51, 8.3e-4, 91.8},
    {A, 1e-5, 1.8e-5, 2.06, 7.8e-4, 81.0},     {A, 1e-6, 1.4e-5, 2.73, 2.0e-4, 86.6},
    {A, 1e-7, 2.5e-6, 3.55, 3.6e-5, 219},      {A, 1e-8, 1.1e-7, 4.52, 8.1e-8, 78.5},
    {A, 1e-9, 2.6e-8, 6.26, 1.6e-8, 284},      {A, 1e-10, 4.4e-9, 7.21, 3.9e-11, 536},
    {A, 1e-11, 2.0e-10, 8.98, 1.2e-10, 958},   {A, 1e-12, 5.1e-11, 11.5, 7.5e-11, 428},
    {B, 1e-3, 1.3e-2, 1.80, 6.1e-3, 1.21},     {B, 1e-4, 6.2e-4, 2.18, 1.3e-4, 1.46},
    {B, 1e-5, 5.5e-4, 3.00, 1.1e-7, 1.79},     {B, 1e-6, 2.4e-5, 4.17, 8.0e-6, 2.36},
    {B, 1e-7, 4.3e-6, 5.60, 1.0e-6, 3.12},     {B, 1e-8, 4.0e-7, 7.83, 1.4e-7, 4.20},
    {B, 1e-9, 1.5e-7, 15.8, 2.1e-8, 5.87},     {B, 1e-10, 4.3e-9, 16.0, 6.0e-9, 11.1},
    {B, 1e-11, 2.4e-9, 23.4, 4.7e-10, 17.1},   {B, 1e-12, 2.4e-10, 34.0, 6.5e-11, 16.6},
    {R8, 1e-3, 6.4e-5, 3.58, 1.9e-9, 64.8},    {R8, 1e-4, 6.0e-6, 3.82, 2.8e-10, 66.5},
    {R8, 1e-5, 4.8e-7, 4.10, 1.5e-11, 110},    {R8, 1e-6, 4.8e-8, 4.55, 1.4e-12, 76.0},
    {R8, 1e-7, 4.4e-9, 5.15, 8.1e-13, 93.9},   {R8, 1e-8, 5.5e-10, 5.82, 1.0e-12, 94.2},
    {R8, 1e-9, 4.7e-11, 6.61, 1.1e-12, 62.2},  {R8, 1e-10, 5.4e-12, 7.84, 9.4e-13, 73.8},
    {R8, 1e-11, 4.4e-13, 9.09, 1.8e-12, 89.6}, {R8, 1e-12, 2e-14, 11.6, 2.0e-12, 115},
    {R4, 1e-3, 1.1e-4, 14.2, 8.7e-6, 6.26},    {R4, 1e-4, 3.5e-5, 16.2, 1.4e-7, 7.09},
    {R4, 1e-5, 8.8e-6, 19.7, 7.5e-9, 8.89},    {R4, 1e-6, 6.7e-7, 25.4, 3.2e-10, 15.9},
    {R4, 1e-7, 1.3e-7, 44.7, 1.7e-11, 16.9},   {R4, 1e-8, 2.0e-8, 46.8, 1.7e-11, 25.8},
    {R4, 1e-9, 3.2e-9, 65.9, 1.2e-13, 41.7},   {R4, 1e-10, 5.2e-10, 98.9, 9.9e-13, 68.0},
    {R4, 1e-11, 8.0e-11, 147, 1.1e-12, 115},   {R4, 1e-12, 1.1e-11, 272, 9.4e-13, 170},
};
#undef A
#undef B
#undef R8
#undef R4
#define NTRADE (int)(sizeof trade / sizeof *trade)

void zp_accuracy_pick(double acc, int method, int stiff, zp_sim_opts *o) {
    int best = -1, closest = -1;
    for (int i = 0; i < NTRADE; i++) {
        const trade_row *t = &trade[i];
        if (method >= 0 && t->method != method) {
            continue;
        }
        double err = stiff ? t->stiff_err : t->err, ms = stiff ? t->stiff_ms : t->ms;
        if (closest < 0 || err < (stiff ? trade[closest].stiff_err : trade[closest].err)) {
            closest = i;
        }
        if (err * ZP_ACCURACY_MARGIN <= acc &&
            (best < 0 || ms < (stiff ? trade[best].stiff_ms : trade[best].ms))) {
            best = i;
        }
    }
    const trade_row *t = &trade[best >= 0 ? best : closest];
    o->method = t->method;
    o->rtol = t->rtol;
    o->atol = t->rtol / 100;
}

int zp_accuracy_stiff(const zp_scene *sc) {
    for (int j = 0; j < sc->ndamping; j++) {
        if (sc->damping[j] > ZP_ACCURACY_STIFF_DAMPING) {
            return 1;
        }
    }
    return 0;
}

/* the estimate meets the request: the tighter run worked and agrees on the verdict */
static int meets(const zp_estimate *e, double acc) {
    return e->ok && !e->sensitive && e->time_error <= acc;
}

zp_status zp_accuracy_run(const zp_model *m, zp_sim_opts *o, const zp_input *in, double acc,
                          zp_sim **s, zp_result *r, zp_estimate *e, zp_accuracy *a) {
    *a = (zp_accuracy){.requested = acc, .met = NAN, .reruns = -1};
    for (;;) {
        a->reruns++;
        *s = zp_sim_create(m, o);
        if (!*s) {
            snprintf(r->message, sizeof r->message, "cannot create the simulator (out of memory)");
            return ZP_ERR_NOMEM;
        }
        zp_status st = zp_sim_run(m, *s, in, r);
        if (st != ZP_OK) {
            return st;
        }
        zp_estimate_run(m, o, in, r, e);
        if (meets(e, acc) || o->rtol <= ZP_RTOL_MIN) {
            break;
        }
        zp_sim_free(*s);
        zp_sim_opts t = zp_estimate_tighter(o);
        o->rtol = t.rtol;
        o->atol = t.atol;
    }
    a->met = e->ok ? e->time_error : NAN;
    a->ok = meets(e, acc);
    a->method = o->method;
    a->rtol = o->rtol;
    return ZP_OK;
}
