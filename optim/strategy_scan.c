/* The scan's global phase (strategies.def): the next points of a low-discrepancy sequence
   (GSL's Sobol, Halton past 40 parameters) shifted by the seed, run in parallel: 64 in each of
   the first two rounds, then doubling each round up to 2048. */
#include <gsl/gsl_qrng.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#include "strategy.h"

#define LDS_FIRST 64 /* points of the sequence in the first round */
#define LDS_MAX 2048 /* ... doubling each round up to this */

typedef struct sequence {
    gsl_qrng *q;                       /* extended in order */
    double shift[ZP_SCHED_MAX_PARAMS]; /* its seeded shift, share of the box */
} sequence;

static void sequence_free(void *state) {
    sequence *sq = state;
    if (sq && sq->q) {
        gsl_qrng_free(sq->q);
    }
    free(sq);
}

static void *sequence_create(const zp_strategy *self, const zp_search_state *S) {
    (void)self;
    sequence *sq = calloc(1, sizeof *sq);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    if (sq) {
        sq->q = gsl_qrng_alloc(S->n <= 40 ? gsl_qrng_sobol : gsl_qrng_halton, S->n);
    }
    if (!sq || !sq->q || !g) {
        gsl_rng_free(g);
        sequence_free(sq);
        return NULL;
    }
    /* the seed shifts the sequence (a Cranley-Patterson rotation): same seed, same points */
    gsl_rng_set(g, S->o->seed);
    for (int k = 0; k < S->n; k++) {
        sq->shift[k] = gsl_rng_uniform(g);
    }
    gsl_rng_free(g);
    return sq;
}

static zp_status sequence_explore(void *state, zp_search_state *S, int round, char *err,
                                  size_t errlen) {
    (void)err;
    (void)errlen;
    sequence *sq = state;
    int count = LDS_FIRST;
    for (int r = 2; r <= round && count < LDS_MAX; r++) {
        count *= 2;
    }
    double *pts = malloc(sizeof *pts * count * S->n);
    if (!pts) {
        return ZP_OK; /* the round goes on without them */
    }
    double v[ZP_SCHED_MAX_PARAMS];
    for (int i = 0; i < count; i++) {
        gsl_qrng_get(sq->q, v);
        for (int k = 0; k < S->n; k++) {
            double u = v[k] + sq->shift[k];
            u -= floor(u);
            pts[(size_t)i * S->n + k] = fmin(S->lo[k] + (S->hi[k] - S->lo[k]) * u, S->hi[k]);
        }
    }
    zp_search_state_batch(S, pts, count);
    free(pts);
    return ZP_OK;
}

const zp_strategy zp_strategy_scan = {.name = "scan",
                                      .phase = ZP_STRATEGY_GLOBAL,
                                      .create = sequence_create,
                                      .free = sequence_free,
                                      .explore = sequence_explore};
