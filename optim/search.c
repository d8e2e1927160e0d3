/* NLopt setup for the search (issue 4 items 2, 3, 6): bounds, a global phase, a local polish
   from several starts, the budget of simulations, the seed, parallel evaluation with one
   workspace per thread, and stopping on request with the best so far kept. */
#include "search.h"

#include <math.h>
#include <nlopt.h>
#include <omp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NSTARTS 4         /* local polishes from distinct good points */
#define DISTINCT 0.02     /* starts differ by this share of the box in some force */
#define XTOL 1e-3         /* N: the polish stops when the forces settle to this */
#define FTOL 1e-6         /* s: ... or the finish time to this */
#define POLISH_STEP 0.02  /* largest first polish step, share of the box */
#define STEP_SHARE 0.25   /* first polish step, share of the survivable width along a line */
#define BASE_BUDGET 40    /* simulations refining the best constant push */
#define POLISH_BUDGET 150 /* simulations per polish: past this COBYLA only creeps */
#define PROGRESS_DT 0.25  /* s between progress reports */
#define MAX_IMP 64        /* improvements recorded per run, for the history */
#define ZOOM 2            /* local minima of a line refined */
#define ZOOM_PTS 12       /* points of each refinement */

/* design note: the scan is ours, not an NLopt global algorithm, because its points are known
   in advance and so run in parallel; the NLopt global algorithms are sequential (see
   docs/search.md for how they compare) */
static const zp_search_algo algos[] = {
    {"scan-cobyla",
     "parallel scan (constant pushes, Latin hypercube, per-section lines), then COBYLA with "
     "the survival constraint from the best starts (default)",
     -1, NLOPT_LN_COBYLA},
    {"scan-bobyqa", "the same scan, then BOBYQA on the penalised time", -1, NLOPT_LN_BOBYQA},
    {"scan-sbplx", "the same scan, then Sbplx on the penalised time", -1, NLOPT_LN_SBPLX},
    {"direct-cobyla", "DIRECT-L on the penalised time, then COBYLA", NLOPT_GN_DIRECT_L,
     NLOPT_LN_COBYLA},
    {"crs2-cobyla", "CRS2 with local mutation on the penalised time, then COBYLA",
     NLOPT_GN_CRS2_LM, NLOPT_LN_COBYLA},
    {"isres-cobyla", "ISRES with the survival constraint, then COBYLA", NLOPT_GN_ISRES,
     NLOPT_LN_COBYLA},
    {"mlsl-cobyla", "MLSL (low-discrepancy starts, BOBYQA) on the penalised time, then COBYLA",
     NLOPT_G_MLSL_LDS, NLOPT_LN_COBYLA},
};
#define NALGO ((int)(sizeof algos / sizeof algos[0]))

int zp_search_algo_count(void) { return NALGO; }
const zp_search_algo *zp_search_algo_get(int i) { return i >= 0 && i < NALGO ? &algos[i] : NULL; }
int zp_search_algo_find(const char *name) {
    for (int i = 0; i < NALGO; i++) {
        if (!strcmp(algos[i].name, name)) {
            return i;
        }
    }
    return -1;
}

typedef struct worker {
    zp_sim *sim;  /* owned */
    zp_result *r; /* owned: large, so kept off the stack */
} worker;

/* evaluated points the starts are chosen from */
typedef struct pool {
    int n, cap;
    double *f; /* owned, N, cap x nsec */
    zp_eval *e; /* owned, cap */
} pool;

typedef struct search {
    const zp_objective *ob;
    const zp_search_opts *o;
    int nsec;
    double lo, hi; /* N */
    worker *w;     /* owned, nw */
    int nw;
    pool p;
    zp_search_result *res;
    double running;        /* s, the best time in the serial history */
    double step[ZP_MAX_SECTIONS]; /* N, first polish step per force: the survivable width */
    struct timespec t0;
    double last_report;    /* s */
} search;

static double since(const struct timespec *t0) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (t.tv_sec - t0->tv_sec) + 1e-9 * (t.tv_nsec - t0->tv_nsec);
}

static int stopped(const search *S) { return S->o->stop && *S->o->stop; }

/* a total order (feasible, score, then the forces), so the best does not depend on which
   thread finished first */
static int ahead(const zp_eval *a, const double *fa, const zp_eval *b, const double *fb, int n) {
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

static void report(search *S, int improved) {
    zp_search_result *res = S->res;
    double now = since(&S->t0);
    if (!S->o->progress || (!improved && now - S->last_report < PROGRESS_DT)) {
        return;
    }
    S->last_report = now;
    zp_search_progress p = {res->evals, now, res->found, res->best.time, res->force};
    S->o->progress(S->o->user, &p, improved);
}

/* one simulation from any thread: the shared counts and the best so far */
static void evaluate(search *S, worker *w, const double *f, zp_eval *e) {
    zp_objective_eval(S->ob, w->sim, f, e, w->r);
#pragma omp critical
    {
        zp_search_result *res = S->res;
        res->evals++;
        res->nfeasible += zp_objective_feasible(e);
        res->nfailed += e->failed;
        int improved = res->evals == 1 || ahead(e, f, &res->best, res->force, S->nsec);
        if (improved) {
            res->best = *e;
            memcpy(res->force, f, sizeof *f * S->nsec);
            res->found = zp_objective_feasible(e);
        }
        report(S, improved && res->found);
    }
}

/* the serial history: improvements of one unit of work, spent after `base` simulations */
static void hist_add(search *S, long at, const zp_eval *e) {
    zp_search_result *res = S->res;
    if (zp_objective_feasible(e) && e->time < S->running && res->nhist < ZP_SEARCH_HIST) {
        S->running = e->time;
        res->hist[res->nhist++] = (zp_search_hist){at, e->time};
    }
}

static void pool_add(search *S, const double *f, const zp_eval *e) {
    pool *p = &S->p;
    if (p->n < p->cap) {
        memcpy(p->f + (size_t)p->n * S->nsec, f, sizeof *f * S->nsec);
        p->e[p->n++] = *e;
    }
}

/* evaluates npt points in parallel, then adds them to the pool and history in order */
static void scan(search *S, const double *pts, int npt, zp_eval *e) {
    long base = S->res->evals;
    int *done = calloc(npt, sizeof *done);
    if (!done) {
        return;
    }
#pragma omp parallel for num_threads(S->nw) schedule(dynamic, 2)
    for (int i = 0; i < npt; i++) {
        if (!stopped(S) && base + i < S->o->max_evals) {
            evaluate(S, &S->w[omp_get_thread_num()], pts + (size_t)i * S->nsec, &e[i]);
            done[i] = 1;
        }
    }
    long at = base;
    for (int i = 0; i < npt; i++) {
        if (done[i]) {
            pool_add(S, pts + (size_t)i * S->nsec, &e[i]);
            hist_add(S, ++at, &e[i]);
        }
    }
    free(done);
}

/* one NLopt run: its evaluations, its own best and its improvements */
typedef struct run_ctx {
    search *S;
    worker *w;
    nlopt_opt opt;
    int alg;      /* nlopt_algorithm */
    int diag;     /* one variable: the same force in every section */
    int penalty;  /* minimise the penalised score; else the time under the constraint */
    int to_pool;  /* keep every point for the polish (sequential runs only) */
    long budget, n;
    double key[ZP_MAX_SECTIONS]; /* NLopt's point of the cached evaluation */
    int have;
    zp_eval e;
    double bestf[ZP_MAX_SECTIONS]; /* N */
    zp_eval best;
    int nimp;
    long imp_at[MAX_IMP];
    zp_eval imp[MAX_IMP];
    nlopt_result status;
} run_ctx;

static int takes_constraint(int alg) {
    return alg == NLOPT_LN_COBYLA || alg == NLOPT_GN_ISRES;
}

/* the run's evaluation at x, simulated once for the objective and the constraint together */
static const zp_eval *run_at(run_ctx *c, const double *x) {
    search *S = c->S;
    int nx = c->diag ? 1 : S->nsec;
    if (c->have && !memcmp(x, c->key, sizeof *x * nx)) {
        return &c->e;
    }
    if (c->n >= c->budget || stopped(S)) {
        /* NLopt stops at its next check; until then it sees a point worse than any run */
        nlopt_force_stop(c->opt);
        c->have = 0;
        c->e.obj = c->e.score = 3 * S->ob->t_max;
        c->e.cons = 360;
        return &c->e;
    }
    double f[ZP_MAX_SECTIONS];
    for (int k = 0; k < S->nsec; k++) {
        f[k] = fmin(fmax(x[c->diag ? 0 : k], S->lo), S->hi);
    }
    evaluate(S, c->w, f, &c->e);
    memcpy(c->key, x, sizeof *x * nx);
    c->have = 1;
    c->n++;
    if (c->n == 1 || ahead(&c->e, f, &c->best, c->bestf, S->nsec)) {
        c->best = c->e;
        memcpy(c->bestf, f, sizeof f);
        if (zp_objective_feasible(&c->e) && c->nimp < MAX_IMP) {
            c->imp_at[c->nimp] = c->n;
            c->imp[c->nimp++] = c->e;
        }
    }
    if (c->to_pool) {
        pool_add(S, f, &c->e);
    }
    return &c->e;
}

static double nl_obj(unsigned n, const double *x, double *grad, void *data) {
    run_ctx *c = data;
    (void)n;
    (void)grad;
    const zp_eval *e = run_at(c, x);
    return c->penalty ? e->score : e->obj;
}

static double nl_cons(unsigned n, const double *x, double *grad, void *data) {
    (void)n;
    (void)grad;
    return run_at(data, x)->cons;
}

/* one NLopt optimisation from x0 (N) with initial steps (N per variable; NULL: NLopt's) */
static void run_nlopt(run_ctx *c, int alg, const double *x0, const double *step) {
    search *S = c->S;
    int nx = c->diag ? 1 : S->nsec;
    c->alg = alg;
    c->penalty = !takes_constraint(alg);
    nlopt_opt opt = nlopt_create((nlopt_algorithm)alg, nx);
    c->status = NLOPT_OUT_OF_MEMORY;
    if (!opt) {
        return;
    }
    c->opt = opt;
    double lb[ZP_MAX_SECTIONS], ub[ZP_MAX_SECTIONS], x[ZP_MAX_SECTIONS], fbest;
    for (int k = 0; k < nx; k++) {
        lb[k] = S->lo;
        ub[k] = S->hi;
        x[k] = x0[k];
    }
    nlopt_result st = nlopt_set_lower_bounds(opt, lb);
    if (st > 0) {
        st = nlopt_set_upper_bounds(opt, ub);
    }
    if (st > 0) {
        st = nlopt_set_min_objective(opt, nl_obj, c);
    }
    if (st > 0 && !c->penalty) {
        st = nlopt_add_inequality_constraint(opt, nl_cons, c, 0);
    }
    if (st > 0 && alg == NLOPT_G_MLSL_LDS) {
        nlopt_opt loc = nlopt_create(NLOPT_LN_BOBYQA, nx);
        st = loc ? nlopt_set_xtol_abs1(loc, XTOL) : NLOPT_OUT_OF_MEMORY;
        if (st > 0) {
            st = nlopt_set_local_optimizer(opt, loc);
        }
        nlopt_destroy(loc);
    }
    if (st > 0) {
        st = nlopt_set_xtol_abs1(opt, XTOL);
    }
    if (st > 0) {
        st = nlopt_set_ftol_abs(opt, FTOL);
    }
    if (st > 0 && step) {
        st = nlopt_set_initial_step(opt, step);
    }
    if (st > 0) {
        /* NLopt counts calls, not simulations; our own count stops the run */
        st = nlopt_set_maxeval(opt, (int)fmin(4 * c->budget + 10, 1e9));
    }
    if (st > 0) {
        st = nlopt_optimize(opt, x, &fbest);
    }
    c->status = st;
    nlopt_destroy(opt);
}

/* the improvements of finished runs, in order, into the serial history */
static void runs_to_hist(search *S, run_ctx *c, int nrun, long base) {
    for (int i = 0; i < nrun; i++) {
        for (int j = 0; j < c[i].nimp; j++) {
            hist_add(S, base + c[i].imp_at[j], &c[i].imp[j]);
        }
        base += c[i].n;
    }
}

static int nlopt_failed(const run_ctx *c, char *err, size_t errlen) {
    if (c->status == NLOPT_INVALID_ARGS || c->status == NLOPT_OUT_OF_MEMORY) {
        snprintf(err, errlen, "NLopt %s refused the search: %s",
                 nlopt_algorithm_name((nlopt_algorithm)c->alg), nlopt_result_to_string(c->status));
        return 1;
    }
    return 0;
}

static uint64_t splitmix(uint64_t *s) {
    uint64_t z = (*s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static double uniform(uint64_t *s) { return (splitmix(s) >> 11) * 0x1.0p-53; }

/* a Latin hypercube of npt points: every force's range cut in npt strata, each hit once */
static void latin(search *S, uint64_t *rng, double *pts, int npt, int *perm) {
    for (int k = 0; k < S->nsec; k++) {
        for (int i = 0; i < npt; i++) {
            perm[i] = i;
        }
        for (int i = npt - 1; i > 0; i--) {
            int j = (int)(splitmix(rng) % (uint64_t)(i + 1));
            int t = perm[i];
            perm[i] = perm[j];
            perm[j] = t;
        }
        for (int i = 0; i < npt; i++) {
            pts[(size_t)i * S->nsec + k] = S->lo + (S->hi - S->lo) * (perm[i] + uniform(rng)) / npt;
        }
    }
}

/* pool entry i's force in section k */
static double pool_f(const search *S, int i, int k) { return S->p.f[(size_t)i * S->nsec + k]; }

static int pool_ahead(const search *S, int i, int j) {
    return ahead(&S->p.e[i], S->p.f + (size_t)i * S->nsec, &S->p.e[j],
                 S->p.f + (size_t)j * S->nsec, S->nsec);
}

/* one force k over [a, b] in npt points, the others at cur; then twice more, finer, around
   the ZOOM best local minima of the score: runs that die further along point at survivable
   bands narrower than the grid */
static void line(search *S, const double *cur, int k, double a, double b, int npt, int depth,
                 double *pts, zp_eval *e) {
    for (int i = 0; i < npt; i++) {
        memcpy(pts + (size_t)i * S->nsec, cur, sizeof *cur * S->nsec);
        pts[(size_t)i * S->nsec + k] = a + (b - a) * i / (npt - 1);
    }
    int n0 = S->p.n;
    scan(S, pts, npt, e);
    int n = S->p.n - n0;
    if (depth == 0 || n < npt) {
        return;
    }
    int best[ZOOM], nb = 0;
    for (int i = n0; i < n0 + n; i++) {
        int lmin = (i == n0 || pool_ahead(S, i, i - 1)) && (i == n0 + n - 1 || pool_ahead(S, i, i + 1));
        if (!lmin) {
            continue;
        }
        /* insert into the best ZOOM local minima, best first */
        int at = nb < ZOOM ? nb++ : ZOOM;
        while (at > 0 && pool_ahead(S, i, best[at - 1])) {
            if (at < ZOOM) {
                best[at] = best[at - 1];
            }
            at--;
        }
        if (at < ZOOM) {
            best[at] = i;
        }
    }
    for (int j = 0; j < nb; j++) {
        int i = best[j];
        double lo = pool_f(S, i > n0 ? i - 1 : i, k), hi = pool_f(S, i < n0 + n - 1 ? i + 1 : i, k);
        line(S, cur, k, lo, hi, ZOOM_PTS, depth - 1, pts, e);
    }
}

/* per-section lines through the best point: each force in turn over its whole range, the
   others held, repeated while a pass improves. Survivable bands can be narrower than any
   affordable grid in all forces at once, but a line resolves one force finely. */
static void lines(search *S, int b, int npt, double *pts, zp_eval *e) {
    double cur[ZP_MAX_SECTIONS];
    memcpy(cur, S->p.f + (size_t)b * S->nsec, sizeof *cur * S->nsec);
    for (int pass = 0; pass < 2 && !stopped(S); pass++) {
        int moved = 0;
        for (int k = 0; k < S->nsec && !stopped(S); k++) {
            int n0 = S->p.n;
            line(S, cur, k, S->lo, S->hi, npt, 2, pts, e);
            for (int i = n0; i < S->p.n; i++) {
                if (pool_ahead(S, i, b)) {
                    b = i;
                    memcpy(cur, S->p.f + (size_t)i * S->nsec, sizeof *cur * S->nsec);
                    moved = 1;
                }
            }
            /* how far force k may move from the best before a run fails: the polish's scale */
            double left = S->lo, right = S->hi;
            for (int i = n0; i < S->p.n; i++) {
                double f = pool_f(S, i, k);
                if (!zp_objective_feasible(&S->p.e[i])) {
                    left = f < cur[k] ? fmax(left, f) : left;
                    right = f > cur[k] ? fmin(right, f) : right;
                }
            }
            S->step[k] = fmin(STEP_SHARE * (right - left), S->step[k]);
        }
        if (!moved) {
            break;
        }
    }
}

/* up to nmax pool points, best first, each differing from the others chosen */
static int pick_starts(search *S, int *idx, int nmax) {
    int n = 0, np = S->p.n, nsec = S->nsec;
    char *used = calloc(np ? np : 1, 1);
    if (!used) {
        return 0;
    }
    while (n < nmax) {
        int b = -1;
        for (int i = 0; i < np; i++) {
            if (!used[i] && (b < 0 || ahead(&S->p.e[i], S->p.f + (size_t)i * nsec, &S->p.e[b],
                                            S->p.f + (size_t)b * nsec, nsec))) {
                b = i;
            }
        }
        if (b < 0) {
            break;
        }
        used[b] = 1;
        int distinct = 1;
        for (int j = 0; j < n && distinct; j++) {
            double d = 0;
            for (int k = 0; k < nsec; k++) {
                d = fmax(d, fabs(S->p.f[(size_t)b * nsec + k] - S->p.f[(size_t)idx[j] * nsec + k]));
            }
            distinct = d > DISTINCT * (S->hi - S->lo);
        }
        if (distinct) {
            idx[n++] = b;
        }
    }
    free(used);
    return n;
}

static int clampi(long v, int lo, int hi) { return (int)(v < lo ? lo : v > hi ? hi : v); }

static zp_status search_phases(search *S, char *err, size_t errlen) {
    const zp_search_opts *o = S->o;
    const zp_search_algo *alg = &algos[o->algo];
    zp_search_result *res = S->res;
    int nsec = S->nsec;
    long B = o->max_evals;
    uint64_t rng = o->seed;
    /* phase sizes follow the number of sections and the budget; the budget caps them all */
    int ndiag = clampi(B / 80, 8, 64);
    int nlat = clampi(B / 40, 8, 128);
    int nline = clampi(B / 80, 8, 64);
    int cap = ndiag + nlat + 1 + 2 * 2 * nsec * (nline + ZOOM * ZOOM_PTS * (1 + ZOOM));
    S->p.cap = alg->global < 0 ? cap : cap + (int)B;
    S->p.f = malloc(sizeof *S->p.f * S->p.cap * nsec);
    S->p.e = malloc(sizeof *S->p.e * S->p.cap);
    double *pts = malloc(sizeof *pts * cap * nsec);
    zp_eval *ev = malloc(sizeof *ev * cap);
    int *perm = malloc(sizeof *perm * cap);
    run_ctx *runs = calloc(NSTARTS + 1, sizeof *runs);
    zp_status st = ZP_ERR_NOMEM;
    if (!S->p.f || !S->p.e || !pts || !ev || !perm || !runs) {
        snprintf(err, errlen, "out of memory for the search");
        goto done;
    }
    st = ZP_OK;
    for (int k = 0; k < nsec; k++) {
        S->step[k] = POLISH_STEP * (S->hi - S->lo);
    }

    /* constant pushes: the baseline, and good starts on courses that reward an even push */
    for (int i = 0; i < ndiag; i++) {
        for (int k = 0; k < nsec; k++) {
            pts[(size_t)i * nsec + k] = S->lo + (S->hi - S->lo) * i / (ndiag - 1);
        }
    }
    scan(S, pts, ndiag, ev);
    int ndiag_done = S->p.n;

    /* the global phase */
    if (alg->global < 0) {
        latin(S, &rng, pts, nlat, perm);
        scan(S, pts, nlat, ev);
        /* lines through the best point so far and through the hardest push: times fall as
           the pushes grow, so the fastest schedules lie towards that corner */
        int from[2];
        pick_starts(S, from, 1);
        for (int k = 0; k < nsec; k++) {
            pts[k] = S->hi;
        }
        scan(S, pts, 1, ev);
        from[1] = S->p.n - 1;
        for (int i = 0; i < 2; i++) {
            lines(S, from[i], nline, pts, ev);
        }
    } else if (!stopped(S)) {
        run_ctx *g = &runs[0];
        *g = (run_ctx){.S = S, .w = &S->w[0], .to_pool = 1};
        g->budget = (B - res->evals) / 2;
        double mid[ZP_MAX_SECTIONS];
        for (int k = 0; k < nsec; k++) {
            mid[k] = 0.5 * (S->lo + S->hi);
        }
        nlopt_srand(o->seed);
        long base = res->evals;
        run_nlopt(g, alg->global, mid, NULL);
        if (nlopt_failed(g, err, errlen)) {
            st = ZP_ERR_INPUT;
            goto done;
        }
        runs_to_hist(S, g, 1, base);
    }

    /* the polish: the best constant push along the diagonal, and NSTARTS schedules, in
       parallel with fixed budgets so that the answer does not depend on the threads */
    int idx[NSTARTS];
    int nstart = pick_starts(S, idx, NSTARTS);
    int bdiag = 0;
    for (int i = 1; i < ndiag_done; i++) {
        if (ahead(&S->p.e[i], S->p.f + (size_t)i * nsec, &S->p.e[bdiag],
                  S->p.f + (size_t)bdiag * nsec, nsec)) {
            bdiag = i;
        }
    }
    long left = B - res->evals;
    long each = (left - BASE_BUDGET) / (nstart > 0 ? nstart : 1);
    each = each < POLISH_BUDGET ? each : POLISH_BUDGET;
    int nrun = ndiag_done > 0 ? nstart + 1 : 0;
    long base = res->evals;
#pragma omp parallel for num_threads(S->nw) schedule(dynamic, 1)
    for (int r = 0; r < nrun; r++) {
        run_ctx *c = &runs[r];
        *c = (run_ctx){.S = S, .w = &S->w[omp_get_thread_num()], .diag = r == 0};
        c->budget = r > 0 ? (each > 0 ? each : 0) : (left < BASE_BUDGET ? left : BASE_BUDGET);
        const double *x0 = S->p.f + (size_t)(r == 0 ? bdiag : idx[r - 1]) * nsec;
        double diag_step = (S->hi - S->lo) / (2.0 * (ndiag - 1));
        if (c->budget > 0) {
            run_nlopt(c, alg->local, x0, r == 0 ? &diag_step : S->step);
        }
    }
    for (int r = 0; r < nrun; r++) {
        if (runs[r].budget > 0 && nlopt_failed(&runs[r], err, errlen)) {
            st = ZP_ERR_INPUT;
            goto done;
        }
    }
    runs_to_hist(S, runs, nrun, base);
    res->nstarts = nstart;

    /* the baseline: the best constant push of the scan and its refinement */
    res->base_found = 0;
    for (int i = 0; i < ndiag_done; i++) {
        const zp_eval *e = &S->p.e[i];
        double f = S->p.f[(size_t)i * nsec];
        if (zp_objective_feasible(e) && (!res->base_found || e->time < res->base.time)) {
            res->base_found = 1;
            res->base = *e;
            res->base_force = f;
        }
    }
    if (nrun > 0 && zp_objective_feasible(&runs[0].best) &&
        (!res->base_found || runs[0].best.time < res->base.time)) {
        res->base_found = 1;
        res->base = runs[0].best;
        res->base_force = runs[0].bestf[0];
    }
done:
    free(pts);
    free(ev);
    free(perm);
    free(runs);
    return st;
}

zp_status zp_search_run(const zp_objective *ob, const zp_sim_opts *so, double lo, double hi,
                        const zp_search_opts *o, zp_search_result *res, char *err,
                        size_t errlen) {
    memset(res, 0, sizeof *res);
    search S = {.ob = ob, .o = o, .nsec = ob->m->nsec, .lo = lo, .hi = hi, .res = res,
                .running = INFINITY};
    clock_gettime(CLOCK_MONOTONIC, &S.t0);
    S.nw = o->nthreads > 0 ? o->nthreads : omp_get_max_threads();
    S.w = calloc(S.nw, sizeof *S.w);
    zp_status st = S.w ? ZP_OK : ZP_ERR_NOMEM;
    /* workspaces are made here, serially: the course evaluators are not thread-safe */
    for (int i = 0; st == ZP_OK && i < S.nw; i++) {
        S.w[i].sim = zp_sim_create(ob->m, so);
        S.w[i].r = malloc(sizeof *S.w[i].r);
        if (!S.w[i].sim || !S.w[i].r) {
            st = ZP_ERR_NOMEM;
        }
    }
    if (st == ZP_OK) {
        st = search_phases(&S, err, errlen);
    } else {
        snprintf(err, errlen, "out of memory creating %d simulator workspaces", S.nw);
    }
    res->nthreads = S.nw;
    res->interrupted = stopped(&S);
    res->wall_s = since(&S.t0);
    for (int i = 0; S.w && i < S.nw; i++) {
        zp_sim_free(S.w[i].sim);
        free(S.w[i].r);
    }
    free(S.w);
    free(S.p.f);
    free(S.p.e);
    return st;
}
