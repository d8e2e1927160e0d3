/* Scenarios, [limits] and the robust search (core/scenario.c, optim/robust.c) against
   independent expectations: the corners of a 1-D range are its ends; a scenario's derived
   model equals one built from the scaled scene; a chain hanging at rest on a straight incline
   under a known acceleration feels |a - g| and carries its weight times that at each joint; a
   bare trolley's kink dv is its speed times the sine of the slope change; exact load peaks
   are at least the finest sampling's; where survival is monotone in the one force, the robust
   optimum is the largest surviving push over 1 + p; verification counts match a brute-force
   loop; the same seed gives the same bits on 1 and 2 threads; the Clopper-Pearson bound makes
   the binomial tail, summed term by term, equal to alpha (and alpha^(1/n) when all pass). */
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "pool.h"
#include "robust.h"
#include "testutil.h"

#define BOUND_TOL 2e-3 /* s: the search polishes forces to ~1e-3 N (as in test_search) */

/* the corners of a 1-D range are exactly its ends; the derived model is the scaled scene's */
static void corners_and_models(void) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    sc.force_error = 5;
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    CHECK(b.d == 1);
    zp_scen_set set;
    CHECK(zp_scen_set_build(&set, &b, m, 6, 1) == ZP_OK);
    CHECK(set.n == 6 && set.ncorner == 2);
    CHECK(set.sc[0].force[0] == 1 - 0.05 && set.sc[1].force[0] == 1 + 0.05);
    for (int j = 2; j < set.n; j++) {
        CHECK(fabs(set.sc[j].force[0] - 1) < 0.05);
    }
    zp_scen_set_free(&set);

    static const char *three =
        "[course]\nx_start = 0\nsection = 40 : -x/10 + 10\n[trolley]\nmass = 30\n"
        "[body]\nlengths = 5, 4, 3\nmasses = 15, 5, 2\ndamping = 1, 2, 3\n";
    static const char *scaled =
        "[course]\nx_start = 0\nsection = 40 : -x/10 + 10\n[trolley]\nmass = 27\n"
        "[body]\nlengths = 5.5, 4.4, 3.3\nmasses = 12, 4, 1.6\ndamping = 2, 4, 6\n";
    zp_scene s3, s4;
    zp_model *m3 = tu_model(three, &s3), *m4 = tu_model(scaled, &s4);
    s3.mass_range[0] = 80;
    s3.mass_range[1] = 120;
    s3.length_range[0] = 110;
    s3.length_range[1] = 110;
    s3.trolley_mass_range[0] = 90;
    s3.trolley_mass_range[1] = 100;
    s3.damping_range[0] = 200;
    s3.damping_range[1] = 300;
    zp_box_from_scene(&s3, m3, &b);
    CHECK(b.d == 4);
    double u[4] = {-1, 0, -1, -1}; /* mass 80 %, length 110 %, trolley 90 %, damping 200 % */
    zp_scenario s;
    zp_box_scenario(&b, u, &s);
    zp_model d;
    zp_scenario_model(m3, &s, &d);
    CHECK_REL(d.mtot, m4->mtot, 1e-14);
    for (int j = 0; j < 3; j++) {
        CHECK_REL(d.B[j], m4->B[j], 1e-14);
        CHECK_REL(d.damp[j], m4->damp[j], 1e-14);
        for (int k = 0; k < 3; k++) {
            CHECK_REL(d.C[j][k], m4->C[j][k], 1e-14);
        }
    }
    zp_model_free(m3);
    zp_model_free(m4);
    zp_model_free(m);
}

/* a chain hanging along g - a on an incline, the whole moving at a: every link feels
   |a - g|, and joint i carries the mass from link i down times |a - g| */
static void hanging_chain(void) {
    static const char *incline =
        "[course]\nx_start = 0\nsection = 200 : -x/10 + 10\n[trolley]\nmass = 30\n"
        "[body]\nlengths = 2, 1.5, 1\nmasses = 15, 5, 2\ndamping = 1\ndeath_angle = 180\n"
        "[solver]\nt_max = 3\n";
    zp_scene sc;
    zp_model *m = tu_model(incline, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    o.track_loads = 0;
    o.peaks = 1;
    double F = 200, al = atan(0.1), g = 9.81, M = 30 + 22;
    double a = (F * cos(al) + M * g * sin(al)) / M;
    double ex = -a * cos(al), ey = -g + a * sin(al); /* g - a */
    double th = atan2(ex, -ey), geff = hypot(ex, ey);
    zp_scenario s;
    zp_scenario_nominal(&s);
    for (int i = 0; i < 3; i++) {
        s.theta[i] = th;
    }
    zp_chain c0, c;
    zp_state_start(m, m->course, &c0);
    zp_scenario_start(&c0, 3, &s, &c);
    zp_schedule sch = tu_sched(m, &F);
    zp_input in = {.sched = &sch, .start = &c};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_T_MAX);
    double below[3] = {22, 7, 2};
    for (int i = 0; i < 3; i++) {
        CHECK_REL(r->peaks.acc_g[i], geff / g, 1e-6);
        CHECK_REL(r->peaks.joint[i], below[i] * geff, 1e-6);
        /* link 1 hangs at th from the vertical; the others in line with it */
        CHECK_NEAR(r->max_rel_angle[i], i ? 0 : fabs(th), 1e-6);
    }
    zp_model_free(m);
}

/* a bare trolley over a kink: the impulse keeps the tangential part, dv = v sin(change) */
static void kink_dv(void) {
    static const char *kink =
        "[course]\nx_start = 0\nsection = 20 : -x/10 + 10\nsection = 40 : -(x - 20)/2 + 8\n"
        "[trolley]\nmass = 30\n[body]\nlengths = 0.2\nmasses = 0.001\ndamping = 0\n";
    zp_scene sc;
    zp_model *m = tu_model(kink, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    zp_schedule sch = tu_sched(m, (double[2]){0, 0});
    zp_input in = {.sched = &sch};
    const zp_result *r = tu_run(m, &o, &in);
    double v = sqrt(2 * 9.81 * 2); /* 2 m down to the kink */
    CHECK(r->ncross == 1);
    CHECK_REL(r->peaks.kink_dv, v * sin(atan(0.5) - atan(0.1)), 2e-4);
    zp_limits l = {{0, 0, 0, 0}};
    l.max[ZP_LIMIT_KINK_DV] = r->peaks.kink_dv / 1.1;
    int which;
    CHECK_NEAR(zp_limits_excess(&l, m, r, &which), 0.1, 1e-12);
    CHECK(which == ZP_LIMIT_KINK_DV);
    zp_model_free(m);
}

/* the exact peaks reach at least the finest sampling of the same run, and not much more */
static void exact_peaks(void) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    zp_schedule sch = tu_sched(m, (double[1]){150});
    zp_input in = {.sched = &sch};
    o.output_dt = 1e-4;
    o.track_loads = 0;
    zp_load_peaks fine = tu_run(m, &o, &in)->peaks;
    o.output_dt = 0;
    o.peaks = 1;
    zp_load_peaks exact = tu_run(m, &o, &in)->peaks;
    o.peaks = 0;
    o.track_loads = 1;
    zp_load_peaks steps = tu_run(m, &o, &in)->peaks;
    CHECK(exact.acc_g[0] >= fine.acc_g[0] - 1e-12);
    CHECK(exact.joint[0] >= fine.joint[0] - 1e-9);
    CHECK_REL(exact.acc_g[0], fine.acc_g[0], 1e-6);
    CHECK_REL(exact.joint[0], fine.joint[0], 1e-6);
    CHECK(exact.acc_g[0] >= steps.acc_g[0] - 1e-12);
    zp_model_free(m);
}

/* the largest push that keeps the margin, by bisection with the simulator alone */
static double largest_push(const zp_model *m, const zp_sim_opts *o, double limit) {
    double lo = 0, hi = 400;
    zp_schedule sch = tu_sched(m, (double[1]){0});
    double *f = sch.p; /* the schedule's one force, set below */
    zp_input in = {.sched = &sch};
    while (hi - lo > 1e-7) {
        f[0] = 0.5 * (lo + hi);
        const zp_result *r = tu_run(m, o, &in);
        int ok = r->outcome == ZP_OUTCOME_FINISHED && r->max_rel_angle[0] <= limit;
        *(ok ? &lo : &hi) = f[0];
    }
    return lo;
}

static zp_search_result res, res2;

static void robust_search(zp_objective *ob, const zp_scene *sc, const zp_sim_opts *o, int nthreads,
                          zp_search_result *r, zp_robust_info *info, long *runs) {
    zp_box b;
    zp_box_from_scene(sc, ob->m, &b);
    zp_scen_set set;
    CHECK(zp_scen_set_build(&set, &b, ob->m, sc->robust_samples, sc->seed) == ZP_OK);
    ob->set = &set;
    zp_search_opts so = {.max_evals = sc->max_evals, .seed = sc->seed, .nthreads = nthreads};
    char err[256];
    double lo[ZP_MAX_SECTIONS], hi[ZP_MAX_SECTIONS];
    tu_scene_box(sc, lo, hi);
    CHECK(zp_robust_search(ob, &b, o, lo, hi, &so, 4, r, info, err, sizeof err) == ZP_OK);
    *runs = set.runs;
    ob->set = NULL;
    zp_scen_set_free(&set);
}

/* survival monotone in the force: the robust optimum is the largest push over 1 + p */
static void monotone(void) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_objective ob = tu_objective(m, &sc, &o);
    double p = 0.05, top = largest_push(m, &o, ob.limit);
    sc.force_error = 100 * p;
    sc.robust_samples = 8;
    zp_robust_info info;
    long runs;
    robust_search(&ob, &sc, &o, 2, &res, &info, &runs);
    zp_schedule sch = tu_sched(m, (double[1]){top / (1 + p)});
    double *f = sch.p;
    zp_input in = {.sched = &sch};
    double t_rob = tu_run(m, &o, &in)->time;
    CHECK(res.found);
    CHECK_NEAR(res.best.time, t_rob, BOUND_TOL);
    CHECK(res.best.time >= t_rob - 1e-9);
    CHECK(res.force[0] * (1 + p) <= top + 1e-6);

    /* verification against a brute-force loop over the same draws, at a schedule some of
       them break (those pushing it past top) */
    double F = top / (1 + p / 2);
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    zp_sim_opts tight = tu_opts(&sc, 1e-10);
    zp_robust_check c;
    const int n = 300;
    CHECK(zp_robust_verify(&ob, &b, &tight, &F, n, 7, 2, NULL, &c) == ZP_OK);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 7 ^ ZP_ROBUST_STREAM_VERIFY);
    int fin = 0, kept = 0;
    for (int i = 0; i < n; i++) {
        f[0] = F * (1 + p * (2 * gsl_rng_uniform(rng) - 1));
        const zp_result *r = tu_run(m, &tight, &in);
        fin += r->outcome == ZP_OUTCOME_FINISHED;
        kept += r->outcome == ZP_OUTCOME_FINISHED && r->max_rel_angle[0] <= ob.limit;
    }
    gsl_rng_free(rng);
    CHECK(c.samples == n && c.survived == fin && c.margin_kept == kept);
    CHECK(c.limits_kept == fin && c.all_kept == kept);
    CHECK(kept > 0 && kept < n);
    CHECK_NEAR(c.lower_95, gsl_cdf_beta_Pinv(0.05, kept, n - kept + 1), 1e-15);
    zp_model_free(m);
}

/* several uncertain quantities: the same seed gives the same bits on 1, 2 and 3 threads (the
   answer, the scenarios the adversary added, the scenario runs and the verification) */
static void threads(void) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_objective ob = tu_objective(m, &sc, &o);
    sc.force_error = 3;
    sc.mass_range[0] = 90;
    sc.mass_range[1] = 110;
    sc.start_angle = 2;
    sc.robust_samples = 4; /* few: the adversary adds a scenario, and the warm restart runs */
    sc.max_g = 3;
    zp_limits_from_scene(&sc, &ob.lim);
    o.peaks = 1;
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    zp_robust_info info[3];
    long runs[3];
    zp_robust_check c[3];
    for (int t = 0; t < 3; t++) {
        zp_search_result *r = t ? &res2 : &res;
        robust_search(&ob, &sc, &o, t + 1, r, &info[t], &runs[t]);
        CHECK(r->found);
        CHECK(zp_robust_verify(&ob, &b, &o, r->force, 200, sc.seed, t + 1, NULL, &c[t]) == ZP_OK);
        if (t == 0) {
            continue;
        }
        CHECK(!memcmp(res.force, res2.force, sizeof res.force));
        CHECK(res.evals == res2.evals && res.best.time == res2.best.time);
        CHECK(info[t].rounds == info[0].rounds && info[t].added == info[0].added);
        CHECK(info[t].worst.cons == info[0].worst.cons && runs[t] == runs[0]);
        CHECK(!memcmp(&c[t], &c[0], sizeof c[0]));
    }
    CHECK(info[0].added >= 1); /* the warm restart ran */
    zp_model_free(m);
}

/* the objective judged over n scenarios of sc's box (seed 3), and a pool of 3 threads helping
   with them: the setting of the shared-scenario tests below */
static zp_pool *with_scenarios(zp_objective *ob, const zp_scene *sc, const zp_sim_opts *o,
                               zp_scen_set *set, int n) {
    zp_box b;
    zp_box_from_scene(sc, ob->m, &b);
    CHECK(zp_scen_set_build(set, &b, ob->m, n, 3) == ZP_OK);
    ob->set = set;
    zp_pool *p = zp_pool_create(ob->m, o, 3);
    CHECK(p && zp_pool_help(p, ob->m, o) == 0);
    return p;
}

/* a survivor's scenarios shared out over 3 threads give what a brute-force loop over the set's
   order gives: the constraint folded up to the first scenario that breaks, that scenario, and
   the runs and fails counted up to it */
static void shared_scenarios(void) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_objective ob = tu_objective(m, &sc, &o);
    sc.force_error = 5;
    sc.start_angle = 3;
    zp_scen_set set;
    zp_pool *p = with_scenarios(&ob, &sc, &o, &set, 24);
    zp_sim *s = zp_sim_create(m, &o);
    zp_result r;
    int broke_late = 0, survived = 0;
    for (int k = 0; k < 40; k++) {
        double f = 10 * k; /* N: from easy pushes to ones most scenarios break */
        long runs = set.runs, fails[64];
        memcpy(fails, set.fails, sizeof *fails * set.n);
        zp_eval e;
        zp_pool_eval(p, &ob, 1, &f, &e, NULL, NULL);
        zp_schedule sch = tu_sched(m, &f);
        zp_input in = {.sched = &sch};
        zp_eval want;
        zp_objective_eval_run(&ob, m, s, &in, &want, &r);
        int nrun = 0, scen = -1;
        for (int i = 0; zp_objective_feasible(&want) && i < set.n && scen < 0; i++) {
            int j = set.order[i];
            in = (zp_input){.sched = &sch, .force_scale = set.sc[j].force, .start = &set.start[j]};
            zp_eval ej;
            zp_objective_eval_run(&ob, &set.m[j], s, &in, &ej, &r);
            double c = zp_objective_scenario_cons(&ob, &ej);
            want.cons = fmax(want.cons, c);
            nrun++;
            scen = c > 0 ? j : -1;
        }
        CHECK(e.cons == want.cons && e.scenario == scen && e.time == want.time);
        CHECK(set.runs - runs == nrun);
        for (int j = 0; j < set.n; j++) {
            CHECK(set.fails[j] - fails[j] == (j == scen));
        }
        broke_late += scen >= 0 && nrun > 1;
        survived += zp_objective_feasible(&want) && scen < 0;
    }
    CHECK(broke_late > 0 && survived > 0);
    zp_sim_free(s);
    zp_pool_free(p);
    zp_scen_set_free(&set);
    zp_model_free(m);
}

/* one schedule's evaluation with its constraint's parts, from inside a job of the pool */
typedef struct parts_job {
    zp_pool *p;
    const zp_objective *ob;
    const double *f;
    zp_eval *e;
    double *parts;
} parts_job;

static void eval_parts_job(void *user, int i, zp_sim *s, zp_result *r) {
    parts_job *b = user;
    zp_pool_objective_eval(b->p, b->ob, s, r, &b->f[i], &b->e[i],
                           b->parts + (size_t)i * ZP_OBJECTIVE_PARTS_MAX);
}

/* the constraint's parts under a scenario set with [limits] (the margin, the highest and the
   lowest arrival speed, each the worst over the runs): what a brute-force loop over the set's
   order gives, part by part, from each run's own parts up to the first scenario that breaks;
   their largest is the whole constraint; the same bits serially and shared over 3 threads; and
   on pushes where the fastest scenario breaks the one limit while the slowest keeps the other
   (and the other way round), the two limits' parts differ in sign (what a polish holds apart) */
static void scenario_parts(void) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_objective ob = tu_objective(m, &sc, &o);
    zp_sim *s = zp_sim_create(m, &o);
    zp_result r;
    double f0 = 40, v[ZP_LIMIT_COUNT]; /* N: the margin slack there */
    zp_schedule sch = tu_sched(m, &f0);
    zp_input in = {.sched = &sch};
    zp_eval e0;
    zp_objective_eval_run(&ob, m, s, &in, &e0, &r);
    CHECK(e0.outcome == ZP_OUTCOME_FINISHED);
    zp_limits_reached(m, &r, v);
    /* km/h: a band about the arrival at f0 that +/-5 % of pushes near it cross on one side */
    ob.lim.max[ZP_LIMIT_ARRIVAL] = 1.02 * v[ZP_LIMIT_ARRIVAL];
    ob.lim.max[ZP_LIMIT_MIN_ARRIVAL] = 0.98 * v[ZP_LIMIT_ARRIVAL];
    sc.force_error = 5;
    zp_scen_set set;
    zp_pool *p = with_scenarios(&ob, &sc, &o, &set, 8);
    int np = zp_objective_parts_count(&ob);
    CHECK(np == 3);
    enum { NF = 41 };
    double f[NF], shared[NF * ZP_OBJECTIVE_PARTS_MAX];
    zp_eval es[NF];
    for (int k = 0; k < NF; k++) {
        f[k] = f0 - 10 + 0.5 * k; /* N: about f0, to pushes every scenario breaks */
    }
    parts_job job = {p, &ob, f, es, shared};
    zp_pool_map(p, NF, eval_parts_job, &job, NULL, NULL);
    int apart = 0, apart_low = 0;
    for (int k = 0; k < NF; k++) {
        double serial[ZP_OBJECTIVE_PARTS_MAX], want[ZP_OBJECTIVE_PARTS_MAX];
        zp_eval e;
        zp_objective_eval_parts(&ob, s, &f[k], &e, &r, serial);
        sch = tu_sched(m, &f[k]);
        in = (zp_input){.sched = &sch};
        zp_eval ej;
        zp_objective_eval_run(&ob, m, s, &in, &ej, &r);
        zp_objective_parts_of(&ob, m, &ej, &r, want);
        int broke = 0;
        for (int i = 0; zp_objective_feasible(&ej) && i < set.n && !broke; i++) {
            int j = set.order[i];
            in = (zp_input){.sched = &sch, .force_scale = set.sc[j].force, .start = &set.start[j]};
            zp_eval es_j;
            zp_objective_eval_run(&ob, &set.m[j], s, &in, &es_j, &r);
            double one[ZP_OBJECTIVE_PARTS_MAX];
            zp_objective_parts_of(&ob, &set.m[j], &es_j, &r, one);
            for (int q = 0; q < np; q++) {
                want[q] = fmax(want[q], one[q]);
            }
            broke = zp_objective_scenario_cons(&ob, &es_j) > 0;
        }
        double largest = -INFINITY;
        for (int q = 0; q < np; q++) {
            CHECK(serial[q] == want[q] && shared[k * ZP_OBJECTIVE_PARTS_MAX + q] == want[q]);
            largest = fmax(largest, want[q]);
        }
        CHECK(largest == e.cons && es[k].cons == e.cons);
        apart += zp_objective_feasible(&ej) && want[1] > 0 && want[2] < 0;
        apart_low += zp_objective_feasible(&ej) && want[1] < 0 && want[2] > 0;
    }
    CHECK(apart > 0 && apart_low > 0);
    zp_pool_free(p);
    zp_sim_free(s);
    zp_scen_set_free(&set);
    zp_model_free(m);
}

/* P(X >= k) for X ~ Binomial(n, p), summed term by term in long double */
static long double binomial_tail(int k, int n, double p) {
    long double sum = 0;
    for (int i = k; i <= n; i++) {
        sum += expl(lgammal(n + 1.0L) - lgammal(i + 1.0L) - lgammal(n - i + 1.0L) + i * logl(p) +
                    (n - i) * log1pl(-(long double)p));
    }
    return sum;
}

/* the one-sided 95 % lower bound L: P(X >= k | L) = 0.05, including where GSL's own beta
   inverse fails to converge (k near n, n large) */
static void clopper_pearson(void) {
    const int cases[][2] = {{1943, 2000}, {1999, 2000}, {1500, 2000}, {10, 2000},
                            {7, 10},      {1, 1},       {63, 64}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int k = cases[i][0], n = cases[i][1];
        double lo = zp_robust_clopper_pearson_lower(k, n, 0.05);
        CHECK(isfinite(lo) && lo > 0 && lo < 1);
        CHECK(fabsl(binomial_tail(k, n, lo) - 0.05L) < 1e-9L);
    }
    CHECK(fabs(zp_robust_clopper_pearson_lower(2000, 2000, 0.05) - pow(0.05, 1.0 / 2000)) < 1e-15);
    CHECK(zp_robust_clopper_pearson_lower(0, 2000, 0.05) == 0);
}

int main(void) {
    clopper_pearson();
    corners_and_models();
    hanging_chain();
    kink_dv();
    exact_peaks();
    monotone();
    shared_scenarios();
    scenario_parts();
    threads();
    return CHECK_DONE();
}
