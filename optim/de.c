/* Differential evolution over the map (search_int.h): SciPy's best1bin with dither, its
   population seeded from the best distinct points scanned, each generation's trials drawn by a
   seeded generator before the batch runs them in parallel, so a seed gives the same generations
   on any thread count. Constraints by the search's total order (survivable first, then the
   penalised score: Deb's rules). */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "search_int.h"

#define POP_PER_PARAM 10 /* members per parameter */
#define POP_MIN 20
#define POP_MAX 80
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

typedef struct ranked {
    const zp_search *S;
    int i;
} ranked;

static int by_rank(const void *pa, const void *pb) {
    const ranked *a = pa, *b = pb;
    const zp_search *S = a->S;
    const double *fa = zp_archive_f(S, a->i), *fb = zp_archive_f(S, b->i);
    if (zp_search_ahead(&S->a.e[a->i], fa, &S->a.e[b->i], fb, S->n)) {
        return -1;
    }
    if (zp_search_ahead(&S->a.e[b->i], fb, &S->a.e[a->i], fa, S->n)) {
        return 1;
    }
    return (a->i > b->i) - (a->i < b->i);
}

/* the first population: the best archive points, each apart from those taken by ZP_DISTINCT of
   the box, then (too few) the best of the rest */
static zp_de *create(const zp_search *S) {
    int n = S->n, np = POP_PER_PARAM * n;
    np = np < POP_MIN ? POP_MIN : np > POP_MAX ? POP_MAX : np;
    if (S->a.n < np) {
        return NULL;
    }
    zp_de *d = calloc(1, sizeof *d);
    ranked *r = malloc(sizeof *r * S->a.n);
    char *taken = calloc(S->a.n, 1);
    if (!d || !r || !taken || !(d->x = malloc(sizeof *d->x * np * n)) ||
        !(d->e = malloc(sizeof *d->e * np)) || !(d->rng = gsl_rng_alloc(gsl_rng_mt19937))) {
        free(r);
        free(taken);
        zp_de_free(d);
        return NULL;
    }
    gsl_rng_set(d->rng, S->o->seed ^ STREAM);
    for (int i = 0; i < S->a.n; i++) {
        r[i] = (ranked){S, i};
    }
    qsort(r, S->a.n, sizeof *r, by_rank);
    for (int pass = 0; pass < 2 && d->np < np; pass++) {
        for (int i = 0; i < S->a.n && d->np < np; i++) {
            const double *f = zp_archive_f(S, r[i].i);
            int ok = !taken[i];
            for (int j = 0; pass == 0 && ok && j < d->np; j++) {
                ok = 0;
                for (int k = 0; k < n && !ok; k++) {
                    ok = fabs(f[k] - d->x[(size_t)j * n + k]) > ZP_DISTINCT * (S->hi[k] - S->lo[k]);
                }
            }
            if (ok) {
                taken[i] = 1;
                memcpy(d->x + (size_t)d->np * n, f, sizeof *f * n);
                d->e[d->np++] = S->a.e[r[i].i];
            }
        }
    }
    free(r);
    free(taken);
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
    if (!S->de && !(S->de = create(S))) {
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
