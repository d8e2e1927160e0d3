/* A cable scene ridden (docs/model.md "A cable that sags"): a bare trolley on the weightless,
   inextensible cable's ellipse finishes when the quadrature of its energy equation says (GSL's
   integration, 1e-9 s); with no drive, damping or drag the bodies' energy plus the cable's own
   Pi_c is conserved on a real cable; both formulations agree; a heavier rider derives its own
   path; and bad [cable] input is an error naming file, line and key. */
#include <gsl/gsl_integration.h>
#include <math.h>
#include <string.h>

#include "cable_ride.h"
#include "estimate.h"
#include "check.h"
#include "formulation.h"
#include "scenario.h"
#include "testutil.h"

#define G 9.81
#define XA 0.0
#define YA 40.0
#define XB 350.0
#define YB 5.0
#define L0 353.0
#define X0 3.5
#define X1 340.0

/* the ellipse |PA| + |PB| = L0 below the chord at x: y by bisection to round-off, and f' by
   implicit differentiation */
static double ellipse(double x, double *fp) {
    double lo = -1000, hi = YA + (YB - YA) * (x - XA) / (XB - XA);
    for (int i = 0; i < 200 && hi - lo > 0; i++) {
        double y = 0.5 * (lo + hi);
        if (!(y > lo && y < hi)) {
            break;
        }
        double s = hypot(x - XA, y - YA) + hypot(x - XB, y - YB);
        if (s > L0) {
            lo = y;
        } else {
            hi = y;
        }
    }
    double y = 0.5 * (lo + hi), ra = hypot(x - XA, y - YA), rb = hypot(x - XB, y - YB);
    double fx = (x - XA) / ra + (x - XB) / rb, fy = (y - YA) / ra + (y - YB) / rb;
    *fp = -fx / fy;
    return y;
}

/* dt/du with x = X0 + u^2 (the start's 1/sqrt singularity taken out): from rest at X0 the
   energy equation gives the speed along the path sqrt(2 g (f(X0) - f(x))) */
static double dt_du(double u, void *p) {
    (void)p;
    double fp0, fp, f0 = ellipse(X0, &fp0), x = X0 + u * u, f = ellipse(x, &fp);
    if (u == 0) {
        return 2 * sqrt(1 + fp0 * fp0) / sqrt(-2 * G * fp0);
    }
    return 2 * u * sqrt(1 + fp * fp) / sqrt(2 * G * (f0 - f));
}

static double quadrature_time(void) {
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
    gsl_function fn = {dt_du, NULL};
    double t, err;
    gsl_integration_qag(&fn, 0, sqrt(X1 - X0), 0, 1e-13, 1000, GSL_INTEG_GAUSS61, w, &t, &err);
    gsl_integration_workspace_free(w);
    return t;
}

/* a trolley of 80 kg and a pendulum of negligible mass (the body needs a link) */
static const char *bare =
    "[cable]\nstart = 0, 40\nend = 350, 5\nlength = 353\nx_start = 3.5\n"
    "sections = 120, 240, 340\n[trolley]\nmass = 80\n[body]\nlengths = 0.5\n"
    "masses = 1e-9\n[solver]\nt_max = 100\n";

static const char *real =
    "[cable]\nstart = 0, 40\nend = 350, 5\ntension = 20000\nweight = 5.7\nea = 7.5e6\n"
    "x_start = 3.5\nsections = 120, 240, 340\n[trolley]\nmass = 5\n[body]\n"
    "lengths = 0.3185, 0.504, 0.9275\nmasses = 6.075, 44.775, 24.15\n[solver]\nt_max = 100\n";

static const zp_result *ride(const zp_model *m, const zp_scene *sc, const char *formulation,
                             double rtol) {
    zp_sim_opts o = tu_opts(sc, rtol);
    o.formulation = zp_formulation_find(formulation);
    double f[3] = {0, 0, 0};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    return tu_run(m, &o, &in);
}

static void check_ellipse(void) {
    zp_scene sc;
    zp_model *m = tu_model(bare, &sc);
    double t = quadrature_time();
    const char *forms[] = {"lagrange", "newton-euler"};
    for (int i = 0; i < 2; i++) {
        const zp_result *r = ride(m, &sc, forms[i], 1e-13);
        CHECK(r->outcome == ZP_OUTCOME_FINISHED && r->ncross == 0);
        printf("ellipse %s: T %.12f s, quadrature %.12f s\n", forms[i], r->time, t);
        CHECK(fabs(r->time - t) < 1e-9);
        CHECK(fabs(zp_estimate_energy_residual(r)) < 1e-6);
        CHECK(fabs(r->pi_final) < 1e-9); /* a weightless, inextensible cable holds none */
    }
    zp_model_free(m);
}

/* the bodies' energy alone is not conserved on a real cable; with Pi_c it is */
static void check_conserved(void) {
    zp_scene sc;
    zp_model *m = tu_model(real, &sc);
    double times[2];
    const char *forms[] = {"lagrange", "newton-euler"};
    for (int i = 0; i < 2; i++) {
        const zp_result *r = ride(m, &sc, forms[i], 1e-11);
        times[i] = r->time;
        double dpi = r->pi_final - r->pi_initial, de = r->e_final - r->e_initial;
        printf("real %s: T %.9f s, bodies' energy change %.6g J, Pi_c change %.6g J, "
               "residual %.3g J\n",
               forms[i], r->time, de, dpi, zp_estimate_energy_residual(r));
        CHECK(r->outcome == ZP_OUTCOME_FINISHED && r->ncross == 0);
        CHECK(fabs(dpi) > 1e3 * fabs(zp_estimate_energy_residual(r)));
        CHECK(fabs(zp_estimate_energy_residual(r)) < 1e-6 * fabs(r->e_initial));
    }
    CHECK(fabs(times[0] - times[1]) < 1e-7);
    zp_model_free(m);
}

/* a heavier rider rides lower: the scenario's model derives its own path, which the nominal
   model does not share */
static void check_scenario_path(void) {
    zp_scene sc;
    zp_model *m = tu_model(real, &sc);
    zp_scenario s;
    zp_scenario_nominal(&s);
    s.mass = 1.5;
    zp_model heavy;
    zp_scenario_model(m, &s, &heavy);
    CHECK(heavy.cable_path && heavy.cable_path != m->cable_path);
    zp_course_err ce;
    zp_course *c = zp_model_course(m, &ce);
    double mid = 175;
    CHECK(zp_model_track(&heavy, c, 1, mid).f < zp_model_track(m, c, 1, mid).f);
    zp_model again;
    zp_scenario_model(m, &s, &again);
    CHECK(again.cable_path == heavy.cable_path); /* built once per load */
    zp_course_free(c);
    zp_model_free(m);
}

/* text's load fails with a message naming test.ini, line and [section] key */
static void check_refused(const char *text, const char *names) {
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    int bad = zp_scene_load_string(text, "test.ini", &sc, &d) != ZP_OK;
    char buf[4096];
    FILE *f = fmemopen(buf, sizeof buf, "w");
    zp_diag_print(&d, f);
    fclose(f);
    CHECK(bad && strstr(buf, names));
    if (!bad || !strstr(buf, names)) {
        fprintf(stderr, "expected `%s` in: %s\n", names, buf);
    }
}

static void check_errors(void) {
    const char *body = "[trolley]\nmass = 5\n[body]\nlengths = 1\nmasses = 70\n";
    char text[1024];
    struct {
        const char *cable, *names;
    } cases[] = {
        {"start = 350, 5\nend = 0, 40\nlength = 400\nsections = 100", "test.ini:3: [cable] end"},
        {"start = 0, 40\nend = 350, 5\nlength = 300\nsections = 100",
         "test.ini:4: [cable] length"},
        {"start = 0, 40\nend = 350, 5\nlength = 360\ntension = 9000\nsections = 100",
         "test.ini:5: [cable] tension"},
        {"start = 0, 40\nend = 350, 5\nweight = 5\nsections = 100", "test.ini:1: [cable] length"},
        {"start = 0, 40\nend = 350, 5\nlength = 360\nsections = 100, 360",
         "test.ini:5: [cable] sections"},
        {"start = 0, 40\nend = 350, 5\nlength = 360\nsections = 100\n[physics]\nkink_radius = 1",
         "test.ini:7: [physics] kink_radius"},
        {"start = 0, 40\nend = 350, 5\nlength = 360\nsections = 100\n[course]\nx_start = 0\n"
         "section = 10 : x",
         "test.ini:6: [course]"},
        {"start = 0, 40\nend = 350, 5\ntension = 9000\nsections = 100",
         "test.ini:4: [cable] tension"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        snprintf(text, sizeof text, "[cable]\n%s\n%s", cases[i].cable, body);
        check_refused(text, cases[i].names);
    }
}

/* the designer's numbers of an unloaded-weight-free ellipse: its lowest point and tensions */
static void check_ride_values(void) {
    zp_cable_def def = {XA, YA, XB, YB, L0, 0, 0, INFINITY};
    zp_cable c;
    char why[256];
    CHECK(zp_cable_build(&def, &c, why, sizeof why) == ZP_OK);
    zp_cable_ride rv;
    CHECK(zp_cable_ride_over(&c, 800, X0, X1, &rv, why, sizeof why) == ZP_OK);
    double fp, xl = rv.x_low, yl = ellipse(xl, &fp);
    CHECK(fabs(rv.y_low - yl) < 1e-9 && fabs(fp) < 1e-7);
    /* one tension throughout a weightless cable: at the anchors as at the trolley */
    CHECK_REL(rv.ta_max, rv.trolley_max, 1e-9);
    CHECK(rv.sag_mid > 0 && rv.sag_max >= rv.sag_mid);
}

int main(void) {
    check_ellipse();
    check_conserved();
    check_scenario_path();
    check_errors();
    check_ride_values();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
