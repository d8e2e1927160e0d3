/* CMA-ES (pagmo2's) over some parameters of a schedule, the others held, on a leg whose best it
   moves: the portfolio's windows (neighbouring parameters, drawn over their box) and the
   bang-bang search (pinned.h: the parameters below the top, started at the schedule). */
#ifndef ZP_SUBSEARCH_H
#define ZP_SUBSEARCH_H

#include "leg.h"

typedef struct zp_subsearch {
    double base[ZP_SCHED_MAX_PARAMS]; /* the schedule: the held parameters, and the start */
    int free[ZP_SCHED_MAX_PARAMS];    /* the parameters searched */
    int nfree;
    int popsize;
    int gens; /* generations of CMA-ES */
    /* share of the box: every member at base, so CMA-ES's mean sits there, with this first
       step; 0: the members drawn over the free parameters' box */
    double step;
    unsigned long seed;
    const char *what; /* what it is, for the message when pagmo refuses: "a window" */
} zp_subsearch;

/* s's generations through zp_leg_eval on leg; base_score: the score of base, where s->step > 0
   starts there. Where pagmo refused or memory ran out, leg->refused and leg->why say so. */
void zp_subsearch_run(const zp_subsearch *s, zp_leg *leg, double base_score);

#endif
