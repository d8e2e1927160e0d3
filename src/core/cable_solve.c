/* The loaded equilibrium (MODEL.md "A cable that sags"). Unknowns z = (ha, mu_a, s, hb, mu_b):
   s is the unstretched length of the side toward the trolley's nearer anchor, the other side's
   is L0 - s (a short side computed as L0 less the long one would keep only a few digits).
   Equations: side A ends at the trolley, side B at anchor B, the heights close, the vertical
   tension drops by W across the trolley, the tension is the same on both sides. f', f'' by
   implicit differentiation: J z' = -R_x, J z'' = -R_zz[z', z'] (R is linear in x). */
#include "cable_solve.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable_newton.h"
#include "cable_segment.h"

#define NZ 5

/* where the continuation starts: lambda = 0 is a problem solved exactly */
typedef enum {
    FROM_WEIGHTLESS, /* the weight lambda w, the trolley carrying W + (1 - lambda) w L0 / 2 */
    FROM_UNLOADED,   /* the load lambda W on the cable's own catenary */
} start_kind;

typedef struct loaded_problem {
    const zp_cable *c;
    double x, load; /* m, N */
    start_kind from;
    double lambda; /* 1: the problem itself */
    int b_short;   /* the unknown s is side B's (the trolley nearer B), else side A's */
} loaded_problem;

/* d sa / d s (d sb / d s is its negative): one side is s, the other L0 - s */
static double sa_sign(const loaded_problem *p) {
    return p->b_short ? -1 : 1;
}

static double side_a_length(const loaded_problem *p, double s) {
    return p->b_short ? p->c->length - s : s;
}

static double side_b_length(const loaded_problem *p, double s) {
    return p->b_short ? s : p->c->length - s;
}

static double weight_at(const loaded_problem *p) {
    return p->from == FROM_WEIGHTLESS ? p->lambda * p->c->weight : p->c->weight;
}

static double load_at(const loaded_problem *p) {
    if (p->from == FROM_UNLOADED) {
        return p->lambda * p->load;
    }
    return p->load + (1 - p->lambda) * p->c->weight * p->c->length / 2;
}

/* the residuals R(z) and side A's rise, along direction dir of z */
static void system_jets(const loaded_problem *p, const double *z, const double *dir,
                        zp_cable_jet *r, zp_cable_jet *rise_a) {
    const zp_cable *c = p->c;
    double w = weight_at(p);
    double k = sa_sign(p);
    zp_cable_jet ha = {z[0], dir[0], 0}, mua = {z[1], dir[1], 0};
    zp_cable_jet sa = {side_a_length(p, z[2]), k * dir[2], 0};
    zp_cable_jet hb = {z[3], dir[3], 0}, mub = {z[4], dir[4], 0};
    zp_cable_jet sb = {side_b_length(p, z[2]), -k * dir[2], 0};
    zp_cable_segment a = zp_cable_segment_ends(ha, mua, sa, w, c->compliance);
    zp_cable_segment b = zp_cable_segment_ends(hb, mub, sb, w, c->compliance);
    r[0] = zp_cable_jet_sub(a.dx, zp_cable_jet_const(p->x - c->xa));
    r[1] = zp_cable_jet_sub(b.dx, zp_cable_jet_const(c->xb - p->x));
    r[2] = zp_cable_jet_sub(zp_cable_jet_add(a.dy, b.dy), zp_cable_jet_const(c->yb - c->ya));
    r[3] = zp_cable_jet_add(zp_cable_jet_sub(b.v0, a.v1), zp_cable_jet_const(load_at(p)));
    r[4] = zp_cable_jet_sub(a.t1, b.t0);
    *rise_a = a.dy;
}

/* one side's ends with their partial derivatives in (h, mu, s), one seed each */
static void side_partials(double h, double mu, double s, double w, double c, zp_cable_segment *g) {
    for (int j = 0; j < 3; j++) {
        zp_cable_jet jh = {h, j == 0, 0}, jmu = {mu, j == 1, 0}, js = {s, j == 2, 0};
        g[j] = zp_cable_segment_ends(jh, jmu, js, w, c);
    }
}

/* R and its Jacobian, and side A's rise's gradient when grad_rise is not NULL. Side A depends
   on (ha, mu_a, sa) alone, side B on (hb, mu_b, sb), sa + sb = L0: three seeds each. */
static int system_jacobian(const loaded_problem *p, const double *z, double *r, double *jac,
                           double *grad_rise) {
    if (!(z[0] > 0 && z[3] > 0)) {
        return -1;
    }
    const zp_cable *c = p->c;
    double w = weight_at(p);
    zp_cable_segment a[3], b[3];
    side_partials(z[0], z[1], side_a_length(p, z[2]), w, c->compliance, a);
    side_partials(z[3], z[4], side_b_length(p, z[2]), w, c->compliance, b);
    r[0] = a[0].dx.v - (p->x - c->xa);
    r[1] = b[0].dx.v - (c->xb - p->x);
    r[2] = a[0].dy.v + b[0].dy.v - (c->yb - c->ya);
    r[3] = b[0].v0.v - a[0].v1.v + load_at(p);
    r[4] = a[0].t1.v - b[0].t0.v;
    /* column j: side A's seed ja[j] and side B's jb[j], each moved by its sign (the shared
       length s moves the two sides oppositely) */
    static const int ja[NZ] = {0, 1, 2, 0, 0}, jb[NZ] = {0, 0, 2, 0, 1};
    const double ka[NZ] = {1, 1, sa_sign(p), 0, 0}, kb[NZ] = {0, 0, -sa_sign(p), 1, 1};
    double sum = r[0] + r[1] + r[2] + r[3] + r[4];
    for (int j = 0; j < NZ; j++) {
        const zp_cable_segment *da = &a[ja[j]], *db = &b[jb[j]];
        jac[0 * NZ + j] = ka[j] * da->dx.d;
        jac[1 * NZ + j] = kb[j] * db->dx.d;
        jac[2 * NZ + j] = ka[j] * da->dy.d + kb[j] * db->dy.d;
        jac[3 * NZ + j] = kb[j] * db->v0.d - ka[j] * da->v1.d;
        jac[4 * NZ + j] = ka[j] * da->t1.d - kb[j] * db->t0.d;
        if (grad_rise) {
            grad_rise[j] = ka[j] * da->dy.d;
        }
        for (int i = 0; i < NZ; i++) {
            sum += jac[i * NZ + j];
        }
    }
    return isfinite(sum) ? 0 : -1;
}

static int newton_residual(const double *z, double *r, double *jac, void *ctx) {
    return system_jacobian(ctx, z, r, jac, NULL);
}

/* The weightless cable with load W: two straight sides of one tension T at P = (x, y) with
   |PA| + |PB| = L0 (1 + c T) and T (sin a_A + sin a_B) = W. Below the chord the sines' sum
   grows and the length grows as P falls: one root in P's depth e below the chord. */
typedef struct straight_problem {
    const zp_cable *c;
    double x, load;
    double rise_a, rise_b; /* m, A and B above the chord's point at x: its height differences */
} straight_problem;

/* a side's sine gain from the chord to depth e below it: r / |(dx, r)| at r = rise + e less
   at r = rise, as e (q0 - r (2 r + e) / (q0 + q1)) / (q0 q1), which does not cancel as e -> 0
   (the sides' sines on the chord cancel each other, so their sum is the sum of the gains) */
static double sine_gain(double dx, double rise, double e, double *length) {
    double q0 = hypot(dx, rise), q1 = hypot(dx, rise + e);
    *length = q1;
    return e * (q0 - rise * (2 * rise + e) / (q0 + q1)) / (q0 * q1);
}

static double straight_tension(const straight_problem *s, double e, double *pa, double *pb) {
    const zp_cable *c = s->c;
    double gains =
        sine_gain(s->x - c->xa, s->rise_a, e, pa) + sine_gain(c->xb - s->x, s->rise_b, e, pb);
    return s->load / gains;
}

static double straight_gap(double e, void *ctx) {
    const straight_problem *s = ctx;
    double pa, pb, t = straight_tension(s, e, &pa, &pb);
    double stretched =
        s->c->compliance > 0 ? s->c->length * (1 + s->c->compliance * t) : s->c->length;
    return pa + pb - stretched;
}

/* P's depth below the chord; NAN when the root is not bracketed */
static double straight_depth(const straight_problem *s) {
    const zp_cable *c = s->c;
    if (s->load == 0) {
        return 0; /* the stretched chord */
    }
    /* the gap is negative on the chord (an elastic cable's tension unbounded there, where it
       is -infinity: the bracket stops short of it) and grows with the depth: by decades up to
       the first positive, down to the first negative */
    double lo = 0, hi = 1e-12 * fmin(s->x - c->xa, c->xb - s->x);
    for (int i = 0; i < 100 && !(straight_gap(hi, (void *)s) > 0); i++) {
        lo = hi;
        hi *= 10;
    }
    if (lo == 0 && c->compliance > 0) {
        lo = hi;
        for (int i = 0; i < 30 && !(straight_gap(lo, (void *)s) < 0); i++) {
            lo *= 0.1;
        }
    }
    return zp_cable_newton_root(straight_gap, (void *)s, lo, hi);
}

/* z at lambda = 0 from the weightless cable (exact: its weight lumped on the trolley); returns
   the tension there, NAN when there is no such solution */
static double weightless_start(const loaded_problem *p, double *z) {
    const zp_cable *c = p->c;
    double chord_y = c->ya + (c->yb - c->ya) * (p->x - c->xa) / (c->xb - c->xa);
    straight_problem s = {c, p->x, load_at(p), c->ya - chord_y, c->yb - chord_y};
    double e = straight_depth(&s), pa, pb, t;
    if (s.load == 0) {
        pa = hypot(p->x - c->xa, s.rise_a);
        pb = hypot(c->xb - p->x, s.rise_b);
        t = (hypot(c->xb - c->xa, c->yb - c->ya) / c->length - 1) / c->compliance;
    } else {
        t = straight_tension(&s, e, &pa, &pb);
    }
    double stretch = 1 + c->compliance * t;
    z[0] = t * (p->x - c->xa) / pa;
    z[1] = asinh((s.rise_a + e) / (p->x - c->xa));
    z[2] = (p->b_short ? pb : pa) / stretch;
    z[3] = t * (c->xb - p->x) / pb;
    z[4] = asinh(-(s.rise_b + e) / (c->xb - p->x));
    return isfinite(z[0] + z[1] + z[2] + z[3] + z[4]) && t > 0 ? t : NAN;
}

/* z at lambda = 0 from the unloaded catenary (exact: the trolley is a point on it, both sides
   at its horizontal tension); returns that tension, NAN when it has no shape of its own */
static double unloaded_start(const loaded_problem *p, double *z) {
    const zp_cable *c = p->c;
    zp_cable_unloaded u;
    char why[ZP_DIAG_TEXT];
    if (zp_cable_hang(c, &u, why, sizeof why) != ZP_OK) {
        return NAN;
    }
    double sa = zp_cable_hang_distance(c, &u, p->x), w = c->weight;
    z[0] = z[3] = u.h;
    z[1] = zp_cable_segment_mu(u.h, u.va, sa, w);
    z[2] = p->b_short ? c->length - sa : sa;
    z[4] = zp_cable_segment_mu(u.h, u.va - w * sa, c->length - sa, w);
    return isfinite(z[1] + z[2] + z[4]) ? u.h : NAN;
}

static void scales(const zp_cable *c, double tension, double *zscale, double *rscale) {
    double chord = hypot(c->xb - c->xa, c->yb - c->ya);
    const double zs[NZ] = {tension, 1, c->length, tension, 1};
    const double rs[NZ] = {chord, chord, chord, tension, tension};
    memcpy(zscale, zs, sizeof zs);
    memcpy(rscale, rs, sizeof rs);
}

/* the state at the solution z: values, f' and f'' by implicit differentiation, energy */
static int finish(const loaded_problem *p, const double *z, zp_cable_state *st) {
    const zp_cable *c = p->c;
    double r[NZ], jac[NZ * NZ], grad_rise[NZ], dz[NZ], ddz[NZ], d2r[NZ];
    const double minus_rx[NZ] = {1, -1, 0, 0, 0}; /* dR/dx = (-1, 1, 0, 0, 0) */
    if (system_jacobian(p, z, r, jac, grad_rise) || zp_cable_newton_linear(NZ, jac, minus_rx, dz)) {
        return -1;
    }
    zp_cable_jet rj[NZ], rise;
    system_jets(p, z, dz, rj, &rise);
    for (int i = 0; i < NZ; i++) {
        d2r[i] = -rj[i].dd;
    }
    if (zp_cable_newton_linear(NZ, jac, d2r, ddz)) {
        return -1;
    }
    double fpp = rise.dd;
    for (int i = 0; i < NZ; i++) {
        fpp += grad_rise[i] * ddz[i];
    }
    double w = c->weight, sa = side_a_length(p, z[2]), sb = side_b_length(p, z[2]);
    zp_cable_segment a = zp_cable_segment_ends(zp_cable_jet_const(z[0]), zp_cable_jet_const(z[1]),
                                               zp_cable_jet_const(sa), w, c->compliance);
    zp_cable_segment b = zp_cable_segment_ends(zp_cable_jet_const(z[3]), zp_cable_jet_const(z[4]),
                                               zp_cable_jet_const(sb), w, c->compliance);
    st->x = p->x;
    st->load = p->load;
    st->f = c->ya + rise.v;
    st->fp = rise.d;
    st->fpp = fpp;
    st->ha = z[0], st->hb = z[3];
    st->t_trolley = 0.5 * (a.t1.v + b.t0.v);
    st->ta = a.t0.v, st->tb = b.t1.v;
    st->va = a.v0.v, st->vb = -b.v1.v;
    st->sa = sa, st->sb = sb;
    st->mu_a = z[1], st->mu_b = z[4];
    st->energy = zp_cable_segment_energy(z[0], z[1], sa, w, c->compliance, c->ya) +
                 zp_cable_segment_energy(z[3], z[4], sb, w, c->compliance, st->f);
    st->denergy = (z[0] - z[3]) - p->load * st->fp;
    return isfinite(st->f + st->fp + st->fpp + st->energy) ? 0 : -1;
}

static zp_status check_input(const zp_cable *c, double load, double x, char *why, size_t whylen) {
    if (!(x > c->xa && x < c->xb)) {
        snprintf(why, whylen, "x = %g m is not between the anchors; expected %g < x < %g", x, c->xa,
                 c->xb);
        return ZP_ERR_INPUT;
    }
    if (!(load >= 0) || !isfinite(load)) {
        snprintf(why, whylen, "load %g N; expected a finite load >= 0", load);
        return ZP_ERR_INPUT;
    }
    double chord = hypot(c->xb - c->xa, c->yb - c->ya);
    if (c->weight == 0 && load == 0 && !(c->compliance > 0 && c->length < chord)) {
        snprintf(why, whylen,
                 "a weightless cable with no load has no shape unless stretched; "
                 "expected a load > 0");
        return ZP_ERR_INPUT;
    }
    return ZP_OK;
}

static int nearer_b(const zp_cable *c, double x) {
    return x - c->xa > c->xb - x;
}

/* 1 when the cable hangs without a load: it has weight, or it is elastic and stretched */
static int hangs_alone(const zp_cable *c) {
    return c->weight > 0 || (c->compliance > 0 && c->length < hypot(c->xb - c->xa, c->yb - c->ya));
}

zp_status zp_cable_solve(const zp_cable *c, double load, double x, zp_cable_state *st, char *why,
                         size_t whylen) {
    zp_status rc = check_input(c, load, x, why, whylen);
    if (rc != ZP_OK) {
        return rc;
    }
    /* two exact problems nearby: the cable's own catenary, closer when the load is lighter
       than the cable, and the weightless cable, closer when it is heavier. Newton straight
       from each, then continuation from each. */
    start_kind first =
        hangs_alone(c) && load < c->weight * c->length ? FROM_UNLOADED : FROM_WEIGHTLESS;
    for (int attempt = 0; attempt < 4; attempt++) {
        loaded_problem p = {c, x, load, attempt % 2 ? !first : first, 0, nearer_b(c, x)};
        double z[NZ], zscale[NZ], rscale[NZ];
        if (p.from == FROM_UNLOADED && !hangs_alone(c)) {
            continue;
        }
        double t = p.from == FROM_UNLOADED ? unloaded_start(&p, z) : weightless_start(&p, z);
        if (isnan(t)) {
            continue;
        }
        scales(c, t, zscale, rscale);
        p.lambda = 1;
        int solved = attempt < 2 ? zp_cable_newton_solve(NZ, newton_residual, &p, z, zscale, rscale)
                                 : zp_cable_newton_continue(NZ, newton_residual, &p, &p.lambda, z,
                                                            zscale, rscale);
        if (solved == 0 && finish(&p, z, st) == 0) {
            return ZP_OK;
        }
    }
    snprintf(why, whylen, "no equilibrium found with the trolley at x = %g m under %g N", x, load);
    return ZP_ERR_NUMERIC;
}

zp_status zp_cable_solve_near(const zp_cable *c, const zp_cable_state *near, double x,
                              zp_cable_state *st, char *why, size_t whylen) {
    zp_status rc = check_input(c, near->load, x, why, whylen);
    if (rc != ZP_OK) {
        return rc;
    }
    loaded_problem p = {c, x, near->load, FROM_WEIGHTLESS, 1, nearer_b(c, x)};
    double s = p.b_short ? near->sb : near->sa;
    double z[NZ] = {near->ha, near->mu_a, s, near->hb, near->mu_b}, zscale[NZ], rscale[NZ];
    scales(c, near->t_trolley, zscale, rscale);
    if (zp_cable_newton_solve(NZ, newton_residual, &p, z, zscale, rscale) == 0 &&
        finish(&p, z, st) == 0) {
        return ZP_OK;
    }
    return zp_cable_solve(c, near->load, x, st, why, whylen);
}
