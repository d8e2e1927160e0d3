/* The trajectory's columns: one table of what each shows, its names and its unit. */
#include "out_columns.h"

#include <math.h>
#include <stdio.h>

#define DEG (180.0 / M_PI)

/* how many columns an entry spans: one, one per link (its %d 1..N), per body (0..N), per
   effect's work integral (named by effect.h's table, shown as it says), one per drive state
   (the applied force of a drive with a response time; none without) */
typedef enum span { ONE, PER_LINK, PER_BODY, PER_WORK, PER_DRIVE } span;

/* an entry: one or two quantities per index (a pair alternates: com0_x, com0_y, com1_x, ..) */
typedef struct entry {
    span per;
    int n; /* quantities per index, 1 or 2 */
    zp_out_quantity q[2];
    const char *csv[2]; /* names, a %d for the index */
    const char *lib;    /* NULL: not in the C library */
    double scale;       /* SI to the CSV's unit */
} entry;

static const entry table[] = {
    {ONE, 1, {ZP_OUT_Q_T}, {"t"}, "t", 1},
    {ONE, 1, {ZP_OUT_Q_SECTION}, {"section"}, "section", 1},
    {ONE, 1, {ZP_OUT_Q_X}, {"x"}, "x", 1},
    {ONE, 1, {ZP_OUT_Q_Y}, {"y"}, "y", 1},
    {ONE, 1, {ZP_OUT_Q_SPEED}, {"speed"}, "speed", 1},
    {PER_LINK, 1, {ZP_OUT_Q_THETA}, {"theta%d_deg"}, "theta%d", DEG},
    {PER_LINK, 1, {ZP_OUT_Q_OMEGA}, {"omega%d_deg_s"}, "omega%d", DEG},
    {PER_LINK, 1, {ZP_OUT_Q_PHI}, {"phi%d_deg"}, "phi%d", DEG},
    {PER_BODY, 2, {ZP_OUT_Q_COM_X, ZP_OUT_Q_COM_Y}, {"com%d_x", "com%d_y"}, NULL, 1},
    {ONE, 1, {ZP_OUT_Q_KINETIC}, {"kinetic"}, "kinetic", 1},
    {ONE, 1, {ZP_OUT_Q_POTENTIAL}, {"potential"}, "potential", 1},
    {ONE, 1, {ZP_OUT_Q_ENERGY}, {"energy"}, NULL, 1},
    {ONE, 1, {ZP_OUT_Q_DRIVE}, {"drive_work"}, "drive_work", 1},
    {PER_DRIVE, 1, {ZP_OUT_Q_F_APPLIED}, {"f_applied"}, NULL, 1},
    {ONE, 1, {ZP_OUT_Q_DAMP}, {"damper_work"}, "damper_work", 1},
    {ONE, 1, {ZP_OUT_Q_IMPULSE}, {"impulse_loss"}, "impulse_loss", 1},
    {ONE, 1, {ZP_OUT_Q_NORMAL}, {"normal_force"}, NULL, 1},
    {PER_WORK, 1, {ZP_OUT_Q_WORK}, {NULL}, NULL, 1},
    {PER_LINK, 2, {ZP_OUT_Q_JOINT_X, ZP_OUT_Q_JOINT_Y}, {"joint%d_fx", "joint%d_fy"}, NULL, 1},
    {PER_LINK, 1, {ZP_OUT_Q_ACC}, {"acc%d_g"}, NULL, 1},
};
#define NENTRY ((int)(sizeof table / sizeof *table))

/* how many indices an entry spans in m */
static int count(const zp_model *m, span per) {
    switch (per) {
    case ONE:
        return 1;
    case PER_LINK:
        return m->nlink;
    case PER_BODY:
        return m->nlink + 1;
    case PER_WORK:
        return ZP_EFFECT_NWORK; /* those shown: skipped() */
    case PER_DRIVE:
        return m->ndrive;
    }
    return 0;
}

/* 1 for index i of en that m does not show (an effect's work it leaves out) */
static int skipped(const zp_model *m, const entry *en, int i) {
    return en->per == PER_WORK && !zp_effect_work_shown(m->physics, i);
}

/* the indices of en that m shows */
static int shown_count(const zp_model *m, const entry *en) {
    int k = 0;
    for (int i = 0; i < count(m, en->per); i++) {
        k += !skipped(m, en, i);
    }
    return k;
}

/* quantity q of row r (its derived view v) at index i (link i 0-based, body i, work i) */
static double value(zp_out_quantity q, const zp_row *r, const zp_row_view *v, int i) {
    switch (q) {
    case ZP_OUT_Q_T:
        return r->t;
    case ZP_OUT_Q_SECTION:
        return r->sec + 1;
    case ZP_OUT_Q_X:
        return r->c.q[0];
    case ZP_OUT_Q_Y:
        return r->c.q[1];
    case ZP_OUT_Q_SPEED:
        return v->speed;
    case ZP_OUT_Q_THETA:
        return r->c.q[2 + i];
    case ZP_OUT_Q_OMEGA:
        return r->c.v[2 + i];
    case ZP_OUT_Q_PHI:
        return v->phi[i];
    case ZP_OUT_Q_COM_X:
        return v->com[i][0];
    case ZP_OUT_Q_COM_Y:
        return v->com[i][1];
    case ZP_OUT_Q_KINETIC:
        return v->e.kinetic;
    case ZP_OUT_Q_POTENTIAL:
        return v->e.potential;
    case ZP_OUT_Q_ENERGY:
        return v->e.kinetic + v->e.potential;
    case ZP_OUT_Q_DRIVE:
        return r->w_drive;
    case ZP_OUT_Q_F_APPLIED:
        return r->f_applied;
    case ZP_OUT_Q_DAMP:
        return r->w_damp;
    case ZP_OUT_Q_IMPULSE:
        return r->e_impulse;
    case ZP_OUT_Q_NORMAL:
        return r->loads.normal;
    case ZP_OUT_Q_WORK:
        return r->w_effect[i];
    case ZP_OUT_Q_JOINT_X:
        return r->loads.joint[i][0];
    case ZP_OUT_Q_JOINT_Y:
        return r->loads.joint[i][1];
    case ZP_OUT_Q_ACC:
        return v->acc_g[i];
    case ZP_OUT_Q_COUNT:
        break;
    }
    return NAN;
}

int zp_out_columns(const zp_model *m, zp_out_column *col) {
    int j = 0;
    for (int e = 0; e < NENTRY; e++) {
        const entry *en = &table[e];
        for (int i = 0; i < count(m, en->per); i++) {
            if (skipped(m, en, i)) {
                continue;
            }
            /* names count links from 1, bodies from 0 (the trolley) */
            int shown = en->per == PER_LINK ? i + 1 : i;
            for (int c = 0; c < en->n; c++, j++) {
                const char *csv =
                    en->per == PER_WORK ? zp_effect_work_names(i)->column : en->csv[c];
                snprintf(col[j].csv, ZP_OUT_COLUMN_NAME, csv, shown);
                snprintf(col[j].lib, ZP_OUT_COLUMN_NAME, en->lib ? en->lib : "", shown);
                col[j].csv_scale = en->scale;
            }
        }
    }
    return j;
}

int zp_out_columns_find(const zp_model *m, zp_out_quantity q, int *n) {
    int j = 0;
    for (int e = 0; e < NENTRY; e++) {
        const entry *en = &table[e];
        int k = shown_count(m, en);
        if (en->n == 1 && en->q[0] == q) {
            *n = k;
            return k ? j : -1;
        }
        j += k * en->n;
    }
    *n = 0;
    return -1;
}

void zp_out_columns_values(const zp_model *m, const zp_row *r, double *v) {
    zp_row_view view;
    zp_row_derive(m, r, &view);
    int j = 0;
    for (int e = 0; e < NENTRY; e++) {
        const entry *en = &table[e];
        for (int i = 0; i < count(m, en->per); i++) {
            for (int c = 0; c < en->n && !skipped(m, en, i); c++) {
                v[j++] = value(en->q[c], r, &view, i);
            }
        }
    }
}
