/* What a designer reads of a cable under one load over a stretch of the ride (docs/model.md "A
   cable that sags", CLI.md `cable`): the tensions, the lowest point and the sag, from exact
   equilibria (cable_solve.h), not from a run: the cable is quasi-static, so each is a function
   of the trolley's x alone. */
#ifndef ZP_CABLE_RIDE_H
#define ZP_CABLE_RIDE_H

#include <stddef.h>

#include "cable.h"
#include "diag.h"

/* intervals of the evenly spaced x the tensions are read at over a ride (tensions vary
   slowly; the path's extrema are refined) */
#define ZP_CABLE_RIDE_SAMPLES 400

typedef struct zp_cable_ride {
    double ta_max, tb_max;     /* N, the largest tension at anchor A, at anchor B */
    double trolley_max;        /* N, the largest tension at the trolley */
    double x_low, y_low;       /* m, the trolley's lowest point */
    double sag_max, x_sag_max; /* m, the largest height of the chord above the trolley, where */
    double sag_mid;            /* m, that height at mid-span (x_A + x_B) / 2 */
    double slope_end;          /* f' at x_hi */
} zp_cable_ride;

/* The values of c under load W (N) over x in [x_lo, x_hi] (xa < x_lo <= x_hi < xb) into out:
   sampled, each extremum of the path refined to round-off where its slope turns. ZP_OK, or an
   error from the equilibrium with why filled. */
zp_status zp_cable_ride_over(const zp_cable *c, double load, double x_lo, double x_hi,
                             zp_cable_ride *out, char *why, size_t whylen);
/* The largest tension at either anchor over the same x into *t_max (NaN on an error): the
   ta_max and tb_max of zp_cable_ride_over to the bit, without its extrema (the [limits]
   max_cable_tension a search judges every run by). */
zp_status zp_cable_ride_anchor_max(const zp_cable *c, double load, double x_lo, double x_hi,
                                   double *t_max, char *why, size_t whylen);

#endif
