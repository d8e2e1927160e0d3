/* The [limits] values of a sensitivity run and their derivatives (sens_peaks.h). The peaks of
   the load histories and of the drive's power are located as the plain run locates its load
   peaks (peaks.c on the dense output, here of the augmented state), so the point of each peak
   carries its sensitivities. */
#include "sens_peaks.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define KMH 3.6 /* km/h per m/s */
/* two histories whose peaks lie closer than this share apart: the largest is a maximum of two
   maxima, not differentiable */
#define TIE_SHARE 1e-9

/* the points kept: the load histories' (felt g per link, then force per joint), then these */
enum { PT_POWER = ZP_PEAKS_MAX, PT_KINK, PT_ARRIVAL, PT_COUNT };

typedef struct point {
    double value; /* -INFINITY: none yet */
    double t;     /* s */
    int sec, arc, to; /* the section and piece read there; the kink's entered section */
    int shifted;      /* 1: at an event, whose time moves by dt */
    double dt[ZP_SCHED_MAX_PARAMS];
    double *ya; /* naug: the state and sensitivities there (before a kink's impulse) */
} point;

struct zp_sens_peaks {
    zp_sens *c;
    zp_limits lim;
    const zp_method *meth;
    void *mwork;
    zp_peaks *loads, *power; /* NULL: not asked for */
    point pt[PT_COUNT];
    double *buf, *f, *u, *yp; /* naug, n, n, n */
    double *mem;
};

zp_sens_peaks *zp_sens_peaks_create(zp_sens *c, const zp_limits *lim, const zp_method *meth,
                                    void *mwork, int *nomem) {
    *nomem = 0;
    if (!lim || !zp_limits_any(lim)) {
        return NULL;
    }
    zp_sens_peaks *P = calloc(1, sizeof *P);
    size_t naug = (size_t)c->naug;
    double *mem = P ? calloc(naug * (PT_COUNT + 1) + 3 * (size_t)c->n, sizeof *mem) : NULL;
    const double *m = lim->max;
    int loads = m[ZP_LIMIT_G] > 0 || m[ZP_LIMIT_JOINT] > 0;
    zp_peaks *pl = mem && loads ? zp_peaks_create(2 * c->sim->m->nlink) : NULL;
    zp_peaks *pp = mem && m[ZP_LIMIT_DRIVE_POWER] > 0 ? zp_peaks_create(1) : NULL;
    if (!mem || (loads && !pl) || (m[ZP_LIMIT_DRIVE_POWER] > 0 && !pp)) {
        zp_peaks_free(pl);
        zp_peaks_free(pp);
        free(mem);
        free(P);
        *nomem = 1;
        return NULL;
    }
    *P = (zp_sens_peaks){.c = c, .lim = *lim, .meth = meth, .mwork = mwork, .loads = pl,
                         .power = pp, .mem = mem};
    for (int q = 0; q < PT_COUNT; q++) {
        P->pt[q].value = -INFINITY;
        P->pt[q].ya = mem + naug * q;
    }
    P->buf = mem + naug * PT_COUNT;
    P->f = P->buf + naug;
    P->u = P->f + c->n;
    P->yp = P->u + c->n;
    return P;
}

void zp_sens_peaks_free(zp_sens_peaks *P) {
    if (P) {
        zp_peaks_free(P->loads);
        zp_peaks_free(P->power);
        free(P->mem);
        free(P);
    }
}

/* the histories at t on the dense output (peaks.h's zp_peaks_fn); exact reads it too: the
   augmented run lands no step for a peak */
static int dense_loads(double t, int exact, double *v, void *user) {
    zp_sens_peaks *P = user;
    double power;
    (void)exact;
    if (P->meth->interpolate(P->mwork, t, P->buf)) {
        return 1;
    }
    zp_sens_rhs_histories(P->c, t, P->buf, v, &power);
    return 0;
}

static int dense_power(double t, int exact, double *v, void *user) {
    zp_sens_peaks *P = user;
    (void)exact;
    if (P->meth->interpolate(P->mwork, t, P->buf)) {
        return 1;
    }
    zp_sens_rhs_histories(P->c, t, P->buf, NULL, v);
    return 0;
}

/* point q is now at (t, ya) on the current section, at an event moving by dt (NULL: none) */
static void keep(zp_sens_peaks *P, int q, double value, double t, const double *ya,
                 const double *dt) {
    point *p = &P->pt[q];
    p->value = value;
    p->t = t;
    p->sec = P->c->sim->sec;
    p->arc = P->c->sim->arc;
    p->shifted = dt != NULL;
    if (dt) {
        memcpy(p->dt, dt, sizeof p->dt);
    }
    if (ya) {
        memcpy(p->ya, ya, sizeof *ya * P->c->naug);
    } else {
        P->meth->interpolate(P->mwork, t, p->ya);
    }
}

/* the points of the histories in pk (offset q0 among the points) whose best rose past `before`;
   at the step's end t (or a restart) ya is the state there, elsewhere the dense output's */
static void kept_rises(zp_sens_peaks *P, const zp_peaks *pk, int q0, const double *before,
                       double t, const double *ya, const double *dt) {
    for (int q = 0; q < pk->nq; q++) {
        if (pk->best[q] > before[q]) {
            double tq = pk->best_t[q];
            keep(P, q0 + q, pk->best[q], tq, tq == t ? ya : NULL, tq == t ? dt : NULL);
        }
    }
}

void zp_sens_peaks_restart(zp_sens_peaks *P, double t, const double *ya, const double *dt) {
    static const double fixed[ZP_SCHED_MAX_PARAMS];
    double v[ZP_PEAKS_MAX], before[ZP_PEAKS_MAX], power;
    if (!P) {
        return;
    }
    zp_sens_rhs_histories(P->c, t, ya, P->loads ? v : NULL, &power);
    if (P->loads) {
        memcpy(before, P->loads->best, sizeof before);
        zp_peaks_restart(P->loads, t, v);
        kept_rises(P, P->loads, 0, before, t, ya, dt ? dt : fixed);
    }
    if (P->power) {
        before[0] = P->power->best[0];
        zp_peaks_restart(P->power, t, &power);
        kept_rises(P, P->power, PT_POWER, before, t, ya, dt ? dt : fixed);
    }
}

void zp_sens_peaks_step(zp_sens_peaks *P, double t, const double *ya) {
    double v[ZP_PEAKS_MAX], before[ZP_PEAKS_MAX], power;
    if (!P || !(P->loads || P->power)) {
        return;
    }
    zp_sens_rhs_histories(P->c, t, ya, P->loads ? v : NULL, &power);
    if (P->loads) {
        memcpy(before, P->loads->best, sizeof before);
        zp_peaks_interval(P->loads, t, v, dense_loads, P);
        kept_rises(P, P->loads, 0, before, t, ya, NULL);
    }
    if (P->power) {
        before[0] = P->power->best[0];
        zp_peaks_interval(P->power, t, &power, dense_power, P);
        kept_rises(P, P->power, PT_POWER, before, t, ya, NULL);
    }
}

void zp_sens_peaks_event(zp_sens_peaks *P, double t, const double *dt) {
    for (int q = 0; P && q < PT_KINK; q++) {
        point *p = &P->pt[q];
        if (p->value > -INFINITY && p->t == t && !p->shifted) {
            p->shifted = 1;
            memcpy(p->dt, dt, sizeof p->dt);
        }
    }
}

void zp_sens_peaks_kink(zp_sens_peaks *P, double t, const double *ya, int to, const double *dt) {
    double dv;
    if (P && P->lim.max[ZP_LIMIT_KINK_DV] > 0 && !zp_sens_rhs_kink_dv(P->c, ya, to, &dv) &&
        dv > P->pt[PT_KINK].value) {
        keep(P, PT_KINK, dv, t, ya, dt);
        P->pt[PT_KINK].to = to;
    }
}

void zp_sens_peaks_finish(zp_sens_peaks *P, double t, const double *ya, const double *dt,
                          int finished) {
    zp_sens_peaks_event(P, t, dt);
    if (P && finished) {
        keep(P, PT_ARRIVAL, zp_sens_rhs_speed(P->c, ya) * KMH, t, ya, dt);
    }
}

/* point q's value at (t, y) with the schedule as it stands */
static double value_at(zp_sens_peaks *P, int q, const point *p, double t, const double *y) {
    double v[ZP_PEAKS_MAX], power, dv;
    if (q < PT_POWER) {
        zp_sens_rhs_histories(P->c, t, y, v, &power);
        return v[q];
    }
    if (q == PT_POWER) {
        zp_sens_rhs_histories(P->c, t, y, NULL, &power);
        return power;
    }
    if (q == PT_KINK) {
        return zp_sens_rhs_kink_dv(P->c, y, p->to, &dv) ? NAN : dv;
    }
    return zp_sens_rhs_speed(P->c, y) * KMH;
}

/* d value / d p_k of point q into d: the five-point stencil along (dt, s_k + f dt, e_k) in
   (time, state, parameters), f the rates of the point's side (dt 0 away from events) */
static void derive(zp_sens_peaks *P, int q, double *d) {
    zp_sens *c = P->c;
    zp_sim *s = c->sim;
    const point *p = &P->pt[q];
    int n = c->n;
    s->sec = p->sec;
    s->arc = p->arc;
    if (p->shifted) {
        zp_sens_rhs_rates(c, p->t, p->ya, P->f);
    }
    static const double at[4] = {2, 1, -1, -2}, wt[4] = {-1, 8, -8, 1};
    for (int k = 0; k < c->np; k++) {
        const double *sk = p->ya + n * (k + 1);
        double tau = p->shifted ? p->dt[k] : 0, p_k = c->sched.p[k];
        double r = fmax(1 / fmax(fabs(p_k), 1), fabs(tau) / fmax(p->t, 1));
        for (int i = 0; i < n; i++) {
            P->u[i] = sk[i] + (p->shifted ? P->f[i] * tau : 0);
            r = i < s->w0 ? fmax(r, fabs(P->u[i]) / fmax(fabs(p->ya[i]), 1)) : r;
        }
        double h = ZP_SENS_STEP / r, sum = 0;
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < n; i++) {
                P->yp[i] = p->ya[i] + at[j] * h * P->u[i];
            }
            c->sched.p[k] = p_k + at[j] * h;
            sum += wt[j] * value_at(P, q, p, p->t + at[j] * h * tau, P->yp);
        }
        c->sched.p[k] = p_k;
        d[k] = sum / (12 * h);
    }
}

/* the point of limit i (-1: none), or why there is none or it is not differentiable there */
static int point_of(const zp_sens_peaks *P, int i, const char **why) {
    const zp_model *m = P->c->sim->m;
    int nl = m->nlink;
    *why = "";
    if (i == ZP_LIMIT_G || i == ZP_LIMIT_JOINT) {
        int q0 = i == ZP_LIMIT_G ? 0 : nl, best = -1, second = -1;
        for (int q = q0; q < q0 + nl; q++) {
            if (i == ZP_LIMIT_G && !(m->g_links >> (q - q0) & 1)) {
                continue;
            }
            if (best < 0 || P->pt[q].value > P->pt[best].value) {
                second = best;
                best = q;
            } else if (second < 0 || P->pt[q].value > P->pt[second].value) {
                second = q;
            }
        }
        if (second >= 0 && P->pt[second].value >= P->pt[best].value * (1 - TIE_SHARE)) {
            *why = "two links reach the peak together (a maximum of two maxima)";
        }
        return best;
    }
    if (i == ZP_LIMIT_ARRIVAL || i == ZP_LIMIT_MIN_ARRIVAL) {
        *why = P->pt[PT_ARRIVAL].value > -INFINITY ? "" : "not reached: the ride did not finish";
        return P->pt[PT_ARRIVAL].value > -INFINITY ? PT_ARRIVAL : -1;
    }
    if (i == ZP_LIMIT_KINK_DV) {
        return PT_KINK; /* no kink crossed: 0, and 0 it stays nearby */
    }
    if (i == ZP_LIMIT_DRIVE_POWER) {
        return PT_POWER;
    }
    *why = i == ZP_LIMIT_G_ENVELOPE ? "not differentiated: the length of an excursion above a level"
                                    : "not differentiated";
    return -1;
}

void zp_sens_peaks_result(zp_sens_peaks *P, zp_sens_limits *l) {
    for (int i = 0; P && i < ZP_LIMIT_COUNT; i++) {
        l->set[i] = P->lim.max[i] > 0;
        if (!l->set[i]) {
            continue;
        }
        const char *why;
        int q = point_of(P, i, &why);
        snprintf(l->why_not[i], sizeof l->why_not[i], "%s", why);
        l->value[i] = q < 0 ? NAN : P->pt[q].value > -INFINITY ? P->pt[q].value : 0;
        l->t[i] = q >= 0 && P->pt[q].value > -INFINITY ? P->pt[q].t : NAN;
        l->has[i] = q >= 0;
        if (q >= 0 && P->pt[q].value > -INFINITY) {
            derive(P, q, l->d[i]);
        }
    }
}
