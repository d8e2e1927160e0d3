/* The search's scans (scan.h): the constant pushes and per-parameter lines, each with zooms. */
#include "scan.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LINE_PTS 49     /* points of a line over a whole range */
#define STEP_SHARE 0.25 /* first polish step, share of the survivable width along a line */
#define ZOOM 2          /* local minima of a line refined */
#define ZOOM_PTS 12     /* points of each refinement */
#define LINE_PASSES 2   /* passes of lines through the best, while they improve */

static double at_share(const zp_search_state *S, int k, double u) {
    return fmin(S->lo[k] + (S->hi[k] - S->lo[k]) * u, S->hi[k]);
}

static int arch_ahead(const zp_search_state *S, int i, int j) {
    return zp_search_state_ahead(&S->a.e[i], zp_search_state_point(S, i), &S->a.e[j],
                                 zp_search_state_point(S, j), S->n);
}

/* the ZOOM best local minima of the score among archive points [n0, n0 + n), best first */
static int local_minima(const zp_search_state *S, int n0, int n, int *best) {
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
static double along(const zp_search_state *S, int i, int k) {
    const double *f = zp_search_state_point(S, i);
    return k >= 0 ? f[k] : (f[0] - S->lo[0]) / (S->hi[0] - S->lo[0]);
}

/* one parameter k over [a, b] in npt points, the others at cur (k < 0: the constant pushes,
   every parameter at the same share of the box from a to b); then twice more, finer, around
   the ZOOM best local minima of the score: runs that die further along point at survivable
   bands narrower than the grid */
static void line(zp_search_state *S, const double *cur, int k, double a, double b, int npt,
                 int depth, double *pts) {
    for (int i = 0; i < npt; i++) {
        double *p = pts + (size_t)i * S->n, t = a + (b - a) * i / (npt - 1);
        for (int j = 0; j < S->n; j++) {
            p[j] = k < 0 ? at_share(S, j, t) : j == k ? t : cur[j];
        }
    }
    int n0 = S->a.n;
    int n = zp_search_state_batch(S, pts, npt);
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

/* 1 when a line in k through cur was scanned already (it differs only in k from its origin);
   else it is remembered as scanned */
static int seen_line(const zp_search_state *S, zp_scan *sc, const double *cur, int k) {
    size_t row = (size_t)S->n + 1;
    for (int j = 0; j < sc->nlined; j++) {
        const double *o = sc->lined + j * row;
        int same = o[S->n] == k;
        for (int i = 0; same && i < S->n; i++) {
            same = i == k || o[i] == cur[i];
        }
        if (same) {
            return 1;
        }
    }
    if (sc->nlined == sc->linecap) {
        int cap = sc->linecap ? 2 * sc->linecap : 64;
        double *l = realloc(sc->lined, sizeof *l * row * cap);
        if (!l) {
            return 1; /* out of memory: not scanned again */
        }
        sc->lined = l;
        sc->linecap = cap;
    }
    double *o = sc->lined + sc->nlined++ * row;
    memcpy(o, cur, sizeof *cur * S->n);
    o[S->n] = k;
    return 0;
}

/* how far parameter k may move from cur before a run fails, among archive points from n0 */
static double survivable_width(const zp_search_state *S, const double *cur, int k, int n0) {
    double left = S->lo[k], right = S->hi[k];
    for (int i = n0; i < S->a.n; i++) {
        double f = zp_search_state_point(S, i)[k];
        if (!zp_objective_feasible(&S->a.e[i])) {
            left = f < cur[k] ? fmax(left, f) : left;
            right = f > cur[k] ? fmin(right, f) : right;
        }
    }
    return right - left;
}

void zp_scan_init(zp_scan *sc, const zp_search_state *S, double share) {
    *sc = (zp_scan){.lined = NULL};
    for (int k = 0; k < S->n; k++) {
        sc->step[k] = share * (S->hi[k] - S->lo[k]);
    }
}

void zp_scan_free(zp_scan *sc) {
    free(sc->lined);
    sc->lined = NULL;
}

int zp_scan_diag(zp_search_state *S) {
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
void zp_scan_lines(zp_search_state *S, zp_scan *sc, const double *origin, const zp_eval *origin_e) {
    double cur[ZP_SCHED_MAX_PARAMS], *pts = malloc(sizeof *pts * LINE_PTS * S->n);
    if (!pts) {
        return;
    }
    memcpy(cur, origin, sizeof *cur * S->n);
    zp_eval be = *origin_e;
    for (int pass = 0; pass < LINE_PASSES && !zp_search_state_halted(S); pass++) {
        int moved = 0;
        for (int k = 0; k < S->n && !zp_search_state_halted(S); k++) {
            if (seen_line(S, sc, cur, k)) {
                continue;
            }
            int n0 = S->a.n;
            line(S, cur, k, S->lo[k], S->hi[k], LINE_PTS, 2, pts);
            for (int i = n0; i < S->a.n; i++) {
                if (zp_search_state_ahead(&S->a.e[i], zp_search_state_point(S, i), &be, cur,
                                          S->n)) {
                    be = S->a.e[i];
                    memcpy(cur, zp_search_state_point(S, i), sizeof *cur * S->n);
                    moved = 1;
                }
            }
            sc->step[k] = fmin(STEP_SHARE * survivable_width(S, cur, k, n0), sc->step[k]);
        }
        if (!moved) {
            break;
        }
    }
    free(pts);
}
