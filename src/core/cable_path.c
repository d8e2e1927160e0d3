/* The loaded-cable path as piecewise Chebyshev series (cable_path.h). Each value has its own
   series fitted to exact equilibria (f' is not the derivative of f's series, which would lose
   accuracy); a piece is halved until every series' last terms are at round-off. */
#include "cable_path.h"

#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

#include "cable_ride.h"
#include "cable_solve.h"

#define NODES 32 /* Chebyshev points per piece: each series' length */
/* the path and the cable's force (NVAL of them: they decide where a piece is halved), then the
   anchor tensions, fitted on the same pieces for the [limits] check (NFIT in all) */
enum { VAL_F, VAL_FP, VAL_FPP, VAL_ENERGY, VAL_HA, VAL_HB, NVAL, VAL_TA = NVAL, VAL_TB, NFIT };
/* a value's series on a piece is done when its last two terms are this small beside the
   value's size, */
#define TAIL_TOL 2e-14
/* or when they are no smaller than the terms before them (PLATEAU times those) and below
   NOISE_MAX: the series has reached the equilibria's own round-off, which halving the piece
   cannot lower. That round-off grows with the cable's stiffness against its tension (EA / T)
   and with the steepness of a side: up to 1e-10 of f'' on a stiff, nearly taut line. A series
   that falls to 1e-8 over its terms and then stops falling is not short of terms. */
#define PLATEAU 0.25
#define PLATEAU_TERMS 6
#define NOISE_MAX 1e-8
#define MAX_PIECES 256 /* past this, pieces are kept whatever their tail (the tail says so) */

typedef struct piece {
    double coef[NFIT][NODES];
} piece;

struct zp_cable_path {
    unsigned long id;    /* unique per path built in this process (the memo's key, not the
                            address, which a later path may reuse) */
    zp_cable cable;
    double load, lo, hi; /* N, m, m */
    int n;               /* pieces */
    int cap;             /* pieces allocated */
    double *ends;        /* owned: n + 1 increasing ends, piece k spans [ends[k], ends[k + 1]] */
    piece *pieces;       /* owned: n */
    double tail;         /* the largest relative last term over the pieces */
};

typedef struct builder {
    zp_cable_path *p;
    double scale[NVAL]; /* each value's largest magnitude, from the first fit */
    char *why;
    size_t whylen;
} builder;

static double node_t(int k) {
    return cos(M_PI * (k + 0.5) / NODES);
}

static void state_values(const zp_cable_state *s, double *v) {
    v[VAL_F] = s->f, v[VAL_FP] = s->fp, v[VAL_FPP] = s->fpp;
    v[VAL_ENERGY] = s->energy, v[VAL_HA] = s->ha, v[VAL_HB] = s->hb;
    v[VAL_TA] = s->ta, v[VAL_TB] = s->tb;
}

/* equilibria at the Chebyshev points of [a, b] (each from its left neighbour, the first from
   seed or from scratch) into st, and each value's series into pc */
static int fit(builder *bd, double a, double b, const zp_cable_state *seed, zp_cable_state *st,
               piece *pc) {
    const zp_cable *c = &bd->p->cable;
    double v[NODES][NFIT];
    const zp_cable_state *near = seed;
    for (int k = NODES - 1; k >= 0; k--) {
        double x = 0.5 * (a + b) + 0.5 * (b - a) * node_t(k);
        zp_status rc = near ? zp_cable_solve_near(c, near, x, &st[k], bd->why, bd->whylen)
                            : zp_cable_solve(c, bd->p->load, x, &st[k], bd->why, bd->whylen);
        if (rc != ZP_OK) {
            return -1;
        }
        state_values(&st[k], v[k]);
        near = &st[k];
    }
    /* c_j = (2 / N) sum_k v_k cos(j pi (k + 1/2) / N), c_0 halved */
    for (int j = 0; j < NODES; j++) {
        double sum[NFIT] = {0};
        for (int k = 0; k < NODES; k++) {
            double cj = cos(M_PI * j * (k + 0.5) / NODES);
            for (int i = 0; i < NFIT; i++) {
                sum[i] += v[k][i] * cj;
            }
        }
        for (int i = 0; i < NFIT; i++) {
            pc->coef[i][j] = sum[i] * (j ? 2.0 : 1.0) / NODES;
        }
    }
    return 0;
}

/* the largest last term of the piece's series (relative to each value's size), and whether
   every series is done */
static double piece_tail(const builder *bd, const piece *pc, int *done) {
    double tail = 0;
    *done = 1;
    for (int i = 0; i < NVAL; i++) {
        const double *c = pc->coef[i];
        double last = fmax(fabs(c[NODES - 1]), fabs(c[NODES - 2])) / bd->scale[i], before = 0;
        for (int j = NODES - 2 - PLATEAU_TERMS; j < NODES - 2; j++) {
            before = fmax(before, fabs(c[j]) / bd->scale[i]);
        }
        int plateau = last >= PLATEAU * before && last <= NOISE_MAX;
        *done &= last <= TAIL_TOL || plateau;
        tail = fmax(tail, last);
    }
    return tail;
}

static int append(builder *bd, double b, const piece *pc, double tail) {
    zp_cable_path *p = bd->p;
    if (p->n == p->cap) {
        int cap = 2 * p->cap;
        double *ends = realloc(p->ends, sizeof *ends * (size_t)(cap + 1));
        if (ends) {
            p->ends = ends;
        }
        piece *pieces = realloc(p->pieces, sizeof *pieces * (size_t)cap);
        if (pieces) {
            p->pieces = pieces;
        }
        if (!ends || !pieces) {
            snprintf(bd->why, bd->whylen, "out of memory building the cable's path");
            return -1;
        }
        p->cap = cap;
    }
    p->pieces[p->n] = *pc;
    p->ends[++p->n] = b;
    p->tail = fmax(p->tail, tail);
    return 0;
}

/* fits [a, b], halving it until the tails are at round-off; pieces are appended left to right */
static int build_piece(builder *bd, double a, double b, const zp_cable_state *seed, int first) {
    zp_cable_state st[NODES];
    piece pc;
    if (fit(bd, a, b, seed, st, &pc)) {
        return -1;
    }
    if (first) {
        for (int i = 0; i < NVAL; i++) {
            bd->scale[i] = 0;
            for (int k = 0; k < NODES; k++) {
                double v[NFIT];
                state_values(&st[k], v);
                bd->scale[i] = fmax(bd->scale[i], fabs(v[i]));
            }
            /* a value that is zero throughout (Pi_c of a weightless inextensible cable) */
            bd->scale[i] = bd->scale[i] > 0 ? bd->scale[i] : 1;
        }
    }
    int done;
    double tail = piece_tail(bd, &pc, &done), m = 0.5 * (a + b);
    if (!done && bd->p->n + 2 <= MAX_PIECES && a < m && m < b) {
        /* each half starts from the equilibrium nearest its left end */
        return build_piece(bd, a, m, &st[NODES - 1], 0) || build_piece(bd, m, b, &st[NODES / 2], 0);
    }
    return append(bd, b, &pc, tail);
}

zp_cable_path *zp_cable_path_create(const zp_cable *c, double load, double x_lo, double x_hi,
                                    char *why, size_t whylen) {
    if (!(c->xa < x_lo && x_lo < x_hi && x_hi < c->xb)) {
        snprintf(why, whylen, "path interval [%g, %g] m; expected %g < x_lo < x_hi < %g", x_lo,
                 x_hi, c->xa, c->xb);
        return NULL;
    }
    zp_cable_path *p = calloc(1, sizeof *p);
    if (p) {
        p->cap = 8;
        p->ends = malloc(sizeof *p->ends * (size_t)(p->cap + 1));
        p->pieces = malloc(sizeof *p->pieces * (size_t)p->cap);
    }
    if (!p || !p->ends || !p->pieces) {
        snprintf(why, whylen, "out of memory building the cable's path");
        zp_cable_path_free(p);
        return NULL;
    }
    static atomic_ulong built;
    p->id = atomic_fetch_add(&built, 1) + 1;
    p->cable = *c;
    p->load = load, p->lo = x_lo, p->hi = x_hi;
    p->ends[0] = x_lo;
    builder bd = {.p = p, .why = why, .whylen = whylen};
    if (build_piece(&bd, x_lo, x_hi, NULL, 1)) {
        zp_cable_path_free(p);
        return NULL;
    }
    return p;
}

void zp_cable_path_free(zp_cable_path *p) {
    if (p) {
        free(p->ends);
        free(p->pieces);
        free(p);
    }
}

/* the piece holding x and x's place t in [-1, 1] on it; -1 outside [lo, hi] */
static int locate(const zp_cable_path *p, double x, double *t) {
    if (!(x >= p->lo && x <= p->hi)) {
        return -1;
    }
    int lo = 0, hi = p->n - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (p->ends[mid] <= x) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    double a = p->ends[lo], b = p->ends[lo + 1];
    *t = fmin(1, fmax(-1, (2 * x - a - b) / (b - a)));
    return lo;
}

/* every series of pc at t (Clenshaw, side by side) */
static void series(const piece *pc, double t, double *out) {
    double b1[NVAL] = {0}, b2[NVAL] = {0};
    for (int j = NODES - 1; j >= 1; j--) {
        for (int i = 0; i < NVAL; i++) {
            double b0 = 2 * t * b1[i] + (pc->coef[i][j] - b2[i]);
            b2[i] = b1[i];
            b1[i] = b0;
        }
    }
    for (int i = 0; i < NVAL; i++) {
        out[i] = t * b1[i] - b2[i] + pc->coef[i][0];
    }
}

/* The equations of motion ask for the course at x (f, f', f'') and then for the cable's force
   there (H_A, H_B, f'): one pass of the series serves both. A series' Clenshaw chain is
   latency-bound, so all six side by side cost what three do; the second ask reads this
   thread's memo of the last x. Each value is the same arithmetic either way, to the bit. */
typedef struct memo {
    unsigned long id; /* the path's id; 0: none */
    double x;
    double out[NVAL];
} memo;
static _Thread_local memo last;

/* every value at x into out (from the memo when x was the last asked of p in this thread): 0,
   or -1 outside the interval */
static int values_at(const zp_cable_path *p, double x, double *out) {
    if (last.id == p->id && last.x == x) {
        for (int i = 0; i < NVAL; i++) {
            out[i] = last.out[i];
        }
        return 0;
    }
    double t;
    int k = locate(p, x, &t);
    if (k < 0) {
        return -1;
    }
    series(&p->pieces[k], t, out);
    last.id = p->id;
    last.x = x;
    for (int i = 0; i < NVAL; i++) {
        last.out[i] = out[i];
    }
    return 0;
}

int zp_cable_path_track(const zp_cable_path *p, double x, double *f) {
    double out[NVAL];
    if (values_at(p, x, out)) {
        f[0] = f[1] = f[2] = NAN;
        return -1;
    }
    f[0] = out[VAL_F];
    f[1] = out[VAL_FP];
    f[2] = out[VAL_FPP];
    return 0;
}

int zp_cable_path_eval(const zp_cable_path *p, double x, zp_cable_path_value *v) {
    double out[NVAL];
    if (values_at(p, x, out)) {
        *v = (zp_cable_path_value){NAN, NAN, NAN, NAN, NAN, NAN, NAN};
        return -1;
    }
    *v = (zp_cable_path_value){.f = out[VAL_F],
                               .fp = out[VAL_FP],
                               .fpp = out[VAL_FPP],
                               .energy = out[VAL_ENERGY],
                               .ha = out[VAL_HA],
                               .hb = out[VAL_HB]};
    v->denergy = (v->ha - v->hb) - p->load * v->fp;
    return 0;
}

/* one series of pc at t (Clenshaw) */
static double series_one(const double *c, double t) {
    double b1 = 0, b2 = 0;
    for (int j = NODES - 1; j >= 1; j--) {
        double b0 = 2 * t * b1 + (c[j] - b2);
        b2 = b1;
        b1 = b0;
    }
    return t * b1 - b2 + c[0];
}

double zp_cable_path_anchor_max(const zp_cable_path *p, double x_lo, double x_hi) {
    double most = -INFINITY;
    for (int i = 0; i <= ZP_CABLE_RIDE_SAMPLES; i++) {
        double x = x_lo + (x_hi - x_lo) * i / ZP_CABLE_RIDE_SAMPLES, t;
        int k = locate(p, x, &t);
        if (k < 0) {
            return NAN;
        }
        const piece *pc = &p->pieces[k];
        most = fmax(most, fmax(series_one(pc->coef[VAL_TA], t), series_one(pc->coef[VAL_TB], t)));
    }
    return most;
}

void zp_cable_path_interval(const zp_cable_path *p, double *lo, double *hi) {
    *lo = p->lo;
    *hi = p->hi;
}

int zp_cable_path_pieces(const zp_cable_path *p) {
    return p->n;
}

double zp_cable_path_tail(const zp_cable_path *p) {
    return p->tail;
}
