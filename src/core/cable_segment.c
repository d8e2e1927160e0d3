/* The elastic catenary segment in (h, mu, s) (cable_segment.h): MODEL.md's ends and energy
   rewritten so that w -> 0 and EA -> infinity are their limits, with series where the closed
   form cancels. */
#include "cable_segment.h"

#include <math.h>

/* below this |q| the closed form of asinhc's derivatives cancels (a factor 1/q^2): series */
#define ASINHC_SERIES 0.5
/* below this |d| sinh(d) - d cancels: series */
#define SHC3_SERIES 1.0
/* a series term this small beside the sum's leading 1 no longer changes it */
#define SERIES_DONE 1e-18

/* asinh(q) / q with its first and second derivatives, as a jet of the jet q */
static zp_cable_jet asinhc(zp_cable_jet q) {
    double x = q.v, g, g1, g2;
    if (fabs(x) < ASINHC_SERIES) {
        /* sum_n a_n x^(2n), a_0 = 1, a_(n+1) / a_n = -(2n + 1)^2 / (2 (n + 1) (2n + 3)) */
        double x2 = x * x, a = 1, pow2n2 = 1; /* a_n and x^(2n - 2) */
        g = 1, g1 = 0, g2 = 0;
        for (int n = 1; n < 80; n++) {
            a *= -(2.0 * n - 1) * (2.0 * n - 1) / (2.0 * n * (2.0 * n + 1));
            double t = a * pow2n2;
            g += t * x2;
            g1 += 2 * n * t * x;
            g2 += 2 * n * (2 * n - 1) * t;
            if (fabs(t) < SERIES_DONE) {
                break;
            }
            pow2n2 *= x2;
        }
    } else {
        /* from (x g)' = 1 / sqrt(1 + x^2) and its derivative */
        double r = sqrt(1 + x * x);
        g = asinh(x) / x;
        g1 = (1 / r - g) / x;
        g2 = (-x / (r * r * r) - 2 * g1) / x;
    }
    return zp_cable_jet_chain(g, g1, g2, q);
}

/* (sinh(d) - d) / d^3 */
static double shc3(double d) {
    if (fabs(d) >= SHC3_SERIES) {
        return (sinh(d) - d) / (d * d * d);
    }
    double t = 1.0 / 6, sum = t;
    for (int k = 0; k < 40 && t > SERIES_DONE * sum; k++) {
        t *= d * d / ((2.0 * k + 4) * (2.0 * k + 5));
        sum += t;
    }
    return sum;
}

zp_cable_segment zp_cable_segment_ends(zp_cable_jet h, zp_cable_jet mu, zp_cable_jet s, double w,
                                       double c) {
    zp_cable_jet ch = zp_cable_jet_cosh(mu), sh = zp_cable_jet_sinh(mu);
    zp_cable_jet half_ws = zp_cable_jet_scale(0.5 * w, s);
    zp_cable_jet q = zp_cable_jet_div(half_ws, zp_cable_jet_mul(h, ch));
    /* sqrt(1 + q^2) = cosh((theta0 - theta1) / 2) */
    zp_cable_jet cq =
        zp_cable_jet_sqrt(zp_cable_jet_add(zp_cable_jet_const(1), zp_cable_jet_mul(q, q)));
    zp_cable_jet ch_h = zp_cable_jet_scale(c, h);
    zp_cable_segment g;
    g.dx = zp_cable_jet_mul(s, zp_cable_jet_add(ch_h, zp_cable_jet_div(asinhc(q), ch)));
    /* the vertical tension halfway along: h sinh(mu) cosh((theta0 - theta1) / 2) */
    zp_cable_jet vm = zp_cable_jet_mul(h, zp_cable_jet_mul(sh, cq));
    zp_cable_jet stretch = zp_cable_jet_mul(ch_h, zp_cable_jet_mul(sh, cq));
    g.dy = zp_cable_jet_scale(
        -1, zp_cable_jet_mul(s, zp_cable_jet_add(stretch, zp_cable_jet_div(sh, ch))));
    g.v0 = zp_cable_jet_add(vm, half_ws);
    g.v1 = zp_cable_jet_sub(vm, half_ws);
    g.t0 = zp_cable_jet_hypot(h, g.v0);
    g.t1 = zp_cable_jet_hypot(h, g.v1);
    return g;
}

double zp_cable_segment_energy(double h, double mu, double s, double w, double c, double y0) {
    double ch = cosh(mu), q = w * s / (2 * h * ch), cq = sqrt(1 + q * q);
    double vm = h * sinh(mu) * cq, asc = q == 0 ? 1 : asinh(q) / q;
    /* c/2 int_0^s (h^2 + v(u)^2) du, v falling linearly from vm + ws/2 to vm - ws/2 */
    double strain = 0.5 * c * s * (h * h + vm * vm + w * s * w * s / 12);
    /* w int_0^s y du: the start's height, the stretch's drop, and the inextensible catenary's
       -(int (T0 - T(u)) du) in closed form, whose 1/w cancellation the series of shc3 takes */
    double d = 2 * asinh(q);
    double sag = -0.5 * w * s * s * tanh(mu) -
                 w * w * s * s * s / (2 * h * ch * ch * ch) * asc * asc * asc * shc3(d);
    double weight = w * s * y0 - w * c * s * s * (0.5 * vm + w * s / 12) + sag;
    return weight + strain;
}

double zp_cable_segment_mu(double h, double v0, double s, double w) {
    return 0.5 * (asinh(v0 / h) + asinh((v0 - w * s) / h));
}
