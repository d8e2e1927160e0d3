/* A cable's designer values over a stretch of x (cable_ride.h): equilibria at evenly spaced x,
   each from its neighbour, and the extrema of the path where its slope crosses the target
   (0 for the lowest point, the chord's slope for the largest sag) found by bisection. */
#include "cable_ride.h"

#include <math.h>

#include "cable_solve.h"

#define BISECT 60   /* halvings: past round-off on any span */

/* the x in [a, b] where the path's slope crosses target (it does: the caller saw it change
   sides), solved near the state at a; its state into st */
static zp_status slope_at(const zp_cable *c, const zp_cable_state *sa, double b, double target,
                          zp_cable_state *st, char *why, size_t whylen) {
    double a = sa->x, side = sa->fp - target;
    zp_cable_state near = *sa;
    *st = *sa;
    for (int i = 0; i < BISECT && b - a > 0; i++) {
        double mid = 0.5 * (a + b);
        zp_status rc = zp_cable_solve_near(c, &near, mid, st, why, whylen);
        if (rc != ZP_OK) {
            return rc;
        }
        if ((st->fp - target > 0) == (side > 0)) {
            a = mid;
            near = *st;
        } else {
            b = mid;
        }
    }
    return ZP_OK;
}

/* the tensions' running maxima over st */
static void tensions(const zp_cable_state *st, zp_cable_ride *out) {
    out->ta_max = fmax(out->ta_max, st->ta);
    out->tb_max = fmax(out->tb_max, st->tb);
    out->trolley_max = fmax(out->trolley_max, st->t_trolley);
}

/* sample i of ZP_CABLE_RIDE_SAMPLES over [x_lo, x_hi] into st, from the one before it (prev,
   sample 0 from scratch): every reader of the samples walks the same chain, so their values
   agree to the bit */
static zp_status sample(const zp_cable *c, double load, double x_lo, double x_hi, int i,
                        const zp_cable_state *prev, zp_cable_state *st, char *why,
                        size_t whylen) {
    double x = x_lo + (x_hi - x_lo) * i / ZP_CABLE_RIDE_SAMPLES;
    return i ? zp_cable_solve_near(c, prev, x, st, why, whylen)
             : zp_cable_solve(c, load, x_lo, st, why, whylen);
}

zp_status zp_cable_ride_anchor_max(const zp_cable *c, double load, double x_lo, double x_hi,
                                   double *t_max, char *why, size_t whylen) {
    zp_cable_ride out = {0};
    zp_cable_state prev, st;
    zp_status rc = ZP_OK;
    for (int i = 0; i <= ZP_CABLE_RIDE_SAMPLES && rc == ZP_OK; i++) {
        rc = sample(c, load, x_lo, x_hi, i, &prev, &st, why, whylen);
        if (rc == ZP_OK) {
            tensions(&st, &out);
            prev = st;
        }
    }
    *t_max = rc == ZP_OK ? fmax(out.ta_max, out.tb_max) : NAN;
    return rc;
}

zp_status zp_cable_ride_over(const zp_cable *c, double load, double x_lo, double x_hi,
                             zp_cable_ride *out, char *why, size_t whylen) {
    double chord = (c->yb - c->ya) / (c->xb - c->xa);
    *out = (zp_cable_ride){0, 0, 0, x_lo, INFINITY, -INFINITY, x_lo, NAN, NAN};
    zp_cable_state prev, st, ext;
    zp_status rc = ZP_OK;
    for (int i = 0; i <= ZP_CABLE_RIDE_SAMPLES && rc == ZP_OK; i++) {
        double x = x_lo + (x_hi - x_lo) * i / ZP_CABLE_RIDE_SAMPLES;
        rc = sample(c, load, x_lo, x_hi, i, &prev, &st, why, whylen);
        if (rc != ZP_OK) {
            break;
        }
        tensions(&st, out);
        double sag = c->ya + chord * (x - c->xa) - st.f;
        if (st.f < out->y_low) {
            out->y_low = st.f, out->x_low = x;
        }
        if (sag > out->sag_max) {
            out->sag_max = sag, out->x_sag_max = x;
        }
        /* an extremum between the samples: refined where the slope crosses */
        for (int k = 0; i && k < 2 && rc == ZP_OK; k++) {
            double target = k ? chord : 0;
            if ((prev.fp - target > 0) == (st.fp - target > 0)) {
                continue;
            }
            rc = slope_at(c, &prev, x, target, &ext, why, whylen);
            double h = c->ya + chord * (ext.x - c->xa) - ext.f;
            if (rc == ZP_OK && !k && ext.f < out->y_low) {
                out->y_low = ext.f, out->x_low = ext.x;
            } else if (rc == ZP_OK && k && h > out->sag_max) {
                out->sag_max = h, out->x_sag_max = ext.x;
            }
        }
        prev = st;
    }
    if (rc != ZP_OK) {
        return rc;
    }
    out->slope_end = prev.fp;
    double mid = 0.5 * (c->xa + c->xb);
    rc = zp_cable_solve(c, load, mid, &st, why, whylen);
    if (rc == ZP_OK) {
        out->sag_mid = 0.5 * (c->ya + c->yb) - st.f;
    }
    return rc;
}

