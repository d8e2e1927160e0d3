/* The search's scan (search_int.h): batches of points run in parallel and cut at the budget in
   their serial order; the constant pushes and per-parameter lines, each with zooms, and a
   seeded low-discrepancy sequence extended in order. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "search_int.h"

#define LINE_PTS 49     /* points of a line over a whole range */
#define STEP_SHARE 0.25 /* first polish step, share of the survivable width along a line */
#define ZOOM 2          /* local minima of a line refined */
#define ZOOM_PTS 12     /* points of each refinement */
#define LINE_PASSES 2   /* passes of lines through the best, while they improve */

const double *zp_archive_f(const zp_search *S, int i) {
    return S->a.f + (size_t)i * S->n;
}

/* doubles the capacity of two parallel arrays of rows of sa and sb bytes; 0: out of memory,
   both arrays still valid */
static int grow(void **a, size_t sa, void **b, size_t sb, int *cap, int first) {
    int nc = *cap ? 2 * *cap : first;
    void *na = realloc(*a, sa * nc);
    *a = na ? na : *a;
    void *nb = na ? realloc(*b, sb * nc) : NULL;
    *b = nb ? nb : *b;
    *cap = nb ? nc : *cap;
    return nb != NULL;
}

int zp_archive_add(zp_search *S, const double *f, const zp_eval *e) {
    zp_archive *a = &S->a;
    void *pf = a->f, *pe = a->e;
    int ok = a->n < a->cap || grow(&pf, sizeof *f * S->n, &pe, sizeof *e, &a->cap, 1024);
    a->f = pf;
    a->e = pe;
    if (!ok) {
        return -1;
    }
    memcpy(a->f + (size_t)a->n * S->n, f, sizeof *f * S->n);
    a->e[a->n] = *e;
    return a->n++;
}

typedef struct batch {
    zp_search *S;
    const double *pts;
    zp_eval *e;
    char *done;
    long left;
} batch;

static void batch_job(void *user, int i, zp_sim *s, zp_result *r) {
    batch *b = user;
    if (i < b->left && !zp_search_stopped(b->S)) {
        zp_search_eval(b->S, s, r, b->pts + (size_t)i * b->S->n, &b->e[i]);
        b->done[i] = 1;
    }
}

int zp_scan_batch(zp_search *S, const double *pts, int npt) {
    batch b = {S, pts, malloc(sizeof *b.e * (npt ? npt : 1)), calloc(npt ? npt : 1, 1),
               S->o->max_evals - S->spent};
    int ndone = 0;
    if (b.e && b.done && !zp_search_halted(S)) {
        S->exhausted |= npt >= b.left;
        zp_pool_map(S->pool, npt, batch_job, &b, NULL, NULL);
        for (int i = 0; i < npt; i++) {
            if (b.done[i] && zp_archive_add(S, pts + (size_t)i * S->n, &b.e[i]) >= 0) {
                zp_search_record(S, ++S->spent, &b.e[i]);
                ndone++;
            }
        }
    }
    free(b.e);
    free(b.done);
    return ndone;
}

static double at_share(const zp_search *S, int k, double u) {
    return fmin(S->lo[k] + (S->hi[k] - S->lo[k]) * u, S->hi[k]);
}

int zp_scan_lds(zp_search *S, int count) {
    double *pts = malloc(sizeof *pts * count * S->n);
    if (!pts) {
        return 0;
    }
    double v[ZP_SCHED_MAX_PARAMS];
    for (int i = 0; i < count; i++) {
        gsl_qrng_get(S->q, v);
        for (int k = 0; k < S->n; k++) {
            double u = v[k] + S->shift[k];
            pts[(size_t)i * S->n + k] = at_share(S, k, u - floor(u));
        }
    }
    int nd = zp_scan_batch(S, pts, count);
    free(pts);
    return nd;
}

static int arch_ahead(const zp_search *S, int i, int j) {
    return zp_search_ahead(&S->a.e[i], zp_archive_f(S, i), &S->a.e[j], zp_archive_f(S, j), S->n);
}

/* the ZOOM best local minima of the score among archive points [n0, n0 + n), best first */
static int local_minima(const zp_search *S, int n0, int n, int *best) {
    int nb = 0;
    for (int i = n0; i < n0 + n; i++) {
        int lmin =
            (i == n0 || arch_ahead(S, i, i - 1)) && (i == n0 + n - 1 || arch_ahead(S, i, i + 1));
        if (!lmin) {
            continue;
        }
        int at = nb < ZOOM ? nb++ : ZOOM;
        while (at > 0 && arch_ahead(S, i, best[at - 1])) {
            if (at < ZOOM) {
                best[at] = best[at - 1];
            }
            at--;
        }
        if (at < ZOOM) {
            best[at] = i;
        }
    }
    return nb;
}

/* where archive point i lies along line k: its parameter k, or (k < 0) its share of the box */
static double along(const zp_search *S, int i, int k) {
    const double *f = zp_archive_f(S, i);
    return k >= 0 ? f[k] : (f[0] - S->lo[0]) / (S->hi[0] - S->lo[0]);
}

/* one parameter k over [a, b] in npt points, the others at cur (k < 0: the constant pushes,
   every parameter at the same share of the box from a to b); then twice more, finer, around
   the ZOOM best local minima of the score: runs that die further along point at survivable
   bands narrower than the grid */
static void line(zp_search *S, const double *cur, int k, double a, double b, int npt, int depth,
                 double *pts) {
    for (int i = 0; i < npt; i++) {
        double *p = pts + (size_t)i * S->n, t = a + (b - a) * i / (npt - 1);
        for (int j = 0; j < S->n; j++) {
            p[j] = k < 0 ? at_share(S, j, t) : j == k ? t : cur[j];
        }
    }
    int n0 = S->a.n;
    int n = zp_scan_batch(S, pts, npt);
    if (depth == 0 || n < npt) {
        return;
    }
    int best[ZOOM];
    int nb = local_minima(S, n0, n, best);
    for (int j = 0; j < nb; j++) {
        int i = best[j];
        double lo = along(S, i > n0 ? i - 1 : i, k);
        double hi = along(S, i < n0 + n - 1 ? i + 1 : i, k);
        line(S, cur, k, lo, hi, ZOOM_PTS, depth - 1, pts);
    }
}

/* 1 when a line in k through cur was scanned already (it differs only in k from its origin) */
static int seen_line(zp_search *S, const double *cur, int k) {
    for (int j = 0; j < S->nlined; j++) {
        const double *o = S->lined + (size_t)j * S->n;
        int same = S->lined_k[j] == k;
        for (int i = 0; same && i < S->n; i++) {
            same = i == k || o[i] == cur[i];
        }
        if (same) {
            return 1;
        }
    }
    void *pl = S->lined, *pk = S->lined_k;
    int ok = S->nlined < S->linecap ||
             grow(&pl, sizeof *cur * S->n, &pk, sizeof *S->lined_k, &S->linecap, 64);
    S->lined = pl;
    S->lined_k = pk;
    if (!ok) {
        return 1;
    }
    memcpy(S->lined + (size_t)S->nlined * S->n, cur, sizeof *cur * S->n);
    S->lined_k[S->nlined++] = k;
    return 0;
}

/* how far parameter k may move from cur before a run fails, among archive points from n0 */
static double survivable_width(const zp_search *S, const double *cur, int k, int n0) {
    double left = S->lo[k], right = S->hi[k];
    for (int i = n0; i < S->a.n; i++) {
        double f = zp_archive_f(S, i)[k];
        if (!zp_objective_feasible(&S->a.e[i])) {
            left = f < cur[k] ? fmax(left, f) : left;
            right = f > cur[k] ? fmin(right, f) : right;
        }
    }
    return right - left;
}

int zp_scan_diag(zp_search *S) {
    double *pts = malloc(sizeof *pts * LINE_PTS * S->n);
    int n0 = S->a.n;
    if (pts) {
        line(S, NULL, -1, 0, 1, LINE_PTS, 2, pts);
    }
    free(pts);
    return S->a.n - n0 >= LINE_PTS ? n0 + LINE_PTS - 1 : -1;
}

/* Survivable bands can be narrower than any affordable grid in all parameters at once, but a
   line resolves one parameter finely. */
void zp_scan_lines(zp_search *S, const double *origin, const zp_eval *origin_e) {
    double cur[ZP_SCHED_MAX_PARAMS], *pts = malloc(sizeof *pts * LINE_PTS * S->n);
    if (!pts) {
        return;
    }
    memcpy(cur, origin, sizeof *cur * S->n);
    zp_eval be = *origin_e;
    for (int pass = 0; pass < LINE_PASSES && !zp_search_halted(S); pass++) {
        int moved = 0;
        for (int k = 0; k < S->n && !zp_search_halted(S); k++) {
            if (seen_line(S, cur, k)) {
                continue;
            }
            int n0 = S->a.n;
            line(S, cur, k, S->lo[k], S->hi[k], LINE_PTS, 2, pts);
            for (int i = n0; i < S->a.n; i++) {
                if (zp_search_ahead(&S->a.e[i], zp_archive_f(S, i), &be, cur, S->n)) {
                    be = S->a.e[i];
                    memcpy(cur, zp_archive_f(S, i), sizeof *cur * S->n);
                    moved = 1;
                }
            }
            S->step[k] = fmin(STEP_SHARE * survivable_width(S, cur, k, n0), S->step[k]);
        }
        if (!moved) {
            break;
        }
    }
    free(pts);
}
