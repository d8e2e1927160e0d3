/* The survival landscape's runs (landscape.h): a list of schedules through the per-thread
   simulator pool, each reduced to its outcome and time. */
#include "landscape.h"

#include <math.h>

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
    zp_schedule sched = zp_schedule_with(w->shape, w->param + (size_t)k * w->shape->np);
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
