/* Forces -> zp_sim_run -> finish time and survival constraint, in the nominal
   scene and in the scenarios of a robust set. Runs that die, stall or break down still score
   by how far they got, so a search can climb out of deadly regions; nothing here ever returns
   NaN or infinity. */
#include "objective.h"

#include <math.h>

#define DEG (180.0 / M_PI)
/* deg kept below the limit besides the margin, so that the margin also holds when the run is
   verified at a 100x tighter tolerance (angles move by ~1e-5 deg between the two) */
#define SLACK 1e-3
/* deg of constraint per unit of relative excess over a [limits] value (10 % over: 9 deg), and
   the relative slack kept below each limit for the same reason as SLACK */
#define LIMIT_DEG 90.0
#define LIMIT_SLACK 1e-5

static void set_score(const zp_objective *ob, zp_eval *e) {
    /* penalty weight: a violation by half a turn costs as much as running out of time */
    e->score = e->obj + fmax(e->cons, 0) * ob->t_max / 180;
}

void zp_objective_eval_run(const zp_objective *ob, const zp_model *m, zp_sim *s, const zp_input *in,
                           zp_eval *e, zp_result *r) {
    int failed = zp_sim_run(m, s, in, r) != ZP_OK;
    double angle = zp_model_angle_used(m, r->max_rel_angle);
    double span = m->xb[m->nsec] - m->xb[0];
    double progress = fmin(fmax((r->x - m->xb[0]) / span, 0), 1);
    if (failed || !isfinite(progress) || !isfinite(angle) || !isfinite(r->time)) {
        progress = 0;
        angle = m->phi_max;
    }
    *e = (zp_eval){.outcome = r->outcome,
                   .failed = failed,
                   .time = r->time,
                   .x = r->x,
                   .angle = angle,
                   .scenario = -1};
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
    } else if (zp_limits_any(&ob->lim)) {
        int which;
        double ex = zp_limits_excess(&ob->lim, m, r, &which);
        e->cons = fmax(e->cons, (ex + LIMIT_SLACK) * LIMIT_DEG);
    }
    set_score(ob, e);
}

double zp_objective_margin_cons(const zp_objective *ob, const zp_eval *e) {
    return (e->angle - ob->limit) * DEG + SLACK;
}

double zp_objective_limit_cons(const zp_objective *ob, int i, double v, double *per_unit) {
    double max = ob->lim.max[i], sign = i == ZP_LIMIT_MIN_ARRIVAL ? -1 : 1;
    /* zp_limits_excess_of's relative excess of this limit alone */
    double ex = sign * (v / max - 1);
    *per_unit = sign * LIMIT_DEG / max;
    return ((isfinite(ex) ? ex : 1) + LIMIT_SLACK) * LIMIT_DEG;
}

double zp_objective_scenario_cons(const zp_objective *ob, const zp_eval *e) {
    /* a scenario that stalls breaks the schedule too, more the earlier it stops */
    if (e->failed || e->outcome != ZP_OUTCOME_FINISHED) {
        return fmax(e->cons, 1 + 180 * (e->obj / ob->t_max - 1));
    }
    return e->cons;
}

zp_schedule zp_objective_schedule(const zp_objective *ob, const double *p) {
    if (ob->shape) {
        return zp_drive_with(ob->shape, p);
    }
    return zp_drive_sections(ob->m->nsec, p, -INFINITY, INFINITY);
}

int zp_objective_eval_nominal(const zp_objective *ob, zp_sim *s, const zp_schedule *sched,
                              zp_eval *e, zp_result *r, double *parts) {
    zp_input in = {.sched = sched};
    zp_objective_eval_run(ob, ob->m, s, &in, e, r);
    if (parts) {
        zp_objective_parts_of(ob, ob->m, e, r, parts);
    }
    return ob->set && ob->set->n > 0 && zp_objective_feasible(e);
}

double zp_objective_scenario(const zp_objective *ob, int i, const zp_schedule *sched, zp_sim *s,
                             zp_result *r, double *obj, double *parts) {
    const zp_scen_set *set = ob->set;
    int j = set->order[i];
    const zp_objective *oj = set->judge && set->judge[j].m ? &set->judge[j] : ob;
    zp_input in = {.sched = sched, .force_scale = set->sc[j].force, .start = &set->start[j]};
    zp_eval ej;
    zp_objective_eval_run(oj, &set->m[j], s, &in, &ej, r);
    if (obj) {
        *obj = ej.obj;
    }
    double cons = zp_objective_scenario_cons(oj, &ej);
    if (parts) {
        zp_objective_parts_of(ob, &set->m[j], &ej, r, parts);
        for (int k = 0, n = zp_objective_parts_count(ob); k < n && cons > ej.cons; k++) {
            parts[k] = cons; /* it stalled: every part broken as the whole */
        }
    }
    return cons;
}

void zp_objective_eval_close(const zp_objective *ob, int nrun, int broke, zp_eval *e) {
    zp_scen_set *set = ob->set;
#pragma omp atomic
    set->runs += nrun;
    if (broke) {
        e->scenario = set->order[nrun - 1];
#pragma omp atomic
        set->fails[e->scenario]++;
    }
    set_score(ob, e);
}

void zp_objective_eval(const zp_objective *ob, zp_sim *s, const double *p, zp_eval *e,
                       zp_result *r) {
    zp_objective_eval_parts(ob, s, p, e, r, NULL);
}

void zp_objective_eval_parts(const zp_objective *ob, zp_sim *s, const double *p, zp_eval *e,
                             zp_result *r, double *parts) {
    zp_schedule sched = zp_objective_schedule(ob, p);
    if (!zp_objective_eval_nominal(ob, s, &sched, e, r, parts)) {
        return;
    }
    int i = 0, broke = 0;
    while (i < ob->set->n && !broke) {
        double obj, sp[ZP_OBJECTIVE_PARTS_MAX];
        double cons = zp_objective_scenario(ob, i++, &sched, s, r, &obj, parts ? sp : NULL);
        if (parts) {
            zp_objective_parts_fold(ob, parts, sp);
        }
        e->cons = fmax(e->cons, cons);
        e->obj = ob->slowest ? fmax(e->obj, obj) : e->obj;
        broke = cons > 0;
    }
    zp_objective_eval_close(ob, i, broke, e);
}

int zp_objective_nscenarios(const zp_objective *ob) {
    return ob->set ? ob->set->n : 0;
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

int zp_objective_parts_count(const zp_objective *ob) {
    int n = 1;
    for (int i = 0; !(ob->set && ob->set->judge) && i < ZP_LIMIT_COUNT; i++) {
        n += ob->lim.max[i] > 0;
    }
    return n;
}

void zp_objective_parts_fold(const zp_objective *ob, double *acc, const double *c) {
    for (int k = 0, n = zp_objective_parts_count(ob); k < n; k++) {
        acc[k] = fmax(acc[k], c[k]);
    }
}

void zp_objective_parts_of(const zp_objective *ob, const zp_model *m, const zp_eval *e,
                           const zp_result *r, double *c) {
    int n = zp_objective_parts_count(ob);
    if (n == 1 || e->failed || e->outcome != ZP_OUTCOME_FINISHED) {
        for (int k = 0; k < n; k++) {
            c[k] = e->cons;
        }
        return;
    }
    double v[ZP_LIMIT_COUNT];
    zp_limits_judged(&ob->lim, m, r, v); /* what e->cons judged, at its cost */
    c[0] = zp_objective_margin_cons(ob, e);
    for (int i = 0, k = 1; i < ZP_LIMIT_COUNT; i++) {
        double per_unit;
        if (ob->lim.max[i] > 0) {
            c[k++] = zp_objective_limit_cons(ob, i, v[i], &per_unit);
        }
    }
}
