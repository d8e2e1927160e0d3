/* Forces -> zp_sim_run -> finish time and survival constraint (issue 4 item 1). Runs that die,
   stall or break down still score by how far they got, so a search can climb out of deadly
   regions; nothing here ever returns NaN or infinity. */
#include "objective.h"

#include <math.h>

#define DEG (180.0 / M_PI)
/* deg kept below the limit besides the margin, so that the margin also holds when the run is
   verified at a 100x tighter tolerance (angles move by ~1e-5 deg between the two) */
#define SLACK 1e-3

zp_schedule zp_objective_schedule(const zp_objective *ob, const double *p) {
    if (ob->shape) {
        return zp_schedule_with(ob->shape, p);
    }
    return zp_schedule_sections(ob->m->nsec, p, -INFINITY, INFINITY);
}

void zp_objective_eval(const zp_objective *ob, zp_sim *s, const double *p, zp_eval *e,
                       zp_result *r) {
    const zp_model *m = ob->m;
    zp_schedule sched = zp_objective_schedule(ob, p);
    zp_input in = {.sched = &sched};
    int failed = zp_sim_run(m, s, &in, r) != ZP_OK;
    double angle = 0;
    for (int i = 0; i < m->nlink; i++) {
        angle = fmax(angle, r->max_rel_angle[i]);
    }
    double span = m->xb[m->nsec] - m->xb[0];
    double progress = fmin(fmax((r->x - m->xb[0]) / span, 0), 1);
    if (failed || !isfinite(progress) || !isfinite(angle) || !isfinite(r->time)) {
        progress = 0;
        angle = m->phi_max;
    }
    *e = (zp_eval){.outcome = r->outcome, .failed = failed, .time = r->time, .x = r->x,
                   .angle = angle};
    /* a run that does not finish ranks after every finish (T <= t_max), nearer the end better;
       one that dies or breaks down also violates the constraint, more the earlier it stops */
    double behind = 1 - progress;
    if (!failed && r->outcome == ZP_OUTCOME_FINISHED) {
        e->obj = r->time;
    } else {
        e->obj = ob->t_max * (1 + behind);
    }
    e->cons = (angle - ob->limit) * DEG + SLACK;
    if (failed || r->outcome == ZP_OUTCOME_DIED) {
        e->cons = (m->phi_max - ob->limit) * DEG + 180 * behind;
    }
    /* penalty weight: a violation by half a turn costs as much as running out of time */
    e->score = e->obj + fmax(e->cons, 0) * ob->t_max / 180;
}

int zp_objective_feasible(const zp_eval *e) {
    return !e->failed && e->outcome == ZP_OUTCOME_FINISHED && e->cons <= 0;
}

int zp_objective_better(const zp_eval *a, const zp_eval *b) {
    int fa = zp_objective_feasible(a), fb = zp_objective_feasible(b);
    if (fa != fb) {
        return fa;
    }
    return a->score < b->score;
}
