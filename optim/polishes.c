/* The polishes of one search and what they show (polishes.h). */
#include "polishes.h"

#include <stdlib.h>
#include <string.h>

#include "basins.h"

int zp_polishes_reserve(zp_polishes *p, int more) {
    if (p->n + more <= p->cap) {
        return 0;
    }
    int cap = 2 * (p->n + more);
    zp_leg_rec *r = realloc(p->rec, sizeof *r * cap);
    if (!r) {
        return -1;
    }
    p->rec = r;
    p->cap = cap;
    return 0;
}

void zp_polishes_free(zp_polishes *p) {
    free(p->rec);
    *p = (zp_polishes){0};
}

int zp_polishes_fresh(const zp_polishes *p, const zp_search_state *S, const double *f) {
    for (int j = 0; j < p->n; j++) {
        if (!zp_search_state_distinct(S, f, p->rec[j].start) ||
            !zp_search_state_distinct(S, f, p->rec[j].end)) {
            return 0;
        }
    }
    return 1;
}

int zp_polishes_visited(const zp_polishes *p, const zp_search_state *S, const zp_islands *m,
                        int is) {
    for (int j = 0; j < m->nnear; j++) {
        if (m->of[j] == is && !zp_polishes_fresh(p, S, zp_search_state_point(S, m->pt[j]))) {
            return 1;
        }
    }
    return 0;
}

/* per archive index, its island in the map of S (-1: outside it), *nisl the islands; NULL when
   out of memory */
static int *island_index(const zp_search_state *S, int *nisl) {
    zp_islands m;
    *nisl = 0;
    if (zp_islands_map(S, &m)) {
        return NULL;
    }
    int *island_of = malloc(sizeof *island_of * (S->a.n ? S->a.n : 1));
    for (int i = 0; island_of && i < S->a.n; i++) {
        island_of[i] = -1;
    }
    for (int j = 0; island_of && j < m.nnear; j++) {
        island_of[m.pt[j]] = m.of[j];
    }
    *nisl = m.n;
    zp_islands_free(&m);
    return island_of;
}

/* the basin of polish j's end: its island in the map (island_of: per archive index, -1 outside
   it), else the first earlier polish whose end is not distinct from it and equally survivable,
   numbered past the islands */
static int basin_of(const zp_polishes *p, const zp_search_state *S, const int *island_of, int nisl,
                    int j) {
    const zp_leg_rec *r = &p->rec[j];
    if (island_of && r->at >= 0 && island_of[r->at] >= 0) {
        return island_of[r->at];
    }
    int feas = zp_objective_feasible(&r->e);
    for (int i = 0; i < j; i++) {
        const zp_leg_rec *q = &p->rec[i];
        if (q->n > 0 && zp_objective_feasible(&q->e) == feas &&
            !zp_search_state_distinct(S, r->end, q->end) &&
            !(island_of && q->at >= 0 && island_of[q->at] >= 0)) {
            return nisl + i;
        }
    }
    return nisl + j;
}

/* polish j's end is survivable and distinct from every earlier survivable end */
static int fresh_end(const zp_polishes *p, const zp_search_state *S, int j) {
    const zp_leg_rec *r = &p->rec[j];
    int fresh = zp_objective_feasible(&r->e);
    for (int i = 0; i < j && fresh; i++) {
        fresh = p->rec[i].n == 0 || !zp_objective_feasible(&p->rec[i].e) ||
                zp_search_state_distinct(S, r->end, p->rec[i].end);
    }
    return fresh;
}

/* design note: the minima counted for Boender and Rinnooy Kan's estimate are the islands the
   polishes ended in, not their distinct end points: COBYLA stops anywhere along the margin's
   boundary of a wide island (on multi6 56 polishes ended at 48 points of one island), and each
   such point counted as a minimum would make any budget look too small */
/* the polishes that ran, into the result's basin counts; how many ran */
static int count_basins(const zp_polishes *p, zp_search_state *S) {
    zp_search_result *res = S->res;
    int nisl, nran = 0;
    int *island_of = island_index(S, &nisl);
    int *basin = malloc(sizeof *basin * (p->n ? p->n : 1));
    for (int j = 0; j < p->n; j++) {
        const zp_leg_rec *r = &p->rec[j];
        if (r->n == 0) {
            continue;
        }
        nran++;
        int b = basin_of(p, S, island_of, nisl, j), isnew = 1;
        for (int i = 0; basin && i < j && isnew; i++) {
            isnew = p->rec[i].n == 0 || basin[i] != b;
        }
        if (basin) {
            basin[j] = b;
        }
        res->nminima += isnew;
        if (fresh_end(p, S, j)) {
            res->nbasins++;
        }
        res->nreached += zp_objective_feasible(&r->e) && res->found &&
                         r->e.time <= res->best.time * (1 + ZP_SEARCH_REACH);
    }
    free(basin);
    free(island_of);
    return nran;
}

void zp_polishes_evidence(const zp_polishes *p, zp_search_state *S, long round_cost) {
    zp_search_result *res = S->res;
    res->nstarts = p->n;
    res->nbasins = res->nreached = res->nminima = 0;
    int nran = count_basins(p, S);
    res->unseen = zp_basins_unseen(nran, res->nminima);
    /* the budget that would help when the search stops short: the polishes the estimate
       still needs (at least one round), at the rate of the costliest round so far */
    int need = ZP_POLISHES_ROUND;
    if (!(res->unseen < ZP_SEARCH_UNSEEN)) {
        need = zp_basins_searches_needed(res->nminima, ZP_SEARCH_UNSEEN) - nran;
        need = need > ZP_POLISHES_ROUND ? need : ZP_POLISHES_ROUND;
    }
    long per = round_cost > 0 ? round_cost : S->spent;
    res->help_evals = S->spent + (long)((need + ZP_POLISHES_ROUND - 1) / ZP_POLISHES_ROUND) * per;
}

void zp_polishes_islands(const zp_polishes *p, zp_search_state *S) {
    zp_search_result *res = S->res;
    zp_islands m;
    if (zp_islands_map(S, &m)) {
        return;
    }
    res->nislands = m.n;
    for (int is = 0; is < m.n; is++) {
        res->npolished += zp_polishes_visited(p, S, &m, is);
        const zp_island *il = &m.isl[is];
        if (res->nshown < ZP_SEARCH_ISLANDS && zp_objective_feasible(&S->a.e[il->head])) {
            int k = res->nshown++;
            res->island_time[k] = S->a.e[il->head].time;
            memcpy(res->island_force[k], zp_search_state_point(S, il->head), sizeof(double) * S->n);
            res->island_pts[k] = il->nfeas;
        }
    }
    zp_islands_free(&m);
}

/* the best polish not used yet whose end is survivable and distinct from the ends kept; -1:
   none (those that cannot be marked used) */
static int next_end(const zp_polishes *p, const zp_search_state *S, int *used) {
    const zp_search_result *res = S->res;
    int b = -1;
    for (int j = 0; j < p->n; j++) {
        const zp_leg_rec *r = &p->rec[j];
        int ok = !used[j] && r->n > 0 && zp_objective_feasible(&r->e);
        for (int i = 0; ok && i < res->nends; i++) {
            ok = zp_search_state_distinct(S, r->end, res->ends[i]);
        }
        used[j] |= !ok;
        if (ok &&
            (b < 0 || zp_search_state_ahead(&r->e, r->end, &p->rec[b].e, p->rec[b].end, S->n))) {
            b = j;
        }
    }
    return b;
}

void zp_polishes_ends(const zp_polishes *p, zp_search_state *S) {
    zp_search_result *res = S->res;
    res->nends = 0;
    int *used = calloc(p->n ? p->n : 1, sizeof *used);
    while (used && res->nends < ZP_SEARCH_ENDS) {
        int b = next_end(p, S, used);
        if (b < 0) {
            break;
        }
        used[b] = 1;
        memcpy(res->ends[res->nends], p->rec[b].end, sizeof *p->rec[b].end * S->n);
        res->ends_time[res->nends++] = p->rec[b].e.time;
    }
    free(used);
}
