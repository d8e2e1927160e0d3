/* The per-thread simulator pool (pool.h): the one place where schedules are shared out over
   OpenMP threads, used by the search, its verification, the landscape and the brute force. */
#include "pool.h"

#include <omp.h>
#include <stdlib.h>

struct zp_pool {
    int nw;
    zp_sim **sim; /* owned, nw */
    zp_result *r; /* owned, nw: large, so kept off the stack */
};

void zp_pool_free(zp_pool *p) {
    if (!p) {
        return;
    }
    for (int i = 0; p->sim && i < p->nw; i++) {
        zp_sim_free(p->sim[i]);
    }
    free(p->sim);
    free(p->r);
    free(p);
}

zp_pool *zp_pool_create(const zp_model *m, const zp_sim_opts *o, int nthreads) {
    zp_pool *p = calloc(1, sizeof *p);
    if (!p) {
        return NULL;
    }
    p->nw = nthreads > 0 ? nthreads : omp_get_max_threads();
    p->sim = calloc((size_t)p->nw, sizeof *p->sim);
    p->r = malloc(sizeof *p->r * p->nw);
    int ok = p->sim && p->r;
    for (int i = 0; ok && i < p->nw; i++) {
        p->sim[i] = zp_sim_create(m, o);
        ok = p->sim[i] != NULL;
    }
    if (!ok) {
        zp_pool_free(p);
        return NULL;
    }
    return p;
}

int zp_pool_threads(const zp_pool *p) {
    return p->nw;
}

void zp_pool_map(zp_pool *p, int n, zp_pool_job job, void *user, zp_pool_done done,
                 void *done_user) {
    int finished = 0;
#pragma omp parallel for num_threads(p->nw) schedule(dynamic, 1)
    for (int i = 0; i < n; i++) {
        int t = omp_get_thread_num();
        job(user, i, p->sim[t], &p->r[t]);
        if (done) {
#pragma omp critical
            done(done_user, ++finished, n);
        }
    }
}

typedef struct eval_batch {
    const zp_objective *ob;
    const double *f;
    zp_eval *e;
} eval_batch;

static void eval_job(void *user, int i, zp_sim *s, zp_result *r) {
    eval_batch *b = user;
    zp_objective_eval(b->ob, s, b->f + (size_t)i * zp_objective_nparams(b->ob), &b->e[i], r);
}

void zp_pool_eval(zp_pool *p, const zp_objective *ob, int n, const double *f, zp_eval *e,
                  zp_pool_done done, void *done_user) {
    eval_batch b = {ob, f, e};
    zp_pool_map(p, n, eval_job, &b, done, done_user);
}
