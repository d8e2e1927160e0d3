/* The loaded cable's equilibrium with the trolley at x (MODEL.md "A cable that sags"): the
   trolley's height f and its exact f', f'', the tensions, and the cable's potential energy. */
#ifndef ZP_CABLE_SOLVE_H
#define ZP_CABLE_SOLVE_H

#include <stddef.h>

#include "cable.h"
#include "diag.h"

/* Two elastic catenaries, A to the trolley and the trolley to B, free to slide through it:
   the same tension on both sides, the vertical tension dropping by the load across it. */
typedef struct zp_cable_state {
    double x;          /* m, the trolley's abscissa, xa < x < xb */
    double load;       /* N, W, the trolley's weight and what hangs from it */
    double f, fp, fpp; /* m, 1, 1/m: the trolley's height and its derivatives in x */
    double ha, hb;     /* N, horizontal tension on the A side, on the B side */
    double t_trolley;  /* N, tension at the trolley (both sides) */
    double ta, tb;     /* N, tension at anchor A, at anchor B */
    double va, vb;     /* N, how hard the cable pulls anchor A down, and anchor B down */
    double sa, sb;     /* m, unstretched cable on each side, sa + sb = L0 */
    double mu_a, mu_b; /* each side's mu (cable_segment.h), to continue from this state */
    double energy;     /* J, Pi_c: the cable's weight (heights from y = 0) and strain energy */
    double denergy;    /* N, dPi_c/dx = (ha - hb) - W fp */
} zp_cable_state;

/* The equilibrium of c with load W (N, >= 0) at x into st, by Newton from the cable's own
   catenary or from the weightless straight-sided solution, whichever is nearer (continuation
   in the load, or in the cable's weight, where Newton alone fails).
   ZP_ERR_INPUT for x outside (xa, xb), a negative or non-finite load, or a weightless cable that
   is neither loaded nor stretched (it has no shape); ZP_ERR_NUMERIC when no equilibrium is
   found. why says which; st is unspecified then. Thread-safe: c is only read. */
zp_status zp_cable_solve(const zp_cable *c, double load, double x, zp_cable_state *st, char *why,
                         size_t whylen);
/* The same at x with near's load, by Newton from near (a solved state at a nearby x); from
   scratch when that fails. */
zp_status zp_cable_solve_near(const zp_cable *c, const zp_cable_state *near, double x,
                              zp_cable_state *st, char *why, size_t whylen);

#endif
