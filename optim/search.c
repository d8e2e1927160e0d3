/* The search's phases (search.h): rounds of scan and polish until a round no longer improves
   the best or the budget, the time or the caller stops it; every unit of work fixed in advance
   and cut at the budget in its serial order, so a larger budget runs everything a smaller one
   does; the evidence of convergence. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <nlopt.h>
#include <stdlib.h>
#include <string.h>

#include "basins.h"
#include "search_int.h"

#define NSTARTS 4         /* local polishes per round, from distinct good points */
#define POLISH_STEP 0.02  /* largest first polish step, share of the box */
#define BASE_BUDGET 40    /* simulations refining the best constant push */
#define POLISH_BUDGET 150 /* simulations per polish: past this COBYLA only creeps */
#define PROGRESS_DT 0.25  /* s between progress reports */
#define LDS_FIRST 64      /* points of the low-discrepancy sequence in the first round */
#define LDS_MAX 2048      /* ... doubling each round up to this */
#define DIAG_STEP 0.002   /* first step of the constant push's polish, share of the box */
#define MAX_ROUNDS 200 /* a bound for a budget too large to end the search; 10x the default
                          budget is spent long before it on every scene measured */
#define GLOBAL_PER_PARAM 500 /* simulations of an NLopt global phase per parameter */

/* design note: the scan is ours, not an NLopt global algorithm, because its points are known
   in advance and so run in parallel; the NLopt global algorithms are sequential (see
   docs/search.md for how they compare) */
static const zp_search_algo algos[] = {
    {"scan-cobyla",
     "parallel scan (constant pushes, low-discrepancy points, per-section lines), then COBYLA "
     "with the survival constraint from the islands of the map, in rounds (default)",
     ZP_SEARCH_SCAN, NLOPT_LN_COBYLA},
    {"scan-bobyqa", "the same scan, then BOBYQA on the penalised time", ZP_SEARCH_SCAN,
     NLOPT_LN_BOBYQA},
    {"scan-sbplx", "the same scan, then Sbplx on the penalised time", ZP_SEARCH_SCAN,
     NLOPT_LN_SBPLX},
    {"direct-cobyla", "DIRECT-L on the penalised time, then COBYLA", NLOPT_GN_DIRECT_L,
     NLOPT_LN_COBYLA},
    {"crs2-cobyla", "CRS2 with local mutation on the penalised time, then COBYLA", NLOPT_GN_CRS2_LM,
     NLOPT_LN_COBYLA},
    {"isres-cobyla", "ISRES with the survival constraint, then COBYLA", NLOPT_GN_ISRES,
     NLOPT_LN_COBYLA},
    {"mlsl-cobyla", "MLSL (low-discrepancy starts, BOBYQA) on the penalised time, then COBYLA",
     NLOPT_G_MLSL_LDS, NLOPT_LN_COBYLA},
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

long zp_search_default_budget(int n) {
    return ZP_SCENE_EVALS_PER_SECTION * (long)(n > 0 ? n : 1);
}

double zp_search_since(const zp_search *S) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (t.tv_sec - S->t0.tv_sec) + 1e-9 * (t.tv_nsec - S->t0.tv_nsec);
}

int zp_search_stopped(const zp_search *S) {
    return (S->o->stop && *S->o->stop) ||
           (S->o->max_time > 0 && zp_search_since(S) > S->o->max_time);
}

int zp_search_halted(const zp_search *S) {
    return S->exhausted || S->spent >= S->o->max_evals || zp_search_stopped(S);
}

int zp_search_ahead(const zp_eval *a, const double *fa, const zp_eval *b, const double *fb, int n) {
    if (zp_objective_better(a, b)) {
        return 1;
    }
    if (zp_objective_better(b, a)) {
        return 0;
    }
    for (int k = 0; k < n; k++) {
        if (fa[k] != fb[k]) {
            return fa[k] < fb[k];
        }
    }
    return 0;
}

void zp_search_report(zp_search *S, int improved) {
    zp_search_result *res = S->res;
    double now = zp_search_since(S);
    if (!S->o->progress || (!improved && now - S->last_report < PROGRESS_DT)) {
        return;
    }
    S->last_report = now;
    zp_search_progress p = {S->phase, S->round,     res->evals, S->o->max_evals, now,
                            res->found, res->best.time, res->force, S->o->restart};
    S->o->progress(S->o->user, &p, improved);
}

void zp_search_eval(zp_search *S, zp_sim *s, zp_result *r, const double *f, zp_eval *e) {
    zp_pool_objective_eval(S->pool, S->ob, s, r, f, e);
#pragma omp critical
    {
        zp_search_result *res = S->res;
        res->evals++;
        res->nfeasible += zp_objective_feasible(e);
        res->nfailed += e->failed;
        int improved = res->evals == 1 || zp_search_ahead(e, f, &res->best, res->force, S->n);
        if (improved) {
            res->best = *e;
            memcpy(res->force, f, sizeof *f * S->n);
            res->found = zp_objective_feasible(e);
        }
        zp_search_report(S, improved && res->found);
    }
}

void zp_search_record(zp_search *S, long at, const zp_eval *e) {
    zp_search_result *res = S->res;
    if (zp_objective_feasible(e) && e->time < S->running && res->nhist < ZP_SEARCH_HIST) {
        S->running = e->time;
        res->hist[res->nhist++] = (zp_search_hist){at, e->time};
    }
}

/* a and b differ by more than ZP_DISTINCT of the box in some parameter */
static int distinct(const zp_search *S, const double *a, const double *b) {
    for (int k = 0; k < S->n; k++) {
        if (fabs(a[k] - b[k]) > ZP_DISTINCT * (S->hi[k] - S->lo[k])) {
            return 1;
        }
    }
    return 0;
}

typedef struct ranked {
    const zp_eval *e;
    const double *f;
    int n, i;
} ranked;

static int by_rank(const void *pa, const void *pb) {
    const ranked *a = pa, *b = pb;
    if (zp_search_ahead(a->e, a->f, b->e, b->f, a->n)) {
        return -1;
    }
    if (zp_search_ahead(b->e, b->f, a->e, a->f, a->n)) {
        return 1;
    }
    return (a->i > b->i) - (a->i < b->i);
}

/* fresh for a polish: distinct from every start and end of the polishes run so far */
static int fresh(const zp_search *S, const double *f) {
    for (int j = 0; j < S->npol; j++) {
        if (!distinct(S, f, S->pol[j].start) || !distinct(S, f, S->pol[j].end)) {
            return 0;
        }
    }
    return 1;
}

/* f may start a polish: fresh and distinct from the n starts chosen in idx */
static int ok_start(const zp_search *S, const double *f, const int *idx, int n) {
    int ok = fresh(S, f);
    for (int j = 0; j < n && ok; j++) {
        ok = distinct(S, f, zp_archive_f(S, idx[j]));
    }
    return ok;
}

/* after the n chosen in idx, archive points up to nmax, best first, each an ok_start */
static int pick_starts(zp_search *S, int *idx, int n, int nmax) {
    ranked *r = malloc(sizeof *r * (S->a.n ? S->a.n : 1));
    if (!r) {
        return n;
    }
    for (int i = 0; i < S->a.n; i++) {
        r[i] = (ranked){&S->a.e[i], zp_archive_f(S, i), S->n, i};
    }
    qsort(r, S->a.n, sizeof *r, by_rank);
    for (int i = 0; i < S->a.n && n < nmax; i++) {
        if (ok_start(S, r[i].f, idx, n)) {
            idx[n++] = r[i].i;
        }
    }
    free(r);
    return n;
}

/* 1 when a polish started or ended in island is of the map m */
static int polished(const zp_search *S, const zp_islands *m, int is) {
    for (int j = 0; j < m->nnear; j++) {
        if (m->of[j] == is && !fresh(S, zp_archive_f(S, m->pt[j]))) {
            return 1;
        }
    }
    return 0;
}

/* design note: the starts come from the map's islands, not from the best points alone: the best
   points of a thin survivable set crowd into one island, and polishes from them all reach the
   same optimum while faster islands nearby are never visited. Half the slots go to the best
   islands no polish has visited, the rest to the best islands again (a thin island's optimum is
   often out of one polish's reach), each island at most once a round; then the best fresh
   points anywhere (the whole map when nothing nearly survives). */
static int island_starts(zp_search *S, int *idx, int nmax) {
    zp_islands m;
    int n = 0;
    if (zp_islands_map(S, &m)) {
        return pick_starts(S, idx, 0, nmax);
    }
    char *used = calloc(m.n ? m.n : 1, 1);
    for (int pass = 0; used && pass < 2; pass++) {
        int quota = pass == 0 ? nmax / 2 : nmax;
        for (int is = 0; is < m.n && n < quota; is++) {
            if (used[is] || (pass == 0 && polished(S, &m, is))) {
                continue;
            }
            for (int j = 0; j < m.nnear; j++) {
                if (m.of[j] == is && ok_start(S, zp_archive_f(S, m.pt[j]), idx, n)) {
                    idx[n++] = m.pt[j];
                    used[is] = 1;
                    break;
                }
            }
        }
    }
    free(used);
    zp_islands_free(&m);
    return pick_starts(S, idx, n, nmax);
}

/* the baseline: the best survivable constant push among archive points [n0, a.n), and the
   best constant push by the total order (the start of its one-variable polish) */
static void base_scan(zp_search *S, int n0) {
    zp_search_result *res = S->res;
    for (int i = n0; i < S->a.n; i++) {
        if (S->bdiag < 0 || zp_search_ahead(&S->a.e[i], zp_archive_f(S, i), &S->a.e[S->bdiag],
                                            zp_archive_f(S, S->bdiag), S->n)) {
            S->bdiag = i;
        }
        const zp_eval *e = &S->a.e[i];
        if (zp_objective_feasible(e) && (!res->base_found || e->time < res->base.time)) {
            res->base_found = 1;
            res->base = *e;
            res->base_force = zp_archive_f(S, i)[0];
            memcpy(res->base_p, zp_archive_f(S, i), sizeof *res->base_p * S->n);
        }
    }
}

/* the scan of round r: constant pushes, the sequence (or an NLopt global phase), lines */
static zp_status scan_round(zp_search *S, int r, char *err, size_t errlen) {
    const zp_search_algo *alg = &algos[S->o->algo];
    S->phase = "scan";
    int hard = -1;
    if (r == 0) {
        hard = zp_scan_diag(S);
        base_scan(S, 0);
    }
    if (r == 0 && alg->global >= 0) {
        zp_status st = zp_polish_global(S, alg->global, GLOBAL_PER_PARAM * (long)S->n, err, errlen);
        if (st) {
            return st;
        }
    } else {
        zp_scan_lds(S, r == 0 ? LDS_FIRST
                              : (LDS_FIRST << (r - 1) < LDS_MAX ? LDS_FIRST << (r - 1) : LDS_MAX));
    }
    /* lines through the best and, first, through the hardest push: times fall as the pushes
       grow, so the fastest schedules lie towards that corner */
    if (!zp_search_halted(S) && S->res->evals > 0) {
        zp_eval be = S->res->best;
        double bf[ZP_SCHED_MAX_PARAMS];
        memcpy(bf, S->res->force, sizeof *bf * S->n);
        zp_scan_lines(S, bf, &be);
    }
    if (hard >= 0 && !zp_search_halted(S)) {
        zp_scan_lines(S, zp_archive_f(S, hard), &S->a.e[hard]);
    }
    return ZP_OK;
}

/* the polish of a round: NSTARTS fresh starts and, once, the best constant push */
static zp_status polish_round(zp_search *S, char *err, size_t errlen) {
    S->phase = "polish";
    if (S->npol + NSTARTS > S->polcap) {
        int cap = 2 * (S->npol + NSTARTS);
        zp_polish_rec *p = realloc(S->pol, sizeof *p * cap);
        if (!p) {
            snprintf(err, errlen, "out of memory for the polish");
            return ZP_ERR_NOMEM;
        }
        S->pol = p;
        S->polcap = cap;
    }
    int idx[NSTARTS], nstart = island_starts(S, idx, NSTARTS);
    zp_polish_job jobs[NSTARTS + 1];
    zp_polish_rec base_rec;
    double diag_step = DIAG_STEP;
    int nj = 0, bdiag = S->bdiag != S->diag_from ? S->bdiag : -1;
    if (bdiag >= 0) {
        S->diag_from = bdiag;
        jobs[nj++] = (zp_polish_job){zp_archive_f(S, bdiag), &diag_step, 1, BASE_BUDGET, &base_rec};
    }
    for (int i = 0; i < nstart; i++) {
        jobs[nj++] = (zp_polish_job){zp_archive_f(S, idx[i]), S->step, 0, POLISH_BUDGET,
                                     &S->pol[S->npol + i]};
    }
    zp_status st = zp_polish_batch(S, algos[S->o->algo].local, jobs, nj, err, errlen);
    /* the ends join the map: the islands they reached count as visited */
    for (int i = bdiag >= 0 ? -1 : 0; i < nstart; i++) {
        zp_polish_rec *p = i < 0 ? &base_rec : &S->pol[S->npol + i];
        if (p->n > 0) {
            p->at = zp_archive_add(S, p->end, &p->e);
        }
    }
    S->npol += nstart;
    zp_search_result *res = S->res;
    if (bdiag >= 0 && base_rec.n > 0 && zp_objective_feasible(&base_rec.e) &&
        (!res->base_found || base_rec.e.time < res->base.time)) {
        res->base_found = 1;
        res->base = base_rec.e;
        res->base_force = base_rec.end[0];
        memcpy(res->base_p, base_rec.end, sizeof *res->base_p * S->n);
    }
    return st;
}

/* the basin of polish j's end: its island in the map (island_of: per archive index, -1 outside
   it), else the first earlier polish whose end is not distinct from it and equally survivable,
   numbered past the islands */
static int basin_of(const zp_search *S, const int *island_of, int nisl, int j) {
    const zp_polish_rec *p = &S->pol[j];
    if (island_of && p->at >= 0 && island_of[p->at] >= 0) {
        return island_of[p->at];
    }
    int feas = zp_objective_feasible(&p->e);
    for (int i = 0; i < j; i++) {
        const zp_polish_rec *q = &S->pol[i];
        if (q->n > 0 && zp_objective_feasible(&q->e) == feas && !distinct(S, p->end, q->end) &&
            !(island_of && q->at >= 0 && island_of[q->at] >= 0)) {
            return nisl + i;
        }
    }
    return nisl + j;
}

/* design note: the minima counted for Boender and Rinnooy Kan's estimate are the islands the
   polishes ended in, not their distinct end points: COBYLA stops anywhere along the margin's
   boundary of a wide island (on multi6 56 polishes ended at 48 points of one island), and each
   such point counted as a minimum would make any budget look too small */
/* the evidence: distinct survivable polish ends, those that reached the best, the basins of
   every polish and what they leave unseen */
static void evidence(zp_search *S) {
    zp_search_result *res = S->res;
    res->nstarts = S->npol;
    res->nbasins = res->nreached = res->nminima = 0;
    zp_islands m;
    int *island_of = NULL, nisl = 0, nran = 0;
    if (!zp_islands_map(S, &m)) {
        island_of = malloc(sizeof *island_of * (S->a.n ? S->a.n : 1));
        for (int i = 0; island_of && i < S->a.n; i++) {
            island_of[i] = -1;
        }
        for (int j = 0; island_of && j < m.nnear; j++) {
            island_of[m.pt[j]] = m.of[j];
        }
        nisl = m.n;
        zp_islands_free(&m);
    }
    int *basin = malloc(sizeof *basin * (S->npol ? S->npol : 1));
    for (int j = 0; j < S->npol; j++) {
        const zp_polish_rec *p = &S->pol[j];
        if (p->n == 0) {
            continue;
        }
        nran++;
        int b = basin_of(S, island_of, nisl, j), isnew = 1;
        for (int i = 0; basin && i < j && isnew; i++) {
            isnew = S->pol[i].n == 0 || basin[i] != b;
        }
        if (basin) {
            basin[j] = b;
        }
        res->nminima += isnew;
        if (!zp_objective_feasible(&p->e)) {
            continue;
        }
        int fresh_end = 1;
        for (int i = 0; i < j && fresh_end; i++) {
            fresh_end = S->pol[i].n == 0 || !zp_objective_feasible(&S->pol[i].e) ||
                        distinct(S, p->end, S->pol[i].end);
        }
        res->nbasins += fresh_end;
        res->nreached += res->found && p->e.time <= res->best.time * (1 + ZP_SEARCH_REACH);
    }
    free(basin);
    free(island_of);
    res->unseen = zp_basins_unseen(nran, res->nminima);
    /* the budget that would help when the search stops short: the polishes the estimate
       still needs (at least one round), at the rate of the costliest round so far */
    int need = NSTARTS;
    if (!(res->unseen < ZP_SEARCH_UNSEEN)) {
        need = zp_basins_searches_needed(res->nminima, ZP_SEARCH_UNSEEN) - nran;
        need = need > NSTARTS ? need : NSTARTS;
    }
    long per = S->round_cost > 0 ? S->round_cost : S->spent;
    res->help_evals = S->spent + (long)((need + NSTARTS - 1) / NSTARTS) * per;
}

/* the islands of the final map, the polish ends in it: how many, how many polished, the best */
static void islands_seen(zp_search *S) {
    zp_search_result *res = S->res;
    zp_islands m;
    if (zp_islands_map(S, &m)) {
        return;
    }
    res->nislands = m.n;
    for (int is = 0; is < m.n; is++) {
        res->npolished += polished(S, &m, is);
        const zp_island *il = &m.isl[is];
        if (res->nshown < ZP_SEARCH_ISLANDS && zp_objective_feasible(&S->a.e[il->head])) {
            int k = res->nshown++;
            res->island_time[k] = S->a.e[il->head].time;
            memcpy(res->island_force[k], zp_archive_f(S, il->head), sizeof(double) * S->n);
            res->island_pts[k] = il->nfeas;
        }
    }
    zp_islands_free(&m);
}

/* the distinct survivable polish ends, best first, for a warm restart */
static void keep_ends(zp_search *S) {
    zp_search_result *res = S->res;
    res->nends = 0;
    int *used = calloc(S->npol ? S->npol : 1, sizeof *used);
    while (used && res->nends < ZP_SEARCH_ENDS) {
        int b = -1;
        for (int j = 0; j < S->npol; j++) {
            const zp_polish_rec *p = &S->pol[j];
            int ok = !used[j] && p->n > 0 && zp_objective_feasible(&p->e);
            for (int i = 0; ok && i < res->nends; i++) {
                ok = distinct(S, p->end, res->ends[i]);
            }
            used[j] |= !ok;
            if (ok &&
                (b < 0 || zp_search_ahead(&p->e, p->end, &S->pol[b].e, S->pol[b].end, S->n))) {
                b = j;
            }
        }
        if (b < 0) {
            break;
        }
        used[b] = 1;
        memcpy(res->ends[res->nends], S->pol[b].end, sizeof *S->pol[b].end * S->n);
        res->ends_time[res->nends++] = S->pol[b].e.time;
    }
    free(used);
}

static double best_time(const zp_search_result *res) {
    return res->found ? res->best.time : INFINITY;
}

static zp_status rounds(zp_search *S, char *err, size_t errlen) {
    zp_search_result *res = S->res;
    for (int k = 0; k < S->n; k++) {
        S->step[k] = POLISH_STEP * (S->hi[k] - S->lo[k]);
    }
    for (int r = 0; r < MAX_ROUNDS; r++) {
        S->round = r;
        long spent0 = S->spent;
        double before = best_time(res);
        zp_status st = scan_round(S, r, err, errlen);
        if (st == ZP_OK && !zp_search_halted(S)) {
            st = polish_round(S, err, errlen);
        }
        if (st || zp_search_halted(S)) {
            return st;
        }
        res->nrounds = r + 1;
        S->round_cost = S->spent - spent0 > S->round_cost ? S->spent - spent0 : S->round_cost;
        double after = best_time(res);
        res->last_gain = isfinite(after) ? (isfinite(before) ? (before - after) / after : 1) : 0;
        /* converged: the round found nothing better, two polishes or more reached the best
           and they leave too few basins unseen for another round to be likely to find one */
        evidence(S);
        res->converged = r >= 1 && res->found && res->last_gain < ZP_SEARCH_CONV &&
                         res->unseen < ZP_SEARCH_UNSEEN && res->nreached >= 2;
        if (res->converged && !S->o->full_budget) {
            return ZP_OK;
        }
    }
    return ZP_OK;
}

static zp_status start(zp_search *S, const zp_sim_opts *so, char *err, size_t errlen) {
    S->pool = zp_pool_create(S->ob->m, so, S->o->nthreads);
    S->q =
        S->n <= 40 ? gsl_qrng_alloc(gsl_qrng_sobol, S->n) : gsl_qrng_alloc(gsl_qrng_halton, S->n);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    if (!S->pool || !S->q || !g || (S->ob->set && zp_pool_help(S->pool, S->ob->m, so))) {
        gsl_rng_free(g);
        snprintf(err, errlen, "out of memory creating the search's workspaces");
        return ZP_ERR_NOMEM;
    }
    /* the seed shifts the sequence (a Cranley-Patterson rotation): same seed, same points */
    gsl_rng_set(g, S->o->seed);
    for (int k = 0; k < S->n; k++) {
        S->shift[k] = gsl_rng_uniform(g);
    }
    gsl_rng_free(g);
    return ZP_OK;
}

/* a search's state over res, its clock started */
static zp_search begin(const zp_objective *ob, const double *lo, const double *hi,
                       const zp_search_opts *o, zp_search_result *res) {
    memset(res, 0, sizeof *res);
    /* the parameters: the schedule's, as its kind counts them */
    zp_search S = {.ob = ob,
                   .o = o,
                   .n = zp_objective_nparams(ob),
                   .lo = lo,
                   .hi = hi,
                   .res = res,
                   .running = INFINITY,
                   .bdiag = -1,
                   .diag_from = -1,
                   .phase = "scan"};
    clock_gettime(CLOCK_MONOTONIC, &S.t0);
    return S;
}

/* how the search ended, and its state freed */
static void end(zp_search *S) {
    zp_search_result *res = S->res;
    const zp_search_opts *o = S->o;
    res->nthreads = S->pool ? zp_pool_threads(S->pool) : 0;
    res->interrupted = o->stop && *o->stop;
    res->timed_out =
        !res->interrupted && !res->converged && o->max_time > 0 && zp_search_since(S) > o->max_time;
    res->budget_out =
        !res->converged && !res->interrupted && !res->timed_out && zp_search_halted(S);
    res->wall_s = zp_search_since(S);
    zp_pool_free(S->pool);
    if (S->q) {
        gsl_qrng_free(S->q);
    }
    free(S->a.f);
    free(S->a.e);
    free(S->pol);
    free(S->lined);
    free(S->lined_k);
}

zp_status zp_search_run(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                        const double *hi, const zp_search_opts *o, zp_search_result *res, char *err,
                        size_t errlen) {
    zp_search S = begin(ob, lo, hi, o, res);
    zp_status st = start(&S, so, err, errlen);
    if (st == ZP_OK) {
        st = rounds(&S, err, errlen);
        evidence(&S);
        islands_seen(&S);
        keep_ends(&S);
    }
    end(&S);
    return st;
}

/* design note: after the adversary adds a scenario the answer breaks by a hair, so the best of
   the grown set lies next to it (or next to another end nearly as fast): short polishes from
   there, with small first steps, find it at a fraction of a full search's cost */
#define WARM_BUDGET 60  /* simulations per warm polish */
#define WARM_STEP 0.002 /* its first step, share of the box */

#define WARM_STARTS (NSTARTS + ZP_SEARCH_ISLANDS)

/* x may start a warm polish: distinct from the n starts before it */
static int warm_new(const zp_search *S, const double *x, const double **xs, int n) {
    for (int i = 0; i < n; i++) {
        if (!distinct(S, x, xs[i])) {
            return 0;
        }
    }
    return 1;
}

/* the warm polishes' starts: the answer, the good ends distinct from it, then the fastest
   point of each of the best islands of the map (the grown set may break the answer's island
   where a slower one still holds) */
static int warm_starts(const zp_search *S, const zp_search_result *prev, const double **x) {
    int n = 0;
    x[n++] = prev->force;
    for (int i = 0; i < prev->nends && n < NSTARTS; i++) {
        if (warm_new(S, prev->ends[i], x, n) &&
            prev->ends_time[i] <= prev->best.time * (1 + ZP_SEARCH_WARM_REACH)) {
            x[n++] = prev->ends[i];
        }
    }
    for (int i = 0; i < prev->nshown && n < WARM_STARTS; i++) {
        if (warm_new(S, prev->island_force[i], x, n)) {
            x[n++] = prev->island_force[i];
        }
    }
    return n;
}

/* the previous best constant push kept when it survives the grown set, else polished again */
static int warm_base(zp_search *S, const zp_search_result *prev, zp_polish_job *job, double *step) {
    zp_search_result *res = S->res;
    if (!prev->base_found) {
        return 0;
    }
    zp_eval e;
    zp_pool_eval(S->pool, S->ob, 1, prev->base_p, &e, NULL, NULL);
    S->spent++; /* counted in res->evals after the polishes (the first counted sets the best) */
    if (zp_objective_feasible(&e)) {
        res->base_found = 1;
        res->base = e;
        res->base_force = prev->base_force;
        memcpy(res->base_p, prev->base_p, sizeof *res->base_p * S->n);
        return 0;
    }
    *step = DIAG_STEP;
    *job = (zp_polish_job){prev->base_p, step, 1, BASE_BUDGET, NULL};
    return 1;
}

static zp_status warm(zp_search *S, const zp_search_result *prev, char *err, size_t errlen) {
    zp_polish_rec rec[WARM_STARTS + 1];
    zp_polish_job jobs[WARM_STARTS + 1];
    double step[ZP_SCHED_MAX_PARAMS], diag_step;
    for (int k = 0; k < S->n; k++) {
        step[k] = WARM_STEP * (S->hi[k] - S->lo[k]);
    }
    S->phase = "polish";
    int nj = warm_base(S, prev, &jobs[0], &diag_step);
    const double *x[WARM_STARTS];
    int nstart = warm_starts(S, prev, x);
    for (int i = 0; i < nstart; i++) {
        jobs[nj++] = (zp_polish_job){x[i], step, 0, WARM_BUDGET, NULL};
    }
    for (int i = 0; i < nj; i++) {
        jobs[i].out = &rec[i];
    }
    zp_status st = zp_polish_batch(S, algos[S->o->algo].local, jobs, nj, err, errlen);
    int base = nj > nstart;
    S->res->evals += prev->base_found;
    if (base && rec[0].n > 0 && zp_objective_feasible(&rec[0].e)) {
        S->res->base_found = 1;
        S->res->base = rec[0].e;
        S->res->base_force = rec[0].end[0];
        memcpy(S->res->base_p, rec[0].end, sizeof *S->res->base_p * S->n);
    }
    S->pol = malloc(sizeof *S->pol * nstart);
    if (S->pol) {
        memcpy(S->pol, rec + base, sizeof *S->pol * nstart);
        S->npol = nstart;
        keep_ends(S);
    }
    return st;
}

zp_status zp_search_warm(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                         const double *hi, const zp_search_opts *o, zp_search_result *res,
                         char *err, size_t errlen) {
    zp_search_result *prev = malloc(sizeof *prev);
    if (!prev) {
        snprintf(err, errlen, "out of memory for the warm restart");
        return ZP_ERR_NOMEM;
    }
    *prev = *res;
    zp_search S = begin(ob, lo, hi, o, res);
    zp_status st = start(&S, so, err, errlen);
    if (st == ZP_OK) {
        st = warm(&S, prev, err, errlen);
    }
    /* the evidence of convergence stays the full search's: its polishes, what they reached */
    res->nrounds = prev->nrounds;
    res->nbasins = prev->nbasins;
    res->nreached = prev->nreached;
    res->converged = prev->converged;
    res->last_gain = prev->last_gain;
    res->nminima = prev->nminima;
    res->unseen = prev->unseen;
    res->help_evals = prev->help_evals;
    res->nislands = prev->nislands;
    res->npolished = prev->npolished;
    res->nshown = prev->nshown;
    memcpy(res->island_time, prev->island_time, sizeof res->island_time);
    memcpy(res->island_force, prev->island_force, sizeof res->island_force);
    memcpy(res->island_pts, prev->island_pts, sizeof res->island_pts);
    res->nhist = prev->nhist;
    memcpy(res->hist, prev->hist, sizeof *res->hist * prev->nhist);
    end(&S);
    res->budget_out = prev->budget_out;
    res->timed_out = prev->timed_out;
    res->nstarts = prev->nstarts;
    res->evals += prev->evals;
    res->nfeasible += prev->nfeasible;
    res->nfailed += prev->nfailed;
    res->wall_s += prev->wall_s;
    free(prev);
    return st;
}
