/* The search's rounds (search.h): each the constant pushes (first round), the global
   strategy's points and lines through the best, then local polishes from the islands of the
   map, until a round no longer improves the best or the budget, the time or the caller stops
   it; every unit of work fixed in advance and cut at the budget in its serial order, so a
   larger budget runs everything a smaller one does. The --algorithm table. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "polishes.h"
#include "scan.h"
#include "search.h"
#include "strategy.h"

#define POLISH_STEP 0.02  /* largest first polish step, share of the box */
#define POLISH_BUDGET 150 /* simulations per polish: past this COBYLA only creeps */
#define MAX_ROUNDS                                                                                 \
    200 /* a bound for a budget too large to end the search; 10x the default                       \
           budget is spent long before it on every scene measured */

static const zp_search_algo algos[] = {
#define ZP_ALGORITHM(name, doc, global, local) {name, doc, &global, &local},
#include "strategies.def"
#undef ZP_ALGORITHM
};
#define NALGO ((int)(sizeof algos / sizeof algos[0]))

int zp_search_algo_count(void) {
    return NALGO;
}
const zp_search_algo *zp_search_algo_get(int i) {
    return i >= 0 && i < NALGO ? &algos[i] : NULL;
}
int zp_search_algo_find(const char *name) {
    for (int i = 0; i < NALGO; i++) {
        if (!strcmp(algos[i].name, name)) {
            return i;
        }
    }
    return -1;
}

int zp_search_algo_default(int nsec, int robust) {
    return nsec >= ZP_SEARCH_PORTFOLIO_SECTIONS && !robust ? zp_search_algo_find("portfolio-cobyla")
                                                          : zp_search_algo_find("scan-cobyla");
}

int zp_search_populations_reached(const zp_search_result *res) {
    return res->found && res->npops > 0 && res->pops_best <= res->best.time * (1 + ZP_SEARCH_REACH);
}

long zp_search_default_budget(int n) {
    return ZP_SCENE_EVALS_PER_SECTION * (long)(n > 0 ? n : 1);
}

/* one search over its rounds */
typedef struct rounds {
    zp_search_state S;
    const zp_search_algo *alg;
    void *global; /* owned: the global strategy's state */
    zp_scan scan;
    zp_polishes pol;
    int bdiag;       /* archive index of the best constant push, -1: none yet */
    int diag_from;   /* ... the last one polished, -1: none */
    long round_cost; /* simulations of the costliest completed round */
} rounds;

/* f may start a polish: fresh and distinct from the n starts chosen in idx */
static int ok_start(const rounds *R, const double *f, const int *idx, int n) {
    const zp_search_state *S = &R->S;
    int ok = zp_polishes_fresh(&R->pol, S, f);
    for (int j = 0; j < n && ok; j++) {
        ok = zp_search_state_distinct(S, f, zp_search_state_point(S, idx[j]));
    }
    return ok;
}

/* after the n chosen in idx, archive points up to nmax, best first, each an ok_start */
static int pick_starts(const rounds *R, int *idx, int n, int nmax) {
    const zp_search_state *S = &R->S;
    int *order = malloc(sizeof *order * (S->a.n ? S->a.n : 1));
    for (int i = 0; order && i < S->a.n; i++) {
        order[i] = i;
    }
    if (order && !zp_search_state_rank(S, order, S->a.n)) {
        for (int i = 0; i < S->a.n && n < nmax; i++) {
            if (ok_start(R, zp_search_state_point(S, order[i]), idx, n)) {
                idx[n++] = order[i];
            }
        }
    }
    free(order);
    return n;
}

/* design note: the starts come from the map's islands, not from the best points alone: the best
   points of a thin survivable set crowd into one island, and polishes from them all reach the
   same optimum while faster islands nearby are never visited. Half the slots go to the best
   islands no polish has visited, the rest to the best islands again (a thin island's optimum is
   often out of one polish's reach), each island at most once a round; then the best fresh
   points anywhere (the whole map when nothing nearly survives). */
static int island_starts(const rounds *R, int *idx, int nmax) {
    const zp_search_state *S = &R->S;
    zp_islands m;
    int n = 0;
    if (zp_islands_map(S, &m)) {
        return pick_starts(R, idx, 0, nmax);
    }
    char *used = calloc(m.n ? m.n : 1, 1);
    for (int pass = 0; used && pass < 2; pass++) {
        int quota = pass == 0 ? nmax / 2 : nmax;
        for (int is = 0; is < m.n && n < quota; is++) {
            if (used[is] || (pass == 0 && zp_polishes_visited(&R->pol, S, &m, is))) {
                continue;
            }
            for (int j = 0; j < m.nnear; j++) {
                if (m.of[j] == is && ok_start(R, zp_search_state_point(S, m.pt[j]), idx, n)) {
                    idx[n++] = m.pt[j];
                    used[is] = 1;
                    break;
                }
            }
        }
    }
    free(used);
    zp_islands_free(&m);
    return pick_starts(R, idx, n, nmax);
}

/* the baseline: the best survivable constant push of the archive (the pushes alone so far),
   and the best constant push by the total order (the start of its one-variable polish) */
static void base_scan(rounds *R) {
    zp_search_state *S = &R->S;
    const zp_search_result *res = S->res;
    for (int i = 0; i < S->a.n; i++) {
        const double *f = zp_search_state_point(S, i);
        const zp_eval *e = &S->a.e[i];
        if (R->bdiag < 0 || zp_search_state_ahead(e, f, &S->a.e[R->bdiag],
                                                  zp_search_state_point(S, R->bdiag), S->n)) {
            R->bdiag = i;
        }
        if (zp_objective_feasible(e) && (!res->base_found || e->time < res->base.time)) {
            zp_search_state_base(S, f, e);
        }
    }
}

/* the scan of round r: constant pushes (first round), the global strategy's points, lines */
static zp_status scan_round(rounds *R, int r, char *err, size_t errlen) {
    zp_search_state *S = &R->S;
    S->phase = "scan";
    int hard = -1;
    if (r == 0) {
        hard = zp_scan_diag(S);
        base_scan(R);
    }
    zp_status st = R->alg->global->explore(R->global, S, r, err, errlen);
    if (st) {
        return st;
    }
    /* lines through the best and, first, through the hardest push: times fall as the pushes
       grow, so the fastest schedules lie towards that corner */
    if (!zp_search_state_halted(S) && S->res->evals > 0) {
        zp_eval be = S->res->best;
        double bf[ZP_SCHED_MAX_PARAMS];
        memcpy(bf, S->res->force, sizeof *bf * S->n);
        zp_scan_lines(S, &R->scan, bf, &be);
    }
    if (hard >= 0 && !zp_search_state_halted(S)) {
        zp_scan_lines(S, &R->scan, zp_search_state_point(S, hard), &S->a.e[hard]);
    }
    return ZP_OK;
}

/* the polish of a round: ZP_POLISHES_ROUND fresh starts and, once, the best constant push */
static zp_status polish_round(rounds *R, char *err, size_t errlen) {
    zp_search_state *S = &R->S;
    S->phase = "polish";
    if (zp_polishes_reserve(&R->pol, ZP_POLISHES_ROUND)) {
        snprintf(err, errlen, "out of memory for the polish");
        return ZP_ERR_NOMEM;
    }
    int idx[ZP_POLISHES_ROUND], nstart = island_starts(R, idx, ZP_POLISHES_ROUND);
    zp_leg_job jobs[ZP_POLISHES_ROUND + 1];
    zp_leg_rec base_rec, *rec = R->pol.rec + R->pol.n;
    double diag_step = ZP_POLISHES_PUSH_STEP;
    int nj = 0, bdiag = R->bdiag != R->diag_from ? R->bdiag : -1;
    if (bdiag >= 0) {
        R->diag_from = bdiag;
        jobs[nj++] = (zp_leg_job){.x0 = zp_search_state_point(S, bdiag),
                                  .step = &diag_step,
                                  .diag = 1,
                                  .cap = ZP_POLISHES_PUSH_BUDGET,
                                  .out = &base_rec};
    }
    for (int i = 0; i < nstart; i++) {
        jobs[nj++] = (zp_leg_job){.x0 = zp_search_state_point(S, idx[i]),
                                  .step = R->scan.step,
                                  .cap = POLISH_BUDGET,
                                  .out = &rec[i]};
    }
    const zp_strategy *local = R->alg->local;
    zp_status st = zp_leg_batch(S, local->polish, local, jobs, nj, err, errlen);
    /* the ends join the map: the islands they reached count as visited */
    for (int i = bdiag >= 0 ? -1 : 0; i < nstart; i++) {
        zp_leg_rec *p = i < 0 ? &base_rec : &rec[i];
        if (p->n > 0) {
            p->at = zp_search_state_add(S, p->end, &p->e);
        }
    }
    R->pol.n += nstart;
    const zp_search_result *res = S->res;
    if (bdiag >= 0 && base_rec.n > 0 && zp_objective_feasible(&base_rec.e) &&
        (!res->base_found || base_rec.e.time < res->base.time)) {
        zp_search_state_base(S, base_rec.end, &base_rec.e);
    }
    return st;
}

static double best_time(const zp_search_result *res) {
    return res->found ? res->best.time : INFINITY;
}

/* round r done: its cost, its gain and, from the evidence, whether the search converged */
static void close_round(rounds *R, int r, long spent0, double before) {
    zp_search_state *S = &R->S;
    zp_search_result *res = S->res;
    res->nrounds = r + 1;
    R->round_cost = S->spent - spent0 > R->round_cost ? S->spent - spent0 : R->round_cost;
    double after = best_time(res);
    res->last_gain = isfinite(after) ? (isfinite(before) ? (before - after) / after : 1) : 0;
    /* converged: the round found nothing better, two polishes or more reached the best
       and they leave too few basins unseen for another round to be likely to find one; and
       the populations, if the strategy evolves any, reached it too: the estimate counts the
       polishes, not the populations' search, which may still be closing in on a faster
       island (m5_3link, seed 3: polishes agreed on 7.4659 s while the populations were at
       7.5446 s; 7.3659 s exists) */
    zp_polishes_evidence(&R->pol, S, R->round_cost);
    res->converged = r >= 1 && res->found && res->last_gain < ZP_SEARCH_CONV &&
                     res->unseen < ZP_SEARCH_UNSEEN && res->nreached >= 2 &&
                     (res->npops == 0 || zp_search_populations_reached(res));
}

static zp_status run_rounds(rounds *R, char *err, size_t errlen) {
    zp_search_state *S = &R->S;
    for (int r = 0; r < MAX_ROUNDS; r++) {
        S->round = r;
        long spent0 = S->spent;
        double before = best_time(S->res);
        zp_status st = scan_round(R, r, err, errlen);
        if (st == ZP_OK && !zp_search_state_halted(S)) {
            st = polish_round(R, err, errlen);
        }
        if (st || zp_search_state_halted(S)) {
            return st;
        }
        close_round(R, r, spent0, before);
        if (S->res->converged && !S->o->full_budget) {
            return ZP_OK;
        }
    }
    return ZP_OK;
}

zp_status zp_search_run(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                        const double *hi, const zp_search_opts *o, zp_search_result *res, char *err,
                        size_t errlen) {
    rounds R = {.alg = zp_search_algo_get(o->algo), .bdiag = -1, .diag_from = -1};
    zp_search_state *S = &R.S;
    zp_search_state_begin(S, ob, lo, hi, o, res);
    zp_scan_init(&R.scan, S, POLISH_STEP);
    zp_status st = zp_search_state_start(S, so, err, errlen);
    const zp_strategy *global = R.alg->global;
    if (st == ZP_OK && !(R.global = global->create(global, S))) {
        snprintf(err, errlen, "out of memory creating the search's workspaces");
        st = ZP_ERR_NOMEM;
    }
    if (st == ZP_OK) {
        st = run_rounds(&R, err, errlen);
        zp_polishes_evidence(&R.pol, S, R.round_cost);
        zp_polishes_islands(&R.pol, S);
        zp_polishes_ends(&R.pol, S);
    }
    if (R.global) {
        global->free(R.global);
    }
    zp_scan_free(&R.scan);
    zp_polishes_free(&R.pol);
    zp_search_state_end(S);
    return st;
}
