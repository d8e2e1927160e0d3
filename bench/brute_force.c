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

#include "cli.h"
#include "pool.h"

#define BATCH 512 /* schedules drawn, then run in parallel */

int main(int argc, char **argv) {
    if (argc < 3) {
        fputs("usage: brute_force SCENE.ini SECONDS [SEED]\n", stderr);
        return 2;
    }
    gsl_set_error_handler_off();
    double seconds = atof(argv[2]);
    unsigned long seed = argc > 3 ? strtoul(argv[3], NULL, 10) : 1;
    zp_scene sc;
    zp_model *m = zp_cli_load(argv[1], &sc);
    zp_diag d;
    zp_diag_init(&d);
    zp_sim_opts o;
    if (!m || zp_sim_opts_from_scene(&sc, &o, &d)) {
        return 2;
    }
    o.method = zp_method_find(sc.search_method);
    o.rtol = sc.search_rtol;
    o.atol = sc.search_rtol / 100;
    o.output_dt = 0;
    o.track_loads = 0;
    zp_objective ob = {m, m->phi_max - sc.margin * M_PI / 180, o.t_max};
    zp_pool *pool = zp_pool_create(m, &o, 0);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double *f = malloc(sizeof *f * BATCH * m->nsec);
    zp_eval *e = malloc(sizeof *e * BATCH);
    if (!pool || !rng || !f || !e) {
        fputs("brute_force: out of memory\n", stderr);
        return 1;
    }
    gsl_rng_set(rng, seed);
    double best_t = INFINITY, best_f[ZP_MAX_SECTIONS] = {0};
    long total = 0, feasible = 0;
    double t0 = omp_get_wtime();
    while (omp_get_wtime() - t0 < seconds) {
        for (int i = 0; i < BATCH * m->nsec; i++) {
            f[i] = sc.force_min + (sc.force_max - sc.force_min) * gsl_rng_uniform(rng);
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
                for (int k = 0; k < m->nsec; k++) {
                    best_f[k] = f[(size_t)i * m->nsec + k];
                }
            }
        }
    }
    double wall = omp_get_wtime() - t0;
    printf("brute force: %ld schedules in %.0f s on %d threads (%.0f/s), %ld finish with the "
           "margin\nbest: %.6f s at",
           total, wall, zp_pool_threads(pool), total / wall, feasible, best_t);
    for (int k = 0; k < m->nsec; k++) {
        printf(" %.4f", best_f[k]);
    }
    printf(" N\n");
    zp_pool_free(pool);
    gsl_rng_free(rng);
    free(f);
    free(e);
    zp_model_free(m);
    return 0;
}
