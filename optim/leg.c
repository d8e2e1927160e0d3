/* The search's legs (leg.h): the variables a strategy sees mapped to parameters, one
   simulation per point however often the strategy asks there, and batches of legs with
   budgets fixed in order. */
#include "leg.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define XTOL 1e-3      /* N: the parameters' resolution */
#define DIAG_XTOL 1e-6 /* share of the box: the resolution of the one variable of the pushes */

void zp_leg_params(const zp_leg *leg, const double *x, double *f) {
    const zp_search_state *S = leg->S;
    for (int k = 0; k < S->n; k++) {
        double v = leg->diag ? S->lo[k] + (S->hi[k] - S->lo[k]) * x[0] : x[k];
        f[k] = fmin(fmax(v, S->lo[k]), S->hi[k]);
    }
}

/* e, `at` simulations into the leg, into its improvements; out of memory, it takes the last
   one's place, so the history still reaches the leg's best */
static void improved(zp_leg *leg, long at, const zp_eval *e) {
    if (leg->nimp == leg->imp_cap) {
        int cap = leg->imp_cap ? 2 * leg->imp_cap : 16;
        zp_leg_imp *grown = realloc(leg->imp, sizeof *grown * (size_t)cap);
        if (grown) {
            leg->imp = grown;
            leg->imp_cap = cap;
        } else if (leg->nimp > 0) {
            leg->nimp--;
        } else {
            return;
        }
    }
    leg->imp[leg->nimp++] = (zp_leg_imp){at, *e};
}

const zp_eval *zp_leg_eval(zp_leg *leg, const double *x) {
    zp_search_state *S = leg->S;
    if (leg->have && !memcmp(x, leg->key, sizeof *x * leg->nx)) {
        return &leg->e;
    }
    if (leg->n >= leg->budget || zp_search_state_stopped(S)) {
        leg->have = 0;
        return NULL;
    }
    double f[ZP_SCHED_MAX_PARAMS];
    zp_leg_params(leg, x, f);
    zp_search_state_eval(S, leg->sim, leg->r, f, &leg->e, leg->nparts > 1 ? leg->parts : NULL);
    memcpy(leg->key, x, sizeof *x * leg->nx);
    leg->have = 1;
    leg->n++;
    if (leg->n == 1 || zp_search_state_ahead(&leg->e, f, &leg->best, leg->bestf, S->n)) {
        leg->best = leg->e;
        memcpy(leg->bestf, f, sizeof *f * S->n);
        if (zp_objective_feasible(&leg->e) && leg->e.time < leg->bar) {
            improved(leg, leg->n, &leg->e);
        }
    }
    if (leg->archive) {
        zp_search_state_add(S, f, &leg->e);
    }
    return &leg->e;
}

double zp_leg_spent_score(const zp_leg *leg) {
    return 3 * leg->S->ob->t_max;
}

int zp_leg_charge(zp_leg *leg, long runs) {
    int fits = leg->n + runs <= leg->budget;
    leg->n = fits ? leg->n + runs : leg->budget;
    return fits && !zp_search_state_stopped(leg->S) ? 0 : -1;
}

/* the leg of job j with the given budget: its variables, their bounds and its start */
static void leg_init(zp_leg *leg, zp_search_state *S, const zp_leg_job *j, long budget) {
    *leg = (zp_leg){.nx = j->diag ? 1 : S->n,
                    .step = j->step,
                    .xtol = j->diag ? DIAG_XTOL : XTOL,
                    .budget = budget,
                    .user = j->user,
                    .S = S,
                    .diag = j->diag,
                    .archive = j->archive,
                    .bar = S->running};
    for (int k = 0; k < leg->nx; k++) {
        leg->lo[k] = j->diag ? 0 : S->lo[k];
        leg->hi[k] = j->diag ? 1 : S->hi[k];
        leg->x0[k] = j->x0[k];
    }
    if (j->diag) {
        int k = 0; /* the start's share of the box, read off a parameter with a range */
        while (k + 1 < S->n && S->hi[k] == S->lo[k]) {
            k++;
        }
        leg->x0[0] = S->hi[k] > S->lo[k] ? (j->x0[k] - S->lo[k]) / (S->hi[k] - S->lo[k]) : 0;
    }
}

int zp_leg_polish_within(zp_leg *leg, zp_leg_run run, const void *how, const double *x0,
                         const double *step, long cap, zp_leg_rec *out) {
    zp_search_state *S = leg->S;
    long left = leg->budget - leg->n;
    if (left <= 0 || zp_search_state_stopped(S)) {
        return -1;
    }
    zp_leg_job job = {.x0 = x0, .step = step, .user = leg->user};
    zp_leg sub;
    leg_init(&sub, S, &job, cap < left ? cap : left);
    sub.sim = leg->sim;
    sub.r = leg->r;
    run(how, &sub);
    for (int j = 0; j < sub.nimp; j++) {
        if (!zp_objective_better(&sub.imp[j].e, &leg->best) && leg->n > 0) {
            continue;
        }
        improved(leg, leg->n + sub.imp[j].at, &sub.imp[j].e);
    }
    free(sub.imp);
    if (sub.n > 0 && (leg->n == 0 ||
                      zp_search_state_ahead(&sub.best, sub.bestf, &leg->best, leg->bestf, S->n))) {
        leg->best = sub.best;
        memcpy(leg->bestf, sub.bestf, sizeof *leg->bestf * S->n);
    }
    leg->n += sub.n;
    leg->have = 0; /* the workspace ran the polish's points since */
    if (sub.refused) {
        leg->refused = 1;
        memcpy(leg->why, sub.why, sizeof leg->why);
    }
    memcpy(out->start, x0, sizeof *out->start * S->n);
    memcpy(out->end, sub.n > 0 ? sub.bestf : x0, sizeof *out->end * S->n);
    out->e = sub.best;
    out->n = sub.n;
    out->at = -1;
    return 0;
}

typedef struct leg_batch {
    zp_leg_run run;
    const void *how;
    zp_leg *legs;
} leg_batch;

static void leg_job(void *user, int i, zp_sim *s, zp_result *r) {
    leg_batch *b = user;
    zp_leg *leg = &b->legs[i];
    leg->sim = s;
    leg->r = r;
    if (leg->budget > 0 && !zp_search_state_stopped(leg->S)) {
        b->run(b->how, leg);
    }
}

/* the leg's improvements into the serial history, its simulations into the count, and what it
   came to into job's record */
static void fold(zp_search_state *S, const zp_leg *leg, const zp_leg_job *job) {
    for (int j = 0; j < leg->nimp; j++) {
        zp_search_state_record(S, S->spent + leg->imp[j].at, &leg->imp[j].e);
    }
    S->spent += leg->n;
    zp_leg_rec *o = job->out;
    if (o) {
        memcpy(o->start, job->x0, sizeof *o->start * S->n);
        memcpy(o->end, leg->n > 0 ? leg->bestf : job->x0, sizeof *o->end * S->n);
        o->e = leg->best;
        o->n = leg->n;
        o->at = -1;
    }
}

zp_status zp_leg_batch(zp_search_state *S, zp_leg_run run, const void *how, const zp_leg_job *jobs,
                       int njob, char *err, size_t errlen) {
    leg_batch b = {run, how, calloc(njob ? njob : 1, sizeof *b.legs)};
    if (!b.legs) {
        snprintf(err, errlen, "out of memory for the polish");
        return ZP_ERR_NOMEM;
    }
    /* budgets fixed in order before any runs: a smaller budget cuts the same legs short */
    long left = S->o->max_evals - S->spent;
    for (int i = 0; i < njob; i++) {
        leg_init(&b.legs[i], S, &jobs[i], left < jobs[i].cap ? (left > 0 ? left : 0) : jobs[i].cap);
        S->exhausted |= left <= jobs[i].cap;
        left -= b.legs[i].budget;
    }
    zp_pool_map(S->pool, njob, leg_job, &b, NULL, NULL);
    zp_status st = ZP_OK;
    for (int i = 0; i < njob; i++) {
        const zp_leg *leg = &b.legs[i];
        if (leg->budget > 0 && leg->refused) {
            snprintf(err, errlen, "%s", leg->why);
            st = ZP_ERR_INPUT;
        }
        fold(S, leg, &jobs[i]);
        free(leg->imp);
    }
    free(b.legs);
    return st;
}
