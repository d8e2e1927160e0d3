/* The scenario sets (scen_set.h): built from the box, grown, ordered worst first. */
#include "scen_set.h"

#include <gsl/gsl_qrng.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "state.h"

#define SOBOL_MAX_DIM 40  /* gsl_qrng_sobol's largest dimension */
#define STREAM_SET 0x5e7u /* the set's shift: a stream apart from the adversary's (robust.c) and
                             from ZP_ROBUST_STREAM_VERIFY */

void zp_scen_set_free(zp_scen_set *set) {
    free(set->u);
    free(set->sc);
    free(set->m);
    free(set->start);
    free(set->order);
    free(set->fails);
    free(set->judge);
    memset(set, 0, sizeof *set);
}

static int grow(zp_scen_set *set) {
    int cap = set->cap ? 2 * set->cap : 64;
    double *u = realloc(set->u, sizeof *u * ZP_BOX_MAX * cap);
    set->u = u ? u : set->u;
    zp_scenario *sc = realloc(set->sc, sizeof *sc * cap);
    set->sc = sc ? sc : set->sc;
    zp_model *m = realloc(set->m, sizeof *m * cap);
    set->m = m ? m : set->m;
    zp_chain *st = realloc(set->start, sizeof *st * cap);
    set->start = st ? st : set->start;
    int *order = realloc(set->order, sizeof *order * cap);
    set->order = order ? order : set->order;
    long *fails = realloc(set->fails, sizeof *fails * cap);
    set->fails = fails ? fails : set->fails;
    zp_objective *judge = set->judge ? realloc(set->judge, sizeof *judge * cap) : NULL;
    set->judge = judge ? judge : set->judge;
    if (!u || !sc || !m || !st || !order || !fails || (set->judge && !judge)) {
        return -1;
    }
    set->cap = cap;
    return 0;
}

zp_status zp_scen_set_add(zp_scen_set *set, const zp_box *b, const zp_model *nom,
                          const double *u) {
    if (set->n == set->cap && grow(set)) {
        return ZP_ERR_NOMEM;
    }
    int j = set->n++;
    memcpy(set->u + (size_t)j * ZP_BOX_MAX, u, sizeof *u * b->d);
    zp_box_scenario(b, u, &set->sc[j]);
    zp_scenario_model(nom, &set->sc[j], &set->m[j]);
    zp_chain c0;
    zp_state_start(nom, nom->course, &c0);
    zp_scenario_start(&c0, nom->nlink, &set->sc[j], &set->start[j]);
    /* a new scenario is the adversary's worst: it goes first */
    memmove(set->order + 1, set->order, sizeof *set->order * j);
    set->order[0] = j;
    set->fails[j] = 0;
    if (set->judge) {
        set->judge[j] = (zp_objective){0}; /* the search's objective */
    }
    return ZP_OK;
}

zp_status zp_scen_set_add_model(zp_scen_set *set, const zp_model *m, const zp_scenario *sc,
                                const zp_chain *start, const zp_objective *judge) {
    if (set->n == set->cap && grow(set)) {
        return ZP_ERR_NOMEM;
    }
    if (judge && !set->judge) {
        /* the scenarios so far keep the search's objective: theirs is marked by m == NULL */
        set->judge = calloc((size_t)set->cap, sizeof *set->judge);
        if (!set->judge) {
            return ZP_ERR_NOMEM;
        }
    }
    int j = set->n++;
    memset(set->u + (size_t)j * ZP_BOX_MAX, 0, sizeof *set->u * ZP_BOX_MAX);
    set->sc[j] = *sc;
    set->m[j] = *m;
    if (start) {
        set->start[j] = *start;
    } else {
        zp_chain c0;
        zp_state_start(m, m->course, &c0);
        zp_scenario_start(&c0, m->nlink, sc, &set->start[j]);
    }
    set->order[j] = j; /* in the order given */
    set->fails[j] = 0;
    if (set->judge) {
        set->judge[j] = judge ? *judge : (zp_objective){0};
        set->judge[j].set = NULL;
    }
    return ZP_OK;
}

/* corner i of the box: coordinate c at -1 or +1 by bit c of i */
static void corner(int d, unsigned long i, double *u) {
    for (int c = 0; c < d; c++) {
        u[c] = (i >> c) & 1 ? 1 : -1;
    }
}

zp_status zp_scen_set_build(zp_scen_set *set, const zp_box *b, const zp_model *nom, int samples,
                            unsigned long seed) {
    memset(set, 0, sizeof *set);
    if (b->d == 0) {
        return ZP_OK;
    }
    gsl_qrng *q = gsl_qrng_alloc(b->d <= SOBOL_MAX_DIM ? gsl_qrng_sobol : gsl_qrng_halton, b->d);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!q || !rng) {
        gsl_qrng_free(q);
        gsl_rng_free(rng);
        return ZP_ERR_NOMEM;
    }
    gsl_rng_set(rng, seed ^ STREAM_SET);
    double shift[ZP_BOX_MAX], p[ZP_BOX_MAX], u[ZP_BOX_MAX];
    for (int c = 0; c < b->d; c++) {
        shift[c] = gsl_rng_uniform(rng);
    }
    int all = b->d < 30 && (1L << b->d) <= samples;
    int ncorner = all ? (int)(1L << b->d) : samples / 2;
    zp_status st = ZP_OK;
    gsl_qrng_get(q, p); /* the first point is the origin: skipped */
    for (int i = 0; i < samples && !st; i++) {
        if (i < ncorner && all) {
            corner(b->d, (unsigned long)i, u);
        } else {
            gsl_qrng_get(q, p);
            for (int c = 0; c < b->d; c++) {
                double w = fmod(p[c] + shift[c], 1.0);
                u[c] = i < ncorner ? (w < 0.5 ? -1 : 1) : 2 * w - 1;
            }
        }
        st = zp_scen_set_add(set, b, nom, u);
    }
    /* the corners first, in the order they were made */
    for (int i = 0; i < set->n; i++) {
        set->order[i] = i;
    }
    set->ncorner = ncorner < set->n ? ncorner : set->n;
    gsl_qrng_free(q);
    gsl_rng_free(rng);
    return st;
}

/* scenario i goes before j: more fails, then the lower index */
static int before(const zp_scen_set *set, int i, int j) {
    return set->fails[i] != set->fails[j] ? set->fails[i] > set->fails[j] : i < j;
}

void zp_scen_set_reorder(zp_scen_set *set) {
    /* insertion sort: a few hundred scenarios at most, between searches */
    for (int a = 1; a < set->n; a++) {
        int v = set->order[a], b = a;
        for (; b > 0 && before(set, v, set->order[b - 1]); b--) {
            set->order[b] = set->order[b - 1];
        }
        set->order[b] = v;
    }
}
