/* The polishes of one search, in the order they ran, and what they show: which points are
   still fresh starts, which islands they visited, the basins they reached and what those leave
   unseen (Boender and Rinnooy Kan), and their distinct survivable ends, kept for a warm
   restart. */
#ifndef ZP_POLISHES_H
#define ZP_POLISHES_H

#include "islands.h"
#include "leg.h"

#define ZP_POLISHES_ROUND 4         /* local polishes per round, from distinct good points */
#define ZP_POLISHES_PUSH_BUDGET 40  /* simulations of the best constant push's polish */
#define ZP_POLISHES_PUSH_STEP 0.002 /* its first step, share of the box */

typedef struct zp_polishes {
    zp_leg_rec *rec; /* n; owned when zp_polishes_reserve made them room */
    int n, cap;
} zp_polishes;

/* room for `more` records past rec[n - 1]: 0, or -1 when out of memory */
int zp_polishes_reserve(zp_polishes *p, int more);
void zp_polishes_free(zp_polishes *p);
/* f may start a polish: distinct from every start and end of the polishes so far */
int zp_polishes_fresh(const zp_polishes *p, const zp_search_state *S, const double *f);
/* 1 when a polish started or ended in island `is` of the map m */
int zp_polishes_visited(const zp_polishes *p, const zp_search_state *S, const zp_islands *m,
                        int is);
/* into S's result: the polishes, the distinct survivable ends, those that reached the best, the
   basins of every polish, what they leave unseen and the budget that would help (rounds of
   ZP_POLISHES_ROUND polishes at round_cost simulations; 0: unknown) */
void zp_polishes_evidence(const zp_polishes *p, zp_search_state *S, long round_cost);
/* into S's result: the islands of the final map, how many a polish visited, the best of them */
void zp_polishes_islands(const zp_polishes *p, zp_search_state *S);
/* into S's result: the distinct survivable ends, best first */
void zp_polishes_ends(const zp_polishes *p, zp_search_state *S);

#endif
