/* The data files of one run's figures (plot_data.h): the pose of a row, or between rows, from
   the chain geometry of docs/model.md "Bodies" (state.c), the course, and the
   trajectory with its derived columns. */
#include "plot_data.h"

#include <math.h>
#include <string.h>

#include "state.h"

#define COURSE_STEP 0.2 /* m between course samples */
/* ---- the state at a chosen moment ---- */

/* the pose of chain c at time t on section sec */
static zp_plot_pose pose_of(const zp_model *m, double t, int sec, const zp_chain *c) {
    zp_plot_pose ps;
    ps.t = t;
    ps.sec = sec;
    ps.speed = hypot(c->v[0], c->v[1]);
    ps.p[0][0] = c->q[0];
    ps.p[0][1] = c->q[1];
    for (int i = 0; i < m->nlink; i++) {
        ps.p[i + 1][0] = ps.p[i][0] + m->len[i] * sin(c->q[2 + i]);
        ps.p[i + 1][1] = ps.p[i][1] - m->len[i] * cos(c->q[2 + i]);
    }
    zp_state_com(m, c, ps.com);
    return ps;
}

zp_plot_pose zp_plot_data_pose_of_row(const zp_model *m, const zp_row *r) {
    return pose_of(m, r->t, r->sec, &r->c);
}

zp_plot_pose zp_plot_data_pose_at_t(const zp_model *m, const zp_row_store *rows, double t) {
    int k = 0;
    while (k + 1 < rows->n && zp_row_store_t(rows, k) < t) {
        k++;
    }
    zp_row ra, rb, *a = &ra, *b = &rb;
    zp_row_store_get(rows, k ? k - 1 : 0, a);
    zp_row_store_get(rows, k, b);
    double u = b->t > a->t ? (t - a->t) / (b->t - a->t) : 1;
    /* positions interpolated linearly: enough for an animation's moving picture */
    zp_chain c;
    for (int j = 0; j < 2 + m->nlink; j++) {
        c.q[j] = a->c.q[j] + u * (b->c.q[j] - a->c.q[j]);
        c.v[j] = a->c.v[j] + u * (b->c.v[j] - a->c.v[j]);
    }
    return pose_of(m, a->t + u * (b->t - a->t), u < 0.5 ? a->sec : b->sec, &c);
}

void zp_plot_data_grow(zp_plot_box *b, double x, double y) {
    b->x0 = fmin(b->x0, x);
    b->x1 = fmax(b->x1, x);
    b->y0 = fmin(b->y0, y);
    b->y1 = fmax(b->y1, y);
}

zp_plot_box zp_plot_data_course(FILE *f, const zp_model *m) {
    zp_plot_box b = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    fputs("x y section\n", f);
    for (int k = 0; k < m->nsec; k++) {
        int npt = 1 + (int)ceil((m->xb[k + 1] - m->xb[k]) / COURSE_STEP);
        for (int j = 0; j <= npt; j++) {
            double x = m->xb[k] + (m->xb[k + 1] - m->xb[k]) * j / npt;
            double y = zp_model_track(m, m->course, k, x).f;
            fprintf(f, "%.6g %.6g %d\n", x, y, k + 1);
            zp_plot_data_grow(&b, x, y);
        }
        fputc('\n', f);
    }
    return b;
}

/* E(0) plus the work done on the system minus the losses so far: the energy row r should have */
static double balance(double e0, const zp_row *r) {
    double b = e0 + r->w_drive - r->w_damp - r->e_impulse;
    for (int w = 0; w < ZP_EFFECT_NWORK; w++) {
        b -= r->w_effect[w];
    }
    return b;
}

/* the drive at row r: the speed along its direction (m/s; horizontal x', tangent the speed
   along the course, signed as x') and the force it applies there (N), the schedule's at once
   with its power cap: a row's chain lies on the course, so its slope is y' / x' */
static void drive_at_row(const zp_model *m, const zp_schedule *sh, const zp_row *r, double *v,
                         double *force) {
    *v =
        m->drive == ZP_DRIVE_TANGENT ? copysign(hypot(r->c.v[0], r->c.v[1]), r->c.v[0]) : r->c.v[0];
    *force = m->ndrive ? r->f_applied
                       : zp_drive_force(sh, &(zp_drive_state){r->t, r->c.q[0], *v, r->sec});
}

/* plot_run.dat: one line per trajectory row, named columns; returns the extent of the
   centres-of-mass paths */
zp_plot_box zp_plot_data_run(FILE *f, const zp_model *m, const zp_row_store *rows,
                             const zp_schedule *sched) {
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
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        if (zp_effect_work_shown(m->physics, k)) {
            fprintf(f, " %s", zp_effect_work_names(k)->plot);
        }
    }
    fputs(" felt_g", f); /* the largest felt g over the judged links ([limits] g_links) */
    fputs(sched ? " drive_speed drive_force\n" : "\n", f);
    double e0 = 0;
    for (int k = 0; k < rows->n; k++) {
        zp_row row;
        zp_row_store_get(rows, k, &row);
        const zp_row *r = &row;
        zp_row_view v;
        zp_row_derive(m, r, &v);
        double total = v.e.kinetic + v.e.potential;
        if (k == 0) {
            e0 = total - r->w_drive + r->w_damp + r->e_impulse;
            for (int w = 0; w < ZP_EFFECT_NWORK; w++) {
                e0 += r->w_effect[w];
            }
        }
        fprintf(f, "%.9g %d %.9g %.9g %.9g", r->t, r->sec + 1, r->c.q[0], r->c.q[1], v.speed);
        for (int i = 0; i <= m->nlink; i++) {
            fprintf(f, " %.9g %.9g", v.com[i][0], v.com[i][1]);
            zp_plot_data_grow(&b, v.com[i][0], v.com[i][1]);
        }
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, " %.9g", v.phi[i] * ZP_PLOT_DEG);
        }
        fprintf(f, " %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g", v.e.kinetic, v.e.potential, total,
                r->w_drive, r->w_damp, r->e_impulse, balance(e0, r), r->loads.normal);
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, " %.9g", v.joint[i]);
        }
        for (int w = 0; w < ZP_EFFECT_NWORK; w++) {
            if (zp_effect_work_shown(m->physics, w)) {
                fprintf(f, " %.9g", r->w_effect[w]);
            }
        }
        double g = 0;
        for (int i = 0; i < m->nlink; i++) {
            g = m->g_links >> i & 1 ? fmax(g, v.acc_g[i]) : g;
        }
        fprintf(f, " %.9g", g);
        if (sched) {
            double dv, force;
            drive_at_row(m, sched, r, &dv, &force);
            fprintf(f, " %.9g %.9g", dv, force);
        }
        fputc('\n', f);
    }
    return b;
}

void zp_plot_data_pose(FILE *f, const zp_model *m, const zp_plot_pose *ps) {
    for (int i = 0; i < m->nlink; i++) {
        fprintf(f, "%.9g %.9g %.9g %.9g %d %.9g %.9g\n", ps->p[i][0], ps->p[i][1], ps->p[i + 1][0],
                ps->p[i + 1][1], i + 1, ps->com[i + 1][0], ps->com[i + 1][1]);
    }
    fputs("\n\n", f);
}