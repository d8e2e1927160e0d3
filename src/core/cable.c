/* The cable's description checked (CONFIG.md [cable]) and its own catenary from A to B: with
   L0 given, the horizontal tension it hangs at; with that tension given, L0. Each is one
   elastic catenary segment solved by Newton from an exact solution of a nearby problem. */
#include "cable.h"

#include <math.h>
#include <stdio.h>

#include "cable_newton.h"
#include "cable_segment.h"

/* The unloaded catenary as a Newton system: the segment from A must end at B. */
typedef struct hang_problem {
    const zp_cable *c;
    double h;      /* N; > 0: the horizontal tension given, unknowns (mu, s); 0: (h, mu) */
    int homotopy;  /* what lambda scales: the compliance, the weight, or nothing */
    double lambda; /* the continuation parameter, 0 .. 1 */
} hang_problem;

enum { SCALE_NONE, SCALE_COMPLIANCE, SCALE_WEIGHT };

static int hang_residual(const double *z, double *r, double *jac, void *ctx) {
    const hang_problem *p = ctx;
    const zp_cable *c = p->c;
    double w = p->homotopy == SCALE_WEIGHT ? p->lambda * c->weight : c->weight;
    double compliance = p->homotopy == SCALE_COMPLIANCE ? p->lambda * c->compliance : c->compliance;
    double h = p->h > 0 ? p->h : z[0], mu = p->h > 0 ? z[0] : z[1];
    double s = p->h > 0 ? z[1] : c->length;
    if (!(h > 0)) {
        return -1;
    }
    for (int j = 0; j < 2; j++) {
        /* seed unknown j: z = (h, mu) or (mu, s) */
        zp_cable_jet jh = {h, p->h > 0 ? 0 : j == 0, 0};
        zp_cable_jet jmu = {mu, p->h > 0 ? j == 0 : j == 1, 0};
        zp_cable_jet js = {s, p->h > 0 && j == 1, 0};
        zp_cable_segment g = zp_cable_segment_ends(jh, jmu, js, w, compliance);
        r[0] = g.dx.v - (c->xb - c->xa);
        r[1] = g.dy.v - (c->yb - c->ya);
        jac[j] = g.dx.d;
        jac[2 + j] = g.dy.d;
    }
    return isfinite(r[0] + r[1] + jac[0] + jac[1] + jac[2] + jac[3]) ? 0 : -1;
}

static double chord(const zp_cable *c) {
    return hypot(c->xb - c->xa, c->yb - c->ya);
}

/* asinh(q) / q falls from 1 (q = 0) to 0: the q > 0 where it is rho, 0 < rho < 1 */
static double asinhc_gap(double q, void *rho) {
    return asinh(q) / q - *(double *)rho;
}

static double asinhc_inverse(double rho) {
    double hi = 1;
    while (asinhc_gap(hi, &rho) > 0) {
        hi *= 2;
    }
    return zp_cable_newton_root(asinhc_gap, &rho, 0x1p-60, hi);
}

/* The exact solution at lambda = 0 of p's homotopy, into z. An inextensible catenary (w > 0):
   with L0, tanh(mu) = -drop / L0 and span = L0 asinhc(q) / cosh(mu); with h, the catenary
   through both anchors, whose length is sqrt((2 h sinh(w span / 2h) / w)^2 + drop^2). A
   weightless elastic chord: one tension stretching L0 to |AB|. */
static int hang_start(const hang_problem *p, double *z) {
    const zp_cable *c = p->c;
    double span = c->xb - c->xa, drop = c->yb - c->ya, w = c->weight;
    if (p->homotopy == SCALE_WEIGHT || w == 0) {
        double t = p->h > 0 ? p->h * chord(c) / span : (chord(c) / c->length - 1) / c->compliance;
        double mu = asinh(-drop / span);
        z[0] = p->h > 0 ? mu : t * span / chord(c);
        z[1] = p->h > 0 ? chord(c) / (1 + t * c->compliance) : mu;
    } else if (p->h > 0) {
        double k = w * span / (2 * p->h), l = hypot(2 * p->h * sinh(k) / w, drop);
        z[0] = atanh(-drop / l);
        z[1] = l;
    } else {
        double mu = atanh(-drop / c->length), q = asinhc_inverse(span * cosh(mu) / c->length);
        z[0] = w * c->length / (2 * q * cosh(mu));
        z[1] = mu;
    }
    return isfinite(z[0]) && isfinite(z[1]) && z[0] != 0 ? 0 : -1;
}

/* A cable of small sag hangs near the parabola, whose sag adds w^2 a^2 d / (24 h^2) to the
   chord d (span a); that is the unstretched length's excess plus its stretch,
   L0 (1 + c h d / a) - d. The gap between the two grows with h: one root. */
static double parabola_gap(double h, void *ctx) {
    const zp_cable *c = ctx;
    double a = c->xb - c->xa, d = chord(c), w = c->weight;
    return c->length * (1 + c->compliance * h * d / a) - d - w * w * a * a * d / (24 * h * h);
}

static double parabola_tension(const zp_cable *c) {
    double lo = 1, hi = 1;
    while (hi < 1e300 && parabola_gap(hi, (void *)c) <= 0) {
        hi *= 2;
    }
    while (lo > 1e-300 && parabola_gap(lo, (void *)c) > 0) {
        lo *= 0.5;
    }
    return zp_cable_newton_root(parabola_gap, (void *)c, lo, hi);
}

/* The catenary from A to B with horizontal tension h (> 0; unknowns mu, s) or with length L0
   (h = 0; unknowns h, mu), into z. With L0, from the parabola first; then (and with h) from
   the nearby exact problem, straight and by continuation. */
static zp_status hang_solve(const zp_cable *c, double h, double *z) {
    hang_problem p = {.c = c, .h = h, .lambda = 1};
    double rscale[2] = {chord(c), chord(c)};
    if (h == 0) {
        double zscale[2] = {parabola_tension(c), 1};
        z[0] = zscale[0];
        z[1] = asinh(-(c->yb - c->ya) / (c->xb - c->xa));
        if (zscale[0] > 0 && zp_cable_newton_solve(2, hang_residual, &p, z, zscale, rscale) == 0) {
            return ZP_OK;
        }
    }
    /* an elastic cable shorter than the chord hangs near the weightless chord; any other near
       its inextensible catenary */
    int taut = h == 0 && c->length < chord(c);
    p.homotopy = taut || c->weight == 0 ? SCALE_WEIGHT : SCALE_COMPLIANCE;
    p.lambda = 0;
    if (hang_start(&p, z)) {
        return ZP_ERR_NUMERIC;
    }
    double zscale[2] = {h > 0 ? 1 : z[0], h > 0 ? c->length + chord(c) : 1};
    double start[2] = {z[0], z[1]};
    p.lambda = 1;
    if (zp_cable_newton_solve(2, hang_residual, &p, z, zscale, rscale) == 0) {
        return ZP_OK;
    }
    z[0] = start[0], z[1] = start[1];
    return zp_cable_newton_continue(2, hang_residual, &p, &p.lambda, z, zscale, rscale)
               ? ZP_ERR_NUMERIC
               : ZP_OK;
}

static zp_status refuse(char *why, size_t whylen, const char *text) {
    snprintf(why, whylen, "%s", text);
    return ZP_ERR_INPUT;
}

zp_cable_def zp_cable_def_of_scene(const zp_scene *sc) {
    return (zp_cable_def){sc->cable_a[0],     sc->cable_a[1],     sc->cable_b[0],
                          sc->cable_b[1],     sc->cable_length,   sc->cable_tension,
                          sc->cable_weight,   sc->cable_ea > 0 ? sc->cable_ea : INFINITY};
}

zp_status zp_cable_build(const zp_cable_def *d, zp_cable *c, char *why, size_t whylen) {
    if (!isfinite(d->xa) || !isfinite(d->ya) || !isfinite(d->xb) || !isfinite(d->yb) ||
        !isfinite(d->length) || !isfinite(d->tension) || !isfinite(d->weight) || isnan(d->ea)) {
        return refuse(why, whylen,
                      "a cable number is not finite; expected finite numbers "
                      "(ea may be infinite: inextensible)");
    }
    if (!(d->xa < d->xb)) {
        return refuse(why, whylen, "anchor A is not left of anchor B; expected x_A < x_B");
    }
    if (d->weight < 0) {
        return refuse(why, whylen, "weight is negative; expected a weight per metre >= 0");
    }
    if (!(d->ea > 0)) {
        return refuse(why, whylen, "ea is not positive; expected EA > 0 (infinite: inextensible)");
    }
    if (d->length < 0 || d->tension < 0) {
        return refuse(why, whylen, "length or tension is negative; expected one of them > 0");
    }
    if ((d->length > 0) == (d->tension > 0)) {
        return refuse(why, whylen, "both or neither of length and tension; expected exactly one");
    }
    *c = (zp_cable){.xa = d->xa,
                    .ya = d->ya,
                    .xb = d->xb,
                    .yb = d->yb,
                    .length = d->length,
                    .weight = d->weight,
                    .ea = d->ea,
                    .compliance = 1 / d->ea};
    if (d->length > 0 && isinf(d->ea) && !(d->length > chord(c))) {
        return refuse(why, whylen,
                      "an inextensible cable not longer than |AB| cannot hang; "
                      "expected length > the anchors' distance");
    }
    if (d->tension > 0 && d->weight == 0 && isinf(d->ea)) {
        return refuse(why, whylen,
                      "a weightless inextensible cable is the taut chord under any "
                      "tension; expected a weight or an ea with tension");
    }
    if (d->tension > 0) {
        double z[2];
        if (hang_solve(c, d->tension, z) != ZP_OK || !(z[1] > 0)) {
            snprintf(why, whylen, "no unstretched length hangs at tension %g N", d->tension);
            return ZP_ERR_NUMERIC;
        }
        c->length = z[1];
    }
    return ZP_OK;
}

/* The unloaded cable's point at unstretched distance u from A (its start pulled up by v0):
   the end of the segment [0, u]. */
static void point_at(const zp_cable *c, double h, double v0, double u, double *x, double *y) {
    double mu = zp_cable_segment_mu(h, v0, u, c->weight);
    zp_cable_segment g = zp_cable_segment_ends(zp_cable_jet_const(h), zp_cable_jet_const(mu),
                                               zp_cable_jet_const(u), c->weight, c->compliance);
    *x = c->xa + g.dx.v;
    *y = c->ya + g.dy.v;
}

typedef struct distance_problem {
    const zp_cable *c;
    double h, v0, x;
} distance_problem;

static double past_x(double u, void *ctx) {
    const distance_problem *m = ctx;
    double x, y;
    point_at(m->c, m->h, m->v0, u, &x, &y);
    return x - m->x;
}

double zp_cable_hang_distance(const zp_cable *c, const zp_cable_unloaded *u, double x) {
    /* x grows with the distance along the cable: one root in [0, L0] */
    distance_problem m = {c, u->h, u->va, x};
    return zp_cable_newton_root(past_x, &m, 0, c->length);
}

zp_status zp_cable_hang(const zp_cable *c, zp_cable_unloaded *u, char *why, size_t whylen) {
    if (c->weight == 0 && !(c->compliance > 0 && c->length < chord(c))) {
        return refuse(why, whylen,
                      "a weightless cable not shorter than |AB| has no shape of "
                      "its own; expected a weight, or an elastic cable stretched");
    }
    double z[2];
    if (hang_solve(c, 0, z) != ZP_OK) {
        snprintf(why, whylen, "the unloaded cable's equilibrium was not found");
        return ZP_ERR_NUMERIC;
    }
    double h = z[0], w = c->weight;
    zp_cable_segment g = zp_cable_segment_ends(zp_cable_jet_const(h), zp_cable_jet_const(z[1]),
                                               zp_cable_jet_const(c->length), w, c->compliance);
    *u = (zp_cable_unloaded){.h = h, .va = g.v0.v, .vb = -g.v1.v, .ta = g.t0.v, .tb = g.t1.v};
    /* the lowest point is where the vertical tension passes zero, if it does */
    if (g.v0.v <= 0) {
        u->x_low = c->xa, u->y_low = c->ya;
    } else if (g.v1.v >= 0) {
        u->x_low = c->xb, u->y_low = c->yb;
    } else {
        point_at(c, h, g.v0.v, g.v0.v / w, &u->x_low, &u->y_low);
    }
    double x_mid, y_mid, s_mid = zp_cable_hang_distance(c, u, 0.5 * (c->xa + c->xb));
    point_at(c, h, g.v0.v, s_mid, &x_mid, &y_mid);
    u->sag_mid = 0.5 * (c->ya + c->yb) - y_mid;
    if (!isfinite(u->sag_mid + u->y_low + u->ta + u->tb)) {
        snprintf(why, whylen, "the unloaded cable's shape is not finite");
        return ZP_ERR_NUMERIC;
    }
    return ZP_OK;
}
