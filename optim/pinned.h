/* The bang-bang search from a schedule. A harder push finishes sooner wherever the margin does
   not hold it back, so in a minimum-time schedule the sections the margin leaves alone push at
   the top of the box (Pontryagin's principle: the control of a minimum-time problem is
   bang-bang off its constraint arcs). A good schedule's parameters within 5 % of the box of
   the top are set to it, and CMA-ES, started at the schedule, searches the others on a leg
   (subsearch.h): a search of few parameters, where CMA-ES does best. */
#ifndef ZP_PINNED_H
#define ZP_PINNED_H

#include "subsearch.h"

/* the search from schedule f with its seed into p (its base the pinned schedule): 1, or 0 when
   there is nothing to search (no parameter near the top, or none away from it) */
int zp_pinned_make(zp_subsearch *p, const zp_search_state *S, const double *f, unsigned long seed);
/* the simulations it may spend */
long zp_pinned_cap(const zp_subsearch *p);
/* a zp_leg_run: how is the zp_subsearch; the pinned schedule first, then CMA-ES from it */
void zp_pinned_run(const void *how, zp_leg *leg);

#endif
