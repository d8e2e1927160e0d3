/* Every registered method through the bare interface, on the harmonic oscillator
   y0' = y1, y1' = -y0 from (1, 0), whose solution (cos t, -sin t) is the expectation:
   step ends and dense output inside a step (to rtol, plus for the GSL methods' cubic Hermite
   its bound h^4/384 max|y''''|, max|y''''| = 1 here), roots of g = y0 (zeros at pi/2 + k pi) with
   direction filtering (only falling crossings when asked: k even), t_stop, the earliest of
   two roots in one step, reset, and a failure status (not a crash) for a broken rhs; with y0
   declared a position, the quintic bound on its dense output and on its value at its extrema
   (roots where only the state is wanted). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "method.h"

#define RTOL 1e-10
/* a solution is met to a few hundred times rtol (global error over ~10 periods) */
#define K_RTOL 1000.0

typedef struct osc {
    int broken_after; /* t > this gives a NaN rate; < 0: never */
    int code;         /* what rhs returns then */
} osc;

static int rhs(double t, const double *y, double *yd, void *user) {
    const osc *o = user;
    yd[0] = y[1];
    yd[1] = -y[0];
    if (o->broken_after >= 0 && t > o->broken_after) {
        yd[1] = NAN;
        return o->code;
    }
    return 0;
}

/* g0 = y0 (zeros at pi/2 + k pi), g1 = y0 - 0.5 (zeros at pi/3, 5 pi/3, ..) */
static int root(double t, const double *y, double *g, void *user) {
    (void)t;
    (void)user;
    g[0] = y[0];
    g[1] = y[0] - 0.5;
    return 0;
}

static void check_method(int id) {
    const zp_method *me = zp_method_get(id);
    CHECK(me && me->name && me->doc && me->doc[0]);
    osc o = {-1, 0};
    zp_method_opts mo = {RTOL, RTOL * 1e-2, 100000, NULL, 0};
    int dir[2] = {-1, 0}; /* g0: falling only (y0 from + to -: t = pi/2 + 2 k pi) */
    void *w = me->create(2, 2, dir, rhs, root, &o, &mo);
    CHECK(w != NULL);
    double y0[2] = {1, 0}, y[2], yi[2], t = 0, tprev = 0, step_start = 0;
    int hermite = !strncmp(me->name, "gsl-", 4);
    double t_end = 20;
    CHECK(me->reset(w, 0, y0, t_end) == 0);
    int roots[2], n0 = 0, n1 = 0, stops = 0, bad_dense = 0, bad_land = 0;
    for (int guard = 0; guard < 100000; guard++) {
        char err[256] = "";
        zp_adv a = me->advance(w, &t, y, roots, err, sizeof err);
        CHECK(a != ZP_ADV_FAIL);
        if (a == ZP_ADV_FAIL) {
            break;
        }
        CHECK(t >= tprev);
        /* dense output half-way back to the previous report, at a step's end (where the
           step's length, for the Hermite bound, is known) */
        double tm = 0.5 * (t + tprev);
        double h = t - step_start;
        double dense_tol = K_RTOL * RTOL + (hermite ? h * h * h * h / 384 : 0);
        if (a != ZP_ADV_ROOT &&
            (me->interpolate(w, tm, yi) != 0 || fabs(yi[0] - cos(tm)) > dense_tol)) {
            bad_dense++;
        }
        /* a landed state carries no interpolant's error: the step's own accuracy */
        if (me->land && a != ZP_ADV_ROOT &&
            (me->land(w, tm, yi) != 0 || fabs(yi[0] - cos(tm)) > K_RTOL * RTOL ||
             fabs(yi[1] + sin(tm)) > K_RTOL * RTOL)) {
            bad_land++;
        }
        CHECK_NEAR(y[0], cos(t), K_RTOL * RTOL);
        CHECK_NEAR(y[1], -sin(t), K_RTOL * RTOL);
        if (a == ZP_ADV_ROOT) {
            if (roots[0]) {
                /* falling zeros of cos only: pi/2 + 2 k pi */
                double k = round((t - M_PI / 2) / (2 * M_PI));
                CHECK_NEAR(t, M_PI / 2 + 2 * k * M_PI, K_RTOL * RTOL);
                CHECK(roots[0] == -1);
                n0++;
            }
            if (roots[1]) {
                double k = round(t / M_PI);
                CHECK(fabs(t - (k * M_PI + M_PI / 3)) < K_RTOL * RTOL ||
                      fabs(t - (k * M_PI - M_PI / 3)) < K_RTOL * RTOL);
                CHECK(roots[1] == (sin(t) > 0 ? -1 : 1));
                n1++;
            }
        }
        tprev = t;
        if (a != ZP_ADV_ROOT) {
            step_start = t;
        }
        if (a == ZP_ADV_STOP) {
            stops++;
            break;
        }
    }
    CHECK(bad_dense == 0);
    if (bad_dense) {
        fprintf(stderr, "%s: %d dense outputs off\n", me->name, bad_dense);
    }
    CHECK(bad_land == 0);
    CHECK(stops == 1);
    CHECK_NEAR(t, t_end, 1e-12);
    /* pi/2 + 2 k pi < 20: k = 0, 1, 2; cos = 1/2 at +-pi/3 + 2 k pi in (0, 20): 7 */
    CHECK(n0 == 3);
    CHECK(n1 == 7);
    long steps = 0, evals = 0;
    me->stats(w, &steps, &evals);
    CHECK(steps > 0 && evals >= steps);
    long rejected = -1;
    me->rejections(w, &rejected);
    CHECK(rejected >= 0);

    /* reset: the same run again gives the same first root, bit for bit */
    double t_a = 0, t_b = 0;
    for (int pass = 0; pass < 2; pass++) {
        CHECK(me->reset(w, 0, y0, t_end) == 0);
        char err[256];
        zp_adv a;
        while ((a = me->advance(w, &t, y, roots, err, sizeof err)) == ZP_ADV_STEP) {
        }
        CHECK(a == ZP_ADV_ROOT);
        *(pass ? &t_b : &t_a) = t;
    }
    CHECK(t_a == t_b);
    CHECK_NEAR(t_a, M_PI / 3, K_RTOL * RTOL);

    /* rates that turn NaN (or are refused: rhs < 0) after t = 1 end in a failure status or a
       non-finite state the caller detects, or stall the method at t = 1 (shrinking steps:
       the caller's step budget ends that); never in a finite run through to t_stop */
    for (int code = 0; code >= -1; code--) {
        o.broken_after = 1;
        o.code = code;
        CHECK(me->reset(w, 0, y0, t_end) == 0);
        int failed = 0;
        double t_last = 0;
        for (int guard = 0; guard < 10000 && !failed; guard++) {
            char err[256] = "";
            zp_adv a = me->advance(w, &t, y, roots, err, sizeof err);
            failed = a == ZP_ADV_FAIL || !isfinite(y[0]) || !isfinite(y[1]);
            if (a == ZP_ADV_FAIL) {
                CHECK(err[0] != '\0');
            } else if (!failed && a != ZP_ADV_STOP) {
                t_last = t;
            }
            if (a == ZP_ADV_STOP) {
                break;
            }
        }
        CHECK(failed || t_last < 1.01);
    }
    me->free(w);
    me->free(NULL);
}

/* g0 = y1: the extrema of y0 (+-1 at k pi), a root where only the state is wanted */
static int root_extrema(double t, const double *y, double *g, void *user) {
    (void)t;
    (void)user;
    g[0] = y[1];
    return 0;
}

/* y0 as a position (npos = 1, its rate y1, its acceleration y1'): dense output inside a step
   and the state at an extremum of y0 meet the quintic Hermite bound
   max|s^3 (1-s)^3| / 6! h^6 max|y^(6)| = h^6 / 46080 (the cubic's h^4/384 is far above it at
   these steps) */
static void check_positions(int id) {
    const zp_method *me = zp_method_get(id);
    osc o = {-1, 0};
    int state_only[1] = {1};
    zp_method_opts mo = {RTOL, RTOL * 1e-2, 100000, state_only, 1};
    void *w = me->create(2, 1, NULL, rhs, root_extrema, &o, &mo);
    CHECK(w != NULL);
    double y0[2] = {1, 0}, y[2], yi[2], t = 0, step_start = 0, t_end = 20;
    CHECK(me->reset(w, 0, y0, t_end) == 0);
    int roots[1], nroot = 0, bad = 0;
    double root_dev = 0; /* the largest ||y0| - 1| at the roots inside the step under way */
    for (int guard = 0; guard < 100000; guard++) {
        char err[256] = "";
        zp_adv a = me->advance(w, &t, y, roots, err, sizeof err);
        CHECK(a != ZP_ADV_FAIL);
        if (a == ZP_ADV_FAIL) {
            break;
        }
        if (a == ZP_ADV_ROOT) {
            /* y0 = cos t is stationary there: +-1 whatever the time (found on the
               interpolant's rate, O(h^4) off, which moves y0 by O(h^8)); checked against
               the bound of the whole step once its end is reported */
            root_dev = fmax(root_dev, fabs(fabs(y[0]) - 1));
            nroot++;
            continue;
        }
        double h = t - step_start, tm = t - 0.3 * h;
        double tol = K_RTOL * RTOL + pow(h, 6) / 46080;
        CHECK(root_dev <= tol);
        if (me->interpolate(w, tm, yi) != 0 || fabs(yi[0] - cos(tm)) > tol) {
            bad++;
        }
        root_dev = 0;
        step_start = t;
        if (a == ZP_ADV_STOP) {
            break;
        }
    }
    CHECK(bad == 0);
    CHECK(nroot == 6); /* k pi in (0, 20): k = 1..6 */
    me->free(w);
}

int main(void) {
    CHECK(zp_method_find("no-such-method") == -1);
    for (int id = 0; id < ZP_METHOD_COUNT; id++) {
        CHECK(zp_method_find(zp_method_get(id)->name) == id);
        check_method(id);
        check_positions(id);
    }
    return CHECK_DONE();
}
