/* A brute-force reference for the search: uniform random schedules over the scene's [drive]
   box through the per-thread simulator pool, in batches, for a fixed wall time; the fastest
   that finishes with the margin kept (the search's own objective and constraint). Same
   integrator as the search's runs ([optimize] method, rtol).
   Usage: brute_force SCENE.ini SECONDS [SEED] */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "pool.h"
#include "setup.h"

#define BATCH 512 /* schedules drawn, then run in parallel */

int main(int argc, char **argv) {
    if (argc < 3) {
        fputs("usage: brute_force SCENE.ini SECONDS [SEED]\n", stderr);
        return 2;
    }
    gsl_set_error_handler_off();
    double seconds = atof(argv[2]);
    unsigned long seed = argc > 3 ? strtoul(argv[3], NULL, 10) : 1;
    static zp_problem st; /* large: kept off the stack */
    zp_overrides none = ZP_OVERRIDES_NONE;
    if (zp_setup_load("brute_force", argv[1], &none, &st)) {
        return 2;
    }
    const zp_schedule *box = &st.sched; /* [drive] min, max */
    int np = box->np;
    zp_objective ob = {.m = st.m, .limit = st.limit, .t_max = st.search.t_max, .shape = box};
    zp_pool *pool = zp_pool_create(st.m, &st.search, 0);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double *f = malloc(sizeof *f * BATCH * np);
    zp_eval *e = malloc(sizeof *e * BATCH);
    if (!pool || !rng || !f || !e) {
        fputs("brute_force: out of memory\n", stderr);
        return 1;
    }
    gsl_rng_set(rng, seed);
    double best_t = INFINITY, best_f[ZP_SCHED_MAX_PARAMS] = {0};
    long total = 0, feasible = 0;
    double t0 = omp_get_wtime();
    while (omp_get_wtime() - t0 < seconds) {
        for (int i = 0; i < BATCH * np; i++) {
            int k = i % np;
            f[i] = box->lo[k] + (box->hi[k] - box->lo[k]) * gsl_rng_uniform(rng);
        }
        zp_pool_eval(pool, &ob, BATCH, f, e, NULL, NULL);
        for (int i = 0; i < BATCH; i++) {
            total++;
            if (!zp_objective_feasible(&e[i])) {
                continue;
            }
            feasible++;
            if (e[i].time < best_t) {
                best_t = e[i].time;
                for (int k = 0; k < np; k++) {
                    best_f[k] = f[(size_t)i * np + k];
                }
            }
        }
    }
    double wall = omp_get_wtime() - t0;
    printf("brute force: %ld schedules in %.0f s on %d threads (%.0f/s), %ld finish with the "
           "margin\nbest: %.6f s at",
           total, wall, zp_pool_threads(pool), total / wall, feasible, best_t);
    for (int k = 0; k < np; k++) {
        printf(" %.4f", best_f[k]);
    }
    printf("\n");
    zp_pool_free(pool);
    gsl_rng_free(rng);
    free(f);
    free(e);
    zp_setup_free(&st);
    return 0;
}
