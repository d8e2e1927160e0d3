/* The optional effects of docs/model.md against independent expectations: the terminal speed of a
   chain with drag on an incline, a trolley with rolling resistance (its acceleration, held at
   t = 0 when tan(alpha) <= mu), energy conserved through rounded kinks, the work-energy audit
   with every effect on, both formulations and lagrange's two paths agreeing with every effect
   on, stops at rest restarted alike by an explicit stepper and CVODE, and a kink radius that
   does not fit named as a scene error. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "testutil.h"

#define G 9.81
#define RHO 1.225

/* the effects a test asks for, laid over a scene before its model is built */
typedef struct effects {
    int ndrag;
    double cda[ZP_MAX_LINKS + 1];
    double wind, mu, radius;
} effects;

/* a model of scene text (NULL: the seed) with the effects; NULL and why in d when it does
   not build */
static zp_model *build(const char *ini, const effects *e, zp_scene *sc, zp_diag *d) {
    zp_diag_init(d);
    if (!ini) {
        zp_scene_load_seed(sc);
    } else if (zp_scene_load_string(ini, "test.ini", sc, d) != ZP_OK) {
        return NULL;
    }
    sc->ndrag = e->ndrag;
    memcpy(sc->drag_area, e->cda, sizeof e->cda);
    sc->air_density = RHO;
    sc->wind = e->wind;
    sc->rolling = e->mu;
    sc->kink_radius = e->radius;
    sc->line_kink_radius = 7;
    return zp_model_build(sc, d);
}

static zp_model *model(const char *ini, const effects *e, zp_scene *sc) {
    zp_diag d;
    zp_model *m = build(ini, e, sc, &d);
    if (!m) {
        zp_diag_print(&d, stderr);
        abort();
    }
    return m;
}

static const char *incline =
    "[course]\nx_start = 0\nsection = 3000 : 600 - 0.2*x\n[trolley]\nmass = 30\n"
    "[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 20\n[solver]\nt_max = 200\n";

/* drag only, F = 0, no wind: the chain settles to v = sqrt(2 M g sin(alpha) / (rho sum CdA)) */
static void check_terminal_speed(int formulation) {
    zp_scene sc;
    effects e = {4, {0.05, 1.5, 1, 0.5}, 0, 0, 0};
    zp_model *m = model(incline, &e, &sc);
    double alpha = atan(0.2), vt = sqrt(2 * m->mtot * G * sin(alpha) / (RHO * 3.05));
    double times[] = {100};
    zp_sim_opts o = tu_opts(&sc, 1e-11);
    o.formulation = formulation;
    double f[1] = {0};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched, .sample_t = times, .nsample = 1};
    const zp_result *r = tu_run(m, &o, &in);
    int n;
    const zp_row *smp = zp_sim_samples(*tu_last_sim(), &n);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && n == 1);
    CHECK_REL(hypot(smp[0].c.v[0], smp[0].c.v[1]), vt, 1e-6);
    CHECK(r->w_effect[ZP_EFFECT_W_DRAG] > 0 && r->w_effect[ZP_EFFECT_W_FRICTION] == 0);
    zp_model_free(m);
}

/* rolling only: the chain started along the effective gravity moves rigidly, so the whole
   system accelerates at g (sin(alpha) - mu cos(alpha)) down the incline; held if tan <= mu */
static void check_rolling(int formulation) {
    zp_scene sc;
    effects e = {0, {0}, 0, 0.15, 0};
    zp_model *m = model("[course]\nx_start = 0\nsection = 500 : 100 - 0.2*x\n[trolley]\n"
                        "mass = 30\n[body]\nlengths = 1\nmasses = 0.5\n",
                        &e, &sc);
    double al = atan(-0.2), a = -G * sin(al) - e.mu * G * cos(al);
    double theta = atan2(-a * cos(al), G + a * sin(al));
    zp_chain start = {{0, 100, theta}, {0}};
    double times[] = {2, 5, 8};
    zp_sim_opts o = tu_opts(&sc, 1e-11);
    o.formulation = formulation;
    double f[1] = {0};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched, .start = &start, .sample_t = times, .nsample = 3};
    const zp_result *r = tu_run(m, &o, &in);
    int n;
    const zp_row *smp = zp_sim_samples(*tu_last_sim(), &n);
    CHECK(n == 3);
    for (int k = 0; k < n; k++) {
        CHECK_REL(smp[k].c.q[0], 0.5 * a * cos(al) * times[k] * times[k], 1e-8);
        /* friction mu N along the path, N = M g cos(alpha) */
        CHECK_REL(smp[k].w_effect[ZP_EFFECT_W_FRICTION],
                  e.mu * m->mtot * G * cos(al) * smp[k].c.q[0] / cos(al), 1e-7);
        CHECK_REL(smp[k].loads.normal, m->mtot * G * cos(al), 1e-8);
    }
    CHECK(r->outcome == ZP_OUTCOME_FINISHED);
    zp_model_free(m);

    /* tan(alpha) = 0.2 <= mu: held at t = 0 */
    e.mu = 0.25;
    m = model("[course]\nx_start = 0\nsection = 500 : 100 - 0.2*x\n[trolley]\nmass = 30\n"
              "[body]\nlengths = 1\nmasses = 0.5\n",
              &e, &sc);
    in.start = NULL;
    r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_HELD_BY_FRICTION);
    CHECK(r->time == 0 && r->x == 0);
    zp_model_free(m);
}

/* a valley rounded at its bottom: friction takes the energy out swing by swing, until the
   trolley comes to rest where static friction holds it, |f'| <= mu there */
static void check_held_in_valley(void) {
    zp_scene sc;
    effects e = {0, {0}, 0, 0.1, 10};
    zp_model *m = model("[course]\nx_start = 0\nsection = 50 : 20 - 0.4*x\n"
                        "section = 100 : 0.4*(x - 50)\n[trolley]\nmass = 30\n[body]\n"
                        "lengths = 2\nmasses = 5\ndamping = 5\n[solver]\nt_max = 1000\n",
                        &e, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    double f[2] = {0, 0};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_HELD_BY_FRICTION);
    CHECK(r->time > 0 && r->ncross > 2 && r->e_impulse == 0);
    CHECK(r->x > m->arc[0].x1 && r->x < m->arc[0].x2);
    zp_model_free(m);
}

static const char *kinked =
    "[course]\nx_start = 0\nsection = 50 : 20 - 0.3*x\nsection = 100 : 5 - 0.05*(x - 50)\n"
    "section = 160 : 2.5 - 0.2*(x - 100)\n[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\n"
    "masses = 15, 5, 2\ndamping = 0\n[solver]\nt_max = 60\n";

/* no drive, damping, drag or friction: rounded kinks keep the energy, sharp ones do not */
static void check_rounded_conserves(void) {
    zp_scene sc;
    effects e = {0, {0}, 0, 0, 10};
    zp_model *m = model(kinked, &e, &sc);
    CHECK(m->narc == 2);
    double f[3] = {0, 0, 0}, prev = INFINITY, scale = m->mtot * G * 30;
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    for (double rtol = 1e-6; rtol >= 1e-10; rtol /= 100) {
        zp_sim_opts o = tu_opts(&sc, rtol);
        const zp_result *r = tu_run(m, &o, &in);
        const zp_crossing *c = tu_crossings();
        double drift = fabs(r->e_final - r->e_initial);
        CHECK(r->outcome == ZP_OUTCOME_FINISHED && r->ncross == 2);
        CHECK(r->e_impulse == 0 && c[0].impulse == 0 && c[1].impulse == 0);
        CHECK_NEAR(drift, 0, 1000 * rtol * scale);
        CHECK(drift < prev);
        prev = drift;
    }
    zp_model_free(m);
    e.radius = 0;
    m = model(kinked, &e, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    CHECK(tu_run(m, &o, &in)->e_impulse > 1);
    zp_model_free(m);
}

static const effects all_on = {4, {0.05, 0.3, 0.2, 0.2}, -3, 0.01, 2};
static const double push[3] = {60, 500, 500};

/* every effect on: E - E0 = W_drive - W_damp - W_drag - W_friction - impulse loss */
static void check_audit_all(int formulation) {
    zp_scene sc;
    zp_model *m = model(NULL, &all_on, &sc);
    double prev = INFINITY;
    zp_schedule sched = tu_sched(m, push);
    zp_input in = {.sched = &sched};
    for (double rtol = 1e-6; rtol >= 1e-10; rtol /= 100) {
        zp_sim_opts o = tu_opts(&sc, rtol);
        o.formulation = formulation;
        const zp_result *r = tu_run(m, &o, &in);
        double drag = r->w_effect[ZP_EFFECT_W_DRAG], fric = r->w_effect[ZP_EFFECT_W_FRICTION];
        double res =
            r->e_final - r->e_initial - r->w_drive + r->w_damp + drag + fric + r->e_impulse;
        double scale = fabs(r->e_initial) + fabs(r->w_drive);
        CHECK(drag > 0 && fric > 0 && r->w_damp > 0 && r->e_impulse == 0);
        CHECK_NEAR(res, 0, 1000 * rtol * scale);
        CHECK(fabs(res) < prev);
        prev = fabs(res);
    }
    zp_model_free(m);
}

/* the seed with rolling and no push comes to rest in the valley after stops that turn round,
   then is held and pulled free in turn by its swinging chain (docs/model.md's stick rule: a hold
   ends the run only once the chain has settled) until t_max, never leaving the stretch where
   static friction can hold it, |f'| = |x/10 - 3| / 5 <= mu: an explicit stepper (which
   restarts at each event) and CVODE agree on how and where */
static void check_rest_restarts(void) {
    zp_scene sc;
    effects e = {4, {0.05, 0.3, 0.25, 0.15}, 0, 0.005, 10};
    zp_model *m = model(NULL, &e, &sc);
    double f[3] = {0, 0, 0};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    const char *meth[2] = {"gsl-rk8pd", "cvode-adams"};
    zp_result r[2];
    for (int k = 0; k < 2; k++) {
        zp_sim_opts o = tu_opts(&sc, 1e-9);
        o.method = zp_method_find(meth[k]);
        r[k] = *tu_run(m, &o, &in);
        CHECK(r[k].outcome == ZP_OUTCOME_STALLED && r[k].stall == r[0].stall);
        CHECK(fabs(r[k].x / 10 - 3) / 5 <= e.mu);
    }
    CHECK_NEAR(r[0].time, r[1].time, 1e-5);
    CHECK_NEAR(r[0].x, r[1].x, 1e-6);
    zp_model_free(m);
}

/* both formulations with every effect on: outcome and time to 1e-9 s */
static void check_formulations_agree(void) {
    zp_scene sc;
    zp_model *m = model(NULL, &all_on, &sc);
    zp_schedule sched = tu_sched(m, push);
    zp_input in = {.sched = &sched};
    zp_result r[2];
    for (int f = 0; f < 2; f++) {
        zp_sim_opts o = tu_opts(&sc, 1e-12);
        o.formulation = f;
        r[f] = *tu_run(m, &o, &in);
    }
    printf("agree: %s %s t %.12g / %s %s t %.12g x %g\n", zp_sim_outcome_name(r[0].outcome),
           zp_sim_stall_name(r[0].stall), r[0].time, zp_sim_outcome_name(r[1].outcome),
           zp_sim_stall_name(r[1].stall), r[1].time, r[0].x);
    CHECK(r[1].outcome == r[0].outcome && r[1].stall == r[0].stall);
    CHECK_NEAR(r[1].time, r[0].time, 1e-9);
    CHECK_REL(r[1].w_effect[ZP_EFFECT_W_DRAG], r[0].w_effect[ZP_EFFECT_W_DRAG], 1e-8);
    CHECK_REL(r[1].w_effect[ZP_EFFECT_W_FRICTION], r[0].w_effect[ZP_EFFECT_W_FRICTION], 1e-8);
    zp_model_free(m);
}

static double uniform(double a, double b) {
    return a + (b - a) * rand() / (double)RAND_MAX;
}

/* rates and loads at random states: lagrange's fixed-size path, its general path and
   newton-euler, every effect on (a hilly course: slopes up to 2, both signs of N) */
static void check_random_states(void) {
    zp_scene sc;
    effects e = {4, {0.05, 0.3, 0.2, 0.2}, -3, 0.3, 0};
    zp_model *m = model("[course]\nx_start = 0\nsection = 140 : 10*sin(x/5)\n[trolley]\nmass = "
                        "30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 1\n",
                        &e, &sc);
    const zp_formulation *fs[3] = {zp_formulation_get(ZP_FORM_LAGRANGE),
                                   &zp_form_lagrange_general, zp_formulation_get(ZP_FORM_NEWTON)};
    void *w[3];
    for (int f = 0; f < 3; f++) {
        w[f] = fs[f]->create(m);
    }
    int n = m->nlink, nq = n + 1, np = 2 + 3 * n;
    for (int trial = 0; trial < 200; trial++) {
        double x = uniform(0, 140);
        zp_drive_now dn = {zp_course_eval(m->course, 0, x), uniform(-200, 400), 0,
                           trial % 10 == 0, 0, 0};
        zp_chain c = {{0}, {0}};
        c.q[0] = x;
        c.q[1] = dn.tr.f;
        c.v[0] = trial % 7 == 0 ? 0 : uniform(-15, 15);
        c.v[1] = dn.tr.fp * c.v[0];
        for (int i = 0; i < n; i++) {
            c.q[2 + i] = uniform(-3, 3);
            c.v[2 + i] = uniform(-4, 4);
        }
        double wk[4] = {1, 2, 3, 4};
        double y[3][6 * ZP_MAX_LINKS + 8], yd[3][6 * ZP_MAX_LINKS + 8];
        zp_loads ld[3];
        for (int f = 0; f < 3; f++) {
            fs[f]->from_chain(m, &c, wk, y[f]);
            CHECK(fs[f]->rhs(m, w[f], &dn, y[f], yd[f], &ld[f]) == 0);
        }
        double W = G * m->mtot;
        for (int f = 1; f < 3; f++) {
            double xdd = f == 2 ? yd[2][np] : yd[f][nq];
            CHECK_NEAR(xdd, yd[0][nq], 1e-9 * G);
            for (int i = 0; i < n; i++) {
                double thdd = f == 2 ? yd[2][np + 4 + 3 * i] : yd[f][nq + 1 + i];
                CHECK_NEAR(thdd, yd[0][nq + 1 + i], 1e-9 * G);
            }
            int w0 = f == 2 ? 2 * np : 2 * nq;
            for (int k = ZP_W_EFFECTS; k < m->nwork; k++) {
                CHECK_NEAR(yd[f][w0 + k], yd[0][2 * nq + k], 1e-9 * W * 20);
            }
            CHECK_NEAR(ld[f].normal, ld[0].normal, 1e-9 * W);
            if (dn.hold) {
                CHECK_NEAR(ld[f].hold, ld[0].hold, 1e-9 * W);
            }
            for (int i = 0; i < n; i++) {
                CHECK_NEAR(ld[f].joint[i][0], ld[0].joint[i][0], 1e-9 * W);
                CHECK_NEAR(ld[f].joint[i][1], ld[0].joint[i][1], 1e-9 * W);
            }
        }
        if (dn.hold) {
            CHECK_NEAR(yd[0][nq], 0, 1e-12 * G); /* held: x'' = 0 */
        }
    }
    for (int f = 0; f < 3; f++) {
        fs[f]->free(w[f]);
    }
    zp_model_free(m);
}

/* a radius that does not fit is a scene error naming the kink and the key's line */
static void check_radius_does_not_fit(void) {
    zp_scene sc;
    zp_diag d;
    effects e = {0, {0}, 0, 0, 300};
    CHECK(build(NULL, &e, &sc, &d) == NULL);
    CHECK(d.n >= 1 && strstr(d.text[0], ":7: [physics] kink_radius:") &&
          strstr(d.text[0], "x = 60"));
    e.radius = 100; /* fits each kink alone; the two arcs overlap */
    CHECK(build(NULL, &e, &sc, &d) == NULL);
    CHECK(d.n >= 1 && strstr(d.text[d.n - 1], "overlap") && strstr(d.text[d.n - 1], "x = 100"));
    e.radius = 2;
    zp_model *m = build(NULL, &e, &sc, &d);
    CHECK(m && m->narc == 2);
    /* the arc touches both sections: same height and slope where it meets them */
    for (int i = 0; m && i < m->narc; i++) {
        const zp_arc *a = &m->arc[i];
        int k = m->kink[i].left;
        zp_track l = zp_course_eval(m->course, k, a->x1),
                 r = zp_course_eval(m->course, k + 1, a->x2);
        zp_track al = zp_model_track(m, m->course, k, a->x1 + 1e-9);
        zp_track ar = zp_model_track(m, m->course, k + 1, a->x2 - 1e-9);
        CHECK_NEAR(al.f, l.f, 1e-8);
        CHECK_NEAR(al.fp, l.fp, 1e-6);
        CHECK_NEAR(ar.f, r.f, 1e-8);
        CHECK_NEAR(ar.fp, r.fp, 1e-6);
        CHECK_NEAR(al.fpp * pow(1 + al.fp * al.fp, -1.5), a->side / a->r, 1e-9);
    }
    zp_model_free(m);
}

/* the same from the command line: exit 2, file:line:key naming the kink, nothing written */
static void check_radius_cli(void) {
    char dir[] = "/tmp/zp_physics_XXXXXX", path[256], cmd[1024], out[4096];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/round.ini", dir);
    FILE *f = fopen(path, "w");
    fputs("[course]\nx_start = 0\nsection = 60 : 0.5*x\nsection = 100 : 30 - 0.1*(x - 60)\n"
          "[trolley]\nmass = 30\n[body]\nlengths = 5\nmasses = 15\n"
          "[physics]\nrolling = 0.01\nkink_radius = 400\n",
          f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "cd %s && '%s' simulate round.ini 2>&1", dir, ZP_EXE);
    CHECK(tu_sh(cmd, out, sizeof out) == 2);
    CHECK(strstr(out, "round.ini:12: [physics] kink_radius:") && strstr(out, "x = 60"));
    snprintf(cmd, sizeof cmd, "%s/out", dir);
    CHECK(!tu_exists(cmd));
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
}

int main(void) {
    check_radius_cli();
    check_radius_does_not_fit();
    check_random_states();
    for (int f = 0; f < 2; f++) {
        check_terminal_speed(f);
        check_rolling(f);
        check_audit_all(f);
    }
    check_held_in_valley();
    check_rest_restarts();
    check_rounded_conserves();
    check_formulations_agree();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
