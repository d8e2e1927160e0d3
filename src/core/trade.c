/* The work-precision study (trade.h). */
#include "trade.h"

#include <math.h>
#include <stdlib.h>

#include "sim_opts.h"

#define REPEAT_BUDGET 1.0 /* s: wall time the repeats of one configuration may take */

const zp_trade_case zp_trade_cases[ZP_TRADE_NCASE] = {
    {"survive", 10, -1, ZP_METHOD_CVODE_ADAMS},
    {"die", 100, -1, ZP_METHOD_CVODE_ADAMS},
    {"stiff", 100, 1e4, ZP_METHOD_CVODE_BDF},
};

const double zp_trade_targets[ZP_TRADE_NTARGET] = {1e-3, 1e-6, 1e-9};

void zp_trade_init(zp_trade_study *st) {
    for (int t = 0; t < ZP_TRADE_NTOL; t++) {
        st->tols[t] = pow(10, -3 - t);
    }
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static zp_trade_reading read_result(const zp_model *m, const zp_result *r, const zp_sim *s) {
    zp_trade_reading d = {.ok = 1,
                          .outcome = r->outcome,
                          .died_link = r->died_link,
                          .time = r->time,
                          .x = r->x,
                          .v = r->v,
                          .evals = r->rhs_evals,
                          .steps = r->steps,
                          .rejected = r->rejected};
    int n;
    const zp_crossing *cross = zp_sim_crossings(s, &n);
    d.nimp = r->ncross;
    for (int k = 0; k < n && k < ZP_TRADE_MAX_IMPULSES; k++) {
        d.impulse[k] = cross[k].impulse;
    }
    for (int i = 0; i < m->nlink; i++) {
        d.angle[i] = r->max_rel_angle[i] * 180 / M_PI;
    }
    return d;
}

/* one configuration: runs repeated within REPEAT_BUDGET (at most max_rep), median wall */
static zp_trade_reading measure(const zp_model *m, zp_sim_opts o, const zp_schedule *sched,
                                int max_rep) {
    zp_result r;
    zp_trade_reading d = {0};
    zp_sim *s = zp_sim_create(m, &o);
    if (!s) {
        return d;
    }
    zp_input in = {.sched = sched};
    double walls[64];
    int n = 0;
    for (double spent = 0; n < max_rep && n < 64 && (n == 0 || spent < REPEAT_BUDGET); n++) {
        if (zp_sim_run(m, s, &in, &r) != ZP_OK) {
            zp_sim_free(s);
            return d;
        }
        walls[n] = r.wall_s;
        spent += r.wall_s;
    }
    d = read_result(m, &r, s);
    qsort(walls, n, sizeof *walls, cmp_double);
    d.wall = n % 2 ? walls[n / 2] : 0.5 * (walls[n / 2 - 1] + walls[n / 2]);
    d.repeats = n;
    zp_sim_free(s);
    return d;
}

static zp_trade_errors compare(const zp_model *m, const zp_trade_reading *a,
                               const zp_trade_reading *ref) {
    zp_trade_errors e = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
    if (!a->ok || a->outcome != ref->outcome || a->died_link != ref->died_link) {
        return e;
    }
    e.time = fabs(a->time - ref->time);
    e.x = fabs(a->x - ref->x);
    e.v = fabs(a->v - ref->v);
    e.angle = 0;
    for (int i = 0; i < m->nlink; i++) {
        e.angle = fmax(e.angle, fabs(a->angle[i] - ref->angle[i]));
    }
    if (a->nimp == ref->nimp) {
        e.impulse = 0;
        for (int k = 0; k < a->nimp && k < ZP_TRADE_MAX_IMPULSES; k++) {
            e.impulse = fmax(e.impulse, fabs(a->impulse[k] - ref->impulse[k]));
        }
    }
    return e;
}

static double worst(zp_trade_errors e) {
    return fmax(fmax(e.time, e.impulse), fmax(fmax(e.angle, e.x), e.v));
}

/* the model and options of case c on the scene base, at its schedule (sched); NULL with the
   scene's problems in d */
static zp_model *case_model(const zp_scene *base, int c, zp_sim_opts *o, zp_schedule *sched,
                            zp_diag *d) {
    const zp_trade_case *tc = &zp_trade_cases[c];
    zp_scene sc = *base;
    zp_schedule shape = zp_drive_of_scene(&sc);
    *sched = zp_drive_constant(&shape, tc->force);
    if (tc->damping >= 0) {
        sc.ndamping = 1;
        sc.damping[0] = tc->damping;
    }
    zp_model *m = zp_model_build(&sc, d);
    if (!m || zp_sim_opts_from_scene(&sc, o, d)) {
        zp_model_free(m);
        return NULL;
    }
    o->output_dt = 0; /* integration and events only, as the search runs */
    o->track_loads = 0;
    return m;
}

zp_status zp_trade_run(const zp_scene *base, int c, int repeats, zp_trade_study *st,
                       void (*on_reference)(void *user, const zp_trade_study *st, int c),
                       void *user, zp_diag *d) {
    zp_sim_opts o;
    zp_schedule sched;
    zp_model *m = case_model(base, c, &o, &sched, d);
    if (!m) {
        return ZP_ERR_INPUT;
    }
    /* the reference: gsl-rk8pd and a CVODE method at ZP_TRADE_REF_RTOL, and how well they
       agree */
    o.rtol = ZP_TRADE_REF_RTOL;
    o.atol = ZP_TRADE_REF_RTOL * ZP_TRADE_ATOL_RATIO;
    o.method = ZP_METHOD_GSL_RK8PD;
    const zp_trade_reading *ref = &st->ref[c];
    st->ref[c] = measure(m, o, &sched, 1);
    o.method = zp_trade_cases[c].ref_cvode;
    zp_trade_reading ref2 = measure(m, o, &sched, 1);
    st->agree[c] = compare(m, &ref2, ref);
    if (on_reference) {
        on_reference(user, st, c);
    }
    if (!ref->ok || !isfinite(worst(st->agree[c]))) {
        zp_model_free(m);
        return ZP_ERR_NUMERIC;
    }
    for (int k = 0; k < ZP_METHOD_COUNT; k++) {
        for (int t = 0; t < ZP_TRADE_NTOL; t++) {
            o.method = k;
            o.rtol = st->tols[t];
            o.atol = st->tols[t] * ZP_TRADE_ATOL_RATIO;
            st->runs[c][k][t] = measure(m, o, &sched, repeats);
            st->errs[c][k][t] = compare(m, &st->runs[c][k][t], ref);
        }
    }
    zp_model_free(m);
    return ZP_OK;
}

double zp_trade_fastest(const zp_trade_study *st, double target, int c, int *bk, int *bt) {
    double best = INFINITY;
    *bk = *bt = -1;
    int c0 = c == ZP_TRADE_NCASE ? 0 : c, c1 = c == ZP_TRADE_NCASE ? ZP_TRADE_NCASE : c + 1;
    for (int k = 0; k < ZP_METHOD_COUNT; k++) {
        for (int t = 0; t < ZP_TRADE_NTOL; t++) {
            double e = 0, w = 0;
            for (int cc = c0; cc < c1; cc++) {
                e = fmax(e, st->errs[cc][k][t].time);
                w += st->runs[cc][k][t].wall;
            }
            if (e <= target && w < best) {
                best = w;
                *bk = k;
                *bt = t;
            }
        }
    }
    return best;
}
