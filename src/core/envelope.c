/* Excursions of felt g above each level of an envelope. A history is read at each interval's
   ends and midpoint; where it changes side of a level between two readings, the crossing is
   bisected on the dense output, so each excursion's length is exact to the bisection. An
   excursion shorter than half an interval between two readings on one side is not seen: it
   would be far shorter than any allowance a ride standard writes. */
#include "envelope.h"

#include <math.h>
#include <string.h>

#define CROSS_ITER 60 /* bisection to the last bits of t */

void zp_envelope_start(zp_envelope *e, int n, const double *level, double t, double g) {
    memset(e, 0, sizeof *e);
    e->n = n;
    memcpy(e->level, level, sizeof *level * (size_t)n);
    e->t = t;
    e->g = g;
    for (int l = 0; l < n; l++) {
        e->since[l] = g > level[l] ? t : NAN;
    }
}

/* the history is above level l from t on (above 1) or below it (0) */
static void side(zp_envelope *e, int l, int above, double t) {
    if (above && isnan(e->since[l])) {
        e->since[l] = t;
    } else if (!above && !isnan(e->since[l])) {
        e->longest[l] = fmax(e->longest[l], t - e->since[l]);
        e->since[l] = NAN;
    }
}

void zp_envelope_jump(zp_envelope *e, double t, double g) {
    for (int l = 0; l < e->n; l++) {
        side(e, l, g > e->level[l], t);
    }
    e->t = t;
    e->g = g;
}

/* the crossing of level l between (ta, ga) and (tb, gb), on opposite sides */
static double crossing(double ta, double ga, double tb, double level, zp_envelope_fn f,
                       void *user) {
    int up = ga <= level; /* rising through the level */
    for (int it = 0; it < CROSS_ITER; it++) {
        double mid = 0.5 * (ta + tb), g;
        if (!(mid > ta && mid < tb) || f(mid, &g, user)) {
            break;
        }
        if ((g > level) == up) {
            tb = mid;
        } else {
            ta = mid;
        }
    }
    return 0.5 * (ta + tb);
}

/* from the last reading to (t, g) */
static void reading(zp_envelope *e, double t, double g, zp_envelope_fn f, void *user) {
    for (int l = 0; l < e->n; l++) {
        int was = e->g > e->level[l], now = g > e->level[l];
        if (was != now) {
            side(e, l, now, crossing(e->t, e->g, t, e->level[l], f, user));
        }
    }
    e->t = t;
    e->g = g;
}

void zp_envelope_interval(zp_envelope *e, double b, double gb, zp_envelope_fn f, void *user) {
    double m = 0.5 * (e->t + b), gm;
    if (m > e->t && m < b && f(m, &gm, user) == 0) {
        reading(e, m, gm, f, user);
    }
    reading(e, b, gb, f, user);
}

void zp_envelope_end(zp_envelope *e, double t) {
    for (int l = 0; l < e->n; l++) {
        side(e, l, 0, t);
    }
}
