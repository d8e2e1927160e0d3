/* The map's islands: the near-survivable points of a search's archive (the NEAR_MAX best of
   those that finish within a few degrees of the margin), grouped into islands: a point joins
   the island of the nearest better point within MLSL's critical distance that no other mapped
   point separates from it. Islands come best first, each headed by its best point. */
#ifndef ZP_ISLANDS_H
#define ZP_ISLANDS_H

#include "search_state.h"

typedef struct zp_island {
    int head;  /* archive index of its best point */
    int npts;  /* near points in it */
    int nfeas; /* of them, survivable */
} zp_island;

typedef struct zp_islands {
    int n;          /* islands */
    int nnear;      /* near points mapped */
    int *pt;        /* owned, nnear: their archive indices, best first */
    int *of;        /* owned, nnear: the island of each */
    zp_island *isl; /* owned, n */
} zp_islands;

/* a run the map keeps as near-survivable: it finished within a few degrees past the margin */
int zp_islands_near(const zp_eval *e);

/* 0, or -1 when out of memory (m empty) */
int zp_islands_map(const zp_search_state *S, zp_islands *m);
void zp_islands_free(zp_islands *m);

#endif
