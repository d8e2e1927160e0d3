/* A run's load peaks: each evaluation of the loads counted in them, and with o.peaks the peak
   locator (peaks.c) and the felt-g envelope (envelope.c) fed the load histories of each step. */
#include "sim_peaks.h"

#include <math.h>

#include "sim_rhs.h"

/* the loads of row r taken into the peaks of a stretch of the course (an arc, the brake zone) */
static void stretch_peaks(const zp_model *m, const zp_row *r, zp_arc_peaks *ap) {
    double joint[ZP_MAX_LINKS], acc_g[ZP_MAX_LINKS];
    zp_row_loads(m, &r->loads, joint, acc_g);
    ap->normal_min = ap->visited ? fmin(ap->normal_min, r->loads.normal) : r->loads.normal;
    ap->normal_max = ap->visited ? fmax(ap->normal_max, r->loads.normal) : r->loads.normal;
    for (int i = 0; i < m->nlink; i++) {
        ap->acc_g = fmax(ap->acc_g, acc_g[i]);
    }
    ap->visited = 1;
}

zp_row zp_sim_peaks_row(zp_sim *s, double t, const double *y) {
    zp_row r = zp_sim_rhs_row(s, t, y);
    zp_load_peaks *p = &s->peaks;
    p->normal_min = fmin(p->normal_min, r.loads.normal);
    p->normal_max = fmax(p->normal_max, r.loads.normal);
    zp_row_loads_max(s->m, &r.loads, p->joint, p->acc_g);
    for (int a = 0; a < s->m->narc; a++) {
        if (r.c.q[0] >= s->m->arc[a].x1 && r.c.q[0] <= s->m->arc[a].x2) {
            stretch_peaks(s->m, &r, &s->arc_peaks[a]);
        }
    }
    if (s->zone) {
        stretch_peaks(s->m, &r, &s->zone_peaks);
    }
    return r;
}

/* every load history at state y: felt acceleration per link (g), then force per joint (N);
   the peaks take them in as a side effect */
static void load_values(zp_sim *s, double t, const double *y, double *v) {
    zp_row r = zp_sim_peaks_row(s, t, y);
    int n = s->m->nlink;
    zp_row_loads(s->m, &r.loads, v + n, v);
    for (int q = 0; q < 2 * n; q++) {
        v[q] = isfinite(v[q]) ? v[q] : 0;
    }
}

/* the load histories at time t inside the last step, from the dense output or (exact, where
   the method offers it) a step landed there */
static int dense_load_values(double t, int exact, double *v, void *user) {
    zp_sim *s = user;
    if (exact && !s->meth->land) {
        exact = 0;
    }
    if ((exact ? s->meth->land : s->meth->interpolate)(s->mwork, t, s->yout)) {
        return 1;
    }
    load_values(s, t, s->yout, v);
    return 0;
}

/* felt g of the judged links among the load histories v (load_values) */
static double judged_g(const zp_model *m, const double *v) {
    double g = 0;
    for (int i = 0; i < m->nlink; i++) {
        g = m->g_links >> i & 1 ? fmax(g, v[i]) : g;
    }
    return g;
}

/* judged felt g at time t inside the last step, from the dense output */
static int dense_judged_g(double t, double *g, void *user) {
    zp_sim *s = user;
    double v[ZP_PEAKS_MAX];
    if (dense_load_values(t, 0, v, s)) {
        return 1;
    }
    *g = judged_g(s->m, v);
    return 0;
}

void zp_sim_peaks_start(zp_sim *s, double t) {
    zp_peaks_reset(s->pk);
    if (s->m->nenv > 0) {
        zp_envelope_start(&s->env, s->m->nenv, s->m->env_g, t, 0);
    }
}

void zp_sim_peaks_restart(zp_sim *s, double t) {
    double v[ZP_PEAKS_MAX];
    load_values(s, t, s->y, v);
    zp_peaks_restart(s->pk, t, v);
    if (s->env.n) {
        zp_envelope_jump(&s->env, t, judged_g(s->m, v));
    }
}

void zp_sim_peaks_step(zp_sim *s, double t, zp_adv adv) {
    double vb[ZP_PEAKS_MAX];
    load_values(s, t, s->y, vb);
    /* a root inside a step is landed, off the step's dense output by its error: the interval
       is read on the one polynomial, or that gap shows as a false maximum */
    if (adv == ZP_ADV_ROOT) {
        dense_load_values(t, 0, vb, s);
    }
    zp_peaks_interval(s->pk, t, vb, dense_load_values, s);
    if (s->env.n) {
        zp_envelope_interval(&s->env, t, judged_g(s->m, vb), dense_judged_g, s);
    }
}

/* W, the drive's power F_applied v at (t, y); *capped 1 where its power cap binds on the
   schedule (a lagging applied force may then lie above or below the cap) */
static double drive_power(const zp_sim *s, double t, const double *y, int *capped) {
    double fp = s->m->drive == ZP_DRIVE_TANGENT ? s->track(s->m, s->course, s->sec, y[0]).fp : 0;
    zp_drive_state st = zp_drive_state_at(s->m->drive, t, y[0], y[s->w0 / 2], s->sec, fp);
    *capped = zp_drive_capped(s->sched, &st);
    return zp_sim_rhs_drive_applied(s, &st, y) * st.v;
}

void zp_sim_peaks_drive_start(zp_sim *s, double t, const double *y, zp_result *r) {
    r->drive_peak_power = fabs(drive_power(s, t, y, &s->drive_capped));
    s->drive_t = t;
}

void zp_sim_peaks_extremes(zp_sim *s, double t, const double *y, zp_result *r) {
    int capped;
    r->drive_peak_power = fmax(r->drive_peak_power, fabs(drive_power(s, t, y, &capped)));
    r->drive_time_at_cap += (t - s->drive_t) * (s->drive_capped + capped) / 2;
    s->drive_t = t;
    s->drive_capped = capped;
    double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
    s->form->relative(s->m, y, phi, w);
    for (int i = 0; i < s->m->nlink; i++) {
        r->max_rel_angle[i] = fmax(r->max_rel_angle[i], fabs(phi[i]));
    }
    r->x_min = fmin(r->x_min, y[0]);
    r->x_max = fmax(r->x_max, y[0]);
    /* load and speed peaks, when asked for, are sampled at every step (one more rhs call) */
    if (s->o.track_loads) {
        zp_chain c = zp_sim_peaks_row(s, t, y).c;
        r->max_speed = fmax(r->max_speed, hypot(c.v[0], c.v[1]));
    }
    if (s->form->constraint_residual) {
        zp_track tr = s->track(s->m, s->course, s->sec, y[0]);
        r->constraint_residual =
            fmax(r->constraint_residual, s->form->constraint_residual(s->m, &tr, y));
    }
}
