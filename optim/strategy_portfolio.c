/* The portfolio's global phase (strategies.def): each round the scan's low-discrepancy points,
   then a share of pagmo2's CMA-ES or differential evolution (sade; the strategy's variant,
   pagmo_pop.h) in NPOP independent populations (one of POP_MAX members from ONE_POP_FROM
   parameters), each evolved serially on a leg of its own with its own seed from the search's,
   the legs in parallel: a count fixed by the scene, so the same seed gives the same bits on any
   thread count. The points a population runs join the map (of its near-survivable ones the
   best, below), so the islands it finds are polished with the others. The map decides the
   share: it doubles after a round whose populations improved the best of the map and halves
   after one where they did not. The one population (from ONE_POP_FROM parameters) has its best
   polished inside its leg every POLISH_EVERY generations where it improved, and from
   WINDOW_WIDTH + 2 parameters its leg searches a window of its best schedule, the rest held,
   every WINDOW_EVERY generations. From ONE_POP_FROM parameters the populations' part of a round
   ends with the bang-bang search (pinned.h) from the map's best, where that is new. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "islands.h"
#include "pagmo_pop.h"
#include "pinned.h"
#include "strategy.h"
#include "subsearch.h"

#define NPOP 4          /* populations below ONE_POP_FROM parameters, whatever the threads */
#define POP_PER_PARAM 5 /* members per parameter ... */
#define POP_MIN 16      /* ... at least ... */
#define POP_MAX 120     /* ... and at most */
/* design note: from this many parameters one population of POP_MAX members (SciPy's 15 per
   parameter, capped) takes the four's share: four of 5 per parameter gather on the first
   islands they meet there (m8 to m12 and multi8 of docs/search.md gained 0.2 % to 4.6 % from
   one; on a second seed m9, m10 and multi8 gained, m8 held and m12 lost 0.9 %), while below
   it the four's separate islands win (m6 and m7 lost 1 % with one) */
#define ONE_POP_FROM 8
/* the variant of portfolio-cobyla: CMA-ES below ONE_POP_FROM parameters, sade from it (the other
   portfolios name their algorithm). Over seeds 1 to 5 of docs/search.md's scenes below 8
   parameters CMA-ES's four populations left m6 and m7 7.7 % and 2.5 % behind the best known in
   all, sade's 11.0 % and 5.2 % (CMA-ES lost m4 0.4 % twice); from 8 one CMA-ES population lost
   m8, m9 and multi8 1.8 % to 86 % and won m12 0.9 % */
#define BY_DIMENSION (-1)
/* simulations of the populations together a round, per point of the scan's sequence in that
   round, at the base share: the two global phases grow together, round by round, and a small
   budget keeps its rounds of lines and polishes. 16 won every multi-section scene of
   docs/search.md on seed 1 but lost m8 6.5 % and multi8 1.4 % on seed 2, whose faster islands
   the lines and polishes find */
#define PER_SCANNED 4
#define SHARE_MAX 8            /* the share grows to this many times the base */
#define SEED_STREAM 0xde5eedUL /* the populations' seeds: a stream apart from the scan's shift */
/* design note: the search's polishes follow a round's populations, so what the one population
   found in the round the budget ends was never polished: multi8's 6.67967 s came at 33999 of
   its 40000 simulations and the population spent the rest; COBYLA from it reaches 6.6705 s in
   243 (10x: 6.67013 s). Polished inside the leg (a polish of the search's kind, COBYLA, of its
   size and first steps), the population's best reaches the map within POLISH_EVERY generations
   of being found. The polish's end joins the map, not the population: put in its place of the
   worst member it drew the differential evolution onto its island (m8 and multi8 0.2-0.9 %
   slower, docs/search.md). Below ONE_POP_FROM (four CMA-ES populations) it lost m7 0.3 %. */
#define POLISH_EVERY 10  /* generations between polishes of the one population's best */
#define POLISH_SIMS 150  /* simulations per polish: the search's */
#define POLISH_STEP 0.02 /* first steps, share of the box: the search's */
/* design note: the course is causal, so with the rest of a good schedule held, a window of
   neighbouring parameters is a search of its own, of the size where CMA-ES does best (below
   ONE_POP_FROM). From m9_6link's default answer (7.5338 s), CMA-ES over sections 3 to 9 with
   sections 1 and 2 held reached 7.25 s in 4000 simulations on 2 seeds of 4, under the 7.3145 s
   the one population reaches by creeping for 450000. So the one population's leg also runs,
   every WINDOW_EVERY generations, CMA-ES over a window of WINDOW_WIDTH parameters of the leg's
   best schedule (the windows start every WINDOW_STRIDE, the last ending at the last parameter,
   taken from the last), its WINDOW_POP members drawn over the window, for WINDOW_GENS
   generations. Over seeds 1 to 5 (docs/search.md) the gaps to the best known fell from 22.2 to
   14.4 % in all on m9 and from 3.8 to 1.9 % on m12, and grew from 44.7 to 45.7 % on m10; every
   40 generations m9 gained less (19.7 %). Only where a window holds two parameters or more: on 8
   (multi8) windows lost 0.05-2 % on three seeds */
#define WINDOW_WIDTH (ONE_POP_FROM - 1)
#define WINDOW_STRIDE 3
#define WINDOW_POP (POP_PER_PARAM * WINDOW_WIDTH) /* as a population below ONE_POP_FROM */
#define WINDOW_GENS 114          /* with the draw, 4025 simulations: what m9's windows needed */
#define WINDOW_EVERY 20          /* generations of the population between windows */
#define WINDOW_STREAM 0x3d5eedUL /* the windows' seeds: a stream apart from the populations' */
#define PINNED_STREAM 0xb4b6UL   /* the bang-bang searches' seeds: another stream */

/* one population and the points it ran in its last leg, to join the archive in order */
typedef struct population {
    zp_pagmo_pop *evo; /* owned */
    zp_leg *leg;       /* the leg evolving it now */
    int gens;          /* generations of this round */
    int npts, cap;
    double *f;        /* owned, cap x n parameters */
    zp_eval *e;       /* owned, cap */
    double polished;  /* the value of the best member last polished from (or what that reached) */
    int window;       /* the last window searched from its leg's best */
    long generations; /* evolved in all rounds: when the windows are due */
    long windows;     /* searched in all rounds: their seeds */
} population;

typedef struct portfolio {
    void *scan; /* owned: the scan's sequence */
    int npop;   /* populations: NPOP, or one from ONE_POP_FROM parameters */
    int popsize;
    int nwindow; /* windows of the one population's best schedule (0: none) */
    int share;   /* times the base share, 1 .. SHARE_MAX */
    int gained;  /* the populations improved the best of the map last round */
    population pop[NPOP];
    long npinned; /* bang-bang searches run (pinned.h), from the map's best */
    double pinned_from[ZP_SCHED_MAX_PARAMS], pinned_to[ZP_SCHED_MAX_PARAMS]; /* the last one's */
} portfolio;

static void portfolio_free(void *state) {
    portfolio *P = state;
    if (!P) {
        return;
    }
    zp_strategy_scan.free(P->scan);
    for (int i = 0; i < NPOP; i++) {
        zp_pagmo_pop_free(P->pop[i].evo);
        free(P->pop[i].f);
        free(P->pop[i].e);
    }
    free(P);
}

static void *portfolio_create(const zp_strategy *self, const zp_search_state *S) {
    portfolio *P = calloc(1, sizeof *P);
    if (!P || !(P->scan = zp_strategy_scan.create(&zp_strategy_scan, S))) {
        portfolio_free(P);
        return NULL;
    }
    int np = S->n < ONE_POP_FROM ? POP_PER_PARAM * S->n : POP_MAX;
    zp_pagmo_algo algo = self->variant != BY_DIMENSION ? (zp_pagmo_algo)self->variant
                         : S->n < ONE_POP_FROM         ? ZP_PAGMO_CMAES
                                                       : ZP_PAGMO_SADE;
    P->npop = S->n < ONE_POP_FROM ? NPOP : 1;
    P->popsize = np < POP_MIN ? POP_MIN : np > POP_MAX ? POP_MAX : np;
    P->nwindow = P->npop == 1 && S->n >= WINDOW_WIDTH + 2
                     ? (S->n - WINDOW_WIDTH + WINDOW_STRIDE - 1) / WINDOW_STRIDE + 1
                     : 0;
    P->share = 1;
    for (int i = 0; i < P->npop; i++) {
        unsigned long seed = (S->o->seed ^ SEED_STREAM) * (unsigned long)P->npop + (unsigned long)i;
        P->pop[i].polished = INFINITY;
        if (!(P->pop[i].evo = zp_pagmo_pop_create(algo, S->n, S->lo, S->hi, P->popsize, seed))) {
            portfolio_free(P);
            return NULL;
        }
    }
    return P;
}

/* the penalised score at x through the leg (dying runs by how far they got), the point kept
   for the archive when it was simulated */
static double fitness(void *user, const double *x) {
    population *p = user;
    zp_leg *leg = p->leg;
    long n0 = leg->n;
    const zp_eval *e = zp_leg_eval(leg, x);
    if (!e) {
        return zp_leg_spent_score(leg);
    }
    if (leg->n > n0 && p->npts < p->cap) {
        zp_leg_params(leg, x, p->f + (size_t)p->npts * leg->S->n);
        p->e[p->npts++] = *e;
    }
    return e->score;
}

/* COBYLA from the population's best where it is better than the last start polished from
   (or that polish's end), the end kept for the map where it gained */
static void polish_best(population *p, zp_leg *leg) {
    const zp_search_state *S = leg->S;
    double x[ZP_SCHED_MAX_PARAMS], step[ZP_SCHED_MAX_PARAMS], value;
    if (zp_pagmo_pop_best(p->evo, x, &value) || !(value < p->polished)) {
        return;
    }
    p->polished = value;
    for (int k = 0; k < S->n; k++) {
        step[k] = POLISH_STEP * (S->hi[k] - S->lo[k]);
    }
    zp_leg_rec rec;
    const zp_strategy *cobyla = &zp_strategy_nlopt_cobyla;
    if (zp_leg_polish_within(leg, cobyla->polish, cobyla, x, step, POLISH_SIMS, &rec) == 0 &&
        rec.n > 0 && rec.e.score < value && p->npts < p->cap) {
        p->polished = rec.e.score;
        memcpy(p->f + (size_t)p->npts * S->n, rec.end, sizeof *rec.end * S->n);
        p->e[p->npts++] = rec.e;
    }
}

/* CMA-ES over population p's next window of its leg's best schedule; the leg's best joins the
   map with the population's points where the window moved it */
static void window_search(const portfolio *P, population *p, zp_leg *leg) {
    const zp_search_state *S = leg->S;
    p->window = (p->window + P->nwindow - 1) % P->nwindow;
    int first = p->window * WINDOW_STRIDE;
    first = first + WINDOW_WIDTH > S->n ? S->n - WINDOW_WIDTH : first;
    zp_subsearch w = {.nfree = WINDOW_WIDTH,
                      .popsize = WINDOW_POP,
                      .gens = WINDOW_GENS,
                      .seed = (S->o->seed ^ WINDOW_STREAM) * 65536UL + (unsigned long)p->windows++,
                      .what = "a window"};
    memcpy(w.base, leg->bestf, sizeof *w.base * S->n);
    for (int j = 0; j < WINDOW_WIDTH; j++) {
        w.free[j] = first + j;
    }
    zp_subsearch_run(&w, leg, 0);
    if (memcmp(leg->bestf, w.base, sizeof *w.base * S->n) && p->npts < p->cap) {
        memcpy(p->f + (size_t)p->npts * S->n, leg->bestf, sizeof *leg->bestf * S->n);
        p->e[p->npts++] = leg->best;
    }
}

/* the windows due in the next gens generations of p */
static long windows_due(const portfolio *P, const population *p, int gens) {
    return P->nwindow ? (p->generations + gens) / WINDOW_EVERY - p->generations / WINDOW_EVERY : 0;
}

static void evolve_leg(const void *how, zp_leg *leg) {
    const portfolio *P = how;
    population *p = leg->user;
    p->leg = leg;
    int every = P->npop == 1 ? POLISH_EVERY : p->gens; /* generations between polishes */
    for (int g = 0; g < p->gens && !leg->refused; g += every) {
        int chunk = p->gens - g < every ? p->gens - g : every;
        long due = windows_due(P, p, chunk);
        if (zp_pagmo_pop_evolve(p->evo, chunk, fitness, p)) {
            leg->refused = 1;
            snprintf(leg->why, sizeof leg->why, "pagmo refused to evolve a population");
            break;
        }
        p->generations += chunk;
        if (P->npop == 1) {
            polish_best(p, leg);
        }
        for (long k = 0; k < due && !leg->refused; k++) {
            window_search(P, p, leg);
        }
    }
}

/* room for what each population may run in the round: cap simulations */
static int make_room(portfolio *P, const zp_search_state *S, int cap) {
    for (int i = 0; i < P->npop; i++) {
        population *p = &P->pop[i];
        free(p->f);
        free(p->e);
        p->f = malloc(sizeof *p->f * (size_t)cap * S->n);
        p->e = malloc(sizeof *p->e * (size_t)cap);
        p->npts = 0;
        p->cap = cap;
        if (!p->f || !p->e) {
            return -1;
        }
    }
    return 0;
}

/* design note: a population gathers around its best, and its near-survivable points would
   fill the map's NEAR_MAX best with its one island and push the other islands off the map; so
   of a population's round only its best near-survivable point joins the map, with every point
   of it that is not near-survivable (those separate islands) */
/* the index of population p's best near-survivable point of the round, -1: none */
static int best_near(const population *p, const zp_search_state *S) {
    int b = -1;
    for (int j = 0; j < p->npts; j++) {
        const double *f = p->f + (size_t)j * S->n;
        if (zp_islands_near(&p->e[j]) &&
            (b < 0 ||
             zp_search_state_ahead(&p->e[j], f, &p->e[b], p->f + (size_t)b * S->n, S->n))) {
            b = j;
        }
    }
    return b;
}

static double best_time(const zp_search_state *S) {
    return S->res->found ? S->res->best.time : INFINITY;
}

/* the bang-bang search (pinned.h) from the map's best, where that is neither the start nor the
   end of the last one; its end joins the map. design note: only beside the one population
   (from ONE_POP_FROM parameters): below, where four CMA-ES populations already search few
   parameters each, it took their budget and lost m7_brake 0.03 % to 1.7 % on seeds 1 to 3; from
   the map's best it gained on every scene of 8 parameters or more over seeds 1 to 5, where from
   the one population's best, inside its leg every WINDOW_EVERY generations (as the windows
   are), it lost multi8 and m8 (docs/search.md) */
static zp_status pinned_search(portfolio *P, zp_search_state *S, char *err, size_t errlen) {
    zp_search_result *res = S->res;
    size_t size = sizeof *res->force * S->n;
    if (!res->found || zp_search_state_halted(S) ||
        (P->npinned > 0 &&
         (!memcmp(res->force, P->pinned_from, size) || !memcmp(res->force, P->pinned_to, size)))) {
        return ZP_OK;
    }
    zp_subsearch pin;
    unsigned long seed = (S->o->seed ^ PINNED_STREAM) * 65536UL + (unsigned long)P->npinned;
    if (!zp_pinned_make(&pin, S, res->force, seed)) {
        return ZP_OK;
    }
    memcpy(P->pinned_from, res->force, size);
    zp_leg_rec rec;
    zp_leg_job job = {.x0 = P->pinned_from, .cap = zp_pinned_cap(&pin), .out = &rec};
    zp_status st = zp_leg_batch(S, zp_pinned_run, &pin, &job, 1, err, errlen);
    res->npinned = ++P->npinned;
    memcpy(P->pinned_to, rec.end, size);
    if (rec.n > 0) {
        zp_search_state_add(S, rec.end, &rec.e);
    }
    return st;
}

/* design note: the share follows the map: while the populations keep improving its best (m5-m7
   of docs/search.md) it grows to SHARE_MAX times the base; where the faster islands come from
   the lines and polishes instead (m8, m10) it falls back to the base, never to nothing. Measured
   against crediting the populations only when they gained more than the polishes after them
   (docs/search.md): neither wins on every scene */
static zp_status portfolio_explore(void *state, zp_search_state *S, int round, char *err,
                                   size_t errlen) {
    portfolio *P = state;
    int n0 = S->a.n;
    zp_status st = zp_strategy_scan.explore(P->scan, S, round, err, errlen);
    /* the first round is the scan's alone: its lines and polishes map the islands before a
       population's best draws the lines through itself (on multi8 a population's 7.47 s
       island otherwise drew the lines and all 12 polishes of three rounds, and the estimate
       claimed convergence there, where the scan's islands hold 6.79 s) */
    if (st || round == 0 || zp_search_state_halted(S)) {
        return st;
    }
    if (round > 1) {
        P->share = P->gained ? (P->share * 2 < SHARE_MAX ? P->share * 2 : SHARE_MAX)
                             : (P->share > 1 ? P->share / 2 : 1);
    }
    long share = (long)P->share * PER_SCANNED * (S->a.n - n0) / P->npop;
    int gens = share > P->popsize ? (int)(share / P->popsize) : 1;
    /* a population drawn afresh (the first round, or after it collapsed) spends popsize more;
       the one population's polishes their own */
    int npolish = P->npop == 1 ? (gens + POLISH_EVERY - 1) / POLISH_EVERY : 0;
    long nwin = windows_due(P, &P->pop[0], gens); /* each drawn afresh, so WINDOW_GENS + 1 */
    long cap = (long)(gens + 1) * P->popsize + (long)npolish * POLISH_SIMS +
               nwin * (WINDOW_GENS + 1) * WINDOW_POP;
    if (make_room(P, S, (gens + 1) * P->popsize + npolish + (int)nwin)) {
        snprintf(err, errlen, "out of memory for the populations");
        return ZP_ERR_NOMEM;
    }
    zp_leg_job jobs[NPOP];
    for (int i = 0; i < P->npop; i++) {
        P->pop[i].gens = gens;
        jobs[i] = (zp_leg_job){.x0 = S->lo, .cap = cap, .user = &P->pop[i]};
    }
    double before = best_time(S);
    st = zp_leg_batch(S, evolve_leg, P, jobs, P->npop, err, errlen);
    zp_search_result *res = S->res;
    if (res->npops == 0) {
        res->npops = P->npop;
        res->pops_best = INFINITY;
    }
    for (int i = 0; i < P->npop; i++) {
        const population *p = &P->pop[i];
        int b = best_near(p, S);
        for (int j = 0; j < p->npts; j++) {
            if (j == b || !zp_islands_near(&p->e[j])) {
                zp_search_state_add(S, p->f + (size_t)j * S->n, &p->e[j]);
            }
            if (zp_objective_feasible(&p->e[j]) && p->e[j].time < res->pops_best) {
                res->pops_best = p->e[j].time;
            }
        }
    }
    res->nwindows = P->pop[0].windows;
    P->gained = best_time(S) < before;
    return st || P->npop > 1 ? st : pinned_search(P, S, err, errlen);
}

/* the portfolios differ only in what evolves their populations */
#define PORTFOLIO(label, algo)                                                                     \
    {                                                                                              \
        .name = label, .phase = ZP_STRATEGY_GLOBAL, .variant = algo, .create = portfolio_create,   \
        .free = portfolio_free, .explore = portfolio_explore                                       \
    }
const zp_strategy zp_strategy_portfolio = PORTFOLIO("portfolio", BY_DIMENSION);
const zp_strategy zp_strategy_portfolio_de =
    PORTFOLIO("portfolio with differential evolution", ZP_PAGMO_SADE);
const zp_strategy zp_strategy_portfolio_cmaes = PORTFOLIO("portfolio with CMA-ES", ZP_PAGMO_CMAES);
