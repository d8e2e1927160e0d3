/* Differential evolution over the box (search_int.h): SciPy's best1bin with dither from a
   Latin hypercube, each generation's trials drawn by a seeded generator before the batch runs
   them in parallel, so a seed gives the same generations
   on any thread count. Constraints by the search's total order (survivable first, then the
   penalised score: Deb's rules). */
#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>

#include "search_int.h"

#define POP_PER_PARAM 15 /* members per parameter (SciPy's popsize) */
#define POP_MIN 20
#define POP_MAX 150
#define CROSS 0.7      /* binomial crossover rate */
#define DITHER_LO 0.5  /* the mutation factor, drawn per generation in [LO, 1) */
#define STREAM 0xde5UL /* the generator's seed: a stream apart from the scan's shift */

struct zp_de {
    int np;       /* members */
    double *x;    /* owned, np x n parameters */
    zp_eval *e;   /* owned, np */
    gsl_rng *rng; /* owned */
};

void zp_de_free(zp_de *d) {
    if (d) {
        free(d->x);
        free(d->e);
        gsl_rng_free(d->rng);
        free(d);
    }
}

/* the first population: a seeded Latin hypercube over the whole box (as SciPy starts), run as
   one batch; NULL when out of memory or the budget cut the batch */
static zp_de *create(zp_search *S) {
    int n = S->n, np = POP_PER_PARAM * n;
    np = np < POP_MIN ? POP_MIN : np > POP_MAX ? POP_MAX : np;
    zp_de *d = calloc(1, sizeof *d);
    int *perm = malloc(sizeof *perm * np);
    if (!d || !perm || !(d->x = malloc(sizeof *d->x * np * n)) ||
        !(d->e = malloc(sizeof *d->e * np)) || !(d->rng = gsl_rng_alloc(gsl_rng_mt19937))) {
        free(perm);
        zp_de_free(d);
        return NULL;
    }
    gsl_rng_set(d->rng, S->o->seed ^ STREAM);
    for (int k = 0; k < n; k++) {
        for (int i = 0; i < np; i++) {
            perm[i] = i;
        }
        for (int i = np - 1; i > 0; i--) {
            int j = (int)gsl_rng_uniform_int(d->rng, (unsigned long)i + 1), t = perm[i];
            perm[i] = perm[j];
            perm[j] = t;
        }
        for (int i = 0; i < np; i++) {
            double u = (perm[i] + gsl_rng_uniform(d->rng)) / np;
            d->x[(size_t)i * n + k] = S->lo[k] + u * (S->hi[k] - S->lo[k]);
        }
    }
    free(perm);
    int n0 = S->a.n;
    if (zp_scan_batch(S, d->x, np) < np || S->a.n < n0 + np) {
        zp_de_free(d);
        return NULL;
    }
    memcpy(d->e, S->a.e + n0, sizeof *d->e * np);
    d->np = np;
    return d;
}

/* the population's best member */
static int best_member(const zp_search *S, const zp_de *d) {
    int b = 0;
    for (int i = 1; i < d->np; i++) {
        if (zp_search_ahead(&d->e[i], d->x + (size_t)i * S->n, &d->e[b], d->x + (size_t)b * S->n,
                            S->n)) {
            b = i;
        }
    }
    return b;
}

/* three distinct members other than i and b */
static void pick3(gsl_rng *g, int np, int i, int b, int *r) {
    for (int k = 0; k < 3; k++) {
        int ok;
        do {
            r[k] = (int)gsl_rng_uniform_int(g, (unsigned long)np);
            ok = r[k] != i && r[k] != b;
            for (int j = 0; j < k; j++) {
                ok &= r[k] != r[j];
            }
        } while (!ok);
    }
}

int zp_de_generations(zp_search *S, long budget) {
    if (!S->de && (zp_search_halted(S) || !(S->de = create(S)))) {
        return 0;
    }
    zp_de *d = S->de;
    int n = S->n, ngen = 0;
    double *trial = malloc(sizeof *trial * d->np * n);
    long stop = S->spent + budget;
    while (trial && !zp_search_halted(S) && S->spent + d->np <= stop) {
        /* best1bin: the best plus a scaled difference of two members (the third is drawn, as
           SciPy draws it, and left unused), crossed with the target, clipped to the box */
        int b = best_member(S, d);
        double F = DITHER_LO + (1 - DITHER_LO) * gsl_rng_uniform(d->rng);
        for (int i = 0; i < d->np; i++) {
            int r[3];
            pick3(d->rng, d->np, i, b, r);
            int jr = (int)gsl_rng_uniform_int(d->rng, (unsigned long)n);
            double *t = trial + (size_t)i * n;
            for (int k = 0; k < n; k++) {
                double v = d->x[(size_t)i * n + k];
                if (k == jr || gsl_rng_uniform(d->rng) < CROSS) {
                    v = d->x[(size_t)b * n + k] +
                        F * (d->x[(size_t)r[0] * n + k] - d->x[(size_t)r[1] * n + k]);
                }
                t[k] = v < S->lo[k] ? S->lo[k] : v > S->hi[k] ? S->hi[k] : v;
            }
        }
        int n0 = S->a.n, nd = zp_scan_batch(S, trial, d->np);
        /* a trial at least as good as its target replaces it */
        for (int i = 0; i < nd && n0 + i < S->a.n; i++) {
            const zp_eval *e = &S->a.e[n0 + i];
            if (!zp_search_ahead(&d->e[i], d->x + (size_t)i * n, e, trial + (size_t)i * n, n)) {
                d->e[i] = *e;
                memcpy(d->x + (size_t)i * n, trial + (size_t)i * n, sizeof *trial * n);
            }
        }
        ngen++;
    }
    free(trial);
    return ngen;
}
