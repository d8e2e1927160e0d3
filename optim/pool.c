/* The per-thread simulator pool (pool.h): the one place where schedules, and a survivor's
   scenarios, are shared out over OpenMP threads, used by the search, its verification, the
   landscape and the brute force. */
#include "pool.h"

#include <math.h>
#include <omp.h>
#include <stdatomic.h>
#include <stdlib.h>

struct zp_pool {
    int nw;
    zp_sim **sim;  /* owned, nw */
    zp_result *r;  /* owned, nw: large, so kept off the stack */
    zp_sim **help; /* owned, nw or NULL: each thread's workspace for the scenarios it helps with */
    zp_result *rh; /* owned, nw or NULL */
};

void zp_pool_free(zp_pool *p) {
    if (!p) {
        return;
    }
    for (int i = 0; i < p->nw; i++) {
        zp_sim_free(p->sim ? p->sim[i] : NULL);
        zp_sim_free(p->help ? p->help[i] : NULL);
    }
    free(p->sim);
    free(p->r);
    free(p->help);
    free(p->rh);
    free(p);
}

/* n workspaces from (m, o), created one after another (the course evaluators are not
   thread-safe), and n result buffers; 0, or -1 when out of memory (what was made is kept for
   zp_pool_free) */
static int create(zp_sim ***sim, zp_result **r, int n, const zp_model *m, const zp_sim_opts *o) {
    *sim = calloc((size_t)n, sizeof **sim);
    *r = malloc(sizeof **r * n);
    int ok = *sim && *r;
    for (int i = 0; ok && i < n; i++) {
        (*sim)[i] = zp_sim_create(m, o);
        ok = (*sim)[i] != NULL;
    }
    return ok ? 0 : -1;
}

zp_pool *zp_pool_create(const zp_model *m, const zp_sim_opts *o, int nthreads) {
    zp_pool *p = calloc(1, sizeof *p);
    if (!p) {
        return NULL;
    }
    p->nw = nthreads > 0 ? nthreads : omp_get_max_threads();
    if (create(&p->sim, &p->r, p->nw, m, o)) {
        zp_pool_free(p);
        return NULL;
    }
    return p;
}

int zp_pool_help(zp_pool *p, const zp_model *m, const zp_sim_opts *o) {
    return p->nw < 2 || p->help ? 0 : create(&p->help, &p->rh, p->nw, m, o);
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
    zp_pool *p;
    const zp_objective *ob;
    const double *f;
    zp_eval *e;
} eval_batch;

static void eval_job(void *user, int i, zp_sim *s, zp_result *r) {
    eval_batch *b = user;
    zp_pool_objective_eval(b->p, b->ob, s, r, b->f + (size_t)i * zp_objective_nparams(b->ob),
                           &b->e[i], NULL);
}

void zp_pool_eval(zp_pool *p, const zp_objective *ob, int n, const double *f, zp_eval *e,
                  zp_pool_done done, void *done_user) {
    eval_batch b = {p, ob, f, e};
    zp_pool_map(p, n, eval_job, &b, done, done_user);
}

/* A survivor's scenarios shared between its own thread and idle ones: positions are taken in
   the set's order, one at a time, and each is run in full; a position past the first that broke
   is moot, so it is not started once that break is known (one started before is wasted). Every
   position before the first break is run: when it was taken, no earlier break was known. */
typedef struct scen_share {
    const zp_objective *ob;
    const zp_schedule *sched;
    int n;           /* positions */
    atomic_int next; /* the next position to take */
    atomic_int stop; /* the first position that broke so far (it only falls); n: none */
    double *cons;    /* owned, 2n: the constraint of each position run, then its objective */
    double *parts;   /* owned, n x ZP_OBJECTIVE_PARTS_MAX: each position's parts, or NULL: none */
} scen_share;

static void share_work(scen_share *sh, zp_sim *s, zp_result *r) {
    for (;;) {
        int i = atomic_fetch_add(&sh->next, 1);
        if (i >= sh->n || i > atomic_load(&sh->stop)) {
            return;
        }
        double *parts = sh->parts ? sh->parts + (size_t)i * ZP_OBJECTIVE_PARTS_MAX : NULL;
        sh->cons[i] =
            zp_objective_scenario(sh->ob, i, sh->sched, s, r, &sh->cons[sh->n + i], parts);
        int stop = atomic_load(&sh->stop);
        while (sh->cons[i] > 0 && i < stop && !atomic_compare_exchange_weak(&sh->stop, &stop, i)) {
        }
    }
}

void zp_pool_objective_eval(zp_pool *p, const zp_objective *ob, zp_sim *s, zp_result *r,
                            const double *f, zp_eval *e, double *parts) {
    int nt = omp_get_num_threads();
    if (!p->help || nt < 2 || nt > p->nw) {
        zp_objective_eval_parts(ob, s, f, e, r, parts);
        return;
    }
    zp_schedule sched = zp_objective_schedule(ob, f);
    if (!zp_objective_eval_nominal(ob, s, &sched, e, r, parts)) {
        return;
    }
    int n = zp_objective_nscenarios(ob);
    scen_share sh = {.ob = ob, .sched = &sched, .n = n, .next = 0, .stop = n};
    sh.cons = malloc(sizeof *sh.cons * 2 * n);
    sh.parts = parts ? malloc(sizeof *sh.parts * ZP_OBJECTIVE_PARTS_MAX * n) : NULL;
    if (!sh.cons || (parts && !sh.parts)) {
        free(sh.cons);
        free(sh.parts);
        zp_objective_eval_parts(ob, s, f, e, r, parts);
        return;
    }
    /* helpers for the threads idle at the batch's end; a task runs only on a thread waiting at
       that barrier or on this one waiting below, so each uses its thread's helper workspace
       while no other task on that thread is running */
    for (int k = 1; k < nt; k++) {
#pragma omp task default(none) shared(sh, p)
        {
            int t = omp_get_thread_num();
            share_work(&sh, p->help[t], &p->rh[t]);
        }
    }
    share_work(&sh, s, r);
#pragma omp taskwait
    /* the serial loop's result: the constraints folded in order up to the first break */
    int stop = atomic_load(&sh.stop);
    int nrun = stop < n ? stop + 1 : n;
    for (int i = 0; i < nrun; i++) {
        if (parts) {
            zp_objective_parts_fold(ob, parts, sh.parts + (size_t)i * ZP_OBJECTIVE_PARTS_MAX);
        }
        e->cons = fmax(e->cons, sh.cons[i]);
        e->obj = ob->slowest ? fmax(e->obj, sh.cons[n + i]) : e->obj;
    }
    zp_objective_eval_close(ob, nrun, stop < n, e);
    free(sh.cons);
    free(sh.parts);
}
