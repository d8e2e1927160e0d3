/* The map's islands (optim/islands.c) and the estimate of unvisited basins (optim/basins.c).
   Independent expectations: Boender and Rinnooy Kan's posterior mean of the number of basins
   against its posterior summed term by term (P(K | n, w) proportional to
   K! (K - 1)! / ((K - w)! (n + K - 1)!) under a flat prior on K); hand-made maps whose islands
   are known by construction: bands of survivable points on a line split by deadly points, and
   two clouds far apart. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "basins.h"
#include "check.h"
#include "islands.h"

/* relative: the brute-force sum is cut at K = 2e6, where the tail of K^(w - n + 1) is below it */
#define SUM_TOL 1e-6

/* the posterior mean of K summed term by term, in logs */
static double posterior_mean(int n, int w) {
    double num = 0, den = 0, ref = NAN;
    for (long K = w; K < 2000000; K++) {
        double lp = lgamma(K + 1.0) + lgamma((double)K) - lgamma(K - w + 1.0) - lgamma(n + K + 0.0);
        if (isnan(ref)) {
            ref = lp;
        }
        double p = exp(lp - ref);
        num += K * p;
        den += p;
    }
    return num / den;
}

static zp_search_state map;
static double lo[2] = {0, 0}, hi[2] = {100, 100};

static void put(double f1, double f2, int feasible, double time) {
    zp_eval e = {.outcome = feasible >= 0 ? ZP_OUTCOME_FINISHED : ZP_OUTCOME_DIED,
                 .time = time,
                 .obj = time,
                 .cons = feasible > 0    ? -1
                         : feasible == 0 ? 3
                                         : 50,
                 .scenario = -1};
    e.score = e.obj + fmax(e.cons, 0);
    CHECK(zp_search_state_add(&map, (double[2]){f1, f2}, &e) >= 0);
}

static void clear(void) {
    free(map.a.f);
    free(map.a.e);
    map = (zp_search_state){.n = 2, .lo = lo, .hi = hi};
}

int main(void) {
    /* the closed form against the posterior summed term by term */
    int cases[][2] = {{10, 1}, {12, 3}, {20, 5}, {40, 12}};
    for (int c = 0; c < 4; c++) {
        int n = cases[c][0], w = cases[c][1];
        CHECK_REL(zp_basins_expected(n, w), posterior_mean(n, w), SUM_TOL);
    }
    CHECK(isinf(zp_basins_expected(5, 3))); /* n <= w + 2: the mean does not exist */
    CHECK(isinf(zp_basins_unseen(4, 2)));
    /* the searches needed: the first n with fewer than 0.5 basins unseen, and not one before */
    for (int w = 1; w <= 12; w++) {
        int need = zp_basins_searches_needed(w, 0.5);
        CHECK(zp_basins_unseen(need, w) < 0.5);
        CHECK(!(zp_basins_unseen(need - 1, w) < 0.5));
    }

    /* a line in f1 at f2 = 50: survivable bands [10, 14] and [20, 30] with a death at 17 between
       them; the slower band holds more points. Two islands, the faster first. */
    clear();
    for (double f = 10; f <= 14; f += 1) {
        put(f, 50, 1, 5 + 0.01 * (f - 14) * (f - 14));
    }
    put(17, 50, -1, 0);
    for (double f = 20; f <= 30; f += 1) {
        put(f, 50, 1, 6 + 0.01 * (f - 25) * (f - 25));
    }
    zp_islands m;
    CHECK(zp_islands_map(&map, &m) == 0);
    CHECK(m.n == 2 && m.nnear == 16);
    CHECK(m.isl[0].npts == 5 && m.isl[1].npts == 11);
    CHECK(zp_search_state_point(&map, m.isl[0].head)[0] == 14);
    CHECK(zp_search_state_point(&map, m.isl[1].head)[0] == 25);
    zp_islands_free(&m);

    /* without the death between them the two bands are one island */
    clear();
    for (double f = 10; f <= 30; f += 1) {
        put(f, 50, 1, 5 + 0.01 * (f - 14) * (f - 14));
    }
    CHECK(zp_islands_map(&map, &m) == 0);
    CHECK(m.n == 1 && m.isl[0].npts == 21 && m.isl[0].nfeas == 21);
    zp_islands_free(&m);

    /* nearly survivable points (3 deg past the margin) map their island; deadly ones do not:
       two clouds at opposite corners, one of them only nearly survivable */
    clear();
    for (int i = 0; i < 5; i++) {
        put(5 + i, 5 + i, 1, 7 + i);
        put(90 + i, 90 - i, 0, 6 + i);
        put(50 + i, 50, -1, 0);
    }
    CHECK(zp_islands_map(&map, &m) == 0);
    CHECK(m.n == 2 && m.nnear == 10);
    CHECK(m.isl[0].nfeas == 5 && m.isl[1].nfeas == 0); /* survivable ranks first */
    zp_islands_free(&m);
    clear();
    return CHECK_DONE();
}
