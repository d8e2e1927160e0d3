/* The map's islands (islands.h): the scanned points that survive or nearly survive, grouped
   into the islands of the thin survivable set by nearest-better linking, best island first. */
#include "islands.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NEAR_DEG 5   /* deg: a finished run this far past the margin still maps its island */
#define NEAR_MAX 256 /* near points mapped, best first: the fast islands are among them */
#define SIGMA 2      /* the critical distance's sigma (Rinnooy Kan and Timmer's MLSL) */
#define LINK_TRIES 4 /* nearest better points tried as a point's link */

int zp_islands_near(const zp_eval *e) {
    return !e->failed && e->outcome == ZP_OUTCOME_FINISHED && e->cons <= NEAR_DEG;
}

/* archive point i in shares of the box */
static void unit(const zp_search_state *S, int i, double *u) {
    const double *f = zp_search_state_point(S, i);
    for (int k = 0; k < S->n; k++) {
        double w = S->hi[k] - S->lo[k];
        u[k] = w > 0 ? (f[k] - S->lo[k]) / w : 0;
    }
}

static double dist2(const double *a, const double *b, int n) {
    double d = 0;
    for (int k = 0; k < n; k++) {
        d += (a[k] - b[k]) * (a[k] - b[k]);
    }
    return d;
}

/* MLSL's critical distance for N points in the unit box of n dimensions: below it two points
   of one basin are expected to be linked by the sample itself */
static double critical(int n, long npts) {
    double N = npts > 2 ? (double)npts : 2;
    return pow(tgamma(1 + 0.5 * n) * SIGMA * log(N) / N, 1.0 / n) / sqrt(M_PI);
}

/* design note: two near points are one island only when no other mapped point breaks the ball
   on the segment between them (the Gabriel test), not merely when they are close: on the seed a
   2 N wide band lies next to deadly ones, and distance alone would merge them */
static int blocked(const double *blk, int nblk, int n, const double *a, const double *b) {
    double m[ZP_SCHED_MAX_PARAMS], r2 = 0.25 * dist2(a, b, n);
    for (int k = 0; k < n; k++) {
        m[k] = 0.5 * (a[k] + b[k]);
    }
    for (int j = 0; j < nblk; j++) {
        if (dist2(blk + (size_t)j * n, m, n) < r2) {
            return 1;
        }
    }
    return 0;
}

void zp_islands_free(zp_islands *m) {
    free(m->pt);
    free(m->of);
    free(m->isl);
    memset(m, 0, sizeof *m);
}

/* the island point j of the map links to (u: the mapped points in shares of the box, rc2 the
   squared critical distance): the island of the nearest better point within it that no
   blocker separates from j, of the LINK_TRIES nearest; -1: none */
static int link_of(const zp_islands *m, const double *u, int j, int n, double rc2,
                   const double *blk, int nblk) {
    int best[LINK_TRIES], nb = 0;
    double bd[LINK_TRIES];
    for (int i = 0; i < j; i++) {
        double d = dist2(u + (size_t)i * n, u + (size_t)j * n, n);
        if (d >= rc2 || (nb == LINK_TRIES && d >= bd[nb - 1])) {
            continue;
        }
        int at = nb < LINK_TRIES ? nb++ : LINK_TRIES - 1;
        for (; at > 0 && bd[at - 1] > d; at--) {
            best[at] = best[at - 1];
            bd[at] = bd[at - 1];
        }
        best[at] = i;
        bd[at] = d;
    }
    for (int t = 0; t < nb; t++) {
        if (!blocked(blk, nblk, n, u + (size_t)best[t] * n, u + (size_t)j * n)) {
            return m->of[best[t]];
        }
    }
    return -1;
}

int zp_islands_map(const zp_search_state *S, zp_islands *m) {
    memset(m, 0, sizeof *m);
    int n = S->n, na = S->a.n, nnear = 0, nblk = 0;
    int *near = malloc(sizeof *near * (na ? na : 1));
    double *blk = malloc(sizeof *blk * (size_t)(na ? na : 1) * n);
    double *u = malloc(sizeof *u * NEAR_MAX * n);
    m->pt = malloc(sizeof *m->pt * NEAR_MAX);
    m->of = malloc(sizeof *m->of * NEAR_MAX);
    m->isl = malloc(sizeof *m->isl * NEAR_MAX);
    /* the near points, best first; every other point can break a link */
    for (int i = 0; near && blk && i < na; i++) {
        if (zp_islands_near(&S->a.e[i])) {
            near[nnear++] = i;
        } else {
            unit(S, i, blk + (size_t)nblk++ * n);
        }
    }
    if (!near || !blk || !u || !m->pt || !m->of || !m->isl ||
        zp_search_state_rank(S, near, nnear)) {
        free(near);
        free(blk);
        free(u);
        zp_islands_free(m);
        return -1;
    }
    m->nnear = nnear < NEAR_MAX ? nnear : NEAR_MAX;
    double rc2 = pow(critical(n, na), 2);
    for (int j = 0; j < m->nnear; j++) {
        m->pt[j] = near[j];
        unit(S, near[j], u + (size_t)j * n);
        /* joins the island of the nearest better point it links to, else heads a new one */
        m->of[j] = link_of(m, u, j, n, rc2, blk, nblk);
        if (m->of[j] < 0) {
            m->of[j] = m->n;
            m->isl[m->n++] = (zp_island){.head = near[j]};
        }
        zp_island *is = &m->isl[m->of[j]];
        is->npts++;
        is->nfeas += zp_objective_feasible(&S->a.e[near[j]]);
    }
    free(near);
    free(blk);
    free(u);
    return 0;
}
