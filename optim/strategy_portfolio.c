/* The portfolio's global phase (strategies.def): each round the scan's low-discrepancy points,
   then a share of differential evolution (pagmo2's sade, pagmo_de.h) in NPOP independent
   populations, each evolved serially on a leg of its own with its own seed from the search's,
   the legs in parallel: a fixed count, so the same seed gives the same bits on any thread
   count. The points a population runs join the map (its near-survivable ones thinned, below),
   so the islands it finds are polished with the others. The map decides the share: it doubles
   after a round whose populations improved the best of the map and halves after one where they
   did not. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "islands.h"
#include "pagmo_de.h"
#include "strategy.h"

#define NPOP 4          /* populations, whatever the threads */
#define VARIANT 6       /* sade's best/1/bin (SciPy's best1bin), with jDE's adaptation */
#define POP_PER_PARAM 5 /* members per parameter ... */
#define POP_MIN 16      /* ... at least ... */
#define POP_MAX 120     /* ... and at most */
/* simulations of the populations together a round, per parameter, at the base share */
#define SHARE_PER_PARAM 600
#define SHARE_MAX 4            /* the share grows to this many times the base */
#define SEED_STREAM 0xde5eedUL /* the populations' seeds: a stream apart from the scan's shift */

/* one population and the points it ran in its last leg, to join the archive in order */
typedef struct population {
    zp_pagmo_de *de; /* owned */
    zp_leg *leg;     /* the leg evolving it now */
    int gens;        /* generations of this round */
    int npts, cap;
    double *f;  /* owned, cap x n parameters */
    zp_eval *e; /* owned, cap */
} population;

/* the near-survivable spots the populations mapped: one point per ZP_DISTINCT of the box,
   the best there so far */
typedef struct spots {
    int n, cap;
    double *f;  /* owned, cap x n parameters */
    zp_eval *e; /* owned, cap */
} spots;

typedef struct portfolio {
    void *scan; /* owned: the scan's sequence */
    spots sp;
    int popsize;
    int share; /* times the base share, 1 .. SHARE_MAX */
    population pop[NPOP];
} portfolio;

static void portfolio_free(void *state) {
    portfolio *P = state;
    if (!P) {
        return;
    }
    zp_strategy_scan.free(P->scan);
    free(P->sp.f);
    free(P->sp.e);
    for (int i = 0; i < NPOP; i++) {
        zp_pagmo_de_free(P->pop[i].de);
        free(P->pop[i].f);
        free(P->pop[i].e);
    }
    free(P);
}

static void *portfolio_create(const zp_strategy *self, const zp_search_state *S) {
    (void)self;
    portfolio *P = calloc(1, sizeof *P);
    if (!P || !(P->scan = zp_strategy_scan.create(&zp_strategy_scan, S))) {
        portfolio_free(P);
        return NULL;
    }
    int np = POP_PER_PARAM * S->n;
    P->popsize = np < POP_MIN ? POP_MIN : np > POP_MAX ? POP_MAX : np;
    P->share = 1;
    for (int i = 0; i < NPOP; i++) {
        unsigned long seed = (S->o->seed ^ SEED_STREAM) * NPOP + (unsigned long)i;
        if (!(P->pop[i].de = zp_pagmo_de_create(S->n, S->lo, S->hi, P->popsize, VARIANT, seed))) {
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
        return 3 * leg->S->ob->t_max; /* the budget is spent: worse than any run */
    }
    if (leg->n > n0 && p->npts < p->cap) {
        zp_leg_params(leg, x, p->f + (size_t)p->npts * leg->S->n);
        p->e[p->npts++] = *e;
    }
    return e->score;
}

static void evolve_leg(const void *how, zp_leg *leg) {
    (void)how;
    population *p = leg->user;
    p->leg = leg;
    if (zp_pagmo_de_evolve(p->de, p->gens, fitness, p)) {
        leg->refused = 1;
        snprintf(leg->why, sizeof leg->why, "pagmo's sade refused the search");
    }
}

/* room for what each population may run in the round: cap simulations */
static int make_room(portfolio *P, const zp_search_state *S, int cap) {
    for (int i = 0; i < NPOP; i++) {
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
   fill the map's NEAR_MAX best with one island and push every other island off it; so a near
   point of a population joins the map only where it is the first or the best so far within
   ZP_DISTINCT of the box. Its other points all join: they separate islands */
/* point f (evaluated e) of a population joins the map; 0: it adds nothing to the map */
static int joins(spots *sp, const zp_search_state *S, const double *f, const zp_eval *e) {
    if (!zp_islands_near(e)) {
        return 1;
    }
    for (int j = 0; j < sp->n; j++) {
        double *g = sp->f + (size_t)j * S->n;
        if (!zp_search_state_distinct(S, f, g)) {
            if (!zp_search_state_ahead(e, f, &sp->e[j], g, S->n)) {
                return 0;
            }
            memcpy(g, f, sizeof *f * S->n);
            sp->e[j] = *e;
            return 1;
        }
    }
    if (sp->n == sp->cap) {
        int cap = sp->cap ? 2 * sp->cap : 64;
        double *nf = realloc(sp->f, sizeof *nf * (size_t)cap * S->n);
        sp->f = nf ? nf : sp->f;
        zp_eval *ne = nf ? realloc(sp->e, sizeof *ne * cap) : NULL;
        sp->e = ne ? ne : sp->e;
        if (!ne) {
            return 1; /* out of memory: it joins unremembered */
        }
        sp->cap = cap;
    }
    memcpy(sp->f + (size_t)sp->n * S->n, f, sizeof *f * S->n);
    sp->e[sp->n++] = *e;
    return 1;
}

static zp_status portfolio_explore(void *state, zp_search_state *S, int round, char *err,
                                   size_t errlen) {
    portfolio *P = state;
    zp_status st = zp_strategy_scan.explore(P->scan, S, round, err, errlen);
    if (st || zp_search_state_halted(S)) {
        return st;
    }
    long share = (long)P->share * SHARE_PER_PARAM * S->n / NPOP;
    int gens = share > P->popsize ? (int)(share / P->popsize) : 1;
    /* a population drawn afresh (the first round, or after it collapsed) spends popsize more */
    int cap = (gens + 1) * P->popsize;
    if (make_room(P, S, cap)) {
        snprintf(err, errlen, "out of memory for the populations");
        return ZP_ERR_NOMEM;
    }
    zp_leg_job jobs[NPOP];
    for (int i = 0; i < NPOP; i++) {
        P->pop[i].gens = gens;
        jobs[i] = (zp_leg_job){.x0 = S->lo, .cap = cap, .user = &P->pop[i]};
    }
    int had = S->res->found;
    double before = S->res->best.time;
    st = zp_leg_batch(S, evolve_leg, NULL, jobs, NPOP, err, errlen);
    for (int i = 0; i < NPOP; i++) {
        const population *p = &P->pop[i];
        for (int j = 0; j < p->npts; j++) {
            const double *f = p->f + (size_t)j * S->n;
            if (joins(&P->sp, S, f, &p->e[j])) {
                S->nclustered += zp_search_state_add(S, f, &p->e[j]) >= 0;
            }
        }
    }
    int gained = S->res->found && (!had || S->res->best.time < before);
    P->share = gained ? (P->share * 2 < SHARE_MAX ? P->share * 2 : SHARE_MAX)
                      : (P->share > 1 ? P->share / 2 : 1);
    return st;
}

const zp_strategy zp_strategy_portfolio = {.name = "portfolio",
                                           .phase = ZP_STRATEGY_GLOBAL,
                                           .create = portfolio_create,
                                           .free = portfolio_free,
                                           .explore = portfolio_explore};
