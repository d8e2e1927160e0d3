/* The search (optim/objective.c, search.c): on scenes whose optimum is known independently it
   finds it; its answer honours the survival constraint; the same seed gives the same bits
   whatever the number of threads.
   Independent expectations: the closed-form time of a trolley pushed down a straight slope
   (the largest push is optimal), and, where a larger push swings the spy further, the time at
   the largest surviving push found by bisection on the simulator alone. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "search.h"
#include "searchutil.h"
#include "strategy.h"
#include "testutil.h"

/* s: the search polishes forces to ~1e-3 N; near the optimum dT/dF ~ 1e-3 s/N */
#define BOUND_TOL 2e-3

static const char *bare = "[course]\nx_start = 0\nsection = 40 : -x/10 + 10\n"
                          "[trolley]\nmass = 30\n"
                          "[body]\nlengths = 0.2\nmasses = 0.001\ndamping = 0\n"
                          "[drive]\nmin = 0\nmax = 50\n"
                          "[optimize]\nmargin = 10\nmax_evals = 300\n";

static zp_search_result res, res2;

static void search(const zp_objective *ob, const zp_sim_opts *o, const zp_scene *sc, int nthreads,
                   zp_search_result *r) {
    tu_search_with(ob, o, sc, 0, nthreads, r);
}

/* a history of many more improvements than it keeps: thinned, it still spans the search, in
   order, every entry one of the improvements, and ends at the last */
static void history_thinning(void) {
    static zp_search_result r;
    memset(&r, 0, sizeof r);
    zp_search_state S = {.res = &r, .running = INFINITY};
    const long nimp = 5 * ZP_SEARCH_HIST + 3;
    for (long k = 0; k < nimp; k++) {
        zp_eval e = {.outcome = ZP_OUTCOME_FINISHED, .time = 100.0 - 1e-3 * (double)k};
        zp_search_state_record(&S, 10 * k + 7, &e);
        zp_eval worse = e;
        worse.time += 1e-4; /* not an improvement: not recorded */
        zp_search_state_record(&S, 10 * k + 8, &worse);
    }
    CHECK(r.hist_halvings > 0 && r.nhist > ZP_SEARCH_HIST / 2 && r.nhist <= ZP_SEARCH_HIST);
    CHECK(r.hist[r.nhist - 1].evals == 10 * (nimp - 1) + 7);
    CHECK(r.hist[r.nhist - 1].time == 100.0 - 1e-3 * (double)(nimp - 1));
    CHECK(r.hist[0].evals < 10 * (1L << r.hist_halvings) + 7); /* it still opens the search */
    for (int i = 0; i < r.nhist; i++) {
        long k = (r.hist[i].evals - 7) / 10;
        CHECK(r.hist[i].evals == 10 * k + 7 && r.hist[i].time == 100.0 - 1e-3 * (double)k);
        CHECK(i == 0 || r.hist[i].evals > r.hist[i - 1].evals);
    }
}

/* one leg that runs a point and then, inside, a COBYLA polish */
typedef struct inside {
    const double *x0, *step;
    long cap;
    int rc;
    zp_leg_rec rec;
} inside;

static void point_then_polish(const void *how, zp_leg *leg) {
    inside *w = leg->user;
    CHECK(zp_leg_eval(leg, leg->S->lo) != NULL);
    w->rc = zp_leg_polish_within(leg, zp_strategy_nlopt_cobyla.polish, how, w->x0, w->step, w->cap,
                                 &w->rec);
}

/* a leg of cap simulations on a fresh state of ob: one polish from x0 as the leg itself
   (within == NULL) or a point and then the polish inside it; what the leg came to into out */
static void leg_alone(const zp_objective *ob, const zp_sim_opts *o, const double *lo,
                      const double *hi, inside *within, const double *x0, const double *step,
                      long cap, zp_leg_rec *out, long *spent) {
    static zp_search_result r;
    zp_search_opts so = {.max_evals = 100000, .seed = 1, .nthreads = 1};
    zp_search_state S;
    char err[256];
    zp_search_state_begin(&S, ob, lo, hi, &so, &r);
    CHECK(zp_search_state_start(&S, o, err, sizeof err) == ZP_OK);
    const zp_strategy *cobyla = &zp_strategy_nlopt_cobyla;
    zp_leg_job job = {.x0 = x0, .step = step, .cap = cap, .user = within, .out = out};
    CHECK(zp_leg_batch(&S, within ? point_then_polish : cobyla->polish, cobyla, &job, 1, err,
                       sizeof err) == ZP_OK);
    *spent = S.spent;
    zp_search_state_end(&S);
}

/* a polish inside a leg runs what the same polish runs as a leg of its own, to the same end,
   every simulation counted in the leg; a leg that has less left cuts it short at that, and one
   with nothing left runs none */
static void polish_within_leg(const zp_model *m, const zp_scene *sc) {
    zp_sim_opts o = tu_opts(sc, 1e-5);
    zp_objective ob = tu_objective(m, sc, &o);
    double lo[ZP_MAX_SECTIONS], hi[ZP_MAX_SECTIONS], x0[ZP_MAX_SECTIONS], step[ZP_MAX_SECTIONS];
    tu_scene_box(sc, lo, hi);
    for (int k = 0; k < sc->nsec; k++) {
        x0[k] = lo[k] + 0.3 * (hi[k] - lo[k]);
        step[k] = 0.02 * (hi[k] - lo[k]);
    }
    const long cap = 150;
    zp_leg_rec solo, outer;
    long spent;
    leg_alone(&ob, &o, lo, hi, NULL, x0, step, cap, &solo, &spent);
    CHECK(solo.n > 10 && spent == solo.n);
    inside w = {.x0 = x0, .step = step, .cap = cap};
    leg_alone(&ob, &o, lo, hi, &w, lo, NULL, 10 * cap, &outer, &spent);
    CHECK(w.rc == 0 && w.rec.n == solo.n && w.rec.e.time == solo.e.time);
    CHECK(!memcmp(w.rec.end, solo.end, sizeof *solo.end * (size_t)sc->nsec));
    CHECK(outer.n == 1 + solo.n && spent == outer.n);
    CHECK(!zp_objective_better(&w.rec.e, &outer.e)); /* the leg's best counts the polish's */
    leg_alone(&ob, &o, lo, hi, &w, lo, NULL, 1 + solo.n / 2, &outer, &spent);
    CHECK(w.rc == 0 && w.rec.n == solo.n / 2 && spent == 1 + solo.n / 2);
    w.rec.n = -1;
    leg_alone(&ob, &o, lo, hi, &w, lo, NULL, 1, &outer, &spent);
    CHECK(w.rc == -1 && w.rec.n == -1 && spent == 1);
}

int main(void) {
    zp_scene sc;

    history_thinning();

    /* a bare trolley: the largest push wins, at the closed-form time */
    {
        zp_model *m = tu_model(bare, &sc);
        zp_sim_opts o = tu_opts(&sc, 1e-8);
        zp_objective ob = tu_objective(m, &sc, &o);
        search(&ob, &o, &sc, 2, &res);
        double t = tu_slope_time(40, 0.1, 50, 30 + 0.001);
        CHECK(res.found);
        CHECK_NEAR(res.force[0], 50, 1e-9);
        CHECK_REL(res.best.time, t, TU_BARE_TOL);
        CHECK(res.evals <= sc.max_evals);
        zp_model_free(m);
    }

    /* a swinging spy whose swing grows with the push: the optimum is the largest push that
       keeps the margin, found here by bisection with the simulator alone */
    {
        zp_model *m = tu_model(tu_swing, &sc);
        zp_sim_opts o = tu_opts(&sc, 1e-8);
        zp_objective ob = tu_objective(m, &sc, &o);
        double lo = 0, hi = 400;
        zp_schedule in_sched = tu_sched(m, (double[1]){0});
        double *f = in_sched.p; /* the schedule's one force, set below */
        zp_input in = {.sched = &in_sched};
        f[0] = hi;
        CHECK(tu_run(m, &o, &in)->max_rel_angle[0] > ob.limit); /* the top of the box kills */
        while (hi - lo > 1e-6) {
            f[0] = 0.5 * (lo + hi);
            const zp_result *r = tu_run(m, &o, &in);
            int ok = r->outcome == ZP_OUTCOME_FINISHED && r->max_rel_angle[0] <= ob.limit;
            *(ok ? &lo : &hi) = f[0];
        }
        f[0] = lo;
        double t_best = tu_run(m, &o, &in)->time;
        search(&ob, &o, &sc, 2, &res);
        CHECK(res.found);
        CHECK_NEAR(res.best.time, t_best, BOUND_TOL);
        CHECK(res.best.time >= t_best - 1e-9); /* nothing survivable beats the boundary */
        /* the constraint is honoured by the returned schedule, re-run independently */
        f[0] = res.force[0];
        const zp_result *r = tu_run(m, &o, &in);
        CHECK(r->outcome == ZP_OUTCOME_FINISHED);
        CHECK(r->max_rel_angle[0] <= ob.limit);
        CHECK(res.base_found && res.base.time >= res.best.time);
        zp_model_free(m);
    }

    /* the seed: same seed, same bits, with two threads twice and with one */
    {
        zp_scene_load_seed(&sc);
        sc.max_evals = 300;
        zp_diag d;
        zp_diag_init(&d);
        zp_model *m = zp_model_build(&sc, &d);
        zp_sim_opts o = tu_opts(&sc, sc.rtol);
        o.atol = sc.atol;
        zp_objective ob = tu_objective(m, &sc, &o);
        search(&ob, &o, &sc, 2, &res);
        search(&ob, &o, &sc, 2, &res2);
        CHECK(!memcmp(res.force, res2.force, sizeof res.force));
        CHECK(res.evals == res2.evals && res.best.time == res2.best.time);
        search(&ob, &o, &sc, 1, &res2);
        CHECK(!memcmp(res.force, res2.force, sizeof res.force));
        CHECK(res.evals == res2.evals && res.nhist == res2.nhist);
        /* the answer survives with the margin */
        CHECK(res.found && res.best.outcome == ZP_OUTCOME_FINISHED);
        CHECK(res.best.angle <= ob.limit);
        /* every --algorithm: a global strategy then a local one, and the same bits on one
           thread and two (the random NLopt global algorithms too: seeded on the thread that
           runs them) */
        sc.max_evals = 150;
        for (int a = 0; a < zp_search_algo_count(); a++) {
            const zp_search_algo *alg = zp_search_algo_get(a);
            CHECK(alg->global->phase == ZP_STRATEGY_GLOBAL);
            CHECK(alg->local->phase == ZP_STRATEGY_LOCAL);
            tu_search_with(&ob, &o, &sc, a, 2, &res);
            tu_search_with(&ob, &o, &sc, a, 1, &res2);
            CHECK(!memcmp(res.force, res2.force, sizeof res.force));
            CHECK(res.evals == res2.evals && res.best.time == res2.best.time);
            CHECK(res.evals <= sc.max_evals);
        }
        zp_model_free(m);
    }
    /* a larger budget runs everything a smaller one does: never a worse best (beyond 1e-9
       relative), on two scenes and four budgets each; and a budget cut before the polish
       reports no baseline it never ran */
    {
        static const char *kinked =
            "[course]\nx_start = 0\nsection = 20 : -x/10 + 10\nsection = 40 : -x/5 + 12\n"
            "[trolley]\nmass = 30\n[body]\nlengths = 1\nmasses = 5\ndamping = 2\n"
            "death_angle = 60\n[drive]\nmin = 0\nmax = 300\n[optimize]\nmargin = 10\n";
        for (int s = 0; s < 2; s++) {
            zp_model *m = NULL;
            if (s == 0) {
                zp_scene_load_seed(&sc);
                zp_diag d;
                zp_diag_init(&d);
                m = zp_model_build(&sc, &d);
            } else {
                m = tu_model(kinked, &sc);
            }
            zp_sim_opts o = tu_opts(&sc, 1e-5);
            zp_objective ob = tu_objective(m, &sc, &o);
            double prev = INFINITY;
            for (long b = 100; b <= 800; b *= 2) {
                sc.max_evals = b;
                search(&ob, &o, &sc, 2, &res);
                CHECK(res.evals <= b);
                double t = res.found ? res.best.time : INFINITY;
                CHECK(t <= prev * (1 + 1e-9));
                prev = t;
                if (b > 100) {
                    tu_history_extends(&res, &res2);
                }
                res2 = res;
                CHECK(!res.base_found || (res.base.time > 0 && zp_objective_feasible(&res.base)));
            }
            zp_model_free(m);
        }
    }
    {
        zp_scene_load_seed(&sc);
        zp_diag d;
        zp_diag_init(&d);
        zp_model *m = zp_model_build(&sc, &d);
        polish_within_leg(m, &sc);
        zp_model_free(m);
    }
    /* the default by the scene: the portfolio from 4 sections without [robust], the scan on
       fewer sections and in every robust search */
    {
        int scan = zp_search_algo_find("scan-cobyla"), pf = zp_search_algo_find("portfolio-cobyla");
        CHECK(scan >= 0 && pf >= 0 && scan != pf);
        CHECK(zp_search_algo_default(1, 0) == scan && zp_search_algo_default(3, 0) == scan);
        CHECK(zp_search_algo_default(4, 0) == pf && zp_search_algo_default(12, 0) == pf);
        CHECK(zp_search_algo_default(4, 1) == scan && zp_search_algo_default(3, 1) == scan);
    }
    /* the gradient polish on the seed: it polishes, the same bits on 1 and 2 threads, its
       answer survivable; with a [limits] value the same and the answer keeps it; and it
       refuses constraints without gradients, saying which */
    {
        zp_scene_load_seed(&sc);
        sc.max_evals = 2000;
        zp_diag d;
        zp_diag_init(&d);
        zp_model *m = zp_model_build(&sc, &d);
        zp_sim_opts o = tu_opts(&sc, sc.rtol);
        o.atol = sc.atol;
        zp_objective ob = tu_objective(m, &sc, &o);
        int a = zp_search_algo_find("scan-slsqp");
        CHECK(a >= 0);
        tu_search_with(&ob, &o, &sc, a, 2, &res);
        tu_search_with(&ob, &o, &sc, a, 1, &res2);
        CHECK(res.nstarts > 0 && res.found && zp_objective_feasible(&res.best));
        CHECK(!memcmp(res.force, res2.force, sizeof res.force));
        CHECK(res.evals == res2.evals && res.best.time == res2.best.time);
        CHECK(res.evals <= sc.max_evals);
        /* a [limits] value is a constraint of its own: the drive's peak power held to 12 kW
           (the free answer draws ~18 kW), the same bits on 1 and 2 threads, the answer keeping
           it when simulated alone 100x tighter, and the limit met, not merely kept away from */
        zp_objective held = ob;
        held.lim.max[ZP_LIMIT_DRIVE_POWER] = 12000;
        tu_search_with(&held, &o, &sc, a, 2, &res);
        tu_search_with(&held, &o, &sc, a, 1, &res2);
        CHECK(res.found && zp_objective_feasible(&res.best));
        CHECK(!memcmp(res.force, res2.force, sizeof res.force));
        CHECK(res.evals == res2.evals && res.best.time == res2.best.time);
        zp_sim_opts tight = o;
        tight.rtol = o.rtol / 100;
        tight.atol = o.atol / 100;
        zp_schedule sched = zp_objective_schedule(&held, res.force);
        zp_input in = {.sched = &sched};
        zp_sim *s = zp_sim_create(m, &tight);
        static zp_result r;
        CHECK(s && zp_sim_run(m, s, &in, &r) == ZP_OK);
        int which;
        CHECK(zp_limits_broken(m, &held.lim, held.limit, &r, &which) == ZP_BREAKS_NOTHING);
        double v[ZP_LIMIT_COUNT];
        zp_limits_reached(m, &r, v);
        printf("scan-slsqp under max_drive_power 12000 W: %.9g s, peak power %.6f W, %ld sims\n",
               res.best.time, v[ZP_LIMIT_DRIVE_POWER], res.evals);
        CHECK(v[ZP_LIMIT_DRIVE_POWER] > 11990);
        zp_sim_free(s);
        /* constraints without gradients are refused, saying which */
        zp_search_opts so = {.algo = a, .max_evals = sc.max_evals, .seed = sc.seed};
        char err[256] = "";
        double lo[ZP_MAX_SECTIONS], hi[ZP_MAX_SECTIONS];
        tu_scene_box(&sc, lo, hi);
        m->phi_max_j[0] = m->phi_max / 2;
        CHECK(zp_search_run(&ob, &o, lo, hi, &so, &res, err, sizeof err) == ZP_ERR_INPUT);
        CHECK(strstr(err, "death angles") != NULL);
        zp_model_free(m);
    }
    return CHECK_DONE();
}
