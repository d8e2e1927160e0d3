/* The bang-bang search from a schedule. A harder push finishes sooner wherever the margin does
   not hold it back, so in a minimum-time schedule the sections the margin leaves alone push at
   the top of the box (Pontryagin's principle: the control of a minimum-time problem is
   bang-bang off its constraint arcs). A good schedule's parameters within ZP_PINNED_NEAR of the
   top are set to it, and CMA-ES, started at the schedule, searches the others on a leg: a
   search of few parameters, where CMA-ES does best. */
#ifndef ZP_PINNED_H
#define ZP_PINNED_H

#include "leg.h"

/* design note: over seeds 1 to 5 of the scenes of 8 parameters or more in docs/search.md, 14 of
   30 runs ended within 0.1 % of the best known at 0.05, 10 at 0.1, against 6 without the search;
   at 0.2 multi8 and m12 lost */
#define ZP_PINNED_NEAR 0.05 /* share of the box: a parameter this close to the top is set to it */
/* design note: from the default's answers on m7_brake, m10_tangent and m12_4link of
   docs/search.md, CMA-ES over the parameters left free reached its best within about 2000
   simulations on every CMA seed that reached it */
#define ZP_PINNED_SIMS 2500 /* CMA-ES's simulations, at most (and the pinned schedule's one) */

typedef struct zp_pinned {
    double base[ZP_SCHED_MAX_PARAMS]; /* the schedule with its near-top parameters at the top */
    int free[ZP_SCHED_MAX_PARAMS];    /* the parameters searched */
    int nfree;
    int popsize;
    long gens; /* generations of CMA-ES */
    unsigned long seed;
} zp_pinned;

/* the search from schedule f with its seed into p: 1, or 0 when there is nothing to search (no
   parameter near the top, or none away from it) */
int zp_pinned_make(zp_pinned *p, const zp_search_state *S, const double *f, unsigned long seed);
/* the simulations it may spend */
long zp_pinned_cap(const zp_pinned *p);
/* a zp_leg_run: how is the zp_pinned; the pinned schedule first, then CMA-ES from it */
void zp_pinned_run(const void *how, zp_leg *leg);

#endif
