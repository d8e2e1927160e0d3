/* Accuracy on request: the work-precision table as data, the pick from it, and the run that
   checks the pick against its error estimate and tightens until the request is met. */
#include "accuracy.h"

#include <math.h>
#include <stdio.h>

#include "method.h"
#include "scene.h"

/* docs/trade.md, seed scene, one machine: for each method and rtol (atol = rtol / 100) the
   finish/death time error in s and the median wall time in ms (the least of three runs of the
   study: the machine was shared). Non-stiff: the worse of the survive (10 N) and die (100 N)
   cases' errors, survive's time; stiff: 100 N with joint damping 1e4 N m s/rad. Update it
   with `zipopt bench trade` when a method changes. */
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
    {A, 1e-3, 3.0e-3, 0.338, 8.2e-4, 50.9},    {A, 1e-4, 1.4e-3, 0.459, 8.4e-4, 53.6},
    {A, 1e-5, 1.8e-5, 0.646, 7.8e-4, 55.6},    {A, 1e-6, 1.4e-5, 0.843, 2.3e-4, 57.7},
    {A, 1e-7, 2.4e-6, 1.13, 3.6e-5, 155},      {A, 1e-8, 1.4e-7, 1.43, 4.1e-8, 58.8},
    {A, 1e-9, 2.6e-8, 1.9, 2.5e-8, 119},       {A, 1e-10, 4.4e-9, 6.33, 1.5e-10, 199},
    {A, 1e-11, 3.4e-10, 6.86, 1.1e-10, 672},   {A, 1e-12, 2.4e-11, 7.6, 6.8e-11, 547},
    {B, 1e-3, 1.3e-2, 0.607, 3.1e-3, 0.378},   {B, 1e-4, 6.1e-4, 0.752, 1.7e-4, 0.482},
    {B, 1e-5, 5.6e-4, 1.02, 5.3e-5, 0.595},    {B, 1e-6, 2.4e-5, 1.38, 8.8e-6, 0.79},
    {B, 1e-7, 4.3e-6, 1.93, 3.0e-7, 1.04},     {B, 1e-8, 4.0e-7, 2.72, 1.4e-7, 1.36},
    {B, 1e-9, 1.5e-7, 7.76, 2.1e-8, 1.9},      {B, 1e-10, 1.2e-8, 9.45, 6.0e-9, 2.62},
    {B, 1e-11, 8.7e-10, 16, 4.7e-10, 7.73},    {B, 1e-12, 3.9e-10, 23.3, 7.0e-11, 9.43},
    {R8, 1e-3, 3.9e-4, 0.17, 4.5e-10, 21.1},   {R8, 1e-4, 1.4e-5, 0.203, 2.6e-9, 18.7},
    {R8, 1e-5, 6.2e-7, 0.251, 1.2e-11, 18.3},  {R8, 1e-6, 1.1e-7, 0.306, 3.0e-11, 18.2},
    {R8, 1e-7, 6.6e-9, 0.381, 8.3e-13, 19.1},  {R8, 1e-8, 1.1e-10, 0.495, 1.1e-12, 14.3},
    {R8, 1e-9, 5.1e-11, 0.641, 1.5e-12, 17.7}, {R8, 1e-10, 7.3e-12, 0.815, 1.6e-12, 23.1},
    {R8, 1e-11, 9.0e-13, 1.07, 2.4e-12, 25.7}, {R8, 1e-12, 3.1e-13, 1.38, 2.1e-12, 32.4},
    {R4, 1e-3, 5.3e-4, 1.23, 9.4e-6, 0.824},   {R4, 1e-4, 8.0e-5, 1.95, 2.0e-7, 1.08},
    {R4, 1e-5, 7.7e-6, 6.81, 9.7e-9, 1.63},    {R4, 1e-6, 7.8e-7, 4.38, 3.1e-9, 4.01},
    {R4, 1e-7, 1.2e-7, 6.73, 3.8e-11, 8.03},   {R4, 1e-8, 2.2e-8, 21.3, 1.9e-11, 14},
    {R4, 1e-9, 3.2e-9, 32.6, 8.0e-13, 22.3},   {R4, 1e-10, 5.1e-10, 66.9, 9.9e-13, 33},
    {R4, 1e-11, 8.0e-11, 64.7, 1.3e-12, 55.6}, {R4, 1e-12, 1.2e-11, 116, 9.4e-13, 91},
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
