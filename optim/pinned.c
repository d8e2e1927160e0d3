/* The bang-bang search from a schedule (pinned.h), through pagmo2's CMA-ES on a leg. */
#include "pinned.h"

#include <stdio.h>
#include <string.h>

#include "pagmo_pop.h"

#define PER_FREE 5      /* members per parameter searched: the portfolio's populations' */
#define MEMBERS_MIN 8   /* at least: pagmo's CMA-ES needs 5 */
#define FIRST_STEP 0.05 /* share of the box: the start is a good schedule, searched near it */

/* design note: only the top is a bang. A parameter at the bottom of the box is one the margin
   holds back, not one it leaves alone: set to the bottom as well, m10_tangent's seed 1 kept
   section 4 at 0 N (6.28410 s) where the fastest known pushes 206 N (6.24780 s), and over seeds
   1 to 3 of m9, m10 and m12 the gaps to the best known added up to 23.1 % against 21.1 % with
   the top alone (both within 0.1 of the box; docs/search.md) */
int zp_pinned_make(zp_pinned *p, const zp_search_state *S, const double *f, unsigned long seed) {
    int npinned = 0;
    p->nfree = 0;
    for (int k = 0; k < S->n; k++) {
        double span = S->hi[k] - S->lo[k];
        p->base[k] = f[k];
        if (span <= 0) {
            continue;
        }
        if (f[k] > S->hi[k] - ZP_PINNED_NEAR * span) {
            p->base[k] = S->hi[k];
            npinned++;
        } else {
            p->free[p->nfree++] = k;
        }
    }
    int np = PER_FREE * p->nfree;
    p->popsize = np < MEMBERS_MIN ? MEMBERS_MIN : np;
    p->gens = ZP_PINNED_SIMS / p->popsize;
    p->seed = seed;
    return npinned > 0 && p->nfree > 0;
}

long zp_pinned_cap(const zp_pinned *p) {
    return 1 + p->gens * p->popsize;
}

typedef struct pinned_leg {
    const zp_pinned *p;
    zp_leg *leg;
} pinned_leg;

/* the penalised score of the free parameters xf in the pinned schedule, through the leg */
static double pinned_fitness(void *user, const double *xf) {
    const pinned_leg *w = user;
    double f[ZP_SCHED_MAX_PARAMS];
    memcpy(f, w->p->base, sizeof *f * w->leg->S->n);
    for (int j = 0; j < w->p->nfree; j++) {
        f[w->p->free[j]] = xf[j];
    }
    const zp_eval *e = zp_leg_eval(w->leg, f);
    return e ? e->score : zp_leg_spent_score(w->leg);
}

void zp_pinned_run(const void *how, zp_leg *leg) {
    const zp_pinned *p = how;
    const zp_search_state *S = leg->S;
    pinned_leg w = {.p = p, .leg = leg};
    const zp_eval *e = zp_leg_eval(leg, p->base);
    if (!e) {
        return;
    }
    double lo[ZP_SCHED_MAX_PARAMS], hi[ZP_SCHED_MAX_PARAMS], x0[ZP_SCHED_MAX_PARAMS];
    for (int j = 0; j < p->nfree; j++) {
        lo[j] = S->lo[p->free[j]];
        hi[j] = S->hi[p->free[j]];
        x0[j] = p->base[p->free[j]];
    }
    zp_pagmo_pop *evo =
        zp_pagmo_pop_create_at(p->nfree, lo, hi, p->popsize, p->seed, x0, e->score, FIRST_STEP);
    if (!evo || zp_pagmo_pop_evolve(evo, (int)p->gens, pinned_fitness, &w)) {
        leg->refused = 1;
        snprintf(leg->why, sizeof leg->why,
                 evo ? "pagmo refused to evolve the bang-bang search"
                     : "out of memory for the bang-bang search");
    }
    zp_pagmo_pop_free(evo);
}
