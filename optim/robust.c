/* The robust search: the [robust] box, scenario sets (corners, then shifted Sobol/Halton
   points), the adversary that grows the set where the answer breaks, and the verification on
   fresh random scenarios with a Clopper-Pearson bound. */
#include "robust.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_qrng.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <nlopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "headroom.h"
#include "held.h"
#include "pool.h"
#include "state.h"
#include "estimate.h"

#define DEG (180.0 / M_PI)
#define ADV_POINTS 128       /* random points of the adversary's first look */
#define ADV_POLISH 2         /* of them, the worst polished locally */
#define ADV_EVALS 60         /* simulations per polish */
#define STREAM_ADV 0xad5u    /* the adversary's seeds: a stream apart from the set's shift
                                (scen_set.c) and from ZP_ROBUST_STREAM_VERIFY */

static double beta_excess(double p, void *params) {
    const double *a = params; /* k, n - k + 1, alpha */
    return gsl_cdf_beta_P(p, a[0], a[1]) - a[2];
}

/* the root of I_p(k, n - k + 1) = alpha by Brent's method: gsl_cdf_beta_Pinv fails to converge
   for large n with k near n (e.g. 1943 of 2000), while the distribution itself stays accurate */
double zp_robust_clopper_pearson_lower(int k, int n, double alpha) {
    if (k <= 0) {
        return 0;
    }
    if (k >= n) {
        return pow(alpha, 1.0 / n); /* I_p(n, 1) = p^n */
    }
    double a[3] = {k, n - k + 1, alpha};
    gsl_function f = {beta_excess, a};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double p = NAN;
    if (s && gsl_root_fsolver_set(s, &f, 0, 1) == GSL_SUCCESS) {
        int st = GSL_CONTINUE;
        for (int i = 0; i < 200 && st == GSL_CONTINUE; i++) {
            gsl_root_fsolver_iterate(s);
            st = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
                                        1e-15, 1e-13);
        }
        p = gsl_root_fsolver_root(s);
    }
    gsl_root_fsolver_free(s);
    return p;
}

/* sched in the scenario at u, judged in full: *w filled; returns the constraint (deg) */
static double scen_judge(const zp_objective *ob, const zp_box *b, const zp_chain *c0,
                         zp_sim *s, zp_result *r, const zp_schedule *sched, const double *u,
                         int tension, zp_robust_worst *w) {
    zp_scenario sc;
    zp_model m;
    zp_chain start;
    zp_box_scenario(b, u, &sc);
    zp_scenario_model(ob->m, &sc, &m);
    zp_scenario_start(c0, m.nlink, &sc, &start);
    zp_input in = {.sched = sched, .force_scale = sc.force, .start = &start};
    zp_eval e;
    zp_objective_eval_run(ob, &m, s, &in, &e, r);
    memcpy(w->u, u, sizeof *u * b->d);
    w->cons = zp_objective_scenario_cons(ob, &e);
    w->margin_deg = (m.phi_max - e.angle) * DEG;
    w->outcome = e.outcome;
    w->time = e.time;
    w->arrival_kmh = !e.failed && e.outcome == ZP_OUTCOME_FINISHED ? r->v * 3.6 : 0;
    w->joint = 1;
    for (int i = 0; i < m.nlink; i++) {
        w->joint = r->max_rel_angle[i] > r->max_rel_angle[w->joint - 1] ? i + 1 : w->joint;
    }
    w->limit = -1;
    w->excess = -1;
    if (zp_limits_any(&ob->lim)) {
        w->excess = e.failed ? 1 : zp_limits_excess(&ob->lim, &m, r, &w->limit);
    }
    w->anchor_tension = 0;
    if (tension && !e.failed) {
        w->anchor_tension = zp_limits_anchor_tension(&m, r);
    }
    return w->cons;
}

/* the adversary's local search: NLopt maximises the constraint over the box */
typedef struct adv_ctx {
    const zp_objective *ob;
    const zp_box *b;
    const zp_chain *c0;
    zp_sim *s;
    zp_result *r;
    const zp_schedule *sched;
    zp_robust_worst best;
    long sims;
} adv_ctx;

static double adv_obj(unsigned n, const double *u, double *grad, void *data) {
    adv_ctx *a = data;
    (void)n;
    (void)grad;
    zp_robust_worst w;
    double c = scen_judge(a->ob, a->b, a->c0, a->s, a->r, a->sched, u, 0, &w);
    a->sims++;
    if (c > a->best.cons) {
        a->best = w;
    }
    return c;
}

/* a batch of scenarios of one schedule, judged in parallel over the pool: pw[i] for u row i */
typedef struct scen_batch {
    const zp_objective *ob;
    const zp_box *b;
    const zp_chain *c0;
    const zp_schedule *sched;
    const double *u;
    zp_robust_worst *pw;
    int tension; /* the verification: each run's anchor tension too ([cable]) */
} scen_batch;

static void scen_job(void *user, int i, zp_sim *s, zp_result *r) {
    scen_batch *sb = user;
    scen_judge(sb->ob, sb->b, sb->c0, s, r, sb->sched, sb->u + (size_t)i * sb->b->d, sb->tension,
               &sb->pw[i]);
}

/* the polishes of the adversary, in parallel: polish k from point top[k] into its own best */
typedef struct polish_batch {
    const zp_objective *ob;
    const zp_box *b;
    const zp_chain *c0;
    const zp_schedule *sched;
    const zp_robust_worst *pw;
    const int *top;
    adv_ctx *a; /* ADV_POLISH */
} polish_batch;

static void polish_job(void *user, int k, zp_sim *s, zp_result *r) {
    polish_batch *pb = user;
    int d = pb->b->d;
    double lo[ZP_BOX_MAX], hi[ZP_BOX_MAX];
    for (int c = 0; c < d; c++) {
        lo[c] = -1;
        hi[c] = 1;
    }
    adv_ctx *a = &pb->a[k];
    *a = (adv_ctx){pb->ob, pb->b, pb->c0, s, r, pb->sched, pb->pw[pb->top[k]], 0};
    nlopt_opt opt = nlopt_create(d > 1 ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA, d);
    double x[ZP_BOX_MAX], val;
    memcpy(x, pb->pw[pb->top[k]].u, sizeof *x * d);
    if (opt) {
        nlopt_set_max_objective(opt, adv_obj, a);
        nlopt_set_lower_bounds(opt, lo);
        nlopt_set_upper_bounds(opt, hi);
        nlopt_set_maxeval(opt, ADV_EVALS);
        nlopt_set_initial_step1(opt, 0.25);
        nlopt_optimize(opt, x, &val);
        nlopt_destroy(opt);
    }
}

/* the worst scenario of force found in the box: ADV_POINTS seeded random points in parallel,
   the worst ADV_POLISH of them polished by BOBYQA (the box's corners included as points) */
static void adversary(const zp_objective *ob, const zp_box *b, zp_pool *w, const double *p,
                      unsigned long seed, int round, zp_robust_worst *worst, long *sims) {
    zp_schedule sched = zp_objective_schedule(ob, p);
    int d = b->d, npt = ADV_POINTS;
    double *u = malloc(sizeof *u * npt * d);
    zp_robust_worst *pw = malloc(sizeof *pw * npt);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    zp_chain c0;
    zp_state_start(ob->m, ob->m->course, &c0);
    worst->cons = -INFINITY;
    if (!u || !pw || !rng) {
        goto out;
    }
    gsl_rng_set(rng, (seed ^ STREAM_ADV) + 7919UL * (unsigned long)round);
    for (int i = 0; i < npt * d; i++) {
        u[i] = 2 * gsl_rng_uniform(rng) - 1;
    }
    scen_batch sb = {ob, b, &c0, &sched, u, pw, 0};
    zp_pool_map(w, npt, scen_job, &sb, NULL, NULL);
    *sims += npt;
    int top[ADV_POLISH];
    for (int k = 0; k < ADV_POLISH; k++) {
        top[k] = -1;
        for (int i = 0; i < npt; i++) {
            int taken = 0;
            for (int j = 0; j < k; j++) {
                taken |= top[j] == i;
            }
            if (!taken && (top[k] < 0 || pw[i].cons > pw[top[k]].cons)) {
                top[k] = i;
            }
        }
        if (pw[top[k]].cons > worst->cons) {
            *worst = pw[top[k]];
        }
    }
    adv_ctx a[ADV_POLISH];
    polish_batch pb = {ob, b, &c0, &sched, pw, top, a};
    zp_pool_map(w, ADV_POLISH, polish_job, &pb, NULL, NULL);
    for (int k = 0; k < ADV_POLISH; k++) {
        *sims += a[k].sims;
        if (a[k].best.cons > worst->cons) {
            *worst = a[k].best;
        }
    }
out:
    free(u);
    free(pw);
    gsl_rng_free(rng);
}

/* the adversary between searches: the answer's worst scenario found joins the set when it
   breaks the answer, while rounds are left */
typedef struct adversary_turn {
    zp_objective *ob;
    const zp_box *b;
    zp_pool *w;
    unsigned long seed;
    int max_rounds;
    zp_robust_info *info;
} adversary_turn;

static zp_status adversary_grow(void *user, const zp_search_result *res, int searches, int *grown,
                                char *err, size_t errlen) {
    adversary_turn *a = user;
    zp_robust_info *info = a->info;
    info->rounds = searches;
    if (!res->found || res->interrupted || a->b->d == 0) {
        return ZP_OK;
    }
    adversary(a->ob, a->b, a->w, res->force, a->seed, info->rounds, &info->worst, &info->sims);
    if (info->worst.cons <= 0 || info->rounds >= a->max_rounds) {
        return ZP_OK;
    }
    /* worst first: what broke candidates most often, then the adversary's find */
    zp_scen_set_reorder(a->ob->set);
    if (zp_scen_set_add(a->ob->set, a->b, a->ob->m, info->worst.u)) {
        snprintf(err, errlen, "out of memory growing the scenario set");
        return ZP_ERR_NOMEM;
    }
    info->added++;
    *grown = 1;
    return ZP_OK;
}

zp_status zp_robust_search(zp_objective *ob, const zp_box *b, const zp_sim_opts *so,
                           const double *lo, const double *hi, const zp_search_opts *o,
                           int max_rounds, zp_search_result *res, zp_robust_info *info, char *err,
                           size_t errlen) {
    memset(info, 0, sizeof *info);
    info->worst.cons = NAN; /* no adversary yet */
    zp_pool *w = NULL;
    if (b->d > 0 && !(w = zp_pool_create(ob->m, so, o->nthreads))) {
        snprintf(err, errlen, "out of memory for the adversary's workspaces");
        return ZP_ERR_NOMEM;
    }
    adversary_turn turn = {ob, b, w, o->seed, max_rounds, info};
    zp_search_grown grown;
    zp_status st =
        zp_search_grow(ob, so, lo, hi, o, res, adversary_grow, &turn, &grown, err, errlen);
    info->rounds = grown.searches;
    zp_pool_free(w);
    return st;
}

/* scenario i (its point u + i d) into the end e when v is larger than e's (the first wins) */
static void spread_take(zp_spread_end *e, double v, int i, const double *u, int d) {
    if (e->sample < 0 || v > e->value) {
        e->value = v;
        e->sample = i;
        memcpy(e->u, u + (size_t)i * d, sizeof *u * (size_t)d);
    }
}

zp_status zp_robust_verify(const zp_objective *ob, const zp_box *b, const zp_sim_opts *so,
                           const double *p, int n, unsigned long seed, int nthreads,
                           const zp_spread *sp, zp_robust_check *c) {
    return zp_robust_verify_each(ob, b, so, p, n, seed, nthreads, sp, c, NULL);
}

zp_status zp_robust_verify_each(const zp_objective *ob, const zp_box *b, const zp_sim_opts *so,
                                const double *p, int n, unsigned long seed, int nthreads,
                                const zp_spread *sp, zp_robust_check *c, zp_robust_worst *each) {
    zp_schedule sched = zp_objective_schedule(ob, p);
    memset(c, 0, sizeof *c);
    c->samples = n;
    c->worst_margin_deg = INFINITY;
    zp_spread_end *ends[5] = {&c->fastest, &c->slowest, &c->arrival_low, &c->arrival_high,
                              &c->tension_high};
    for (int k = 0; k < 5; k++) {
        ends[k]->value = NAN;
        ends[k]->sample = -1;
    }
    zp_pool *w = NULL;
    double *u = malloc(sizeof *u * (size_t)n * (b->d + 1));
    zp_robust_worst *pw = malloc(sizeof *pw * (size_t)(n + 1));
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!u || !pw || !rng || !(w = zp_pool_create(ob->m, so, nthreads))) {
        free(u);
        free(pw);
        gsl_rng_free(rng);
        return ZP_ERR_NOMEM;
    }
    gsl_rng_set(rng, seed ^ ZP_ROBUST_STREAM_VERIFY);
    for (long i = 0; i < (long)n * b->d; i++) {
        u[i] = 2 * gsl_rng_uniform(rng) - 1;
    }
    zp_chain c0;
    zp_state_start(ob->m, ob->m->course, &c0);
    scen_batch sb = {ob, b, &c0, &sched, u, pw, 1};
    zp_status st = zp_spread_map(sp, w, n, scen_job, &sb, pw, sizeof *pw, NULL, NULL);
    for (int i = 0; !st && i < n; i++) {
        int fin = pw[i].outcome == ZP_OUTCOME_FINISHED;
        int margin = fin && pw[i].margin_deg >= (ob->m->phi_max - ob->limit) * DEG;
        int limits = fin && pw[i].excess <= 0;
        c->survived += fin;
        c->margin_kept += margin;
        c->limits_kept += limits;
        c->all_kept += margin && limits;
        if (fin) {
            c->worst_margin_deg = fmin(c->worst_margin_deg, pw[i].margin_deg);
            spread_take(&c->fastest, -pw[i].time, i, u, b->d);
            spread_take(&c->slowest, pw[i].time, i, u, b->d);
            spread_take(&c->arrival_low, -pw[i].arrival_kmh, i, u, b->d);
            spread_take(&c->arrival_high, pw[i].arrival_kmh, i, u, b->d);
            if (ob->m->cable_paths) {
                spread_take(&c->tension_high, pw[i].anchor_tension, i, u, b->d);
            }
        }
    }
    /* two ends were kept as the largest of -value: back to the value */
    c->fastest.value = -c->fastest.value;
    c->arrival_low.value = -c->arrival_low.value;
    c->lower_95 = zp_robust_clopper_pearson_lower(c->all_kept, n, 0.05);
    if (each && !st) {
        memcpy(each, pw, sizeof *pw * (size_t)n);
    }
    zp_pool_free(w);
    free(u);
    free(pw);
    gsl_rng_free(rng);
    return st;
}

zp_status zp_robust_setup(zp_robust_problem *p, const zp_scene *sc, const zp_model *m,
                          double limit, const zp_schedule *shape, const zp_sim_opts *so,
                          const zp_sim_opts *search, zp_sim_opts *fast) {
    memset(p, 0, sizeof *p);
    p->ob = (zp_objective){.m = m, .limit = limit, .t_max = so->t_max, .shape = shape,
                           .slowest = sc->objective_slowest};
    zp_limits_from_scene(sc, &p->ob.lim);
    *fast = *search;
    fast->peaks = zp_limits_need_peaks(&p->ob.lim);
    zp_box_from_scene(sc, m, &p->box);
    zp_box_widen(&p->box, sc->safety_factor, &p->hold);
    p->robust = sc->robust && p->box.d > 0;
    if (p->robust && zp_scen_set_build(&p->set, &p->hold, m, sc->robust_samples, sc->seed)) {
        return ZP_ERR_NOMEM;
    }
    p->ob.set = p->robust ? &p->set : NULL;
    return ZP_OK;
}

/* rank 0's word to the other ranks after its search: verify this schedule, or go home */
typedef struct answer {
    int verify;
    double force[ZP_SCHED_MAX_PARAMS];
} answer;

void zp_robust_release(const zp_spread *sp) {
    answer a = {0};
    if (zp_spread_active(sp)) {
        sp->bcast(sp->user, &a, sizeof a);
    }
}

/* rank 0's answer on every rank: *verify and res->force as rank 0 has them; -1: not sent */
static int share_answer(const zp_spread *sp, int *verify, zp_search_result *res) {
    answer a = {.verify = *verify};
    memcpy(a.force, res->force, sizeof a.force);
    if (sp->bcast(sp->user, &a, sizeof a)) {
        return -1;
    }
    memcpy(res->force, a.force, sizeof a.force);
    *verify = a.verify;
    return 0;
}

zp_status zp_robust_solve(zp_robust_problem *p, const zp_scene *sc, const zp_sim_opts *fast,
                          const double *lo, const double *hi,
                          const zp_search_opts *o, zp_search_result *res, char *err,
                          size_t errlen) {
    const zp_spread *sp = zp_spread_active(p->spread) ? p->spread : NULL;
    zp_status st = ZP_OK;
    if (!sp || sp->rank == 0) {
        st = zp_robust_search(&p->ob, &p->hold, fast, lo, hi, o, p->robust ? ZP_ROBUST_ROUNDS : 1,
                              res, &p->info, err, errlen);
    }
    int verify = !st && p->robust && !res->interrupted;
    if (sp && share_answer(sp, &verify, res)) {
        snprintf(err, errlen, "the MPI ranks could not share the search's answer");
        return ZP_ERR_IO;
    }
    if (!verify) {
        return st;
    }
    /* the fresh scenarios at the search's own integrator made 100x tighter: its error is then
       far below what a margin or a limit can notice, at a fifth of the [solver] rerun's cost
       (the nominal answer itself is verified with [solver], 100x tighter) */
    zp_sim_opts to = zp_estimate_tighter(fast);
    to.output_dt = 0;
    to.track_loads = 0;
    st = zp_robust_verify(&p->ob, &p->box, &to, res->force, sc->verify_samples, sc->seed,
                          o->nthreads, sp, &p->check);
    /* the worst margin is over everything held as well as everything verified (rank 0 alone
       holds the set the search grew) */
    zp_held h;
    if (!st && (!sp || sp->rank == 0) &&
        !(st = zp_held_check(&p->ob, &p->hold, &p->info.worst, &to, res->force, o->nthreads, &h))) {
        p->check.held_margin_deg = h.worst_margin_deg;
        p->check.held_worst = h.worst;
        p->check.worst_margin_deg = fmin(p->check.worst_margin_deg, h.worst_margin_deg);
        /* past the stated box, along the adversary's worst direction */
        p->check.headroom.safety_factor = sc->safety_factor;
        zp_headroom_find(&p->ob, &p->box, &p->hold,
                         isfinite(p->info.worst.cons) ? p->info.worst.u : NULL, &to, res->force,
                         &p->check.headroom);
    }
    if (st) {
        snprintf(err, errlen, "%s",
                 st == ZP_ERR_IO ? "the MPI ranks could not exchange the verification"
                                 : "out of memory verifying the scenarios");
    }
    return st;
}

void zp_robust_problem_free(zp_robust_problem *p) { zp_scen_set_free(&p->set); }
