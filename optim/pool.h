/* One simulator workspace per thread and deterministic parallel runs of a batch over them: each
   job writes its own slot, so results come out in input order whatever thread ran which. */
#ifndef ZP_POOL_H
#define ZP_POOL_H

#include "objective.h"

typedef struct zp_pool zp_pool;

/* job i of a batch, on the calling thread's workspace s (r: that thread's result buffer) */
typedef void (*zp_pool_job)(void *user, int i, zp_sim *s, zp_result *r);
/* called after each finished job, serialised; done counts the batch's jobs finished so far */
typedef void (*zp_pool_done)(void *user, int done, int total);

/* nthreads workspaces (0: OpenMP's default), created one after another (the course evaluators
   are not thread-safe). NULL when out of memory. */
zp_pool *zp_pool_create(const zp_model *m, const zp_sim_opts *o, int nthreads);
void zp_pool_free(zp_pool *p);
/* A second workspace per thread (from m and o), with which a thread idle at a batch's end helps
   another run a survivor's scenarios (zp_pool_objective_eval). 0, or -1 when out of memory. */
int zp_pool_help(zp_pool *p, const zp_model *m, const zp_sim_opts *o);
int zp_pool_threads(const zp_pool *p);

/* Runs job(user, i, ...) for every i in [0, n) over the pool's threads; done(done_user, ..)
   after each (done may be NULL). */
void zp_pool_map(zp_pool *p, int n, zp_pool_job job, void *user, zp_pool_done done,
                 void *done_user);

/* Scores n schedules (f: n rows of zp_objective_nparams(ob) values) through ob into e[n], in
   parallel. */
void zp_pool_eval(zp_pool *p, const zp_objective *ob, int n, const double *f, zp_eval *e,
                  zp_pool_done done, void *done_user);

/* zp_objective_eval_parts of parameters f from inside a job of p (s and r: its workspace), the
   survivor's scenarios run in parallel by the threads idle at the batch's end when p has
   helpers: e, parts (may be NULL), the set's counts and fails come out bit for bit as the
   serial loop gives them (r then holds some run of the schedule). */
void zp_pool_objective_eval(zp_pool *p, const zp_objective *ob, zp_sim *s, zp_result *r,
                            const double *f, zp_eval *e, double *parts);

#endif
