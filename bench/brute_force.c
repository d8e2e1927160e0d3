/* A brute-force reference for the search (issue 4): uniform random schedules over the scene's
   [drive] box, on every core, for a fixed wall time; the fastest that finishes with the margin
   kept. Same integrator as the search's runs ([optimize] method, rtol).
   Usage: brute_force SCENE.ini SECONDS [SEED] */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "setup.h"

int main(int argc, char **argv) {
    if (argc < 3) {
        fputs("usage: brute_force SCENE.ini SECONDS [SEED]\n", stderr);
        return 2;
    }
    gsl_set_error_handler_off();
    double seconds = atof(argv[2]);
    unsigned long seed = argc > 3 ? strtoul(argv[3], NULL, 10) : 1;
    static zp_setup st; /* large: kept off the stack */
    zp_overrides none = ZP_OVERRIDES_NONE;
    if (zp_setup_load("brute_force", argv[1], &none, &st)) {
        return 2;
    }
    const zp_model *m = st.m;
    const zp_sim_opts o = st.search;
    const zp_schedule *box = &st.sched; /* [drive] min, max */
    double limit = st.limit;
    int nt = omp_get_max_threads();
    zp_sim **sims = malloc(sizeof *sims * nt);
    for (int i = 0; i < nt; i++) {
        sims[i] = zp_sim_create(m, &o); /* serially: libmatheval is not thread-safe */
    }
    double best_t = INFINITY, best_f[ZP_MAX_SECTIONS] = {0};
    long total = 0, feasible = 0;
    double t0 = omp_get_wtime();
#pragma omp parallel reduction(+ : total, feasible)
    {
        int id = omp_get_thread_num();
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(rng, seed * 1000 + id);
        zp_result res;
        zp_result *r = &res;
        zp_schedule sched = *box;
        double *f = sched.p;
        zp_input in = {.sched = &sched};
        while (omp_get_wtime() - t0 < seconds) {
            for (int k = 0; k < sched.np; k++) {
                f[k] = box->lo[k] + (box->hi[k] - box->lo[k]) * gsl_rng_uniform(rng);
            }
            total++;
            if (zp_sim_run(m, sims[id], &in, r) || r->outcome != ZP_OUTCOME_FINISHED) {
                continue;
            }
            int ok = 1;
            for (int i = 0; i < m->nlink; i++) {
                ok &= r->max_rel_angle[i] <= limit;
            }
            if (!ok) {
                continue;
            }
            feasible++;
#pragma omp critical
            if (r->time < best_t) {
                best_t = r->time;
                for (int k = 0; k < m->nsec; k++) {
                    best_f[k] = f[k];
                }
            }
        }
        gsl_rng_free(rng);
    }
    printf("brute force: %ld schedules in %.0f s on %d threads (%.0f/s), %ld finish with the "
           "margin\nbest: %.6f s at", total, omp_get_wtime() - t0, nt,
           total / (omp_get_wtime() - t0), feasible, best_t);
    for (int k = 0; k < m->nsec; k++) {
        printf(" %.4f", best_f[k]);
    }
    printf(" N\n");
    return 0;
}
