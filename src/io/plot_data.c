/* The data files of one run's figures (plot_parts.h): the pose at a chosen moment from the
   trajectory rows and the chain geometry of MODEL.md "Bodies" (state.c), the course, and the
   trajectory with its derived columns. */
#include <math.h>
#include <string.h>

#include "plot_parts.h"
#include "state.h"

#define COURSE_STEP 0.2 /* m between course samples */
/* ---- the state at a chosen moment ---- */


/* the pose a fraction u of the way from row a to row b (positions interpolated linearly) */
static zp_plot_pose pose_between(const zp_model *m, const zp_row *a, const zp_row *b, double u) {
    zp_plot_pose ps;
    zp_chain c;
    for (int k = 0; k < 2 + m->nlink; k++) {
        c.q[k] = a->c.q[k] + u * (b->c.q[k] - a->c.q[k]);
        c.v[k] = a->c.v[k] + u * (b->c.v[k] - a->c.v[k]);
    }
    ps.t = a->t + u * (b->t - a->t);
    ps.sec = u < 0.5 ? a->sec : b->sec;
    ps.speed = hypot(c.v[0], c.v[1]);
    ps.p[0][0] = c.q[0];
    ps.p[0][1] = c.q[1];
    for (int i = 0; i < m->nlink; i++) {
        ps.p[i + 1][0] = ps.p[i][0] + m->len[i] * sin(c.q[2 + i]);
        ps.p[i + 1][1] = ps.p[i][1] - m->len[i] * cos(c.q[2 + i]);
    }
    zp_state_com(m, &c, ps.com);
    return ps;
}

int zp_plot_pose_at(const zp_model *m, const zp_row *rows, int n, zp_plot_at kind, double at,
                   zp_plot_pose *ps) {
    for (int k = 0; k < n; k++) {
        double v = kind == ZP_PLOT_AT_X ? rows[k].c.q[0] : rows[k].t;
        if (v >= at) {
            double prev = k ? (kind == ZP_PLOT_AT_X ? rows[k - 1].c.q[0] : rows[k - 1].t) : v;
            double u = k && v > prev ? (at - prev) / (v - prev) : 1;
            *ps = pose_between(m, &rows[k ? k - 1 : 0], &rows[k], u);
            return 0;
        }
    }
    return -1;
}



void zp_plot_grow(zp_plot_box *b, double x, double y) {
    b->x0 = fmin(b->x0, x);
    b->x1 = fmax(b->x1, x);
    b->y0 = fmin(b->y0, y);
    b->y1 = fmax(b->y1, y);
}

zp_plot_box zp_plot_write_course(FILE *f, const zp_model *m) {
    zp_plot_box b = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    fputs("x y section\n", f);
    for (int k = 0; k < m->nsec; k++) {
        int npt = 1 + (int)ceil((m->xb[k + 1] - m->xb[k]) / COURSE_STEP);
        for (int j = 0; j <= npt; j++) {
            double x = m->xb[k] + (m->xb[k + 1] - m->xb[k]) * j / npt;
            double y = zp_course_eval(m->course, k, x).f;
            fprintf(f, "%.6g %.6g %d\n", x, y, k + 1);
            zp_plot_grow(&b, x, y);
        }
        fputc('\n', f);
    }
    return b;
}

/* plot_run.dat: one line per trajectory row, named columns; returns the extent of the
   centres-of-mass paths */
zp_plot_box zp_plot_write_run(FILE *f, const zp_model *m, const zp_row *rows, int n) {
    zp_plot_box b = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    fputs("t section x y speed", f);
    for (int i = 0; i <= m->nlink; i++) {
        fprintf(f, " com%d_x com%d_y", i, i);
    }
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, " phi%d", i);
    }
    fputs(" kinetic potential total drive_work damper_loss kink_loss balance normal", f);
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, " joint%d", i);
    }
    fputc('\n', f);
    double e0 = 0;
    for (int k = 0; k < n; k++) {
        const zp_row *r = &rows[k];
        zp_row_view v;
        zp_row_derive(m, r, &v);
        double total = v.e.kinetic + v.e.potential;
        if (k == 0) {
            e0 = total - r->w_drive + r->w_damp + r->e_impulse;
        }
        fprintf(f, "%.9g %d %.9g %.9g %.9g", r->t, r->sec + 1, r->c.q[0], r->c.q[1], v.speed);
        for (int i = 0; i <= m->nlink; i++) {
            fprintf(f, " %.9g %.9g", v.com[i][0], v.com[i][1]);
            zp_plot_grow(&b, v.com[i][0], v.com[i][1]);
        }
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, " %.9g", v.phi[i] * ZP_PLOT_DEG);
        }
        fprintf(f, " %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g", v.e.kinetic, v.e.potential, total,
                r->w_drive, r->w_damp, r->e_impulse, e0 + r->w_drive - r->w_damp - r->e_impulse,
                r->loads.normal);
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, " %.9g", v.joint[i]);
        }
        fputc('\n', f);
    }
    return b;
}

void zp_plot_write_pose(FILE *f, const zp_model *m, const zp_plot_pose *ps) {
    for (int i = 0; i < m->nlink; i++) {
        fprintf(f, "%.9g %.9g %.9g %.9g %d %.9g %.9g\n", ps->p[i][0], ps->p[i][1], ps->p[i + 1][0],
                ps->p[i + 1][1], i + 1, ps->com[i + 1][0], ps->com[i + 1][1]);
    }
    fputs("\n\n", f);
}