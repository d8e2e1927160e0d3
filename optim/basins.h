/* Boender and Rinnooy Kan's estimate of the basins a multistart search has not visited. */
#ifndef ZP_BASINS_H
#define ZP_BASINS_H

/* The posterior expected number of basins after n local searches found w distinct minima:
   w (n - 1) / (n - w - 2); INFINITY while n <= w + 2 (too few searches to say). */
double zp_basins_expected(int n, int w);
/* Expected basins not yet found: zp_basins_expected(n, w) - w (INFINITY when unknown). */
double zp_basins_unseen(int n, int w);
/* The fewest local searches after which w minima leave fewer than `unseen` expected basins
   unfound (no new minimum found meanwhile). */
int zp_basins_searches_needed(int w, double unseen);

#endif
