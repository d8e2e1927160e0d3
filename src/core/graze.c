/* The crossing of a grazing death on the dense output: the first time a joint's |relative
   angle| reaches the death angle inside the advance that ended past it. */
#include "graze.h"

#include <math.h>
#include <string.h>

#define GRAZE_ITER 100

typedef struct graze_fn {
    const zp_model *m;
    const zp_formulation *f;
    const zp_method *meth;
    void *mwork;
    int link;
    double *y; /* scratch, n */
} graze_fn;

/* the death angle less |phi_link| at time t on the dense output: > 0 inside */
static double inside(double t, void *p) {
    graze_fn *g = p;
    double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
    if (g->meth->interpolate(g->mwork, t, g->y)) {
        return NAN;
    }
    g->f->relative(g->m, g->y, phi, w);
    return g->m->phi_max_j[g->link] - fabs(phi[g->link]);
}

/* the crossing of joint `link` in [ta, tb] (inside at ta, not at tb), by bisection to the last
   bit: a death ends the run, so its few dozen interpolations are paid once, and nothing is
   allocated */
static double crossing(graze_fn *g, double ta, double tb) {
    double lo = ta, hi = tb;
    if (!(inside(ta, g) > 0)) {
        return ta;
    }
    for (int it = 0; it < GRAZE_ITER; it++) {
        double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) {
            break;
        }
        if (inside(mid, g) > 0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return hi; /* the bracket's end where the joint is at or past the death angle */
}

int zp_graze_locate(const zp_model *m, const zp_formulation *f, const zp_method *meth, void *mwork,
                    double ta, double tb, const double *yb, int n, double *t, double *y,
                    int *link) {
    double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
    f->relative(m, yb, phi, w);
    graze_fn g = {m, f, meth, mwork, 0, y};
    int found = 0;
    for (int i = 0; i < m->nlink; i++) {
        if (!(fabs(phi[i]) >= m->phi_max_j[i])) {
            continue;
        }
        g.link = i;
        double ti = crossing(&g, ta, tb);
        if (!found || ti < *t) {
            *t = ti;
            *link = i;
        }
        found = 1;
    }
    if (found && (*t >= tb || meth->interpolate(mwork, *t, y))) {
        *t = tb; /* the interpolant misses it: the advance's end, where the joint is past */
        memcpy(y, yb, sizeof *y * n);
    }
    return found;
}
