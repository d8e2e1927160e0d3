/* The loaded-cable path as a fast table: piecewise Chebyshev series of f, f', f'', Pi_c, H_A and
   H_B fitted once per (cable, load) to exact equilibria, then evaluated in tens of nanoseconds. */
#ifndef ZP_CABLE_PATH_H
#define ZP_CABLE_PATH_H

#include <stddef.h>

#include "cable.h"
#include "diag.h"

typedef struct zp_cable_path zp_cable_path;

/* Everything the path knows at one x. */
typedef struct zp_cable_path_value {
    double f, fp, fpp; /* m, 1, 1/m: the trolley's height and its derivatives in x */
    double energy;     /* J, Pi_c */
    double denergy;    /* N, dPi_c/dx = (ha - hb) - W fp */
    double ha, hb;     /* N, horizontal tension on the A side, on the B side */
} zp_cable_path_value;

/* Builds the path of c (copied) under load W (N) over [x_lo, x_hi], xa < x_lo < x_hi < xb:
   each piece fitted to the equilibria (cable_solve.h) at its Chebyshev points and halved until
   its series' last terms are at round-off. NULL with why filled on bad input (the interval,
   the load), an equilibrium not found, or no memory. Read-only once built: any number of
   threads may evaluate it. */
zp_cable_path *zp_cable_path_create(const zp_cable *c, double load, double x_lo, double x_hi,
                                    char *why, size_t whylen);
void zp_cable_path_free(zp_cable_path *p);

/* f, f', f'' at x into f[3]: 0, or -1 when x is outside the built interval (or NaN): f is then
   NaN and nothing past the interval is evaluated. */
int zp_cable_path_track(const zp_cable_path *p, double x, double *f);
/* Every value at x: 0, or -1 outside the interval (every field NaN). */
int zp_cable_path_eval(const zp_cable_path *p, double x, zp_cable_path_value *v);

/* The largest tension at either anchor (N) at the ZP_CABLE_RIDE_SAMPLES + 1 evenly spaced x of
   [x_lo, x_hi] that zp_cable_ride_anchor_max solves exactly, from the fitted series (their
   agreement: about 1e-13 of the tension); NaN when the interval leaves the path's. */
double zp_cable_path_anchor_max(const zp_cable_path *p, double x_lo, double x_hi);
/* The built interval [*lo, *hi] (m). */
void zp_cable_path_interval(const zp_cable_path *p, double *lo, double *hi);
/* The pieces the interval was cut into. */
int zp_cable_path_pieces(const zp_cable_path *p);
/* The fit's own error estimate: its largest last series term over all pieces and values, each
   relative to that value's largest magnitude over the interval. */
double zp_cable_path_tail(const zp_cable_path *p);

#endif
