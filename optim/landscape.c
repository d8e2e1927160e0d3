/* The survival landscape's runs (landscape.h): a list of schedules shared out over OpenMP
   threads, each thread with its own simulator workspace. */
#include "landscape.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

zp_status zp_landscape_sweep(const zp_model *m, const zp_sim_opts *o, const double *force, int n,
                             zp_landscape_point *out, zp_landscape_progress progress, void *user) {
    int nth = omp_get_max_threads();
    zp_sim **sims = calloc((size_t)nth, sizeof *sims);
    zp_result *res = calloc((size_t)nth, sizeof *res); /* large: one per thread, off the stack */
    int ok = sims && res;
    /* workspaces one after another: each compiles its own course */
    for (int t = 0; ok && t < nth; t++) {
        sims[t] = zp_sim_create(m, o);
        ok = sims[t] != NULL;
    }
    int done = 0;
    if (ok) {
#pragma omp parallel num_threads(nth)
        {
            int t = omp_get_thread_num();
#pragma omp for schedule(dynamic)
            for (int k = 0; k < n; k++) {
                zp_schedule sched =
                    zp_schedule_sections(m->nsec, force + (size_t)k * m->nsec, 0, 0);
                zp_input in = {.sched = &sched};
                zp_result *r = &res[t];
                zp_landscape_point *p = &out[k];
                p->failed = zp_sim_run(m, sims[t], &in, r) != ZP_OK;
                p->outcome = r->outcome;
                p->stall = r->stall;
                p->time = r->time;
                p->x = r->x;
                p->died_link = r->died_link;
                zp_limits_reached(m, r, p->reached);
                p->max_rel_angle = 0;
                for (int i = 0; i < m->nlink; i++) {
                    p->max_rel_angle = fmax(p->max_rel_angle, r->max_rel_angle[i]);
                }
#pragma omp critical
                {
                    done++;
                    if (progress) {
                        progress(user, done, n);
                    }
                }
            }
        }
    }
    for (int t = 0; sims && t < nth; t++) {
        zp_sim_free(sims[t]);
    }
    free(sims);
    free(res);
    return ok ? ZP_OK : ZP_ERR_NOMEM;
}
