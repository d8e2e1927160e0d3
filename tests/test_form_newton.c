/* The "newton-euler" formulation against independent expectations: (a) at random states its
   accelerations and loads equal those of "lagrange", derived separately in minimal
   coordinates; (b) a chain hanging at rest on a flat course carries the weight of the links
   below each joint (closed form); (c) whole runs of both formulations at tight tolerances end
   the same way at the same time, with the same kink impulses and loads at sample times;
   (d) the drift off the constraints stays near the tolerance and does not grow with time. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "testutil.h"

#define G 9.81
/* two direct solves of well-conditioned systems of at most 44 unknowns agree to ~1e4 eps */
#define TOL_SOLVE 1e-10
/* lagrange's fixed-size path against its general path (GSL) and against newton-euler's
   accelerations: the same physics solved two ways, ~1e2 eps apart on these states */
#define TOL_FAST 1e-12
/* finish and death times of the two formulations, at TIGHT_RTOL (the figure) */
#define TOL_TIME 1e-9
#define TIGHT_RTOL 1e-12
/* impulses and loads follow the state, which both runs hold to ~1e3 TIGHT_RTOL */
#define K_STATE 1e3
/* the drift stays below what the integrator is asked for on positions of the scene's size */
#define K_DRIFT 1.0
/* loads of a chain at rest, against the weight, per unit of the requested rtol */
#define K_REST 10.0

static unsigned long rng_state = 12345;
static double worst_rel; /* (a): largest difference relative to its scale, for the log */
static double worst_fast; /* (a): the same, lagrange's fixed-size against its general path */

/* uniform in [lo, hi): a fixed linear congruential sequence, the same on every machine */
static double uniform(double lo, double hi) {
    rng_state = rng_state * 6364136223846793005UL + 1442695040888963407UL;
    return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

static const char *chain_ini(const char *course, const char *lengths, const char *masses,
                             const char *forces) {
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "[course]\nx_start = 0\n%s\n[trolley]\nmass = 30\n"
             "[body]\nlengths = %s\nmasses = %s\ndamping = 1\n[drive]\nforces = %s\n",
             course, lengths, masses, forces);
    return buf;
}

/* the largest magnitude in a list: the scale a relative comparison is taken against */
static double scale_of(const double *v, int n) {
    double s = 0;
    for (int i = 0; i < n; i++) {
        s = fmax(s, fabs(v[i]));
    }
    return s;
}

/* lagrange's rates dl and loads ll at yl (its fixed-size path) against its general path */
static void check_general_path(const zp_model *m, const zp_drive_now *dn, const double *yl,
                               const double *dl, const zp_loads *ll) {
    const zp_formulation *fg = &zp_form_lagrange_general;
    void *wg = fg->create(m);
    int ns = fg->nstate(m), n = m->nlink;
    double dg[2 * ZP_NQ + 2];
    zp_loads lg;
    CHECK(fg->rhs(m, wg, dn, yl, dg, &lg) == 0);
    double sd = fmax(scale_of(dl + n + 1, n + 1), G);
    for (int i = 0; i < ns; i++) {
        double scale = i < n + 1 ? fmax(1, fabs(dl[i])) : i < 2 * n + 2 ? sd : fabs(dl[i]);
        worst_fast = fmax(worst_fast, fabs(dg[i] - dl[i]) / scale);
        CHECK_NEAR(dg[i], dl[i], TOL_FAST * scale);
    }
    double f[2 * ZP_MAX_LINKS + 1];
    f[0] = ll->normal;
    for (int i = 0; i < n; i++) {
        f[1 + 2 * i] = ll->joint[i][0];
        f[2 + 2 * i] = ll->joint[i][1];
    }
    double sf = scale_of(f, 2 * n + 1);
    CHECK_NEAR(lg.normal, ll->normal, TOL_FAST * sf);
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(lg.joint[i][0], ll->joint[i][0], TOL_FAST * sf);
        CHECK_NEAR(lg.joint[i][1], ll->joint[i][1], TOL_FAST * sf);
    }
    fg->free(wg);
}

/* (a) both formulations from one chain state; compare q'', Y'', loads and power terms */
static void check_random_states(const zp_model *m, int drive_tangent) {
    const zp_formulation *fl = zp_formulation_get(ZP_FORM_LAGRANGE);
    const zp_formulation *fn = zp_formulation_get(ZP_FORM_NEWTON);
    void *wl = fl->create(m), *wn = fn->create(m);
    int nn = fn->nstate(m), n = m->nlink, np = 2 + 3 * n;
    CHECK(nn == 2 * np + 2 && 5 * n + 4 == np + 2 * n + 2);
    for (int trial = 0; trial < 50; trial++) {
        /* the course (10 sin(x/5): slopes up to 2) under a random x */
        double x = uniform(0, 140);
        zp_drive_now dn = {zp_course_eval(m->course, 0, x), 0, 0, 0, 0, 0};
        double F = uniform(-200, 400), norm = sqrt(1 + dn.tr.fp * dn.tr.fp);
        dn.fx = drive_tangent ? F / norm : F;
        dn.fy = drive_tangent ? F * dn.tr.fp / norm : 0;
        zp_chain c = {{0}, {0}};
        c.q[0] = x;
        c.q[1] = dn.tr.f;
        c.v[0] = uniform(-15, 15);
        c.v[1] = dn.tr.fp * c.v[0];
        for (int i = 0; i < n; i++) {
            c.q[2 + i] = uniform(-3, 3);
            c.v[2 + i] = uniform(-4, 4);
        }
        double wk[2] = {uniform(0, 1e3), uniform(0, 1e2)};
        double yl[2 * ZP_NQ + 2], yn[6 * ZP_MAX_LINKS + 6], dl[2 * ZP_NQ + 2],
            dnw[6 * ZP_MAX_LINKS + 6];
        fl->from_chain(m, &c, wk, yl);
        fn->from_chain(m, &c, wk, yn);
        zp_loads ll, ln;
        CHECK(fl->rhs(m, wl, &dn, yl, dl, &ll) == 0);
        CHECK(fn->rhs(m, wn, &dn, yn, dnw, &ln) == 0);
        /* the state starts on the constraints */
        CHECK(fn->constraint_residual(m, &dn.tr, yn) <= 1e-13 * (1 + fabs(dn.tr.f)));

        int nq = n + 1;
        double acc_l[ZP_NQ + 1], acc_n[ZP_NQ + 1];
        acc_l[0] = dl[nq];
        acc_n[0] = dnw[np];
        acc_l[1] = dn.tr.fp * dl[nq] + dn.tr.fpp * c.v[0] * c.v[0]; /* Y'' on the course */
        acc_n[1] = dnw[np + 1];
        for (int i = 0; i < n; i++) {
            acc_l[2 + i] = dl[nq + 1 + i];
            acc_n[2 + i] = dnw[np + 4 + 3 * i];
        }
        double sa = fmax(scale_of(acc_l, n + 2), G);
        for (int i = 0; i < n + 2; i++) {
            worst_rel = fmax(worst_rel, fabs(acc_n[i] - acc_l[i]) / sa);
        }
        for (int i = 0; i < n + 2; i++) {
            CHECK_NEAR(acc_n[i], acc_l[i], TOL_FAST * sa);
        }
        check_general_path(m, &dn, yl, dl, &ll);
        /* loads: every force against the largest force, accelerations against theirs */
        double fl_[2 * ZP_MAX_LINKS + 1], al_[2 * ZP_MAX_LINKS + 2];
        fl_[0] = ll.normal;
        for (int i = 0; i < n; i++) {
            fl_[1 + 2 * i] = ll.joint[i][0];
            fl_[2 + 2 * i] = ll.joint[i][1];
        }
        for (int b = 0; b <= n; b++) {
            al_[2 * b] = ll.acc[b][0];
            al_[2 * b + 1] = ll.acc[b][1];
        }
        double sf = scale_of(fl_, 2 * n + 1), sacc = fmax(scale_of(al_, 2 * n + 2), G);
        worst_rel = fmax(worst_rel, fabs(ln.normal - ll.normal) / sf);
        for (int i = 0; i < n; i++) {
            worst_rel = fmax(worst_rel, hypot(ln.joint[i][0] - ll.joint[i][0],
                                              ln.joint[i][1] - ll.joint[i][1]) / sf);
        }
        CHECK_NEAR(ln.normal, ll.normal, TOL_SOLVE * sf);
        for (int i = 0; i < n; i++) {
            CHECK_NEAR(ln.joint[i][0], ll.joint[i][0], TOL_SOLVE * sf);
            CHECK_NEAR(ln.joint[i][1], ll.joint[i][1], TOL_SOLVE * sf);
        }
        for (int b = 0; b <= n; b++) {
            CHECK_NEAR(ln.acc[b][0], ll.acc[b][0], TOL_SOLVE * sacc);
            CHECK_NEAR(ln.acc[b][1], ll.acc[b][1], TOL_SOLVE * sacc);
        }
        /* drive power and damper loss rates */
        CHECK_NEAR(dnw[2 * np], dl[2 * nq], TOL_SOLVE * (1 + fabs(dl[2 * nq])));
        CHECK_NEAR(dnw[2 * np + 1], dl[2 * nq + 1], TOL_SOLVE * (1 + fabs(dl[2 * nq + 1])));
        /* positions move with the velocities */
        CHECK(dnw[0] == yn[np] && dnw[4] == yn[np + 4]);
    }
    fl->free(wl);
    fn->free(wn);
}

static void check_random_all(void) {
    static const char *const shapes[][2] = {
        {"5", "22"}, {"5, 5", "15, 7"}, {"5, 5, 5", "15, 5, 2"}, {"4, 4, 4, 3", "12, 5, 3, 2"},
        {"3, 2, 2, 1, 1", "8, 4, 3, 2, 1"}, {"2, 2, 1, 1, 1, 1", "6, 5, 4, 3, 2, 1"},
        {"1, 1, 2, 1, 1, 2, 1", "2, 3, 1, 4, 1, 2, 1"},
        {"1, 2, 1, 3, 1, 2, 1, 0.5", "3, 2, 4, 1, 2, 1, 1, 0.5"}};
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
        zp_scene sc;
        zp_model *m = tu_model(
            chain_ini("section = 140 : 10*sin(x/5)", shapes[k][0], shapes[k][1], "0"), &sc);
        check_random_states(m, 0);
        check_random_states(m, 1);
        zp_model_free(m);
    }
}

/* (b) at rest on y = 0 with no drive: joint i carries the weight of links i..N, the course
   the weight of everything, and nothing accelerates, at any time of a run (to within what
   the integrator holds the state at rest to: K_REST rtol) */
static void check_hanging(int form) {
    zp_scene sc;
    zp_model *m = tu_model(chain_ini("section = 50 : 0", "5, 3, 2", "15, 5, 2", "0"), &sc);
    const double rtol = 1e-10;
    zp_sim_opts o = tu_opts(&sc, rtol);
    o.formulation = form;
    o.t_max = 5;
    double times[] = {0, 1, 4.5};
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched, .sample_t = times, .nsample = 3};
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK);
    CHECK(r.outcome == ZP_OUTCOME_STALLED && r.stall == ZP_STALL_T_MAX);
    int ns;
    const zp_row *smp = zp_sim_samples(s, &ns);
    CHECK(ns == 3);
    double W = G * m->mtot;
    for (int k = 0; k < ns; k++) {
        CHECK_NEAR(smp[k].loads.normal, W, K_REST * rtol * W);
        double below = 0;
        for (int i = m->nlink - 1; i >= 0; i--) {
            below += m->mass[i];
            CHECK_NEAR(smp[k].loads.joint[i][0], 0, K_REST * rtol * W);
            CHECK_NEAR(smp[k].loads.joint[i][1], G * below, K_REST * rtol * W);
        }
        for (int b = 0; b <= m->nlink; b++) {
            CHECK_NEAR(hypot(smp[k].loads.acc[b][0], smp[k].loads.acc[b][1]), 0, K_REST * rtol * G);
        }
    }
    /* the run's load extremes are these same numbers */
    CHECK_NEAR(r.peaks.normal_min, W, K_REST * rtol * W);
    CHECK_NEAR(r.peaks.normal_max, W, K_REST * rtol * W);
    CHECK_NEAR(r.peaks.joint[0], W - G * m->m0, K_REST * rtol * W);
    CHECK_NEAR(r.peaks.acc_g[0], 1, K_REST * rtol); /* hanging at rest, each link feels 1 g */
    zp_sim_free(s);
    zp_model_free(m);
}

/* (c) one scene and schedule through both formulations at TIGHT_RTOL */
static void check_agree(const char *what, const zp_model *m, const zp_scene *sc,
                        const double *force, zp_outcome expect) {
    double times[] = {0.5, 2, 4, 6.5, 9, 12.5, 15};
    static zp_result r[2];
    zp_row smp[2][7];
    static zp_crossing cr[2][ZP_MAX_CROSSINGS]; /* each formulation's kink crossings */
    int ns[2], nc[2];
    for (int f = 0; f < 2; f++) {
        zp_sim_opts o = tu_opts(sc, TIGHT_RTOL);
        o.formulation = f;
        zp_schedule in_sched = tu_sched(m, force);
        zp_input in = {.sched = &in_sched, .sample_t = times, .nsample = 7};
        zp_sim *s = zp_sim_create(m, &o);
        CHECK(zp_sim_run(m, s, &in, &r[f]) == ZP_OK);
        const zp_row *rows = zp_sim_samples(s, &ns[f]);
        memcpy(smp[f], rows, sizeof(zp_row) * ns[f]);
        const zp_crossing *c = zp_sim_crossings(s, &nc[f]);
        memcpy(cr[f], c, sizeof *c * nc[f]);
        zp_sim_free(s);
    }
    if (zp_tol_scale() == 0) {
        double dlam = 0, dload = 0;
        for (int k = 0; k < r[0].ncross && k < r[1].ncross; k++) {
            dlam = fmax(dlam, fabs(cr[1][k].impulse - cr[0][k].impulse));
        }
        for (int k = 0; k < ns[0] && k < ns[1]; k++) {
            dload = fmax(dload, fabs(smp[1][k].loads.normal - smp[0][k].loads.normal));
            for (int i = 0; i < m->nlink; i++) {
                const double *a = smp[1][k].loads.joint[i], *b = smp[0][k].loads.joint[i];
                dload = fmax(dload, hypot(a[0] - b[0], a[1] - b[1]));
            }
        }
        printf("%-22s %-8s t %.9f dt %9.2e kinks %d dLambda %.1e N s dload %.1e N drift %.1e m\n",
               what, zp_sim_outcome_name(r[0].outcome), r[0].time, r[1].time - r[0].time,
               r[0].ncross, dlam, dload, r[1].constraint_residual);
    }
    CHECK(r[0].outcome == expect);
    CHECK(r[1].outcome == r[0].outcome && r[1].stall == r[0].stall);
    CHECK(r[1].died_link == r[0].died_link);
    CHECK_NEAR(r[1].time, r[0].time, TOL_TIME);
    CHECK(r[1].ncross == r[0].ncross);
    for (int k = 0; k < r[0].ncross && k < r[1].ncross; k++) {
        double lam = fabs(cr[0][k].impulse);
        CHECK_NEAR(cr[1][k].t, cr[0][k].t, TOL_TIME);
        CHECK_NEAR(cr[1][k].impulse, cr[0][k].impulse, K_STATE * TIGHT_RTOL * lam);
        CHECK_NEAR(cr[1][k].energy_lost, cr[0][k].energy_lost,
                   K_STATE * TIGHT_RTOL * lam * lam / m->mtot);
    }
    /* loads at the sample times both runs reached, against the weight of everything */
    double W = G * m->mtot;
    CHECK(ns[1] == ns[0]);
    for (int k = 0; k < ns[0] && k < ns[1]; k++) {
        CHECK_NEAR(smp[1][k].loads.normal, smp[0][k].loads.normal, K_STATE * TIGHT_RTOL * W);
        for (int i = 0; i < m->nlink; i++) {
            for (int a = 0; a < 2; a++) {
                CHECK_NEAR(smp[1][k].loads.joint[i][a], smp[0][k].loads.joint[i][a],
                           K_STATE * TIGHT_RTOL * W);
            }
        }
    }
    /* each run's load extremes include every sample it took (the step sequences differ, so
       the extremes of the two runs are not compared with each other) */
    for (int f = 0; f < 2; f++) {
        for (int k = 0; k < ns[f]; k++) {
            const zp_loads *ld = &smp[f][k].loads;
            CHECK(r[f].peaks.normal_min <= ld->normal && ld->normal <= r[f].peaks.normal_max);
            for (int i = 0; i < m->nlink; i++) {
                CHECK(hypot(ld->joint[i][0], ld->joint[i][1]) <= r[f].peaks.joint[i]);
                CHECK(hypot(ld->acc[i + 1][0], ld->acc[i + 1][1] + G) / G <= r[f].peaks.acc_g[i]);
            }
        }
    }
}

static void check_runs(void) {
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    zp_scene_load_seed(&sc);
    zp_model *m = zp_model_build(&sc, &d);
    CHECK(m != NULL);
    if (!m) {
        return;
    }
    static const struct {
        double f[3];
        zp_outcome expect;
    } seed[] = {{{10, 10, 10}, ZP_OUTCOME_FINISHED}, {{20, 20, 20}, ZP_OUTCOME_FINISHED},
                {{25, 25, 25}, ZP_OUTCOME_FINISHED}, {{100, 100, 100}, ZP_OUTCOME_DIED},
                {{40, 0, 30}, ZP_OUTCOME_FINISHED},  {{60, 10, 40}, ZP_OUTCOME_DIED},
                {{10, 0, 0}, ZP_OUTCOME_DIED}}; /* the last rolls back over x = 100 first */
    for (size_t k = 0; k < sizeof seed / sizeof seed[0]; k++) {
        char what[64];
        snprintf(what, sizeof what, "seed %g/%g/%g N", seed[k].f[0], seed[k].f[1], seed[k].f[2]);
        check_agree(what, m, &sc, seed[k].f, seed[k].expect);
    }
    zp_model_free(m);

    static const struct {
        const char *what, *course, *lengths, *masses, *forces;
        zp_outcome expect;
    } other[] = {
        {"smooth course", "section = 120 : 20 - x/6 + 2*cos(x/7)", "5, 5, 5", "15, 5, 2", "30",
         ZP_OUTCOME_DIED},
        {"flat course", "section = 50 : 0", "5, 5, 5", "15, 5, 2", "15", ZP_OUTCOME_FINISHED},
        {"seed course, 1 link", "section = 60 : (x/10 - 3)^2 + 1\nsection = 100 : -x/10 + 16\n"
         "section = 140 : -(x/10 - 12)^2 + 10", "5", "22", "20, 20, 20", ZP_OUTCOME_FINISHED},
        {"seed course, 2 links", "section = 60 : (x/10 - 3)^2 + 1\nsection = 100 : -x/10 + 16\n"
         "section = 140 : -(x/10 - 12)^2 + 10", "5, 5", "15, 7", "20, 20, 20",
         ZP_OUTCOME_FINISHED},
        {"seed course, 4 links", "section = 60 : (x/10 - 3)^2 + 1\nsection = 100 : -x/10 + 16\n"
         "section = 140 : -(x/10 - 12)^2 + 10", "4, 4, 4, 3", "12, 5, 3, 2", "20, 20, 20",
         ZP_OUTCOME_FINISHED},
    };
    for (size_t k = 0; k < sizeof other / sizeof other[0]; k++) {
        zp_model *mo = tu_model(
            chain_ini(other[k].course, other[k].lengths, other[k].masses, other[k].forces), &sc);
        check_agree(other[k].what, mo, &sc, sc.forces, other[k].expect);
        zp_model_free(mo);
    }
}

/* (d) a trolley rocking in a valley until t_max: the largest drift over 120 s is no larger
   than over the first 20 s (up to a factor 2), and near rtol times the size of the scene */
static void check_drift(void) {
    zp_scene sc;
    zp_model *m = tu_model(chain_ini("section = 100 : (x/10 - 5)^2", "5, 5, 5", "15, 5, 2", "0"),
                           &sc);
    double drift[2], t_max[2] = {20, 120};
    for (int k = 0; k < 2; k++) {
        zp_sim_opts o = tu_opts(&sc, 1e-8);
        o.formulation = ZP_FORM_NEWTON;
        o.t_max = t_max[k];
        zp_schedule in_sched = tu_sched(m, sc.forces);
        zp_input in = {.sched = &in_sched};
        const zp_result *r = tu_run(m, &o, &in);
        CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_T_MAX);
        drift[k] = r->constraint_residual;
    }
    if (zp_tol_scale() == 0) {
        printf("drift at rtol 1e-8: %.3g m over 20 s, %.3g m over 120 s\n", drift[0], drift[1]);
    }
    CHECK(drift[1] <= 2 * drift[0]);
    CHECK_NEAR(drift[1], 0, K_DRIFT * 1e-8 * 100);
    zp_model_free(m);
}

int main(void) {
    gsl_set_error_handler_off();
    CHECK(zp_formulation_find("newton-euler") == ZP_FORM_NEWTON);
    CHECK(zp_formulation_get(ZP_FORM_NEWTON)->doc[0] != '\0');
    check_random_all();
    if (zp_tol_scale() == 0) {
        printf("random states: largest relative difference %.2e (fixed-size against general "
               "path %.2e)\n",
               worst_rel, worst_fast);
    }
    check_hanging(ZP_FORM_LAGRANGE);
    check_hanging(ZP_FORM_NEWTON);
    check_runs();
    check_drift();
    return CHECK_DONE();
}
