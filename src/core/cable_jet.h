/* Second-order jets: a quantity with its first and second derivatives along one direction of
   the cable's unknowns, so the equilibrium's Jacobian and the path's f'' come exact from the
   same formulas that give the values (no finite differences, no hand-derived partials). */
#ifndef ZP_CABLE_JET_H
#define ZP_CABLE_JET_H

#include <math.h>

/* g(t0 + e) = v + d e + dd e^2 / 2 + O(e^3) */
typedef struct zp_cable_jet {
    double v, d, dd;
} zp_cable_jet;

static inline zp_cable_jet zp_cable_jet_const(double v) {
    return (zp_cable_jet){v, 0, 0};
}

static inline zp_cable_jet zp_cable_jet_add(zp_cable_jet a, zp_cable_jet b) {
    return (zp_cable_jet){a.v + b.v, a.d + b.d, a.dd + b.dd};
}

static inline zp_cable_jet zp_cable_jet_sub(zp_cable_jet a, zp_cable_jet b) {
    return (zp_cable_jet){a.v - b.v, a.d - b.d, a.dd - b.dd};
}

static inline zp_cable_jet zp_cable_jet_scale(double k, zp_cable_jet a) {
    return (zp_cable_jet){k * a.v, k * a.d, k * a.dd};
}

static inline zp_cable_jet zp_cable_jet_mul(zp_cable_jet a, zp_cable_jet b) {
    return (zp_cable_jet){a.v * b.v, a.d * b.v + a.v * b.d,
                          a.dd * b.v + 2 * a.d * b.d + a.v * b.dd};
}

static inline zp_cable_jet zp_cable_jet_div(zp_cable_jet a, zp_cable_jet b) {
    double v = a.v / b.v, d = (a.d - v * b.d) / b.v;
    return (zp_cable_jet){v, d, (a.dd - 2 * d * b.d - v * b.dd) / b.v};
}

/* g(u) from g, g', g'' at u.v (the chain rule to second order) */
static inline zp_cable_jet zp_cable_jet_chain(double g, double g1, double g2, zp_cable_jet u) {
    return (zp_cable_jet){g, g1 * u.d, g2 * u.d * u.d + g1 * u.dd};
}

static inline zp_cable_jet zp_cable_jet_sqrt(zp_cable_jet u) {
    double r = sqrt(u.v);
    return zp_cable_jet_chain(r, 0.5 / r, -0.25 / (r * u.v), u);
}

static inline zp_cable_jet zp_cable_jet_sinh(zp_cable_jet u) {
    double s = sinh(u.v), c = cosh(u.v);
    return zp_cable_jet_chain(s, c, s, u);
}

static inline zp_cable_jet zp_cable_jet_cosh(zp_cable_jet u) {
    double s = sinh(u.v), c = cosh(u.v);
    return zp_cable_jet_chain(c, s, c, u);
}

/* sqrt(a^2 + b^2): a tension from its horizontal and vertical parts */
static inline zp_cable_jet zp_cable_jet_hypot(zp_cable_jet a, zp_cable_jet b) {
    return zp_cable_jet_sqrt(zp_cable_jet_add(zp_cable_jet_mul(a, a), zp_cable_jet_mul(b, b)));
}

#endif
