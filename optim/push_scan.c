/* The best constant push (push_scan.h): a grid of shares, then each fast island's edge
   bisected. Within a survivable band the finish time falls as the push grows until the chain
   folds, so a band's fastest point lies at an edge next to a death, finer than any grid. */
#include "push_scan.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pool.h"

/* a band of survivable grid points [a, b] and the bisection of its fast edge */
typedef struct island {
    int a, b;
    double best;         /* s, its fastest grid point's time */
    double u_ok, u_dead; /* shares: the survivable end and the dying one being bisected */
} island;

static void at_share(const double *lo, const double *hi, int n, double u, double *p) {
    for (int k = 0; k < n; k++) {
        p[k] = fmin(lo[k] + (hi[k] - lo[k]) * u, hi[k]);
    }
}

/* keeps (u, p, e) in out when it survives and is faster (a tie keeps the smaller push) */
static void take(zp_push_scan *out, int n, double u, const double *p, const zp_eval *e) {
    if (zp_objective_feasible(e) &&
        (!out->found || e->time < out->e.time || (e->time == out->e.time && u < out->share))) {
        out->found = 1;
        out->share = u;
        out->e = *e;
        memcpy(out->p, p, sizeof *p * (size_t)n);
    }
}

/* the survivable bands of the grid whose faster end has a dying neighbour, the
   ZP_PUSH_SCAN_ISLANDS fastest first, each set up to bisect towards that neighbour; how many */
static int fast_islands(const zp_eval *e, int npts, island *isl) {
    int n = 0;
    for (int i = 0; i < npts;) {
        if (!zp_objective_feasible(&e[i])) {
            i++;
            continue;
        }
        island c = {.a = i, .best = INFINITY};
        for (; i < npts && zp_objective_feasible(&e[i]); i++) {
            c.b = i;
            c.best = fmin(c.best, e[i].time);
        }
        int right = e[c.b].time <= e[c.a].time; /* the faster end, refined if a run dies past it */
        if (right ? c.b + 1 == npts : c.a == 0) {
            continue;
        }
        c.u_ok = (double)(right ? c.b : c.a) / (npts - 1);
        c.u_dead = (double)(right ? c.b + 1 : c.a - 1) / (npts - 1);
        int at = n < ZP_PUSH_SCAN_ISLANDS ? n++ : ZP_PUSH_SCAN_ISLANDS;
        while (at > 0 && c.best < isl[at - 1].best) {
            if (at < ZP_PUSH_SCAN_ISLANDS) {
                isl[at] = isl[at - 1];
            }
            at--;
        }
        if (at < ZP_PUSH_SCAN_ISLANDS) {
            isl[at] = c;
        }
    }
    return n;
}

int zp_push_scan_points(long max_evals) {
    long n = max_evals / 4;
    return (int)(n < ZP_PUSH_SCAN_MIN   ? ZP_PUSH_SCAN_MIN
                 : n > ZP_PUSH_SCAN_MAX ? ZP_PUSH_SCAN_MAX
                                        : n);
}

zp_status zp_push_scan_run(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                           const double *hi, int npts, int nthreads, zp_push_scan *out) {
    *out = (zp_push_scan){.npts = npts};
    int n = zp_objective_nparams(ob);
    size_t rows = (size_t)(npts > ZP_PUSH_SCAN_ISLANDS ? npts : ZP_PUSH_SCAN_ISLANDS);
    double *f = malloc(sizeof *f * rows * (size_t)n);
    zp_eval *e = malloc(sizeof *e * rows);
    zp_pool *pool = f && e ? zp_pool_create(ob->m, so, nthreads) : NULL;
    if (!pool) {
        free(f);
        free(e);
        return ZP_ERR_NOMEM;
    }
    for (int i = 0; i < npts; i++) {
        at_share(lo, hi, n, (double)i / (npts - 1), f + (size_t)i * n);
    }
    zp_pool_eval(pool, ob, npts, f, e, NULL, NULL);
    out->evals = npts;
    for (int i = 0; i < npts; i++) {
        take(out, n, (double)i / (npts - 1), f + (size_t)i * n, &e[i]);
    }
    island isl[ZP_PUSH_SCAN_ISLANDS];
    int ni = fast_islands(e, npts, isl);
    for (int step = 0; step < ZP_PUSH_SCAN_BISECT && ni > 0; step++) {
        for (int j = 0; j < ni; j++) {
            at_share(lo, hi, n, (isl[j].u_ok + isl[j].u_dead) / 2, f + (size_t)j * n);
        }
        zp_pool_eval(pool, ob, ni, f, e, NULL, NULL);
        out->evals += ni;
        for (int j = 0; j < ni; j++) {
            double u = (isl[j].u_ok + isl[j].u_dead) / 2;
            take(out, n, u, f + (size_t)j * n, &e[j]);
            *(zp_objective_feasible(&e[j]) ? &isl[j].u_ok : &isl[j].u_dead) = u;
        }
    }
    zp_pool_free(pool);
    free(f);
    free(e);
    return ZP_OK;
}
