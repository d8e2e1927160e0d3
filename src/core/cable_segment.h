/* One elastic catenary segment (MODEL.md "A cable that sags", Irvine): where its end lies from
   its start, the tensions at both ends, and the potential energy it holds. */
#ifndef ZP_CABLE_SEGMENT_H
#define ZP_CABLE_SEGMENT_H

#include "cable_jet.h"

/* A segment of unstretched length s and horizontal tension h, weight w per unstretched metre,
   compliance c = 1/EA (0: inextensible). Its vertical tension pulls its start up by v0 and
   falls to v1 = v0 - w s at its end; theta = asinh(v / h) is the hyperbolic slope there (the
   cable's dy/dx = -sinh(theta)). It is described by mu = (theta0 + theta1) / 2 rather than by
   v0: in (h, mu, s) the MODEL.md ends are free of the 1/w that cancels as w -> 0,
     dx = s (c h + asinhc(q) / cosh mu),  dy = -s (c h sinh mu sqrt(1 + q^2) + tanh mu),
   with q = w s / (2 h cosh mu) = sinh((theta0 - theta1) / 2) and asinhc(q) = asinh(q) / q. */
typedef struct zp_cable_segment {
    zp_cable_jet dx, dy; /* m, the end minus the start (y up) */
    zp_cable_jet v0, v1; /* N, vertical tension at the start (pulling it up), at the end */
    zp_cable_jet t0, t1; /* N, tension magnitude at the start, at the end */
} zp_cable_segment;

/* The segment's ends, each with its derivatives along the direction the jets h, mu, s carry. */
zp_cable_segment zp_cable_segment_ends(zp_cable_jet h, zp_cable_jet mu, zp_cable_jet s, double w,
                                       double c);
/* J, the potential energy the segment holds with its start at height y0 (m): its weight's,
   w times the height of each unstretched element, plus its strain energy, T^2 c / 2 per
   unstretched metre. */
double zp_cable_segment_energy(double h, double mu, double s, double w, double c, double y0);
/* mu of the segment of unstretched length s whose start is pulled up by v0 (N). */
double zp_cable_segment_mu(double h, double v0, double s, double w);

#endif
