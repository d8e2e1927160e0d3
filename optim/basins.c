/* What the local searches have not seen: Boender and Rinnooy Kan's Bayesian estimate of the
   number of basins from the number of local searches and the distinct minima they found
   (Math. Programming 37, 1987: uniform prior on the number of basins and on their sizes). */
#include "basins.h"

#include <math.h>

double zp_basins_expected(int n, int w) {
    if (w <= 0) {
        return n > 0 ? 0 : INFINITY;
    }
    if (n <= w + 2) {
        return INFINITY; /* the posterior mean exists only from w + 3 searches on */
    }
    return (double)w * (n - 1) / (n - w - 2);
}

double zp_basins_unseen(int n, int w) {
    double e = zp_basins_expected(n, w);
    return isfinite(e) ? e - w : INFINITY;
}

int zp_basins_searches_needed(int w, double unseen) {
    if (w <= 0) {
        return 1;
    }
    /* w (w + 1) / (n - w - 2) < unseen */
    return (int)floor(w + 2 + w * (w + 1.0) / unseen) + 1;
}
