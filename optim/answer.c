/* Problem -> answer (answer.h): the robust search with its fresh-scenario check, then the
   answer rerun, [solver] accuracy and the held verdict (again for the search's next
   candidates only when its best does not hold), the robustness runs, the scene's own forces
   and the diagnosis, each step at most once, in this order, for every caller. */
#include "answer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "search_state.h"

#define NROBUST 200 /* robustness runs per perturbation level (ZP_ANSWER_REPORTED) */

zp_answer_opts zp_answer_opts_of(const zp_problem *p, zp_answer_depth depth) {
    return (zp_answer_opts){
        .depth = depth,
        .search = {.max_evals = p->max_evals,
                   .seed = p->seed,
                   .algo = zp_search_algo_default(p->m->nsec, p->sc.robust)}};
}

static int stage(const zp_answer_opts *o, zp_answer_stage s, const zp_answer *a) {
    return o->stage ? o->stage(o->user, s, a) : 0;
}

/* the (robust) search over p's bounds (its runs' options in fast) and, with [robust], its answer
   on fresh scenarios */
static zp_status search(const zp_problem *p, const zp_answer_opts *o, zp_answer *a,
                        zp_sim_opts *fast, char *err, size_t errlen) {
    if (zp_robust_setup(&a->rp, &p->sc, p->m, p->limit, &p->sched, &p->sim, &p->search, fast)) {
        snprintf(err, errlen, "out of memory building the scenarios");
        if (!o->spread || o->spread->rank == 0) {
            zp_robust_release(o->spread); /* the other ranks wait for rank 0's answer */
        }
        return ZP_ERR_NOMEM;
    }
    a->rp.spread = o->spread;
    return zp_robust_solve(&a->rp, &p->sc, fast, p->sched.lo, p->sched.hi, &o->search, &a->res,
                           err, errlen);
}

/* whether the answer holds when rerun with [solver] (v->run) and 100x tighter (v->tight): it
   finishes with the margin at both, at times that agree. The search ranks with [optimize]'s
   own, possibly much looser, tolerance. 0 with why in why. */
static int holds(const zp_problem *p, const zp_verify *v, char *why, size_t n) {
    int which;
    zp_breaks b = zp_problem_breaks(p, v->run, &which);
    if (b == ZP_BREAKS_DEATH || b == ZP_BREAKS_STALL) {
        snprintf(why, n, "rerun with [solver] it %s at %.4f s",
                 zp_sim_outcome_name(v->run->outcome), v->run->time);
    } else if (b == ZP_BREAKS_MARGIN) {
        snprintf(why, n,
                 "rerun with [solver] its largest joint angle is %.2f deg, past the %.2f deg the "
                 "margin allows",
                 zp_model_angle_used(p->m, v->run->max_rel_angle) * 180 / M_PI,
                 p->limit * 180 / M_PI);
    } else if (b == ZP_BREAKS_LIMIT) {
        snprintf(why, n, "rerun with [solver] it breaks [limits] %s", zp_limits_name(which));
    } else if (!v->agree) {
        snprintf(why, n, "it is not verified at the tighter tolerance (rtol %.0e)", v->rtol);
    } else {
        return 1;
    }
    return 0;
}

/* one candidate rerun and judged: what the answer keeps of it */
typedef struct trial {
    int ran;              /* v.run and best are made */
    zp_verify v;
    zp_sim *best;         /* owned */
    zp_sim_opts run_opts; /* v.run's options */
    zp_accuracy acc;
} trial;

static void trial_free(trial *t) {
    zp_verify_free(&t->v);
    zp_sim_free(t->best);
    t->best = NULL;
}

/* force rerun with p->answer on the nominal scene (the scenarios were checked above), 100x
   tighter and, reported, to [solver] accuracy: all that holds() judges */
static zp_status rerun(const zp_problem *p, const zp_objective *ob, const double *force,
                       int reported, trial *t, char *err, size_t errlen) {
    t->run_opts = p->answer;
    zp_status rc = zp_verify_begin(ob, &p->answer, force, &t->best, &t->v, err, errlen);
    t->ran = !rc;
    if (!rc) {
        rc = zp_verify_tight(ob, &p->answer, force, &t->v, err, errlen);
    }
    if (!rc && reported && p->sc.accuracy > 0) {
        rc = zp_verify_accuracy(ob, &p->answer, force, p->sc.accuracy, &t->best, &t->v,
                                &t->run_opts, &t->acc, err, errlen);
    }
    return rc;
}

/* the next candidates the search kept after its best, in x[] (borrowed from r) by ranked time:
   its islands' bests and polish ends, each distinct from the best and from those before it
   (as the search tells points apart); how many, ZP_ANSWER_FALLBACKS at most */
static int candidates(const zp_problem *p, const zp_search_result *r, const double **x) {
    const double *pt[ZP_SEARCH_ISLANDS + ZP_SEARCH_ENDS];
    double time[ZP_SEARCH_ISLANDS + ZP_SEARCH_ENDS];
    int n = 0, np = p->sched.np;
    for (int i = 0; i < r->nshown; i++, n++) {
        pt[n] = r->island_force[i];
        time[n] = r->island_time[i];
    }
    for (int i = 0; i < r->nends; i++, n++) {
        pt[n] = r->ends[i];
        time[n] = r->ends_time[i];
    }
    int nx = 0;
    while (nx < ZP_ANSWER_FALLBACKS) {
        int b = -1; /* the fastest left; ties to the first listed */
        for (int j = 0; j < n; j++) {
            if (pt[j] && (b < 0 || time[j] < time[b])) {
                b = j;
            }
        }
        if (b < 0) {
            break;
        }
        int distinct = 1;
        for (int i = -1; distinct && i < nx; i++) {
            distinct = zp_search_state_apart(np, p->sched.lo, p->sched.hi, pt[b],
                                             i < 0 ? r->force : x[i]);
        }
        if (distinct) {
            x[nx++] = pt[b];
        }
        pt[b] = NULL;
    }
    return nx;
}

/* the search's best t does not hold (why in a->unheld): the next candidates rerun alike, the
   first that holds replacing it in t and as a->res's best (scored again at the search's
   options fast, as the search scored it); none holding, t and a are left as they were */
static zp_status fall_back(const zp_problem *p, const zp_objective *ob, const zp_sim_opts *fast,
                           int reported, zp_answer *a, trial *t) {
    const double *x[ZP_ANSWER_FALLBACKS];
    int n = candidates(p, &a->res, x);
    zp_answer_fallback *fb = &a->fallback;
    if (n > 0) {
        fb->first_time = a->res.best.time;
        memcpy(fb->first_force, a->res.force, sizeof fb->first_force);
        snprintf(fb->why, sizeof fb->why, "%s", a->unheld);
    }
    for (int i = 0; i < n && !fb->taken; i++) {
        trial c = {0};
        char why[256];
        fb->tried++;
        if (rerun(p, ob, x[i], reported, &c, why, sizeof why) ||
            !holds(p, &c.v, why, sizeof why)) {
            trial_free(&c);
            continue;
        }
        zp_sim *s = zp_sim_create(p->m, fast);
        zp_result *r = malloc(sizeof *r);
        if (!s || !r) {
            zp_sim_free(s);
            free(r);
            trial_free(&c);
            return ZP_ERR_NOMEM;
        }
        fb->taken = 1;
        a->unheld[0] = '\0';
        memcpy(a->res.force, x[i], sizeof *x[i] * (size_t)p->sched.np);
        zp_objective_eval(ob, s, a->res.force, &a->res.best, r);
        zp_sim_free(s);
        free(r);
        trial_free(t);
        *t = c;
    }
    return ZP_OK;
}

/* the answer rerun and judged (with its fallbacks when the search's best does not hold), then,
   reported, perturbed at the scene's force error and twice it */
static zp_status verify(const zp_problem *p, const zp_answer_opts *o, const zp_sim_opts *fast,
                        zp_answer *a, char *err, size_t errlen) {
    int reported = o->depth == ZP_ANSWER_REPORTED;
    zp_objective ob = a->rp.ob;
    ob.set = NULL;
    trial t = {0};
    zp_status rc = rerun(p, &ob, a->res.force, reported, &t, err, errlen);
    int judged = a->found && !a->res.interrupted;
    if (!rc && judged && !holds(p, &t.v, a->unheld, sizeof a->unheld) && !a->rp.robust) {
        rc = fall_back(p, &ob, fast, reported, a, &t);
        if (rc) {
            snprintf(err, errlen, "out of memory for the next candidate");
        }
    }
    a->v = t.v;
    a->best = t.best;
    a->run_opts = t.run_opts;
    a->acc = t.acc;
    if ((t.ran && stage(o, ZP_ANSWER_RERUN, a)) || stage(o, ZP_ANSWER_CHECKING, a)) {
        return ZP_ERR_IO;
    }
    if (p->sc.force_error > 0) { /* the level the scene holds the answer to, and twice it */
        a->v.level[0] = p->sc.force_error / 100;
        a->v.level[1] = fmin(2 * p->sc.force_error / 100, 0.99);
    }
    int nrobust = reported && !a->res.interrupted ? NROBUST : 0;
    if (!rc) {
        rc = zp_verify_robustness(&ob, &p->answer, a->res.force, a->seed, nrobust, 0, &a->v,
                                  o->checked, o->user, err, errlen);
    }
    if (stage(o, ZP_ANSWER_CHECKED, a)) {
        return ZP_ERR_IO;
    }
    if (rc) {
        return rc;
    }
    a->verified = 1;
    /* not found unless it (or a fallback) holds with [solver] */
    a->found = a->found && !a->unheld[0];
    return ZP_OK;
}

/* the scene's own [drive] forces, judged as the search judges (peaks where limits need them),
   for the report's comparison */
static zp_status run_given(const zp_problem *p, zp_answer *a, char *err, size_t errlen) {
    if (p->sc.nforce <= 0) {
        return ZP_OK;
    }
    zp_sim *s = zp_sim_create(p->m, &p->search);
    a->given = malloc(sizeof *a->given);
    zp_input in = {.sched = &p->sched};
    zp_status st = s && a->given ? zp_sim_run(p->m, s, &in, a->given) : ZP_ERR_NOMEM;
    if (st) {
        snprintf(err, errlen, "the run of the scene's [drive] forces failed: %s",
                 s && a->given ? a->given->message : "out of memory");
    }
    zp_sim_free(s);
    return st;
}

/* 1 when every parameter of f lies at the same share of its range */
static int is_push(const zp_problem *p, const double *f) {
    const zp_schedule *sh = &p->sched;
    double u0 = (f[0] - sh->lo[0]) / (sh->hi[0] - sh->lo[0]);
    for (int k = 1; k < sh->np; k++) {
        if (fabs((f[k] - sh->lo[k]) / (sh->hi[k] - sh->lo[k]) - u0) > 1e-12) {
            return 0;
        }
    }
    return 1;
}

/* without [robust], the best constant push by its own scan (push_scan.h), at the search's
   options: the search's 49 pushes and zooms miss bands narrower than their spacing. With
   [robust] the baseline stays the search's, held to the scenarios (a scan would run them
   for every push). */
static zp_status push_best(const zp_problem *p, const zp_answer_opts *o, zp_answer *a,
                           char *err, size_t errlen) {
    zp_search_result *res = &a->res;
    if (a->rp.robust) {
        return ZP_OK;
    }
    zp_push_scan *ps = &a->push;
    if (res->found && is_push(p, res->force)) { /* the fastest schedule is a push: no scan */
        *ps = (zp_push_scan){.found = 1, .e = res->best};
        memcpy(ps->p, res->force, sizeof ps->p);
    } else {
        zp_objective ob = a->rp.ob;
        ob.set = NULL;
        if (zp_push_scan_run(&ob, &p->search, p->sched.lo, p->sched.hi,
                             zp_push_scan_points(a->max_evals), o->search.nthreads, ps)) {
            snprintf(err, errlen, "out of memory for the constant pushes' scan");
            return ZP_ERR_NOMEM;
        }
    }
    if (ps->found && (!res->base_found || ps->e.time < res->base.time)) {
        res->base_found = 1;
        res->base = ps->e;
        res->base_force = ps->p[0];
        memcpy(res->base_p, ps->p, sizeof ps->p);
    }
    return ZP_OK;
}

/* with a profile, the best constant-per-section schedule of the same scene (answer.h's
   zp_answer_constant): p with one force per section, the profile's bounds and cap, solved
   through this same path to its verified answer, silently */
static zp_status run_constant(const zp_problem *p, const zp_answer_opts *o, zp_answer *a,
                              char *err, size_t errlen) {
    const zp_schedule *sh = &p->sched;
    if (sh->kind != ZP_SCHED_PROFILE || sh->knots < 2) {
        return ZP_OK;
    }
    zp_problem *q = malloc(sizeof *q);
    zp_answer *c = calloc(1, sizeof *c);
    if (!q || !c) {
        free(q);
        free(c);
        snprintf(err, errlen, "out of memory for the constant schedule's search");
        return ZP_ERR_NOMEM;
    }
    *q = *p;
    double mean[ZP_MAX_SECTIONS]; /* each section's knots' mean: the scene's forces, constant */
    for (int k = 0; k < sh->nsec; k++) {
        mean[k] = 0;
        for (int j = 0; j < sh->knots; j++) {
            mean[k] += sh->p[k * sh->knots + j] / sh->knots;
        }
    }
    q->sched = zp_drive_sections(sh->nsec, mean, sh->lo[0], sh->hi[0]);
    q->sched.power = sh->power;
    zp_answer_opts co = {.depth = ZP_ANSWER_VERIFIED, .search = o->search};
    co.search.max_evals = a->max_evals;
    co.search.seed = a->seed;
    co.search.progress = NULL;
    zp_status st = zp_answer_solve(q, &co, c, err, errlen);
    if (!st) {
        zp_answer_constant *k = &a->constant;
        k->ran = 1;
        k->found = c->found && !c->res.interrupted;
        k->time = c->v.run->time;
        k->nsec = sh->nsec;
        memcpy(k->force, c->res.force, sizeof *k->force * (size_t)sh->nsec);
        k->evals = c->res.evals;
    }
    zp_answer_free(c);
    free(c);
    free(q);
    return st;
}

/* the fresh scenarios the answer fails, told apart by what breaks and where: the
   verification's scenarios run again with its options, each verdict kept; without memory no
   diagnosis */
static void diagnose(const zp_problem *p, zp_answer *a) {
    int n = a->rp.check.samples;
    zp_robust_worst *each = malloc(sizeof *each * (size_t)n);
    a->diag = malloc(sizeof *a->diag);
    zp_robust_check c;
    if (!each || !a->diag ||
        zp_robust_verify_each(&a->rp.ob, &a->rp.box, &p->verify, a->res.force, n, p->sc.seed, 0,
                              NULL, &c, each)) {
        free(a->diag);
        a->diag = NULL;
    } else {
        zp_diagnose(&a->rp.box, &a->rp.ob, each, n, a->diag);
    }
    free(each);
}

zp_status zp_answer_solve(const zp_problem *p, const zp_answer_opts *o, zp_answer *a, char *err,
                          size_t errlen) {
    memset(a, 0, sizeof *a);
    a->pb = p;
    a->algo = zp_search_algo_get(o->search.algo)->name;
    a->max_evals = o->search.max_evals;
    a->seed = o->search.seed;
    zp_sim_opts fast;
    zp_status st = search(p, o, a, &fast, err, errlen);
    a->found = a->res.found;
    if (st || o->depth == ZP_ANSWER_SEARCHED || (o->spread && o->spread->rank != 0)) {
        return st; /* another rank's share of the fresh scenarios is rank 0's too */
    }
    if ((st = verify(p, o, &fast, a, err, errlen)) || o->depth == ZP_ANSWER_VERIFIED) {
        return st;
    }
    if ((st = run_given(p, a, err, errlen)) || (st = push_best(p, o, a, err, errlen)) ||
        (st = run_constant(p, o, a, err, errlen))) {
        return st;
    }
    if (stage(o, ZP_ANSWER_COMPARED, a)) {
        return ZP_ERR_IO;
    }
    const zp_robust_check *c = &a->rp.check;
    if (a->rp.robust && c->samples > 0 && c->all_kept < c->samples) {
        if (stage(o, ZP_ANSWER_DIAGNOSING, a)) {
            return ZP_ERR_IO;
        }
        diagnose(p, a);
    }
    return ZP_OK;
}

void zp_answer_free(zp_answer *a) {
    zp_verify_free(&a->v);
    zp_sim_free(a->best);
    a->best = NULL;
    free(a->given);
    free(a->diag);
    a->given = NULL;
    a->diag = NULL;
    zp_robust_problem_free(&a->rp);
}

int zp_answer_scenarios(const zp_answer *a) {
    return a->rp.robust ? a->rp.set.n : 0;
}
