/* The answer's fallback (optim/answer.c): when the search's best, ranked with a loose
   [optimize] integrator, does not hold when rerun with [solver], the answer is the search's
   next candidate by ranked time that holds; when none holds, the best is written as the
   closest candidate; when the best holds, nothing changes.
   Independent expectation: the schedules rerun here with the scene's [solver] and 100x tighter
   and judged by hand (finished, largest joint angle within death angle - margin), and the
   search and verification assembled by hand from their own entry points (robust.h,
   verify.h). */
#define _GNU_SOURCE /* open_memstream */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "answer.h"
#include "check.h"
#include "estimate.h"
#include "report.h"
#include "report_text.h"
#include "testutil.h"

/* The seed scene (config/seed.ini) ranked with gsl-rk8pd at a loose rtol: the search's best
   sits at the margin as the loose runs see it, past it as [solver] does. */
static const char *const seed_loose =
    "[scene]\nname = seed\ngravity = 9.81\n"
    "[course]\nx_start = 0\nsection = 60  : (x/10 - 3)^2 + 1\nsection = 100 : -x/10 + 16\n"
    "section = 140 : -(x/10 - 12)^2 + 10\n"
    "[trolley]\nmass = 30\n"
    "[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 1\ndeath_angle = 180\n"
    "[drive]\ndirection = horizontal\nforces = 100, 100, 100\nmin = 0\nmax = 500\n"
    "[solver]\nmethod = cvode-adams\nrtol = 1e-8\natol = 1e-10\nt_max = 120\n"
    "formulation = lagrange\noutput_dt = 0.02\n"
    "[optimize]\nmargin = 10\nmax_evals = %d\nseed = %d\nmethod = gsl-rk8pd\nrtol = %s\n";

static void load(int max_evals, int seed, const char *rtol, zp_problem *p) {
    char text[2048];
    snprintf(text, sizeof text, seed_loose, max_evals, seed, rtol);
    zp_diag d;
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(text, "fallback.ini", &p->sc, &d) == ZP_OK);
    CHECK(zp_problem_build(p, 0, &d) == 0 && d.n == 0);
}

/* force run with the options o: its result (static until the next call) */
static const zp_result *run(const zp_problem *p, const zp_sim_opts *o, const double *force) {
    zp_schedule s = zp_drive_with(&p->sched, force);
    zp_input in = {.sched = &s};
    return tu_run(p->m, o, &in);
}

/* finished with every joint within the margin */
static int kept(const zp_problem *p, const zp_result *r) {
    return r->outcome == ZP_OUTCOME_FINISHED &&
           zp_model_angle_used(p->m, r->max_rel_angle) <= p->limit;
}

static int same(const double *x, const double *y, int n) {
    return !memcmp(x, y, sizeof *x * (size_t)n);
}

/* the text of what write(f, a) prints; free it */
static char *written(void (*write)(FILE *, const zp_answer *), const zp_answer *a) {
    char *buf = NULL;
    size_t n = 0;
    FILE *f = open_memstream(&buf, &n);
    write(f, a);
    fclose(f);
    return buf;
}

static void write_md(FILE *f, const zp_answer *a) {
    zp_report_place w = {NULL, ".", 0};
    zp_report_write_md(f, a, &w);
}

/* rtol 1e-3, seed 1, 400 runs: the best (10.29 s ranked) keeps the margin at rtol 1e-3 but
   reaches 170.24 deg of the 170 allowed with [solver]; the next candidate (13.29 s) holds */
static void check_taken(void) {
    static zp_problem p;
    load(400, 1, "1e-3", &p);
    char err[512];
    static zp_answer a, b;
    zp_answer_opts o = zp_answer_opts_of(&p, ZP_ANSWER_REPORTED);
    o.search.nthreads = 1;
    CHECK(zp_answer_solve(&p, &o, &a, err, sizeof err) == ZP_OK);
    const zp_answer_fallback *fb = &a.fallback;
    int np = p.sched.np;
    CHECK(a.res.found && a.found && a.verified && !a.unheld[0]);
    CHECK(fb->taken && fb->tried >= 1 && fb->tried <= ZP_ANSWER_FALLBACKS);
    CHECK(strstr(fb->why, "past the 170.00 deg the margin allows") != NULL);
    /* the best was ranked faster, and the search scored it survivable: so it does again at
       the search's options, bit for bit */
    CHECK(fb->first_time < a.res.best.time && !same(fb->first_force, a.res.force, np));
    zp_objective ob = a.rp.ob;
    zp_sim *s = zp_sim_create(p.m, &p.search);
    zp_result *r = malloc(sizeof *r);
    zp_eval e;
    zp_objective_eval(&ob, s, fb->first_force, &e, r);
    CHECK(zp_objective_feasible(&e) && e.time == fb->first_time);
    /* the answer is one the search kept, its time as the search ranked it */
    int kept_by_search = 0;
    for (int i = 0; i < a.res.nshown; i++) {
        kept_by_search |=
            same(a.res.island_force[i], a.res.force, np) && a.res.island_time[i] == a.res.best.time;
    }
    for (int i = 0; i < a.res.nends; i++) {
        kept_by_search |=
            same(a.res.ends[i], a.res.force, np) && a.res.ends_time[i] == a.res.best.time;
    }
    CHECK(kept_by_search && zp_objective_feasible(&a.res.best));
    zp_objective_eval(&ob, s, a.res.force, &e, r);
    CHECK(e.time == a.res.best.time);
    zp_sim_free(s);
    free(r);

    /* by hand: the best fails with [solver], the answer holds with it and 100x tighter */
    CHECK(!kept(&p, run(&p, &p.answer, fb->first_force)));
    const zp_result *ans = run(&p, &p.answer, a.res.force);
    CHECK(kept(&p, ans) && ans->time == a.v.run->time);
    zp_sim_opts tight = zp_estimate_tighter(&p.answer);
    const zp_result *t = run(&p, &tight, a.res.force);
    CHECK(kept(&p, t) && fabs(t->time - ans->time) <= ZP_VERIFY_DT && a.v.agree);
    /* the robustness runs are the answer's */
    CHECK(a.v.robust_done && a.v.rob[0].n == 200);

    /* the same on two threads, only verified: the same answer and fallback, bit for bit */
    o = zp_answer_opts_of(&p, ZP_ANSWER_VERIFIED);
    o.search.nthreads = 2;
    CHECK(zp_answer_solve(&p, &o, &b, err, sizeof err) == ZP_OK);
    CHECK(b.found && same(b.res.force, a.res.force, np) && b.v.run->time == a.v.run->time);
    CHECK(!memcmp(&b.fallback, &a.fallback, sizeof a.fallback));
    CHECK(b.res.best.time == a.res.best.time && !b.v.robust_done);

    /* what the outputs say */
    char *json = written(zp_summary_write_json, &a);
    CHECK(strstr(json, "\"fallback\": {\"rejected\": 1, \"taken\": true, \"first_time\": ") ||
          (fb->tried > 1 && strstr(json, "\"taken\": true")));
    CHECK(strstr(json, "\"found\": true") != NULL);
    char *text = written(zp_report_text_write, &a);
    CHECK(strstr(text, "fallback: the fastest ranked schedule (") != NULL);
    CHECK(strstr(text, "no schedule found") == NULL);
    char *md = written(write_md, &a);
    CHECK(strstr(md, "**Fallback**: the fastest ranked schedule (") != NULL);
    printf("taken: best %.6f s ranked (%s); answer %.6f s ranked, %.6f s with [solver], "
           "%d tried\n",
           fb->first_time, fb->why, a.res.best.time, a.v.run->time, fb->tried);
    free(json);
    free(text);
    free(md);
    zp_answer_free(&a);
    zp_answer_free(&b);
    zp_problem_free(&p);
}

/* rtol 1e-2, seed 4, 400 runs: the best and the next candidate both pass the margin with
   [solver]: nothing found, the best written as the closest candidate, as before */
static void check_none_holds(void) {
    static zp_problem p;
    load(400, 4, "1e-2", &p);
    char err[512];
    static zp_answer a;
    zp_answer_opts o = zp_answer_opts_of(&p, ZP_ANSWER_REPORTED);
    CHECK(zp_answer_solve(&p, &o, &a, err, sizeof err) == ZP_OK);
    const zp_answer_fallback *fb = &a.fallback;
    CHECK(a.res.found && !a.found && a.unheld[0] && !fb->taken && fb->tried >= 1);
    CHECK(same(fb->first_force, a.res.force, p.sched.np) && fb->first_time == a.res.best.time);
    CHECK(!strcmp(fb->why, a.unheld));
    const zp_result *r = run(&p, &p.answer, a.res.force);
    CHECK(!kept(&p, r) && r->time == a.v.run->time);
    char *json = written(zp_summary_write_json, &a);
    CHECK(strstr(json, "\"taken\": false") && strstr(json, "\"found\": false"));
    char *text = written(zp_report_text_write, &a);
    CHECK(strstr(text, "no schedule found") && strstr(text, "nor do the next"));
    free(json);
    free(text);
    zp_answer_free(&a);
    zp_problem_free(&p);
}

/* rtol 1e-3, seed 1, 200 runs: the best holds; the answer is the search's best and its
   verification, exactly as assembled by hand, with nothing tried after it and nothing said */
static void check_unchanged(void) {
    static zp_problem p;
    load(200, 1, "1e-3", &p);
    char err[512];
    static zp_robust_problem rp;
    static zp_search_result res;
    zp_sim_opts fast;
    CHECK(zp_robust_setup(&rp, &p.sc, p.m, p.limit, &p.sched, &p.sim, &p.search, &fast) == ZP_OK);
    zp_search_opts so = {.max_evals = p.max_evals, .seed = p.seed};
    CHECK(zp_robust_solve(&rp, &p.sc, &fast, p.sched.lo, p.sched.hi, &so, &res, err, sizeof err) ==
          ZP_OK);
    zp_objective ob = rp.ob;
    zp_verify v;
    zp_sim *best = NULL;
    CHECK(zp_verify_run(&ob, &p.answer, res.force, p.seed, 0, 0, &best, &v, NULL, NULL, err,
                        sizeof err) == ZP_OK);
    static zp_answer a;
    zp_answer_opts o = zp_answer_opts_of(&p, ZP_ANSWER_REPORTED);
    CHECK(zp_answer_solve(&p, &o, &a, err, sizeof err) == ZP_OK);
    CHECK(res.found && a.found && !a.unheld[0] && a.fallback.tried == 0 && !a.fallback.taken);
    CHECK(same(a.res.force, res.force, p.sched.np) && a.res.evals == res.evals);
    CHECK(!memcmp(&a.res.best, &res.best, sizeof res.best));
    CHECK(a.v.run->time == v.run->time && a.v.tight->time == v.tight->time && a.v.agree == v.agree);
    char *json = written(zp_summary_write_json, &a);
    CHECK(strstr(json, "\"fallback\"") == NULL);
    free(json);
    zp_answer_free(&a);
    zp_verify_free(&v);
    zp_sim_free(best);
    zp_robust_problem_free(&rp);
    zp_problem_free(&p);
}

int main(void) {
    check_taken();
    check_none_holds();
    check_unchanged();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
