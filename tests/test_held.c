/* The robust answer's worst margin (optim/held.c, robust.c) is the smallest over everything the
   search held it to and verified it on: the nominal scene, every scenario of the set, the
   adversary's worst and the fresh scenarios; and the population's spread (fastest and slowest
   finish, lowest and highest arrival speed, each with its scenario) is that of the fresh ones.
   Independent expectation: a brute-force loop that reruns each of them one at a time at the
   verification's tolerance (the fresh ones drawn from the documented stream) and takes the
   extremes by hand. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "estimate.h"
#include "robust.h"
#include "testutil.h"

#define DEG (180.0 / M_PI)

/* the margin (deg) of one run, NAN when it does not finish */
static double margin_of(const zp_model *m, const zp_sim_opts *o, const zp_input *in) {
    const zp_result *r = tu_run(m, o, in);
    double a = 0;
    for (int i = 0; i < m->nlink; i++) {
        a = fmax(a, r->max_rel_angle[i]);
    }
    return r->outcome == ZP_OUTCOME_FINISHED ? (m->phi_max - a) * DEG : NAN;
}

static void check_worst_margin(int nthreads) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    sc.force_error = 5;
    sc.mass_range[0] = 80;
    sc.mass_range[1] = 120;
    sc.start_angle = 3;
    sc.robust = 1;
    sc.robust_samples = 8;
    sc.verify_samples = 100;
    zp_sim_opts o = tu_opts(&sc, 1e-8), fast;
    zp_robust_problem pb;
    CHECK(zp_robust_setup(&pb, &sc, m, m->phi_max - sc.margin / DEG, NULL, &o, &o, &fast) == ZP_OK);
    zp_search_opts so = {.max_evals = sc.max_evals, .seed = sc.seed, .nthreads = nthreads};
    double lo = sc.force_min, hi = sc.force_max;
    static zp_search_result res;
    char err[256];
    CHECK(zp_robust_solve(&pb, &sc, &fast, &lo, &hi, &so, &res, err, sizeof err) == ZP_OK);
    CHECK(res.found);

    /* brute force at the verification's tolerance */
    zp_sim_opts to = zp_estimate_tighter(&fast);
    to.output_dt = 0;
    to.track_loads = 0;
    zp_schedule sched = tu_sched(m, res.force);
    zp_input in = {.sched = &sched};
    double held = margin_of(m, &to, &in);
    for (int j = 0; j < pb.set.n; j++) {
        zp_input ij = {
            .sched = &sched, .force_scale = pb.set.sc[j].force, .start = &pb.set.start[j]};
        held = fmin(held, margin_of(&pb.set.m[j], &to, &ij));
    }
    zp_chain c0, start;
    zp_state_start(m, m->course, &c0);
    zp_scenario s;
    zp_model ms;
    CHECK(isfinite(pb.info.worst.cons));
    zp_box_scenario(&pb.box, pb.info.worst.u, &s);
    zp_scenario_model(m, &s, &ms);
    zp_scenario_start(&c0, ms.nlink, &s, &start);
    zp_input iw = {.sched = &sched, .force_scale = s.force, .start = &start};
    held = fmin(held, margin_of(&ms, &to, &iw));

    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, sc.seed ^ ZP_ROBUST_STREAM_VERIFY);
    double fresh = INFINITY, u[ZP_BOX_MAX];
    double t_lo = INFINITY, t_hi = -INFINITY, v_lo = INFINITY, v_hi = -INFINITY;
    int i_tlo = -1, i_thi = -1, i_vlo = -1, i_vhi = -1;
    for (int i = 0; i < sc.verify_samples; i++) {
        for (int k = 0; k < pb.box.d; k++) {
            u[k] = 2 * gsl_rng_uniform(rng) - 1;
        }
        zp_box_scenario(&pb.box, u, &s);
        zp_scenario_model(m, &s, &ms);
        zp_scenario_start(&c0, ms.nlink, &s, &start);
        zp_input ir = {.sched = &sched, .force_scale = s.force, .start = &start};
        fresh = fmin(fresh, margin_of(&ms, &to, &ir));
        /* the spread over the finishers, the first of equals kept */
        const zp_result *rr = tu_run(&ms, &to, &ir);
        if (rr->outcome == ZP_OUTCOME_FINISHED) {
            double v = rr->v * 3.6;
            i_tlo = rr->time < t_lo ? i : i_tlo;
            t_lo = fmin(t_lo, rr->time);
            i_thi = rr->time > t_hi ? i : i_thi;
            t_hi = fmax(t_hi, rr->time);
            i_vlo = v < v_lo ? i : i_vlo;
            v_lo = fmin(v_lo, v);
            i_vhi = v > v_hi ? i : i_vhi;
            v_hi = fmax(v_hi, v);
        }
    }
    const zp_robust_check *c = &pb.check;
    CHECK(c->fastest.value == t_lo && c->fastest.sample == i_tlo);
    CHECK(c->slowest.value == t_hi && c->slowest.sample == i_thi);
    CHECK(c->arrival_low.value == v_lo && c->arrival_low.sample == i_vlo);
    CHECK(c->arrival_high.value == v_hi && c->arrival_high.sample == i_vhi);
    CHECK(t_lo < t_hi && v_lo < v_hi);
    gsl_rng_free(rng);
    CHECK(pb.check.held_margin_deg == held);
    CHECK(pb.check.worst_margin_deg == fmin(held, fresh));
    printf("%d threads: held %.6f deg, fresh %.6f deg, reported %.6f deg (held worst at %d)\n",
           nthreads, held, fresh, pb.check.worst_margin_deg, pb.check.held_worst);
    zp_robust_problem_free(&pb);
    zp_model_free(m);
}

int main(void) {
    check_worst_margin(1);
    check_worst_margin(2);
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
