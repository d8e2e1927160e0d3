/* The survival landscape's runs (landscape.h): the schedules a plan asks for, run through the
   per-thread simulator pool, each reduced to its outcome and time. */
#include "landscape.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pool.h"

typedef struct sweep {
    const zp_model *m;
    const zp_schedule *shape;
    const double *param;
    zp_landscape_point *out;
} sweep;

static void sweep_job(void *user, int k, zp_sim *s, zp_result *r) {
    const sweep *w = user;
    const zp_model *m = w->m;
    zp_schedule sched = zp_drive_with(w->shape, w->param + (size_t)k * w->shape->np);
    zp_input in = {.sched = &sched};
    zp_landscape_point *p = &w->out[k];
    p->failed = zp_sim_run(m, s, &in, r) != ZP_OK;
    p->outcome = r->outcome;
    p->stall = r->stall;
    p->time = r->time;
    p->x = r->x;
    p->died_link = r->died_link;
    zp_limits_reached(m, r, p->reached);
    p->max_rel_angle = zp_model_angle_used(m, r->max_rel_angle);
}

zp_status zp_landscape_sweep(const zp_model *m, const zp_sim_opts *o, const zp_schedule *shape,
                             const double *param, int n, zp_landscape_point *out,
                             zp_landscape_progress progress, void *user, const zp_spread *sp) {
    zp_pool *pool = zp_pool_create(m, o, 0);
    if (!pool) {
        return ZP_ERR_NOMEM;
    }
    sweep w = {m, shape, param, out};
    zp_status st = zp_spread_map(sp, pool, n, sweep_job, &w, out, sizeof *out, progress, user);
    zp_pool_free(pool);
    return st;
}

int zp_landscape_slice_runs(const zp_landscape_plan *p) {
    return p->si >= 0 ? p->rx.n * p->ry.n : 0;
}

double *zp_landscape_params(const zp_landscape_plan *p, const zp_schedule *base) {
    int np = base->np, n1 = p->push.n, n2 = zp_landscape_slice_runs(p);
    double *param = malloc(sizeof *param * (size_t)(n1 + n2) * (size_t)np);
    if (!param) {
        return NULL;
    }
    for (int k = 0; k < n1; k++) {
        zp_schedule push = zp_drive_constant(base, zp_fig_landscape_at(&p->push, k));
        memcpy(param + (size_t)k * np, push.p, sizeof *param * (size_t)np);
    }
    for (int k = 0; k < n2; k++) {
        double *f = param + (size_t)(n1 + k) * np;
        memcpy(f, base->p, sizeof *f * (size_t)np);
        f[p->si] = zp_fig_landscape_at(&p->rx, k % p->rx.n);
        f[p->sj] = zp_fig_landscape_at(&p->ry, k / p->rx.n);
    }
    return param;
}
