/* A row's derived quantities, computed by one function for every reader, and the packed store
   of a run's rows. */
#include "row.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a square sum this far below a maximum's square puts the magnitude below the maximum whatever
   the rounding (a few ulps in each); magnitudes below ROW_MAG_TINY are always compared whole */
#define ROW_SQ_BELOW (1 - 1e-9)
#define ROW_MAG_TINY 1e-100

void zp_row_loads(const zp_model *m, const zp_loads *loads, double *joint, double *acc_g) {
    for (int i = 0; i < m->nlink; i++) {
        joint[i] = hypot(loads->joint[i][0], loads->joint[i][1]);
        acc_g[i] = hypot(loads->acc[i + 1][0], loads->acc[i + 1][1] + m->g) / m->g;
    }
}

/* fmax(peak, hypot(a, b) / scale): the hypot, slow in libm, only where it may win */
static double max_hypot(double peak, double a, double b, double scale) {
    double top = peak * scale;
    if (top > ROW_MAG_TINY && a * a + b * b < top * top * ROW_SQ_BELOW) {
        return peak;
    }
    return fmax(peak, hypot(a, b) / scale);
}

void zp_row_loads_max(const zp_model *m, const zp_loads *loads, double *joint, double *acc_g) {
    for (int i = 0; i < m->nlink; i++) {
        joint[i] = max_hypot(joint[i], loads->joint[i][0], loads->joint[i][1], 1);
        acc_g[i] = max_hypot(acc_g[i], loads->acc[i + 1][0], loads->acc[i + 1][1] + m->g, m->g);
    }
}

void zp_row_derive(const zp_model *m, const zp_row *r, zp_row_view *v) {
    v->speed = hypot(r->c.v[0], r->c.v[1]);
    zp_state_com(m, &r->c, v->com);
    zp_state_relative(m, &r->c, v->phi, v->w);
    v->e = zp_state_energy(m, &r->c);
    zp_row_loads(m, &r->loads, v->joint, v->acc_g);
}

/* a packed row: t, section, e_impulse, normal, hold, the work integrals, the drive's states,
   then the chain's coordinates and rates, the joint forces and the body accelerations */
enum { ROW_T, ROW_SEC, ROW_E_IMPULSE, ROW_NORMAL, ROW_HOLD, ROW_WORK };

int zp_row_store_init(zp_row_store *t, const zp_model *m, int cap) {
    int nq = 2 + m->nlink;
    *t = (zp_row_store){.cap = cap, .nlink = m->nlink, .nwork = m->nwork, .ndrive = m->ndrive};
    t->stride = ROW_WORK + m->nwork + m->ndrive + 2 * nq + 2 * m->nlink + 2 * (m->nlink + 1);
    t->v = malloc(sizeof *t->v * (size_t)t->stride * (size_t)cap);
    return t->v ? 0 : -1;
}

void zp_row_store_free(zp_row_store *t) {
    free(t->v);
    t->v = NULL;
    t->n = t->cap = 0;
}

void zp_row_store_put(zp_row_store *t, const zp_row *r) {
    double *p = t->v + (size_t)t->n++ * (size_t)t->stride;
    int nq = 2 + t->nlink;
    p[ROW_T] = r->t;
    p[ROW_SEC] = r->sec;
    p[ROW_E_IMPULSE] = r->e_impulse;
    p[ROW_NORMAL] = r->loads.normal;
    p[ROW_HOLD] = r->loads.hold;
    double w[ZP_W_MAX] = {[ZP_W_DRIVE] = r->w_drive, [ZP_W_DAMP] = r->w_damp};
    memcpy(w + ZP_W_EFFECTS, r->w_effect, sizeof r->w_effect);
    memcpy(p + ROW_WORK, w, sizeof *w * t->nwork);
    p += ROW_WORK + t->nwork;
    if (t->ndrive) {
        *p++ = r->f_applied;
    }
    memcpy(p, r->c.q, sizeof *p * nq);
    memcpy(p + nq, r->c.v, sizeof *p * nq);
    memcpy(p + 2 * nq, r->loads.joint, sizeof *p * 2 * t->nlink);
    memcpy(p + 2 * nq + 2 * t->nlink, r->loads.acc, sizeof *p * 2 * (t->nlink + 1));
}

void zp_row_store_get(const zp_row_store *t, int k, zp_row *r) {
    const double *p = t->v + (size_t)k * (size_t)t->stride;
    int nq = 2 + t->nlink;
    memset(r, 0, sizeof *r);
    r->t = p[ROW_T];
    r->sec = (int)p[ROW_SEC];
    r->e_impulse = p[ROW_E_IMPULSE];
    r->loads.normal = p[ROW_NORMAL];
    r->loads.hold = p[ROW_HOLD];
    double w[ZP_W_MAX] = {0};
    memcpy(w, p + ROW_WORK, sizeof *w * t->nwork);
    r->w_drive = w[ZP_W_DRIVE];
    r->w_damp = w[ZP_W_DAMP];
    memcpy(r->w_effect, w + ZP_W_EFFECTS, sizeof r->w_effect);
    p += ROW_WORK + t->nwork;
    if (t->ndrive) {
        r->f_applied = *p++;
    }
    memcpy(r->c.q, p, sizeof *p * nq);
    memcpy(r->c.v, p + nq, sizeof *p * nq);
    memcpy(r->loads.joint, p + 2 * nq, sizeof *p * 2 * t->nlink);
    memcpy(r->loads.acc, p + 2 * nq + 2 * t->nlink, sizeof *p * 2 * (t->nlink + 1));
}

double zp_row_store_t(const zp_row_store *t, int k) {
    return t->v[(size_t)k * (size_t)t->stride + ROW_T];
}
