/* CMA-ES over some parameters of a schedule, the others held (subsearch.h). */
#include "subsearch.h"

#include <stdio.h>
#include <string.h>

#include "pagmo_pop.h"

typedef struct subsearch_leg {
    const zp_subsearch *s;
    zp_leg *leg;
} subsearch_leg;

/* the penalised score of the free parameters xf in the held schedule, through the leg */
static double subsearch_fitness(void *user, const double *xf) {
    const subsearch_leg *w = user;
    double f[ZP_SCHED_MAX_PARAMS];
    memcpy(f, w->s->base, sizeof *f * w->leg->S->n);
    for (int j = 0; j < w->s->nfree; j++) {
        f[w->s->free[j]] = xf[j];
    }
    const zp_eval *e = zp_leg_eval(w->leg, f);
    return e ? e->score : zp_leg_spent_score(w->leg);
}

void zp_subsearch_run(const zp_subsearch *s, zp_leg *leg, double base_score) {
    const zp_search_state *S = leg->S;
    double lo[ZP_SCHED_MAX_PARAMS], hi[ZP_SCHED_MAX_PARAMS], x0[ZP_SCHED_MAX_PARAMS];
    for (int j = 0; j < s->nfree; j++) {
        lo[j] = S->lo[s->free[j]];
        hi[j] = S->hi[s->free[j]];
        x0[j] = s->base[s->free[j]];
    }
    zp_pagmo_pop *evo =
        s->step > 0
            ? zp_pagmo_pop_create_at(s->nfree, lo, hi, s->popsize, s->seed, x0, base_score, s->step)
            : zp_pagmo_pop_create(ZP_PAGMO_CMAES, s->nfree, lo, hi, s->popsize, s->seed);
    subsearch_leg w = {.s = s, .leg = leg};
    if (!evo || zp_pagmo_pop_evolve(evo, s->gens, subsearch_fitness, &w)) {
        leg->refused = 1;
        snprintf(leg->why, sizeof leg->why,
                 evo ? "pagmo refused to evolve %s" : "out of memory for %s", s->what);
    }
    zp_pagmo_pop_free(evo);
}
