/* The one path from a scene to its answer (optim/problem.c, answer.c): the problem's run
   profiles are the scene's [solver] and [optimize] settings; each depth of zp_answer_solve does
   the steps of the one below it with the same bits, then its own; its stages come in order.
   Independent expectation: the same steps assembled by hand from the search's and the
   verification's own entry points (robust.h, verify.h), as the commands once did. */
#include <math.h>
#include <string.h>

#include "answer.h"
#include "check.h"
#include "estimate.h"
#include "testutil.h"

/* tu_swing with a schedule of its own, [robust] force error and a small budget */
static const char *const scene =
    "[course]\nx_start = 0\nsection = 40 : -x/10 + 10\n"
    "[trolley]\nmass = 30\n"
    "[body]\nlengths = 1\nmasses = 5\ndamping = 2\ndeath_angle = 30\n"
    "[drive]\nmin = 0\nmax = 400\nforces = 50\n"
    "[optimize]\nmargin = 5\nmax_evals = 80\n"
    "[robust]\nforce_error = 5\nsamples = 4\nverify_samples = 20\n";

static void load(const char *text, int flags, zp_problem *p) {
    zp_diag d;
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(text, "answer.ini", &p->sc, &d) == ZP_OK);
    CHECK(zp_problem_build(p, flags, &d) == 0 && d.n == 0);
}

/* the profiles: [solver] shown, [optimize] searched with nothing but the verdict, the check
   100x tighter than the search; outcomes only drops the trajectory */
static void check_profiles(void) {
    static zp_problem p, q;
    load(scene, 0, &p);
    const zp_scene *sc = &p.sc;
    CHECK(p.limit == p.m->phi_max - sc->margin * M_PI / 180);
    CHECK(p.max_evals == 80 && p.seed == sc->seed && p.sched.np == 1 && p.sched.p[0] == 50);
    CHECK(p.sim.output_dt == sc->output_dt && p.sim.output_dt > 0 && p.sim.track_loads);
    CHECK(p.search.method == zp_method_find(sc->search_method) && p.search.method >= 0);
    CHECK(p.search.rtol == sc->search_rtol && p.search.atol == sc->search_rtol / 100);
    CHECK(p.search.output_dt == 0 && !p.search.track_loads && !p.search.peaks);
    CHECK(p.search.formulation == p.sim.formulation && p.search.t_max == p.sim.t_max);
    zp_sim_opts tight = zp_estimate_tighter(&p.search);
    CHECK(!memcmp(&p.verify, &tight, sizeof tight));
    load(scene, ZP_PROBLEM_OUTCOMES, &q);
    CHECK(q.sim.output_dt == 0 && q.answer.output_dt == 0 && q.sim.track_loads);
    zp_problem_free(&p);
    zp_problem_free(&q);

    /* a limit that needs the peaks located: the answer and the search locate them */
    char text[1024];
    snprintf(text, sizeof text, "%s[limits]\nmax_g = 9\n", scene);
    load(text, 0, &p);
    CHECK(p.answer.peaks && p.search.peaks && !p.sim.peaks);
    zp_problem_free(&p);

    /* an unknown [optimize] method is one of the problems, named */
    snprintf(text, sizeof text, "%s[optimize]\nmethod = nonesuch\n", scene);
    zp_diag d;
    zp_diag_init(&d);
    p.m = NULL;
    if (zp_scene_load_string(text, "answer.ini", &p.sc, &d) == ZP_OK) {
        CHECK(zp_problem_build(&p, 0, &d) == -1 && d.n == 1 && strstr(d.text[0], "nonesuch"));
    }
    zp_problem_free(&p);
}

/* the stages seen, in order */
typedef struct seen {
    int n;
    zp_answer_stage s[8];
} seen;

static int on_stage(void *user, zp_answer_stage s, const zp_answer *a) {
    seen *w = user;
    CHECK(s != ZP_ANSWER_RERUN || (a->v.run && a->best));
    if (w->n < 8) {
        w->s[w->n++] = s;
    }
    return 0;
}

static void check_depths(void) {
    static zp_problem p;
    load(scene, 0, &p);
    char err[512];

    /* by hand: the robust search, then the answer rerun at the answer profile */
    static zp_robust_problem rp;
    static zp_search_result res;
    zp_sim_opts fast;
    CHECK(zp_robust_setup(&rp, &p.sc, p.m, p.limit, &p.sched, &p.sim, &p.search, &fast) == ZP_OK);
    CHECK(!memcmp(&fast, &p.search, sizeof fast));
    zp_search_opts so = {.max_evals = p.max_evals, .seed = p.seed};
    CHECK(zp_robust_solve(&rp, &p.sc, &fast, p.sched.lo, p.sched.hi, &so, &res, err,
                          sizeof err) == ZP_OK);
    zp_objective ob = rp.ob;
    ob.set = NULL;
    zp_verify v;
    zp_sim *best = NULL;
    CHECK(zp_verify_run(&ob, &p.answer, res.force, p.seed, 0, 0, &best, &v, NULL, NULL, err,
                        sizeof err) == ZP_OK);

    static zp_answer a[3];
    seen w = {0};
    for (int depth = ZP_ANSWER_SEARCHED; depth <= ZP_ANSWER_REPORTED; depth++) {
        zp_answer_opts o = zp_answer_opts_of(&p, depth);
        o.stage = on_stage;
        o.user = &w;
        CHECK(zp_answer_solve(&p, &o, &a[depth], err, sizeof err) == ZP_OK);
        const zp_search_result *r = &a[depth].res;
        CHECK(!memcmp(r->force, res.force, sizeof res.force) && r->evals == res.evals);
        CHECK(r->found == res.found && a[depth].found == res.found && res.found);
        CHECK(!memcmp(&a[depth].rp.check, &rp.check, sizeof rp.check));
        CHECK(zp_answer_scenarios(&a[depth]) == rp.set.n && rp.set.n > 0);
        CHECK(a[depth].verified == (depth > ZP_ANSWER_SEARCHED));
        if (depth > ZP_ANSWER_SEARCHED) {
            CHECK(a[depth].v.run->time == v.run->time && a[depth].v.tight->time == v.tight->time);
            CHECK(a[depth].v.agree == v.agree && !a[depth].unheld[0]);
        }
    }
    /* reported: robustness at the scene's force error and twice it, the scene's own forces
       run at the search's options */
    const zp_answer *r = &a[ZP_ANSWER_REPORTED];
    CHECK(!a[ZP_ANSWER_VERIFIED].v.robust_done && r->v.robust_done);
    CHECK(r->v.rob[0].level == 0.05 && r->v.rob[1].level == 0.10 && r->v.rob[0].n == 200);
    CHECK(!a[ZP_ANSWER_VERIFIED].given && r->given);
    zp_input in = {.sched = &p.sched};
    const zp_result *given = tu_run(p.m, &p.search, &in);
    CHECK(r->given && r->given->time == given->time && r->given->outcome == given->outcome);
    /* the stages: two for the verified depth, four for the reported (nothing to diagnose when
       every fresh scenario is kept) */
    static const zp_answer_stage want[] = {
        ZP_ANSWER_RERUN,    ZP_ANSWER_CHECKING, ZP_ANSWER_CHECKED,
        ZP_ANSWER_RERUN,    ZP_ANSWER_CHECKING, ZP_ANSWER_CHECKED, ZP_ANSWER_COMPARED};
    CHECK(rp.check.all_kept == rp.check.samples && !r->diag);
    CHECK(w.n == 7 && !memcmp(w.s, want, sizeof want));
    for (int i = 0; i < 3; i++) {
        zp_answer_free(&a[i]);
    }
    zp_verify_free(&v);
    zp_sim_free(best);
    zp_robust_problem_free(&rp);
    zp_problem_free(&p);
}

int main(void) {
    check_profiles();
    check_depths();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
