/* The levels of what robustness costs (tradeoff.h). */
#include "tradeoff.h"

#include <string.h>

#define KMH 3.6

void zp_tradeoff_init(zp_tradeoff *T, const zp_problem *su, const double *level, int n, int given,
                      int power) {
    memset(T, 0, sizeof *T); /* large: no temporary of it on the stack */
    T->su = su;
    T->n = n;
    T->given = given;
    T->power = power;
    for (int i = 0; i < n; i++) {
        T->L[i].p = level[i];
    }
}

double zp_tradeoff_cost(const zp_tradeoff *T, int i) {
    return T->L[i].time - T->L[0].time;
}

/* the answer's arrival speed: one nominal run at the search's tolerance */
static int arrival_of(const zp_tradeoff *T, int i, double *kmh, char *err, size_t errlen) {
    const zp_problem *su = T->su;
    zp_sim *s = zp_sim_create(su->m, &T->pb[i].search);
    zp_schedule sched = zp_drive_with(&T->pb[i].sched, T->L[i].force);
    zp_input in = {.sched = &sched};
    static zp_result run;
    int bad = !s || zp_sim_run(su->m, s, &in, &run);
    if (bad) {
        snprintf(err, errlen, "the answer's run failed: %s", s ? run.message : "out of memory");
    } else {
        *kmh = run.v * KMH;
    }
    zp_sim_free(s);
    return bad ? -1 : 0;
}

zp_status zp_tradeoff_solve(zp_tradeoff *T, int i,
                            void (*progress)(void *user, const zp_search_progress *p, int improved),
                            void *user, char *err, size_t errlen) {
    zp_tradeoff_level *out = &T->L[i];
    zp_problem *pb = &T->pb[i];
    *pb = *T->su;
    if (T->power) {
        pb->sc.drive_power = out->p;
        pb->sched.power = out->p;
    } else {
        pb->sc.force_error = out->p;
        pb->sc.robust = pb->sc.robust || out->p > 0;
    }
    zp_answer_opts o = zp_answer_opts_of(pb, ZP_ANSWER_SEARCHED);
    o.search.max_time = T->max_time;
    o.search.stop = T->stop;
    o.search.progress = progress;
    o.search.user = user;
    zp_status st = zp_answer_solve(pb, &o, &T->ans[i], err, errlen);
    if (st) {
        return st;
    }
    const zp_search_result *res = &T->ans[i].res;
    out->found = res->found;
    out->done = !res->interrupted;
    out->from = i;
    out->time = res->best.time;
    out->scenarios = zp_answer_scenarios(&T->ans[i]);
    out->check = T->ans[i].rp.check;
    memcpy(out->force, res->force, sizeof out->force);
    return arrival_of(T, i, &out->arrival, err, errlen) ? ZP_ERR_NUMERIC : ZP_OK;
}

/* level i adopts the fastest other answer (or the given schedule) that survives its held
   scenarios; 1 when it did, 0 when its own stands, -1 out of memory */
static int adopt(zp_tradeoff *T, int i) {
    const zp_problem *su = T->su;
    zp_tradeoff_level *L = &T->L[i];
    zp_robust_problem *rp = &T->ans[i].rp;
    zp_sim *s = zp_sim_create(su->m, &T->pb[i].search);
    if (!s) {
        return -1;
    }
    int adopted = 0;
    for (int j = -1; j < T->ndone; j++) { /* -1: the schedule the scene or user gave */
        if (j < 0 ? !T->given : j == i || !T->L[j].found || (L->found && T->L[j].time >= L->time)) {
            continue;
        }
        const double *p = j < 0 ? su->sched.p : T->L[j].force;
        zp_eval e;
        static zp_result r;
        zp_objective_eval(&rp->ob, s, p, &e, &r);
        if (zp_objective_feasible(&e) && (!L->found || e.time < L->time)) {
            memcpy(L->force, p, sizeof *p * (size_t)su->sched.np);
            L->time = e.time;
            L->found = adopted = 1;
            L->from = j < 0 ? ZP_TRADEOFF_GIVEN : T->L[j].from;
        }
    }
    zp_sim_free(s);
    return adopted;
}

/* Each level keeps the fastest of its own answer and the others' (and the schedule given)
   that survives its own held scenarios: an answer robust to +/-5 % is as good a candidate at
   +/-2 % as the +/-2 % search's, which may have stopped in a slower island. */
int zp_tradeoff_exchange(zp_tradeoff *T, char *err, size_t errlen) {
    const zp_problem *su = T->su;
    for (int i = 0; i < T->ndone; i++) {
        zp_tradeoff_level *L = &T->L[i];
        zp_robust_problem *rp = &T->ans[i].rp;
        int adopted = adopt(T, i);
        if (adopted < 0) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        if (!adopted) {
            continue;
        }
        if (rp->robust && zp_robust_verify(&rp->ob, &rp->box, &T->pb[i].verify, L->force,
                                           su->sc.verify_samples, su->seed, 0, NULL, &L->check)) {
            snprintf(err, errlen, "out of memory verifying the scenarios");
            return -1;
        }
        if (arrival_of(T, i, &L->arrival, err, errlen)) {
            return -1;
        }
    }
    return 0;
}

void zp_tradeoff_free(zp_tradeoff *T) {
    for (int i = 0; i < T->n; i++) {
        zp_answer_free(&T->ans[i]);
    }
}
