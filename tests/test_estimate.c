/* The error estimate beside every answer. Independent expectations: against a reference at
   rtol 1e-13 by gsl-rk8pd, the estimate (the difference from a run 100x tighter) is the true
   error of the answer up to the tighter run's own error (triangle inequality), and it shrinks
   with the tolerance; a verdict is flagged sensitive exactly when it flips: bisection finds
   the survival threshold force separately at rtol 1e-4 and 1e-6, and a force between the two
   thresholds dies at one tolerance and finishes at the other. The energy audit is docs/model.md's
   balance, drag and friction work included: a scene with every [physics] effect is not
   flagged at its own tolerances. */
#include <math.h>

#include "check.h"
#include "estimate.h"
#include "scene_load.h"
#include "testutil.h"

/* the reference's own error, far below the errors compared here */
#define REF_ERR 1e-10

static zp_outcome outcome_at(const zp_model *m, zp_sim_opts o, double force) {
    double f[ZP_MAX_SECTIONS];
    for (int k = 0; k < m->nsec; k++) {
        f[k] = force;
    }
    zp_schedule in_sched = tu_sched(m, f);
    zp_input in = {.sched = &in_sched};
    return tu_run(m, &o, &in)->outcome;
}

/* the force where the seed dies instead of finishing, to 1e-9 N, at one tolerance */
static double threshold(const zp_model *m, zp_sim_opts o) {
    double lo = 10, hi = 100; /* finishes at 10 N, dies at 100 N (test_sim) */
    for (int i = 0; i < 60 && hi - lo > 1e-9; i++) {
        double mid = 0.5 * (lo + hi);
        *(outcome_at(m, o, mid) == ZP_OUTCOME_FINISHED ? &lo : &hi) = mid;
    }
    return 0.5 * (lo + hi);
}

int main(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    CHECK(m != NULL);
    zp_schedule in_sched = tu_sched(m, (double[3]){10, 10, 10});
    double *force = in_sched.p; /* the schedule's forces, changed below */
    zp_input in = {.sched = &in_sched};

    /* the estimate against the true error, for two tolerances */
    zp_sim_opts o = tu_opts(&sc, 1e-13);
    o.method = ZP_METHOD_GSL_RK8PD;
    double t_ref = tu_run(m, &o, &in)->time;
    double est_prev = INFINITY;
    for (double rtol = 1e-5; rtol >= 1e-7; rtol /= 100) {
        o = tu_opts(&sc, rtol);
        zp_result r = *tu_run(m, &o, &in);
        zp_estimate e;
        zp_estimate_run(m, &o, &in, &r, &e);
        CHECK(e.ok && !e.sensitive);
        CHECK_NEAR(e.rtol, rtol / 100, 1e-20);
        double true_err = fabs(r.time - t_ref), tight_err = fabs(e.time - t_ref);
        CHECK_NEAR(e.time_error, true_err, tight_err + REF_ERR);
        CHECK(tight_err < true_err); /* else the estimate says nothing */
        CHECK(e.time_error < est_prev);
        est_prev = e.time_error;
    }

    /* a force between the thresholds at two tolerances flips the verdict: flagged */
    zp_sim_opts loose = tu_opts(&sc, 1e-4), tight = tu_opts(&sc, 1e-6);
    double f_loose = threshold(m, loose), f_tight = threshold(m, tight);
    CHECK(fabs(f_loose - f_tight) > 1e-8); /* resolvable by the bisection */
    double f_mid = 0.5 * (f_loose + f_tight);
    for (int k = 0; k < m->nsec; k++) {
        force[k] = f_mid;
    }
    zp_result r = *tu_run(m, &loose, &in);
    zp_estimate e;
    zp_estimate_run(m, &loose, &in, &r, &e);
    CHECK(e.ok);
    CHECK(e.sensitive);
    CHECK(e.outcome != r.outcome);
    CHECK(outcome_at(m, tight, f_mid) == e.outcome);
    /* and a force well inside one verdict is not flagged */
    for (int k = 0; k < m->nsec; k++) {
        force[k] = 100;
    }
    r = *tu_run(m, &loose, &in);
    zp_estimate_run(m, &loose, &in, &r, &e);
    CHECK(e.ok && !e.sensitive && r.outcome == ZP_OUTCOME_DIED);

    /* at the rtol floor the tighter run still tightens atol by the whole factor */
    o = tu_opts(&sc, ZP_ESTIMATE_RTOL_MIN);
    r = *tu_run(m, &o, &in);
    zp_estimate_run(m, &o, &in, &r, &e);
    CHECK(e.rtol == ZP_ESTIMATE_RTOL_MIN && e.atol == o.atol / ZP_ESTIMATE_FACTOR);

    /* the energy audit (docs/model.md) of the answer: small at the default tolerances, flagged at
       the loosest the scene allows (rtol 1e-2, atol 1: a drift of 1 m or 1 rad per step) */
    for (int k = 0; k < m->nsec; k++) {
        force[k] = 10;
    }
    for (int loose_run = 0; loose_run < 2; loose_run++) {
        o = tu_opts(&sc, loose_run ? 1e-2 : 1e-8);
        o.atol = loose_run ? 1 : 1e-10;
        r = *tu_run(m, &o, &in);
        zp_estimate_run(m, &o, &in, &r, &e);
        double audit = r.e_final - r.e_initial - r.w_drive + r.w_damp + r.e_impulse;
        double scale = fabs(r.e_initial) + fabs(r.e_final) + fabs(r.w_drive) + fabs(r.w_damp) +
                       fabs(r.e_impulse);
        CHECK(e.ok && e.energy_residual == audit);
        CHECK(e.energy_large == loose_run);
        CHECK(loose_run ? fabs(audit) > 1e-2 * scale : fabs(audit) < 1e-6 * scale);
    }
    zp_model_free(m);

    /* seed_real (drag, rolling, arcs) with a push that finishes: drag and friction take out
       about 23 kJ, which the audit books (docs/model.md), so its residual is small and unflagged */
    zp_diag d;
    zp_diag_init(&d);
    m = zp_scene_load(ZP_SOURCE_DIR "/config/seed_real.ini", &sc, &d) == ZP_OK
            ? zp_model_build(&sc, &d)
            : NULL;
    CHECK(m != NULL);
    in_sched = tu_sched(m, (double[3]){80, 500, 500});
    o = tu_opts(&sc, sc.rtol);
    o.atol = sc.atol;
    r = *tu_run(m, &o, &in);
    zp_estimate_run(m, &o, &in, &r, &e);
    double drag = r.w_effect[ZP_EFFECT_W_DRAG], fric = r.w_effect[ZP_EFFECT_W_FRICTION];
    double audit = r.e_final - r.e_initial - r.w_drive + r.w_damp + drag + fric + r.e_impulse;
    double scale = fabs(r.e_initial) + fabs(r.e_final) + fabs(r.w_drive) + fabs(r.w_damp) +
                   fabs(drag) + fabs(fric) + fabs(r.e_impulse);
    CHECK(r.outcome == ZP_OUTCOME_FINISHED && drag > 1e4 && fric > 0);
    CHECK(e.ok && !e.energy_large);
    CHECK_NEAR(e.energy_residual, audit, 1e-9 * scale);
    CHECK(fabs(audit) < 1e-6 * scale);
    zp_model_free(m);
    return CHECK_DONE();
}
