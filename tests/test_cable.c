/* The loaded cable (cable.h, cable_solve.h) against what is known without it: a weightless
   inextensible cable rides the ellipse with foci A and B; a weightless elastic one two straight
   sides under one tension; with no load the trolley rides the unloaded catenary, which closes
   by MODEL.md's own formulas; Pi_c against quadrature of its definition and dPi_c/dx against a
   numerical derivative of Pi_c; f' and f'' against numerical derivatives of f; a heavier rider
   never rides higher; the realistic line of 350 m; bad input refused with a reason. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <string.h>

#include "cable.h"
#include "cable_solve.h"
#include "check.h"

#define G 9.81
/* closed forms against the solve: a few hundred round-offs of the geometry */
#define TOL_CLOSED 1e-12
/* numerical derivatives (five points, a step of STEP of the distance to the nearer anchor, the
   length over which the path bends most): their truncation and the round-off of f divided by
   the step */
#define STEP 1e-3
#define TOL_NUMERIC 1e-8
/* Pi_c against adaptive quadrature of MODEL.md's definition */
#define TOL_QUAD 1e-12

static zp_cable build(zp_cable_def d) {
    zp_cable c;
    char why[256];
    zp_status rc = zp_cable_build(&d, &c, why, sizeof why);
    CHECK(rc == ZP_OK);
    if (rc != ZP_OK) {
        fprintf(stderr, "build: %s\n", why);
    }
    return c;
}

static zp_cable_state solve(const zp_cable *c, double load, double x) {
    zp_cable_state s;
    char why[256];
    zp_status rc = zp_cable_solve(c, load, x, &s, why, sizeof why);
    CHECK(rc == ZP_OK);
    if (rc != ZP_OK) {
        fprintf(stderr, "solve at x = %g, W = %g: %s\n", x, load, why);
    }
    return s;
}

static double span(const zp_cable *c) {
    return c->xb - c->xa;
}

/* the x of the i-th of n interior test points, from 1 % to 99 % of the span */
static double interior(const zp_cable *c, int i, int n) {
    return c->xa + span(c) * (0.01 + 0.98 * i / (n - 1));
}

/* the lower arc of the ellipse |PA| + |PB| = L at x: y, y', y'' from its parametric form */
static void ellipse(const zp_cable *c, double x, double *y) {
    double phi = atan2(c->yb - c->ya, c->xb - c->xa);
    double a = c->length / 2, e = hypot(c->xb - c->xa, c->yb - c->ya) / 2;
    double b = sqrt(a * a - e * e), xm = (c->xa + c->xb) / 2, ym = (c->ya + c->yb) / 2;
    /* x - xm = a cos t cos phi - b sin t sin phi = r cos(t + psi) */
    double r = hypot(a * cos(phi), b * sin(phi)), psi = atan2(b * sin(phi), a * cos(phi));
    double best = INFINITY;
    for (int sign = -1; sign <= 1; sign += 2) {
        double t = sign * acos((x - xm) / r) - psi;
        double yt = ym + a * cos(t) * sin(phi) + b * sin(t) * cos(phi);
        if (yt < best) {
            best = yt;
            double xd = -a * sin(t) * cos(phi) - b * cos(t) * sin(phi);
            double yd = -a * sin(t) * sin(phi) + b * cos(t) * cos(phi);
            double xdd = -a * cos(t) * cos(phi) + b * sin(t) * sin(phi);
            double ydd = -a * cos(t) * sin(phi) - b * sin(t) * cos(phi);
            y[0] = yt;
            y[1] = yd / xd;
            y[2] = (ydd * xd - yd * xdd) / (xd * xd * xd);
        }
    }
}

/* w = 0, EA infinite: the ellipse for any load, and no cable energy, so H_A - H_B = W f' */
static void test_ellipse(void) {
    zp_cable c = build((zp_cable_def){
        .xa = 0, .ya = 30, .xb = 120, .yb = 10, .length = 130, .weight = 0, .ea = INFINITY});
    const double loads[] = {1e-3, 1, 800, 1e6};
    for (int l = 0; l < 4; l++) {
        for (int i = 0; i < 9; i++) {
            double x = interior(&c, i, 9), y[3] = {NAN, NAN, NAN};
            zp_cable_state s = solve(&c, loads[l], x);
            ellipse(&c, x, y);
            CHECK_NEAR(s.f, y[0], TOL_CLOSED * c.length);
            CHECK_NEAR(s.fp, y[1], TOL_CLOSED * fmax(1, fabs(y[1])));
            CHECK_NEAR(s.fpp, y[2], TOL_CLOSED * fmax(1 / c.length, fabs(y[2])));
            CHECK(s.energy == 0);
            CHECK_NEAR(s.ha - s.hb, loads[l] * s.fp, TOL_CLOSED * s.t_trolley);
            CHECK_NEAR(s.sa + s.sb, c.length, TOL_CLOSED * c.length);
        }
    }
}

/* f, f', f'' (and Pi_c) at x by five-point differences of the solve */
static void numeric_derivatives(const zp_cable *c, double load, double x, double *d) {
    double h = STEP * fmin(x - c->xa, c->xb - x), f[5], fp[5], e[5];
    for (int k = 0; k < 5; k++) {
        zp_cable_state s = solve(c, load, x + (k - 2) * h);
        f[k] = s.f, fp[k] = s.fp, e[k] = s.energy;
    }
    d[0] = (f[0] - 8 * f[1] + 8 * f[3] - f[4]) / (12 * h);
    d[1] = (fp[0] - 8 * fp[1] + 8 * fp[3] - fp[4]) / (12 * h);
    d[2] = (e[0] - 8 * e[1] + 8 * e[3] - e[4]) / (12 * h);
}

/* w = 0, finite EA: two straight sides under one tension T, |PA| + |PB| = L0 (1 + T / EA) and
   T (sin a_A + sin a_B) = W; slack (L0 > |AB|) and stretched (L0 < |AB|) */
static void test_weightless_elastic(void) {
    const double lengths[] = {104, 99.5};
    for (int l = 0; l < 2; l++) {
        zp_cable c = build((zp_cable_def){
            .xa = 0, .ya = 0, .xb = 100, .yb = -10, .length = lengths[l], .weight = 0, .ea = 2e5});
        for (int i = 0; i < 7; i++) {
            double x = interior(&c, i, 7), load = 1500, d[3];
            zp_cable_state s = solve(&c, load, x);
            double pa = hypot(x - c.xa, s.f - c.ya), pb = hypot(c.xb - x, s.f - c.yb);
            double t = s.t_trolley, sines = (c.ya - s.f) / pa + (c.yb - s.f) / pb;
            CHECK_REL(pa + pb, c.length * (1 + t / c.ea), TOL_CLOSED);
            CHECK_REL(t * sines, load, TOL_CLOSED);
            CHECK_REL(s.ta, t, TOL_CLOSED);
            CHECK_REL(s.tb, t, TOL_CLOSED);
            /* the strain energy T^2 L0 / (2 EA), and its derivative */
            CHECK_REL(s.energy, t * t * c.length / (2 * c.ea), TOL_CLOSED);
            numeric_derivatives(&c, load, x, d);
            CHECK_NEAR(s.fp, d[0], TOL_NUMERIC * fmax(1, fabs(s.fp)));
            CHECK_NEAR(s.fpp, d[1], TOL_NUMERIC * fmax(1 / span(&c), fabs(s.fpp)));
            CHECK_NEAR(s.denergy, d[2], TOL_NUMERIC * (fabs(s.ha - s.hb) + fabs(load * s.fp)));
        }
    }
}

/* MODEL.md's segment, literally: its end from its start (h, v0, s) */
static void model_segment(const zp_cable *c, double h, double v0, double s, double *dx,
                          double *dy) {
    double w = c->weight, v1 = v0 - w * s;
    *dx = h * s / c->ea + h / w * (asinh(v0 / h) - asinh(v1 / h));
    *dy = -(w * s * (v0 / w - s / 2) / c->ea +
            h / w * (sqrt(1 + (v0 / h) * (v0 / h)) - sqrt(1 + (v1 / h) * (v1 / h))));
}

/* the cables the remaining tests share: the realistic line (350 m span, 35 m drop, 12 mm steel
   rope strung to 20 kN horizontal), a heavy slack rope, a taut elastic one */
static zp_cable realistic(void) {
    return build((zp_cable_def){
        .xa = 0, .ya = 40, .xb = 350, .yb = 5, .tension = 20000, .weight = 5.4, .ea = 8e6});
}

static zp_cable slack(void) {
    return build((zp_cable_def){
        .xa = 0, .ya = 0, .xb = 100, .yb = 30, .length = 160, .weight = 10, .ea = INFINITY});
}

static zp_cable taut(void) {
    return build((zp_cable_def){
        .xa = -20, .ya = 12, .xb = 80, .yb = 2, .length = 100.2, .weight = 2, .ea = 3e5});
}

/* the unloaded catenary closes from A to B by MODEL.md's formulas (and at the tension it was
   strung to); with no load the trolley rides it, and a tiny load barely moves it */
static void test_unloaded(void) {
    zp_cable cables[3] = {realistic(), slack(), taut()};
    for (int k = 0; k < 3; k++) {
        const zp_cable *c = &cables[k];
        zp_cable_unloaded u;
        char why[256];
        CHECK(zp_cable_hang(c, &u, why, sizeof why) == ZP_OK);
        double dx, dy;
        model_segment(c, u.h, u.va, c->length, &dx, &dy);
        CHECK_NEAR(dx, span(c), TOL_CLOSED * c->length);
        CHECK_NEAR(dy, c->yb - c->ya, TOL_CLOSED * c->length);
        CHECK_REL(u.ta, hypot(u.h, u.va), TOL_CLOSED);
        CHECK_REL(u.tb, hypot(u.h, u.vb), TOL_CLOSED);
        if (k == 0) {
            CHECK_REL(u.h, 20000, TOL_CLOSED);
        }
        for (int i = 0; i < 7; i++) {
            double x = interior(c, i, 7);
            /* the unloaded cable's point above x: bisection on MODEL.md's dx along it */
            double lo = 0, hi = c->length;
            for (int it = 0; it < 200 && hi - lo > 4 * DBL_EPSILON * c->length; it++) {
                double mid = 0.5 * (lo + hi);
                model_segment(c, u.h, u.va, mid, &dx, &dy);
                *(dx < x - c->xa ? &lo : &hi) = mid;
            }
            model_segment(c, u.h, u.va, 0.5 * (lo + hi), &dx, &dy);
            zp_cable_state s = solve(c, 0, x), tiny = solve(c, 1e-6, x);
            CHECK_NEAR(s.f, c->ya + dy, TOL_CLOSED * c->length);
            CHECK_REL(s.ha, u.h, TOL_CLOSED);
            CHECK_REL(s.hb, u.h, TOL_CLOSED);
            CHECK(tiny.f < s.f && s.f - tiny.f < 1e-6);
        }
        /* the lowest point and the mid-span sag from the solve at W = 0 */
        zp_cable_state mid = solve(c, 0, 0.5 * (c->xa + c->xb));
        CHECK_NEAR(u.sag_mid, 0.5 * (c->ya + c->yb) - mid.f, TOL_CLOSED * c->length);
        if (u.x_low > c->xa && u.x_low < c->xb) {
            zp_cable_state low = solve(c, 0, u.x_low);
            CHECK_NEAR(low.f, u.y_low, TOL_CLOSED * c->length);
            CHECK_NEAR(low.fp, 0, TOL_CLOSED);
        }
    }
}

/* Pi_c by quadrature of its definition over one side: w y + T^2 / (2 EA) per unstretched
   metre, y from MODEL.md's segment */
typedef struct side {
    const zp_cable *c;
    double h, v0, y0;
} side;

static double side_density(double u, void *ctx) {
    const side *sd = ctx;
    double dx, dy, v = sd->v0 - sd->c->weight * u;
    model_segment(sd->c, sd->h, sd->v0, u, &dx, &dy);
    return sd->c->weight * (sd->y0 + dy) + (sd->h * sd->h + v * v) / (2 * sd->c->ea);
}

static double side_energy(const zp_cable *c, double h, double v0, double y0, double s,
                          gsl_integration_workspace *ws) {
    side sd = {c, h, v0, y0};
    gsl_function f = {side_density, &sd};
    double e = NAN, err;
    CHECK(gsl_integration_qag(&f, 0, s, 0, TOL_QUAD / 10, 1000, GSL_INTEG_GAUSS41, ws, &e, &err) ==
          0);
    return e;
}

/* Pi_c against quadrature; dPi_c/dx = (H_A - H_B) - W f' and f', f'' against numerical
   derivatives of the solve */
static void test_energy_and_derivatives(void) {
    zp_cable cables[3] = {realistic(), slack(), taut()};
    const double loads[3] = {85 * G, 400, 2000};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    for (int k = 0; k < 3; k++) {
        const zp_cable *c = &cables[k];
        for (int i = 0; i < 5; i++) {
            double x = interior(c, i, 5), load = loads[k], d[3];
            zp_cable_state s = solve(c, load, x);
            double va_b = s.va - c->weight * s.sa - load; /* side B's start, past the trolley */
            double quad = side_energy(c, s.ha, s.va, c->ya, s.sa, ws) +
                          side_energy(c, s.hb, va_b, s.f, s.sb, ws);
            CHECK_NEAR(s.energy, quad, TOL_QUAD * (fabs(quad) + c->weight * c->length * 10));
            CHECK_REL(s.vb, -(va_b - c->weight * s.sb), TOL_CLOSED);
            numeric_derivatives(c, load, x, d);
            CHECK_NEAR(s.fp, d[0], TOL_NUMERIC * fmax(1, fabs(s.fp)));
            CHECK_NEAR(s.fpp, d[1], TOL_NUMERIC * fmax(1 / span(c), fabs(s.fpp)));
            CHECK_NEAR(s.denergy, d[2], TOL_NUMERIC * (fabs(s.ha - s.hb) + fabs(load * s.fp)));
            CHECK(s.denergy == (s.ha - s.hb) - load * s.fp);
        }
    }
    gsl_integration_workspace_free(ws);
}

/* L0 from the unloaded tension: a weightless elastic cable is the chord stretched by
   T = H |AB| / span; any cable hangs back at the tension it was strung to; an elastic cable
   exactly as long as |AB| hangs, stretched by its own weight */
static void test_tension_given(void) {
    zp_cable c = build((zp_cable_def){
        .xa = 0, .ya = 0, .xb = 80, .yb = 6, .tension = 5000, .weight = 0, .ea = 1e6});
    double chord = hypot(80, 6);
    CHECK_REL(c.length, chord / (1 + 5000 * chord / 80 / 1e6), TOL_CLOSED);
    const zp_cable strung[] = {
        c,
        build((zp_cable_def){
            .xa = 0, .ya = 0, .xb = 80, .yb = 6, .tension = 300, .weight = 20, .ea = INFINITY}),
        build((zp_cable_def){
            .xa = 0, .ya = 0, .xb = 80, .yb = -60, .tension = 50000, .weight = 3, .ea = 2e6}),
    };
    const double tensions[] = {5000, 300, 50000};
    for (int k = 0; k < 3; k++) {
        zp_cable_unloaded u;
        char why[256];
        CHECK(zp_cable_hang(&strung[k], &u, why, sizeof why) == ZP_OK);
        CHECK_REL(u.h, tensions[k], TOL_CLOSED);
    }
    zp_cable exact = build((zp_cable_def){
        .xa = 0, .ya = 0, .xb = 80, .yb = 6, .length = chord, .weight = 4, .ea = 5e5});
    zp_cable_state s = solve(&exact, 0, 40);
    CHECK(s.f < 3);
    CHECK_NEAR(s.sa + s.sb, exact.length, TOL_CLOSED * exact.length);
}

/* a heavier rider never rides higher: f strictly decreasing in W at every interior x */
static void test_heavier_lower(void) {
    zp_cable cables[4] = {
        realistic(), slack(), taut(),
        build((zp_cable_def){
            .xa = 0, .ya = 0, .xb = 100, .yb = -10, .length = 104, .weight = 0, .ea = 2e5})};
    const double loads[] = {0, 1, 10, 100, 1000, 1e4, 1e5};
    for (int k = 0; k < 4; k++) {
        for (int i = 0; i < 7; i++) {
            double x = interior(&cables[k], i, 7), last = INFINITY;
            for (int l = cables[k].weight > 0 ? 0 : 1; l < 7; l++) {
                double f = solve(&cables[k], loads[l], x).f;
                CHECK(f < last);
                last = f;
            }
        }
    }
}

/* the line of the issue: 350 m span, 35 m drop, 12 mm steel rope (5.4 N/m, EA 8e6 N) strung to
   20 kN (the unloaded cable's horizontal tension, CONFIG.md [cable] tension): an 85 kg load
   sags about 2.56 m more at mid-span than the empty rope */
static void test_realistic(void) {
    zp_cable c = realistic();
    double mid = 0.5 * (c.xa + c.xb);
    zp_cable_state empty = solve(&c, 0, mid), loaded = solve(&c, 85 * G, mid);
    zp_cable_unloaded u;
    char why[256];
    CHECK(zp_cable_hang(&c, &u, why, sizeof why) == ZP_OK);
    printf("realistic line: L0 = %.6f m, unloaded sag at mid-span %.4f m, anchor tensions "
           "%.1f / %.1f N; 85 kg at mid-span: %.4f m lower than the empty rope, trolley "
           "tension %.1f N, H_A %.1f N, H_B %.1f N\n",
           c.length, u.sag_mid, u.ta, u.tb, empty.f - loaded.f, loaded.t_trolley, loaded.ha,
           loaded.hb);
    CHECK_NEAR(empty.f - loaded.f, 2.56, 0.005);
    /* the trolley's start and end stay solvable close to the anchors */
    CHECK(solve(&c, 85 * G, c.xa + 1e-6).f < c.ya);
    CHECK(solve(&c, 85 * G, c.xb - 1e-6).f > c.yb);
    /* from a neighbour, the same equilibrium */
    zp_cable_state near;
    CHECK(zp_cable_solve_near(&c, &loaded, mid + 3, &near, why, sizeof why) == ZP_OK);
    zp_cable_state cold = solve(&c, 85 * G, mid + 3);
    CHECK_NEAR(near.f, cold.f, TOL_CLOSED * c.length);
    CHECK_REL(near.fpp, cold.fpp, TOL_CLOSED);
}

/* bad input: a status and a reason, never a crash */
static void refused(zp_cable_def d, zp_status want, const char *reason) {
    zp_cable c;
    char why[256] = "";
    zp_status rc = zp_cable_build(&d, &c, why, sizeof why);
    CHECK(rc == want);
    CHECK(strstr(why, reason) != NULL);
    if (rc != want || !strstr(why, reason)) {
        fprintf(stderr, "refused: got %d `%s`, expected `%s`\n", rc, why, reason);
    }
}

static void test_bad_input(void) {
    const zp_cable_def ok = {
        .xa = 0, .ya = 10, .xb = 100, .yb = 0, .length = 102, .weight = 1, .ea = INFINITY};
    zp_cable_def d = ok;
    d.xb = 0;
    refused(d, ZP_ERR_INPUT, "x_A < x_B");
    d = ok, d.xb = -5;
    refused(d, ZP_ERR_INPUT, "x_A < x_B");
    d = ok, d.length = 100;
    refused(d, ZP_ERR_INPUT, "cannot hang");
    d = ok, d.weight = -1;
    refused(d, ZP_ERR_INPUT, "weight");
    d = ok, d.ea = 0;
    refused(d, ZP_ERR_INPUT, "EA > 0");
    d = ok, d.ea = -3;
    refused(d, ZP_ERR_INPUT, "EA > 0");
    d = ok, d.ya = NAN;
    refused(d, ZP_ERR_INPUT, "not finite");
    d = ok, d.tension = 1000;
    refused(d, ZP_ERR_INPUT, "exactly one");
    d = ok, d.length = 0;
    refused(d, ZP_ERR_INPUT, "exactly one");
    d = ok, d.length = 0, d.tension = 1000, d.weight = 0;
    refused(d, ZP_ERR_INPUT, "taut chord");
    /* an elastic cable shorter than |AB| hangs, stretched */
    d = ok, d.length = 90, d.ea = 1e6;
    zp_cable c = build(d);
    CHECK(solve(&c, 0, 50).t_trolley > 0);

    zp_cable_state s;
    char why[256];
    c = build(ok);
    CHECK(zp_cable_solve(&c, 100, 0, &s, why, sizeof why) == ZP_ERR_INPUT);
    CHECK(strstr(why, "between the anchors"));
    CHECK(zp_cable_solve(&c, 100, 100, &s, why, sizeof why) == ZP_ERR_INPUT);
    CHECK(zp_cable_solve(&c, 100, NAN, &s, why, sizeof why) == ZP_ERR_INPUT);
    CHECK(zp_cable_solve(&c, -1, 50, &s, why, sizeof why) == ZP_ERR_INPUT);
    CHECK(strstr(why, "load"));
    CHECK(zp_cable_solve(&c, INFINITY, 50, &s, why, sizeof why) == ZP_ERR_INPUT);
    /* a weightless slack cable has no shape without a load */
    d = ok, d.weight = 0;
    c = build(d);
    CHECK(zp_cable_solve(&c, 0, 50, &s, why, sizeof why) == ZP_ERR_INPUT);
    zp_cable_unloaded u;
    CHECK(zp_cable_hang(&c, &u, why, sizeof why) == ZP_ERR_INPUT);
    CHECK(strstr(why, "no shape"));
}

int main(void) {
    gsl_set_error_handler_off(); /* as the program does: every GSL status is checked */
    test_ellipse();
    test_weightless_elastic();
    test_unloaded();
    test_energy_and_derivatives();
    test_tension_given();
    test_heavier_lower();
    test_realistic();
    test_bad_input();
    return CHECK_DONE();
}
