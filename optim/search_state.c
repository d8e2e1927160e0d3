/* The state of one search (search_state.h): the budget in the serial order, the evaluation
   entry point, the archive and the progress. */
#include "search_state.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PROGRESS_DT 0.25 /* s between progress reports */

static double zp_search_state_since(const zp_search_state *S) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (t.tv_sec - S->t0.tv_sec) + 1e-9 * (t.tv_nsec - S->t0.tv_nsec);
}

void zp_search_state_begin(zp_search_state *S, const zp_objective *ob, const double *lo,
                           const double *hi, const zp_search_opts *o, zp_search_result *res) {
    memset(res, 0, sizeof *res);
    /* the parameters: the schedule's, as its kind counts them */
    *S = (zp_search_state){.ob = ob,
                           .o = o,
                           .n = zp_objective_nparams(ob),
                           .lo = lo,
                           .hi = hi,
                           .res = res,
                           .running = INFINITY,
                           .phase = "scan"};
    clock_gettime(CLOCK_MONOTONIC, &S->t0);
}

zp_status zp_search_state_start(zp_search_state *S, const zp_sim_opts *so, char *err,
                                size_t errlen) {
    S->so = so;
    S->pool = zp_pool_create(S->ob->m, so, S->o->nthreads);
    if (!S->pool || (S->ob->set && zp_pool_help(S->pool, S->ob->m, so))) {
        snprintf(err, errlen, "out of memory creating the search's workspaces");
        return ZP_ERR_NOMEM;
    }
    return ZP_OK;
}

void zp_search_state_end(zp_search_state *S) {
    zp_search_result *res = S->res;
    const zp_search_opts *o = S->o;
    res->nthreads = S->pool ? zp_pool_threads(S->pool) : 0;
    res->interrupted = o->stop && *o->stop;
    res->timed_out = !res->interrupted && !res->converged && o->max_time > 0 &&
                     zp_search_state_since(S) > o->max_time;
    res->budget_out =
        !res->converged && !res->interrupted && !res->timed_out && zp_search_state_halted(S);
    res->wall_s = zp_search_state_since(S);
    zp_pool_free(S->pool);
    free(S->a.f);
    free(S->a.e);
}

int zp_search_state_stopped(const zp_search_state *S) {
    return (S->o->stop && *S->o->stop) ||
           (S->o->max_time > 0 && zp_search_state_since(S) > S->o->max_time);
}

int zp_search_state_halted(const zp_search_state *S) {
    return S->exhausted || S->spent >= S->o->max_evals || zp_search_state_stopped(S);
}

int zp_search_state_ahead(const zp_eval *a, const double *fa, const zp_eval *b, const double *fb,
                          int n) {
    if (zp_objective_better(a, b)) {
        return 1;
    }
    if (zp_objective_better(b, a)) {
        return 0;
    }
    for (int k = 0; k < n; k++) {
        if (fa[k] != fb[k]) {
            return fa[k] < fb[k];
        }
    }
    return 0;
}

typedef struct ranked {
    const zp_search_state *S;
    int i;
} ranked;

static int by_rank(const void *pa, const void *pb) {
    const ranked *a = pa, *b = pb;
    const zp_search_state *S = a->S;
    const double *fa = zp_search_state_point(S, a->i), *fb = zp_search_state_point(S, b->i);
    if (zp_search_state_ahead(&S->a.e[a->i], fa, &S->a.e[b->i], fb, S->n)) {
        return -1;
    }
    if (zp_search_state_ahead(&S->a.e[b->i], fb, &S->a.e[a->i], fa, S->n)) {
        return 1;
    }
    return (a->i > b->i) - (a->i < b->i);
}

int zp_search_state_rank(const zp_search_state *S, int *idx, int n) {
    ranked *r = malloc(sizeof *r * (n ? n : 1));
    if (!r) {
        return -1;
    }
    for (int j = 0; j < n; j++) {
        r[j] = (ranked){S, idx[j]};
    }
    qsort(r, n, sizeof *r, by_rank);
    for (int j = 0; j < n; j++) {
        idx[j] = r[j].i;
    }
    free(r);
    return 0;
}

int zp_search_state_apart(int n, const double *lo, const double *hi, const double *a,
                          const double *b) {
    for (int k = 0; k < n; k++) {
        if (fabs(a[k] - b[k]) > ZP_DISTINCT * (hi[k] - lo[k])) {
            return 1;
        }
    }
    return 0;
}

int zp_search_state_distinct(const zp_search_state *S, const double *a, const double *b) {
    return zp_search_state_apart(S->n, S->lo, S->hi, a, b);
}

static void zp_search_state_report(zp_search_state *S, int improved) {
    zp_search_result *res = S->res;
    double now = zp_search_state_since(S);
    if (!S->o->progress || (!improved && now - S->last_report < PROGRESS_DT)) {
        return;
    }
    S->last_report = now;
    zp_search_progress p = {S->phase,   S->round,       res->evals, S->o->max_evals, now,
                            res->found, res->best.time, res->force, S->o->restart};
    S->o->progress(S->o->user, &p, improved);
}

void zp_search_state_eval(zp_search_state *S, zp_sim *s, zp_result *r, const double *f, zp_eval *e,
                          double *parts) {
    zp_pool_objective_eval(S->pool, S->ob, s, r, f, e, parts);
#pragma omp critical
    {
        zp_search_result *res = S->res;
        res->evals++;
        res->nfeasible += zp_objective_feasible(e);
        res->nfailed += e->failed;
        int improved = res->evals == 1 || zp_search_state_ahead(e, f, &res->best, res->force, S->n);
        if (improved) {
            res->best = *e;
            memcpy(res->force, f, sizeof *f * S->n);
            res->found = zp_objective_feasible(e);
        }
        zp_search_state_report(S, improved && res->found);
    }
}

void zp_search_state_record(zp_search_state *S, long at, const zp_eval *e) {
    zp_search_result *res = S->res;
    if (!zp_objective_feasible(e) || e->time >= S->running) {
        return;
    }
    S->running = e->time;
    if (res->nhist == ZP_SEARCH_HIST) {
        /* full: keep the later of each pair, so the history still spans the whole search and
           ends at its best (every entry kept is a true point of it) */
        for (int i = 0; i < ZP_SEARCH_HIST / 2; i++) {
            res->hist[i] = res->hist[2 * i + 1];
        }
        res->nhist = ZP_SEARCH_HIST / 2;
        res->hist_halvings++;
    }
    res->hist[res->nhist++] = (zp_search_hist){at, e->time};
}

void zp_search_state_base(zp_search_state *S, const double *f, const zp_eval *e) {
    zp_search_result *res = S->res;
    res->base_found = 1;
    res->base = *e;
    res->base_force = f[0];
    memcpy(res->base_p, f, sizeof *res->base_p * S->n);
}

const double *zp_search_state_point(const zp_search_state *S, int i) {
    return S->a.f + (size_t)i * S->n;
}

int zp_search_state_add(zp_search_state *S, const double *f, const zp_eval *e) {
    zp_archive *a = &S->a;
    if (a->n == a->cap) {
        /* both arrays grow together; on failure both stay valid at the old capacity */
        int cap = a->cap ? 2 * a->cap : 1024;
        double *nf = realloc(a->f, sizeof *f * S->n * cap);
        a->f = nf ? nf : a->f;
        zp_eval *ne = nf ? realloc(a->e, sizeof *e * cap) : NULL;
        a->e = ne ? ne : a->e;
        if (!ne) {
            return -1;
        }
        a->cap = cap;
    }
    memcpy(a->f + (size_t)a->n * S->n, f, sizeof *f * S->n);
    a->e[a->n] = *e;
    return a->n++;
}

typedef struct batch {
    zp_search_state *S;
    const double *pts;
    zp_eval *e;
    char *done;
    long left;
} batch;

static void batch_job(void *user, int i, zp_sim *s, zp_result *r) {
    batch *b = user;
    if (i < b->left && !zp_search_state_stopped(b->S)) {
        zp_search_state_eval(b->S, s, r, b->pts + (size_t)i * b->S->n, &b->e[i], NULL);
        b->done[i] = 1;
    }
}

int zp_search_state_batch(zp_search_state *S, const double *pts, int npt) {
    batch b = {S, pts, malloc(sizeof *b.e * (npt ? npt : 1)), calloc(npt ? npt : 1, 1),
               S->o->max_evals - S->spent};
    int ndone = 0;
    if (b.e && b.done && !zp_search_state_halted(S)) {
        S->exhausted |= npt >= b.left;
        zp_pool_map(S->pool, npt, batch_job, &b, NULL, NULL);
        for (int i = 0; i < npt; i++) {
            if (b.done[i] && zp_search_state_add(S, pts + (size_t)i * S->n, &b.e[i]) >= 0) {
                zp_search_state_record(S, ++S->spent, &b.e[i]);
                ndone++;
            }
        }
    }
    free(b.e);
    free(b.done);
    return ndone;
}
