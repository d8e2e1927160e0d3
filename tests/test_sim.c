/* Whole runs against independent expectations (docs/model.md "Checks"):
   closed forms (a chain hanging along the effective gravity on a straight incline, for both
   drive directions; the small-oscillation frequency of a rod on a free trolley), energy
   conservation and the work-energy audit shrinking with the tolerance, dampers never adding
   energy, outcomes (death on the seed at 100 N robust to tolerance and method, roll-back at
   t = 0, trapped at a sharp kink, t_max), a sample at a kink showing the state after it,
   the exact largest joint angle, bit-for-bit reproducibility (outputs included), still frames
   at exactly the asked x or t, and a clean numerical failure. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "testutil.h"

#define G 9.81
/* closed forms are met to a few hundred times the requested rtol */
#define K_RTOL 300.0

static const char *incline_ini(const char *dir) {
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "[course]\nx_start = 0\nsection = 200 : 100 - 0.2*x\n"
             "[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 1\n"
             "[drive]\ndirection = %s\nforces = 50\n",
             dir);
    return buf;
}

/* on a straight slope the chain started along the effective gravity translates rigidly:
   theta = atan(f') - atan(F / (M g)) for the horizontal drive; x = a cos(alpha) t^2 / 2 */
static void check_effective_gravity(const char *dir) {
    zp_scene sc;
    zp_model *m = tu_model(incline_ini(dir), &sc);
    double F = 50, M = m->mtot, alpha = atan(-0.2);
    double a, theta;
    if (!strcmp(dir, "horizontal")) {
        a = F * cos(alpha) / M - G * sin(alpha);
        theta = alpha - atan(F / (M * G));
    } else {
        a = F / M - G * sin(alpha);
        theta = atan2(-a * cos(alpha), G + a * sin(alpha));
    }
    zp_chain start = {{0}, {0}};
    start.q[1] = 100;
    for (int i = 0; i < m->nlink; i++) {
        start.q[2 + i] = theta;
    }
    double times[] = {1, 3, 5};
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched, .start = &start, .sample_t = times, .nsample = 3};
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK);
    double L = 200 / cos(alpha);
    CHECK(r.outcome == ZP_OUTCOME_FINISHED);
    CHECK_REL(r.time, sqrt(2 * L / a), K_RTOL * 1e-10);
    int n;
    const zp_row *smp = zp_sim_samples(s, &n);
    CHECK(n == 3);
    for (int k = 0; k < n; k++) {
        CHECK_REL(smp[k].c.q[0], 0.5 * a * cos(alpha) * times[k] * times[k], K_RTOL * 1e-10);
        for (int i = 0; i < m->nlink; i++) {
            CHECK_NEAR(smp[k].c.q[2 + i], theta, 1e-7);
        }
    }
    zp_sim_free(s);
    zp_model_free(m);
}

/* a rod on a free trolley on a flat course: w^2 = 6 g (m0 + m) / (l (4 m0 + m)) */
static void check_small_oscillation(void) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = -50\nsection = 50 : 0*x\n[trolley]\nmass = 10\n"
                           "[body]\nlengths = 2\nmasses = 5\n[solver]\nt_max = 20\n",
                           &sc);
    zp_chain start = {{0}, {0}};
    start.q[0] = -50;
    start.q[2] = 0.01;
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    o.output_dt = 1e-3;
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched, .start = &start};
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK);
    CHECK(r.outcome == ZP_OUTCOME_STALLED && r.stall == ZP_STALL_T_MAX);
    int n, ncross = 0;
    double first = 0, last = 0;
    const zp_row_store *rows = zp_sim_rows(s);
    n = rows->n;
    for (int k = 1; k < n; k++) {
        zp_row r0, r1;
        zp_row_store_get(rows, k - 1, &r0);
        zp_row_store_get(rows, k, &r1);
        double a = r0.c.q[2], b = r1.c.q[2];
        if (a < 0 && b >= 0) { /* upward zero crossing, linearly interpolated */
            double t = r0.t + (r1.t - r0.t) * (-a) / (b - a);
            first = ncross ? first : t;
            last = t;
            ncross++;
        }
    }
    double w = sqrt(6 * G * (10 + 5) / (2 * (4 * 10 + 5)));
    CHECK(ncross >= 5);
    /* amplitude 0.01 rad: the nonlinear period shift is ~theta0^2/16 ~ 6e-6 */
    CHECK_REL((last - first) / (ncross - 1), 2 * M_PI / w, 2e-5);
    zp_sim_free(s);
    zp_model_free(m);
}

/* F = 0, c = 0 on a smooth course: the energy drift is bounded by the tolerance and shrinks */
static void check_conservation(void) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 250 : 20 + 0.002*(x - 100)^2\n"
                           "[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\n"
                           "[solver]\nt_max = 40\n",
                           &sc);
    double prev = INFINITY;
    for (double rtol = 1e-6; rtol >= 1e-10; rtol /= 100) {
        zp_sim_opts o = tu_opts(&sc, rtol);
        zp_schedule in_sched = tu_sched(m, sc.forces);
        zp_input in = {.sched = &in_sched};
        const zp_result *r = tu_run(m, &o, &in);
        double drift = fabs(r->e_final - r->e_initial);
        CHECK(r->outcome == ZP_OUTCOME_STALLED && r->ncross == 0);
        CHECK(r->w_drive == 0 && r->w_damp == 0);
        CHECK_NEAR(drift, 0, 1000 * rtol * fabs(r->e_initial));
        CHECK(drift < prev);
        prev = drift;
    }
    zp_model_free(m);
}

/* the seed at 10 N crosses both kinks and finishes: E - E0 = W_drive - W_damp - impulse loss */
static void check_audit(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    double f[3] = {10, 10, 10}, prev = INFINITY;
    for (double rtol = 1e-6; rtol >= 1e-10; rtol /= 100) {
        zp_sim_opts o = tu_opts(&sc, rtol);
        zp_schedule in_sched = tu_sched(m, f);
        zp_input in = {.sched = &in_sched};
        const zp_result *r = tu_run(m, &o, &in);
        double res = r->e_final - r->e_initial - r->w_drive + r->w_damp + r->e_impulse;
        CHECK(r->outcome == ZP_OUTCOME_FINISHED);
        CHECK(r->ncross == 2 && r->e_impulse > 0);
        /* drive work of a horizontal constant push is F times the distance */
        CHECK_REL(r->w_drive, 10 * 140, 100 * rtol);
        CHECK_NEAR(res, 0, 1000 * rtol * r->e_initial);
        CHECK(fabs(res) < prev);
        prev = fabs(res);
    }
    zp_model_free(m);
}

/* no drive on the seed: the dampers only take energy, row by row, and it never finishes */
static void check_dampers(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    double f[3] = {0, 0, 0};
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    o.output_dt = 0.05;
    zp_schedule in_sched = tu_sched(m, f);
    zp_input in = {.sched = &in_sched};
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK);
    CHECK(r.outcome == ZP_OUTCOME_STALLED && r.stall == ZP_STALL_T_MAX);
    CHECK_NEAR(r.time, 120, 1e-9);
    const zp_row_store *rows = zp_sim_rows(s);
    for (int k = 1; k < rows->n; k++) {
        zp_row r0, r1;
        zp_row_store_get(rows, k - 1, &r0);
        zp_row_store_get(rows, k, &r1);
        CHECK(r1.w_damp >= r0.w_damp);
        zp_energy e = zp_state_energy(m, &r1.c);
        CHECK(e.kinetic + e.potential <= r.e_initial + 1e-6 * r.e_initial);
    }
    zp_sim_free(s);
    zp_model_free(m);
}

/* the study's 100 N kills: the same joint at the same time at every tolerance and method */
static void check_seed_death(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    zp_sim_opts ref_o = tu_opts(&sc, 1e-12);
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched};
    zp_result ref = *tu_run(m, &ref_o, &in);
    CHECK(ref.outcome == ZP_OUTCOME_DIED);
    CHECK(ref.died_link >= 1 && ref.died_link <= 3);
    /* the death root is located exactly: that joint's largest angle is the death angle */
    CHECK_NEAR(ref.max_rel_angle[ref.died_link - 1], M_PI, 1e-9);
    for (int method = 0; method < ZP_METHOD_COUNT; method++) {
        for (double rtol = 1e-6; rtol >= 1e-10; rtol /= 100) {
            zp_sim_opts o = tu_opts(&sc, rtol);
            o.method = method;
            const zp_result *r = tu_run(m, &o, &in);
            CHECK(r->outcome == ZP_OUTCOME_DIED && r->died_link == ref.died_link);
            CHECK_NEAR(r->time, ref.time, 1e4 * rtol);
            CHECK_NEAR(r->x, ref.x, 1e5 * rtol);
        }
    }
    zp_model_free(m);
}

/* starting uphill with too weak a push rolls back at once: caught at t = 0 */
static void check_rollback(void) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 50 : 0.5*x\n[trolley]\nmass = 30\n"
                           "[body]\nlengths = 1\nmasses = 10\n",
                           &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    double weak = 100, strong = 300; /* holding force: M g f' = 40 * 9.81 * 0.5 = 196 N */
    zp_schedule in_sched = tu_sched(m, &weak);
    zp_input in = {.sched = &in_sched};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_ROLLED_BACK);
    CHECK(r->time == 0 && r->x == 0);
    in_sched = tu_sched(m, &strong);
    r = tu_run(m, &o, &in);
    CHECK(r->outcome != ZP_OUTCOME_STALLED || r->stall != ZP_STALL_ROLLED_BACK);
    zp_model_free(m);
}

/* slopes -1 then 3: 1 + s1 s2 < 0, so the impulse sends a trolley back out: trapped */
static void check_trapped(void) {
    zp_scene sc;
    zp_model *m =
        tu_model("[course]\nx_start = 0\nsection = 10 : -x\nsection = 30 : 3*(x - 10) - 10\n"
                 "[trolley]\nmass = 30\n[body]\nlengths = 0.5\nmasses = 0.1\n",
                 &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_TRAPPED_AT_KINK);
    CHECK_NEAR(r->x, 10, 1e-9);
    CHECK(r->ncross == 1 && tu_crossings()[0].energy_lost > 0);
    zp_model_free(m);
}

/* a trolley (with a feather-light link) released in a symmetric V of slopes +-0.5: each
   plastic crossing keeps r = cos(2 atan 0.5) = 0.6 of the speed, so the crossings accumulate
   (Zeno) at T = t1 (1 + r) / (1 - r) = 4 t1, where it is trapped at the kink, having lost
   all of m g h in impulses; the first crossing at t1 = sqrt(2 L / (g sin a)) loses 1 - r^2 */
static void check_zeno_vee(void) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 10 : -0.5*x + 10\n"
                           "section = 20 : 0.5*(x - 10) + 5\n[trolley]\nmass = 30\n"
                           "[body]\nlengths = 0.2\nmasses = 1e-6\ndamping = 1e-6\n",
                           &sc);
    double a = atan(0.5), t1 = sqrt(2 * (10 / cos(a)) / (G * sin(a))), mgh = 30 * G * 5;
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_TRAPPED_AT_KINK);
    CHECK_NEAR(r->x, 10, 1e-12);
    CHECK_NEAR(tu_crossings()[0].t, t1, 1e-6);
    /* link mass 1e-6 of the trolley's: closed forms hold to ~1e-7 relative */
    CHECK_REL(tu_crossings()[0].energy_lost, (1 - 0.36) * mgh, 1e-6);
    CHECK(r->ncross > 20);
    CHECK_NEAR(r->time, 4 * t1, 1e-5); /* stopped within ZP_ZENO_DT of the limit */
    CHECK_REL(r->e_impulse, mgh, 1e-6);
    zp_model_free(m);
}

/* a sample at a kink's time shows the state after the impulse; the largest joint angle is
   exact: no trajectory row exceeds it, and the finest rows come close to it */
static void check_samples_and_extremes(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    double f[3] = {10, 10, 10};
    zp_sim_opts o = tu_opts(&sc, 1e-9);
    zp_schedule in_sched = tu_sched(m, f);
    zp_input in = {.sched = &in_sched};
    zp_result first = *tu_run(m, &o, &in);
    CHECK(first.ncross == 2);
    double tk[2] = {tu_crossings()[0].t, tu_crossings()[1].t};
    o.output_dt = 1e-3;
    in.sample_t = tk;
    in.nsample = 2;
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK);
    int n;
    const zp_row *smp = zp_sim_samples(s, &n);
    CHECK(n == 2);
    double slope_after[2] = {-0.1, 0.4};
    for (int k = 0; k < n; k++) {
        CHECK(smp[k].sec == k + 1);
        CHECK_NEAR(smp[k].c.v[1], slope_after[k] * smp[k].c.v[0], 1e-9);
    }
    const zp_row_store *rows = zp_sim_rows(s);
    double row_max[ZP_MAX_LINKS] = {0};
    for (int k = 0; k < rows->n; k++) {
        double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
        zp_row row;
        zp_row_store_get(rows, k, &row);
        zp_state_relative(m, &row.c, phi, w);
        for (int i = 0; i < m->nlink; i++) {
            row_max[i] = fmax(row_max[i], fabs(phi[i]));
        }
    }
    for (int i = 0; i < m->nlink; i++) {
        CHECK(row_max[i] <= r.max_rel_angle[i] + 1e-12);
        CHECK_NEAR(row_max[i], r.max_rel_angle[i], 1e-4); /* rows 1 ms apart, rates ~1 rad/s */
    }
    zp_sim_free(s);
    zp_model_free(m);
}

/* same inputs, same bits: one workspace twice, and a second workspace on the same model */
static void check_reproducible(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    double f[3] = {20, 12, 25};
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_schedule in_sched = tu_sched(m, f);
    zp_input in = {.sched = &in_sched};
    zp_sim *a = zp_sim_create(m, &o), *b = zp_sim_create(m, &o);
    static zp_result r1, r2, r3;
    CHECK(zp_sim_run(m, a, &in, &r1) == ZP_OK);
    CHECK(zp_sim_run(m, a, &in, &r2) == ZP_OK);
    CHECK(zp_sim_run(m, b, &in, &r3) == ZP_OK);
    CHECK(r1.time == r2.time && r1.time == r3.time);
    CHECK(r1.x == r2.x && r1.x == r3.x && r1.e_final == r3.e_final);
    CHECK(memcmp(r1.max_rel_angle, r3.max_rel_angle, sizeof r1.max_rel_angle) == 0);
    CHECK(r1.steps == r3.steps && r1.rhs_evals == r3.rhs_evals);
    /* asking for a trajectory and samples does not change the answer by a bit */
    zp_sim_opts traj = o;
    traj.output_dt = 0.01;
    double times[] = {0.5, 7.25, 13};
    zp_schedule with_samples_sched = tu_sched(m, f);
    zp_input with_samples = {.sched = &with_samples_sched, .sample_t = times, .nsample = 3};
    zp_sim *c = zp_sim_create(m, &traj);
    CHECK(zp_sim_run(m, c, &with_samples, &r2) == ZP_OK);
    CHECK(r1.time == r2.time && r1.x == r2.x && r1.steps == r2.steps);
    zp_sim_free(c);
    zp_sim_free(a);
    zp_sim_free(b);
    zp_model_free(m);
}

/* forces beyond what doubles can integrate end in a numerical failure with a message */
static void check_numeric_failure(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    double f[3] = {1e300, 1e300, 1e300};
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_schedule in_sched = tu_sched(m, f);
    zp_input in = {.sched = &in_sched};
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_ERR_NUMERIC);
    CHECK(strstr(r.message, "numerical failure at t = ") != NULL);
    CHECK(strstr(r.message, "nan") == NULL);
    /* the workspace is still good for the next run */
    in_sched = tu_sched(m, sc.forces);
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK && r.outcome == ZP_OUTCOME_DIED);
    zp_sim_free(s);
    zp_model_free(m);
}

/* the bits of a result that frames must leave alone */
static int same_run(const zp_result *a, const zp_result *b) {
    return a->outcome == b->outcome && a->time == b->time && a->x == b->x &&
           a->e_final == b->e_final && a->steps == b->steps && a->ncross == b->ncross &&
           !memcmp(a->max_rel_angle, b->max_rel_angle, sizeof a->max_rel_angle) &&
           !memcmp(&a->peaks, &b->peaks, sizeof a->peaks);
}

/* still frames come from the dense output at exactly the asked moment: at x on the course
   (y = f(x)), at the kink x = 60 the state after the impulse; each equals a sample taken at
   its time by an independent run; and a run with frames is bit for bit the run without */
static void check_frames(const char *method) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    double f[3] = {20, 20, 20};
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    o.method = zp_method_find(method);
    zp_schedule sched = tu_sched(m, f);
    zp_input plain = {.sched = &sched};
    static zp_result r0, r1, r2;
    zp_sim *s0 = zp_sim_create(m, &o), *s1 = zp_sim_create(m, &o), *s2 = zp_sim_create(m, &o);
    CHECK(zp_sim_run(m, s0, &plain, &r0) == ZP_OK && r0.outcome == ZP_OUTCOME_FINISHED);
    double xs[] = {0, 20, 60, 100.5, 140};
    zp_input at_x = {.sched = &sched, .frame_at = xs, .nframe = 5, .frame_at_x = 1};
    CHECK(zp_sim_run(m, s1, &at_x, &r1) == ZP_OK);
    CHECK(same_run(&r0, &r1));
    int n;
    const zp_row *fr = zp_sim_frames(s1, &n);
    CHECK(n == 5);
    double ts[5];
    for (int k = 0; k < n; k++) {
        ts[k] = fr[k].t;
        CHECK_NEAR(fr[k].c.q[0], xs[k], 1e-9);
        CHECK_NEAR(fr[k].c.q[1], zp_course_eval(m->course, fr[k].sec, xs[k]).f, 1e-9);
    }
    CHECK(fr[2].sec == 1); /* x = 60: after the kink, moving along the next section */
    CHECK_NEAR(fr[2].c.v[1], -0.1 * fr[2].c.v[0], 1e-9);
    CHECK(fr[2].t == zp_sim_crossings(s1, &n)[0].t);
    /* the independent check: samples at the frames' times, in a run without frames */
    zp_input at_t = {.sched = &sched, .sample_t = ts, .nsample = 5};
    CHECK(zp_sim_run(m, s2, &at_t, &r2) == ZP_OK);
    const zp_row *smp = zp_sim_samples(s2, &n);
    CHECK(n == 5);
    /* the finish line's frame is the run's end state (a sample there may be interpolated) */
    CHECK(fr[4].c.q[0] == r0.x && hypot(fr[4].c.v[0], fr[4].c.v[1]) == r0.v);
    for (int k = 0; k < 4; k++) {
        CHECK(smp[k].sec == fr[k].sec);
        for (int j = 0; j < 2 + m->nlink; j++) {
            CHECK_NEAR(smp[k].c.q[j], fr[k].c.q[j], 1e-12);
            CHECK_NEAR(smp[k].c.v[j], fr[k].c.v[j], 1e-12);
        }
    }
    /* frames at t are those samples, bit for bit, and leave the run alone */
    zp_input frames_t = {.sched = &sched, .frame_at = ts, .nframe = 5};
    CHECK(zp_sim_run(m, s1, &frames_t, &r1) == ZP_OK);
    CHECK(same_run(&r0, &r1));
    fr = zp_sim_frames(s1, &n);
    CHECK(n == 5);
    for (int k = 0; k < n; k++) {
        CHECK(!memcmp(&fr[k].c, &smp[k].c, sizeof fr[k].c) && fr[k].t == smp[k].t);
    }
    zp_sim_free(s0);
    zp_sim_free(s1);
    zp_sim_free(s2);
    zp_model_free(m);
}

int main(void) {
    check_numeric_failure();
    check_effective_gravity("horizontal");
    check_effective_gravity("tangent");
    check_small_oscillation();
    check_conservation();
    check_audit();
    check_dampers();
    check_seed_death();
    check_rollback();
    check_trapped();
    check_zeno_vee();
    check_samples_and_extremes();
    check_reproducible();
    check_frames("cvode-adams");
    check_frames("gsl-rk8pd");
    return CHECK_DONE();
}
