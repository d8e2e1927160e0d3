/* The bang-bang search from a schedule (pinned.h): which parameters it searches, then CMA-ES
   over them (subsearch.h). */
#include "pinned.h"

/* design note: over seeds 1 to 5 of the scenes of 8 parameters or more in docs/search.md, 14 of
   30 runs ended within 0.1 % of the best known at 0.05, 10 at 0.1, against 6 without the search;
   at 0.2 multi8 and m12 lost */
#define PINNED_NEAR 0.05 /* share of the box: a parameter this close to the top is set to it */
/* design note: from the default's answers on m7_brake, m10_tangent and m12_4link of
   docs/search.md, CMA-ES over the parameters left free reached its best within about 2000
   simulations on every CMA seed that reached it */
#define PINNED_SIMS 2500 /* CMA-ES's simulations, at most (and the pinned schedule's one) */
#define PER_FREE 5       /* members per parameter searched: the portfolio's populations' */
#define MEMBERS_MIN 8    /* at least: pagmo's CMA-ES needs 5 */
#define FIRST_STEP 0.05  /* share of the box: the start is a good schedule, searched near it */

/* design note: only the top is a bang. A parameter at the bottom of the box is one the margin
   holds back, not one it leaves alone: set to the bottom as well, m10_tangent's seed 1 kept
   section 4 at 0 N (6.28410 s) where the fastest known pushes 206 N (6.24780 s), and over seeds
   1 to 3 of m9, m10 and m12 the gaps to the best known added up to 23.1 % against 21.1 % with
   the top alone (both within 0.1 of the box; docs/search.md) */
int zp_pinned_make(zp_subsearch *p, const zp_search_state *S, const double *f, unsigned long seed) {
    int npinned = 0;
    p->nfree = 0;
    for (int k = 0; k < S->n; k++) {
        double span = S->hi[k] - S->lo[k];
        p->base[k] = f[k];
        if (span <= 0) {
            continue;
        }
        if (f[k] > S->hi[k] - PINNED_NEAR * span) {
            p->base[k] = S->hi[k];
            npinned++;
        } else {
            p->free[p->nfree++] = k;
        }
    }
    int np = PER_FREE * p->nfree;
    p->popsize = np < MEMBERS_MIN ? MEMBERS_MIN : np;
    p->gens = PINNED_SIMS / p->popsize;
    p->step = FIRST_STEP;
    p->seed = seed;
    p->what = "the bang-bang search";
    return npinned > 0 && p->nfree > 0;
}

long zp_pinned_cap(const zp_subsearch *p) {
    return 1 + p->gens * p->popsize;
}

void zp_pinned_run(const void *how, zp_leg *leg) {
    const zp_subsearch *p = how;
    const zp_eval *e = zp_leg_eval(leg, p->base);
    if (e) {
        zp_subsearch_run(p, leg, e->score);
    }
}
