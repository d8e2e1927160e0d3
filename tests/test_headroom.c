/* Headroom past the [robust] box and safety_factor (optim/headroom.c) on a 1-D case whose
   breaking point is known by construction: on tu_swing survival is monotone in the one force,
   so a schedule F with force error p breaks exactly where F (1 + s p) reaches the largest push
   that keeps the margin (found here by bisecting whole runs); the headroom must bracket that
   s; likewise where it stops finishing alive (the largest push that does not die). With
   safety_factor k the robust optimum is that largest push over 1 + k p, and its headroom is k.
   Also: safety_factor is refused below 1 at its line. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "estimate.h"
#include "headroom.h"
#include "robust.h"
#include "testutil.h"

#define DEG (180.0 / M_PI)
#define PUSH_TOL 1e-7 /* N: the bisection of the largest push */
#define SLACK_N                                                                                    \
    1e-2 /* N: what the search's slack under the margin (objective.c) and its                      \
            polish (~1e-3 N, as in test_robust) may leave below the edge */

/* the largest constant push keeping the margin (limit, rad; INFINITY: finishing alive is
   enough), at options o */
static double largest_push(const zp_model *m, const zp_sim_opts *o, double limit) {
    double lo = 0, hi = 400;
    zp_schedule sch = tu_sched(m, (double[1]){0});
    zp_input in = {.sched = &sch};
    while (hi - lo > PUSH_TOL) {
        sch.p[0] = 0.5 * (lo + hi);
        const zp_result *r = tu_run(m, o, &in);
        int ok = r->outcome == ZP_OUTCOME_FINISHED && r->max_rel_angle[0] <= limit;
        *(ok ? &lo : &hi) = sch.p[0];
    }
    return lo;
}

static void check_headroom(double safety) {
    zp_scene sc;
    zp_model *m = tu_model(tu_swing, &sc);
    double p = 0.15; /* wide enough that the rider stops finishing alive inside 4x */
    sc.force_error = 100 * p;
    sc.robust = 1;
    sc.robust_samples = 8;
    sc.verify_samples = 50;
    sc.safety_factor = safety;
    zp_sim_opts o = tu_opts(&sc, 1e-8), fast;
    double limit = m->phi_max - sc.margin / DEG;
    zp_robust_problem pb;
    CHECK(zp_robust_setup(&pb, &sc, m, limit, NULL, &o, &o, &fast) == ZP_OK);
    zp_search_opts so = {.max_evals = sc.max_evals, .seed = sc.seed, .nthreads = 2};
    double lo = sc.force_min, hi = sc.force_max;
    static zp_search_result res;
    char err[256];
    CHECK(zp_robust_solve(&pb, &sc, &fast, &lo, &hi, &so, &res, err, sizeof err) == ZP_OK);
    CHECK(res.found);

    /* the breaking point by construction, at the headroom's own tolerance */
    zp_sim_opts to = zp_estimate_tighter(&fast);
    to.output_dt = 0;
    double top = largest_push(m, &to, limit);
    double s_break = (top / res.force[0] - 1) / p;
    double s_alive = (largest_push(m, &to, INFINITY) / res.force[0] - 1) / p;
    const zp_headroom *h = &pb.check.headroom;
    CHECK(h->safety_factor == safety);
    for (int l = 0; l < ZP_HEADROOM_LINES; l++) {
        const zp_headroom_line *L = &h->line[l];
        int want = l == 0 || l == ZP_HEADROOM_LINES - 1; /* force error, and the box */
        CHECK((L->range >= 0) == want);
        if (!want) {
            continue;
        }
        printf("safety %g: F = %.6f N, top %.6f N, breaks by construction at %.6fx; "
               "%s holds to %.6fx, breaks at %.6fx (%s)\n",
               safety, res.force[0], top, s_break, zp_headroom_range_name(L->range), L->holds,
               L->breaks, L->limited_by);
        /* the bracket holds the known point (the push's bisection, in units of s) */
        double tol = PUSH_TOL / (p * res.force[0]);
        CHECK(L->holds <= s_break + tol && L->breaks >= s_break - tol);
        CHECK(L->breaks - L->holds <= 1e-3);
        CHECK(!strcmp(L->limited_by, "margin"));
        /* finishing alive: the push that first dies, or beyond the search's cap (4x) */
        printf("  finishes alive to %.6fx (%s at %.6fx); by construction %.6fx\n", L->alive,
               L->ends_by, L->dies, s_alive);
        if (isfinite(L->dies)) {
            CHECK(L->alive <= s_alive + tol && L->dies >= s_alive - tol);
            CHECK(!strcmp(L->ends_by, "died"));
        } else {
            CHECK(s_alive >= 4 && L->alive == 4);
        }
    }
    /* the optimum held to the widened box: the largest push over 1 + k p, a hair below it
       (the search keeps SLACK = 1e-3 deg under the margin, ~4e-3 N here) */
    double edge = res.force[0] * (1 + safety * p);
    CHECK(edge <= top + PUSH_TOL && edge >= top - SLACK_N);
    CHECK(s_break >= safety && s_break <= safety + SLACK_N / (p * res.force[0]));
    zp_robust_problem_free(&pb);
    zp_model_free(m);
}

/* safety_factor below 1 (or one that takes a range to 0 %) is refused at its line */
static void check_bad_factor(void) {
    const char *bad[] = {"[robust]\nforce_error = 5\nsafety_factor = 0.9\n",
                         "[robust]\nmass_range = 50, 120\nsafety_factor = 2.5\n"};
    for (int k = 0; k < 2; k++) {
        char ini[1024];
        snprintf(ini, sizeof ini, "%s%s", tu_swing, bad[k]);
        zp_scene sc;
        zp_diag d;
        zp_diag_init(&d);
        CHECK(zp_scene_load_string(ini, "bad.ini", &sc, &d) != ZP_OK);
        char msg[4096] = "";
        FILE *f = fmemopen(msg, sizeof msg, "w");
        zp_diag_print(&d, f);
        fclose(f);
        CHECK(strstr(msg, "bad.ini:") && strstr(msg, "safety_factor"));
    }
}

int main(void) {
    check_headroom(1);
    check_headroom(1.2);
    check_bad_factor();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
