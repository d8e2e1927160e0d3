/* The sensitivity run: the plain run's events with the jumps of the sensitivities at each.
 * At an event time t_e where g(y(t_e, p)) = 0 the time moves by dt_e/dp = -(g_y s) / (g_y f-); a
 * state jump y+ = h(y-) carries the sensitivities as s+ = h_y (s- + f- dt_e/dp) - f+ dt_e/dp
 * (saltation; h the identity where only the rates jump: a section switch on a rounded course,
 * an arc's tangent point, a brake zone's end). Kinks and the finish are roots in x, g_y s = s_x; a
 * death is the root |phi_i| = phi_max, dt_e/dp = -s_phi / phi'. The margin is the largest |phi_i|
 * over the run: at an interior maximum phi' = 0 and its derivative is sgn(phi) s_phi there; at an
 * event (a kink, the end) the time's shift adds sgn(phi) phi' dt_e/dp. */
#include "sens.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "events.h"
#include "sens_int.h"
#include "sens_peaks.h"
#include "sim.h"
#include "sim_events.h"
#include "sim_rhs.h"

/* the loop's own state beside the workspace */
typedef struct sens_loop {
    zp_sens c;
    const zp_method *meth;
    void *mwork;
    double *ya;       /* n (1 + np): state and sensitivities */
    double *fm, *fp;  /* n: rates before and after an event */
    double *u, *ym;   /* n: a direction, the state before an event */
    double dt[ZP_SCHED_MAX_PARAMS]; /* dt_e/dp of the event at hand */
    double breaks[ZP_SCHED_MAX_BREAKS];
    int nbreak;
    int roots[ZP_EVENTS_MAX];
    zp_sens_peaks *pk; /* owned; NULL: no [limits] */
    long seen_steps, seen_evals; /* the method's counts since its last reset, already added */
} sens_loop;

static void not_smooth(zp_sens_result *r, const char *why) {
    if (r->smooth) {
        r->smooth = 0;
        snprintf(r->why_not, sizeof r->why_not, "%s", why);
    }
}

static double stop_after(const sens_loop *L, double t, double t_max) {
    for (int i = 0; i < L->nbreak; i++) {
        if (L->breaks[i] > t) {
            return fmin(L->breaks[i], t_max);
        }
    }
    return t_max;
}

/* the integrator starts afresh at t (its counts from 0); 0 on success */
static int restart(sens_loop *L, double t) {
    L->seen_steps = L->seen_evals = 0;
    return L->meth->reset(L->mwork, t, L->ya, stop_after(L, t, L->c.sim->o.t_max));
}

/* the steps and rate evaluations the method made since the run last looked, into r: its
   counts run from its last reset, and a root that does not restart it (a joint's extremum)
   must not add them again */
static void count(sens_loop *L, zp_sens_result *r) {
    long steps = 0, evals = 0;
    L->meth->stats(L->mwork, &steps, &evals);
    r->steps += steps - L->seen_steps;
    r->rhs_evals += evals - L->seen_evals;
    L->seen_steps = steps;
    L->seen_evals = evals;
}

/* dt_e/dp of a root of g = x - level at the state now: -s_x / x' */
static void time_shift_x(sens_loop *L) {
    int n = L->c.n, iv = L->c.sim->w0 / 2;
    for (int k = 0; k < L->c.np; k++) {
        L->dt[k] = -L->ya[n * (k + 1)] / L->ya[iv];
    }
}

/* a candidate for the margin: joint i's |phi| now, its derivative shifted by L->dt (0 at an
   interior extremum, where phi' = 0) */
static void margin_candidate(sens_loop *L, zp_sens_result *r, double t, int i, int shifted) {
    const zp_sim *s = L->c.sim;
    double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
    s->form->relative(s->m, L->ya, phi, w);
    if (!(fabs(phi[i]) > r->margin_angle)) {
        return;
    }
    r->margin_angle = fabs(phi[i]);
    r->margin_link = i;
    r->margin_t = t;
    double sg = phi[i] < 0 ? -1 : 1;
    for (int k = 0; k < L->c.np; k++) {
        /* relative() is linear in the state: applied to s_k it gives s_phi */
        double sphi[ZP_MAX_LINKS], sw[ZP_MAX_LINKS];
        s->form->relative(s->m, L->ya + L->c.n * (k + 1), sphi, sw);
        r->dmargin[k] = sg * (sphi[i] + (shifted ? w[i] * L->dt[k] : 0));
    }
}

static void margin_all(sens_loop *L, zp_sens_result *r, double t, int shifted) {
    for (int i = 0; i < L->c.sim->m->nlink; i++) {
        margin_candidate(L, r, t, i, shifted);
    }
}

/* the sensitivities across an event at t that moves the state by map (NULL: the identity)
   into section `to`: s+ = h_y (s- + f- dt) - f+ dt */
static int jump(sens_loop *L, double t, int to, zp_event ev) {
    zp_sens *c = &L->c;
    zp_sim *s = c->sim;
    int n = c->n, is_kink = ev == ZP_EVENT_KINK;
    if (zp_sens_rhs_rates(c, t, L->ya, L->fm)) {
        return 1;
    }
    double *y_minus = L->ym;
    memcpy(y_minus, L->ya, sizeof *y_minus * n);
    if (is_kink) {
        if (zp_sens_rhs_kink_map(c, y_minus, to, L->ya)) {
            return 1;
        }
    } else {
        memcpy(s->y, L->ya, sizeof *s->y * n);
        memcpy(s->roots, L->roots, sizeof *s->roots * s->nroot);
        ev == ZP_EVENT_ZONE ? zp_sim_events_zone(s) : zp_sim_events_tangent(s);
        memcpy(L->ya, s->y, sizeof *s->y * n);
    }
    int from = s->sec;
    s->sec = to;
    zp_sim_events_place(s, L->ya[0], L->ya[s->w0 / 2]);
    int rc = zp_sens_rhs_rates(c, t, L->ya, L->fp);
    for (int k = 0; k < c->np && !rc; k++) {
        double *sk = L->ya + n * (k + 1);
        for (int i = 0; i < n; i++) {
            L->u[i] = sk[i] + L->fm[i] * L->dt[k];
        }
        if (is_kink) {
            s->sec = from; /* the map reads the chain on the section it leaves */
            rc = zp_sens_rhs_kink_deriv(c, y_minus, L->u, to, sk);
            s->sec = to;
        } else {
            memcpy(sk, L->u, sizeof *sk * n);
        }
        for (int i = 0; i < n; i++) {
            sk[i] -= L->fp[i] * L->dt[k];
        }
    }
    return rc;
}

/* the run ends at t on ev: its time's derivative (0 for t_max) and the margin's end point */
static void finish(sens_loop *L, zp_sens_result *r, double t, zp_event ev, int link) {
    zp_sim *s = L->c.sim;
    int n = L->c.n;
    r->time = t;
    if (ev == ZP_EVENT_DEATH) {
        double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
        s->form->relative(s->m, L->ya, phi, w);
        for (int k = 0; k < L->c.np; k++) {
            double sp[ZP_MAX_LINKS], sw[ZP_MAX_LINKS];
            s->form->relative(s->m, L->ya + n * (k + 1), sp, sw);
            L->dt[k] = -sp[link] / w[link];
        }
    } else if (ev == ZP_EVENT_FINISH || ev == ZP_EVENT_ROLLBACK) {
        time_shift_x(L);
    } else {
        memset(L->dt, 0, sizeof L->dt);
    }
    memcpy(r->dtime, L->dt, sizeof r->dtime);
    margin_all(L, r, t, 1);
    zp_sens_peaks_finish(L->pk, t, L->ya, L->dt, ev == ZP_EVENT_FINISH);
    r->outcome = ev == ZP_EVENT_DEATH ? ZP_OUTCOME_DIED
                 : ev == ZP_EVENT_FINISH ? ZP_OUTCOME_FINISHED
                                         : ZP_OUTCOME_STALLED;
    r->stall = ev == ZP_EVENT_ROLLBACK ? ZP_STALL_ROLLED_BACK
               : ev == ZP_EVENT_NONE   ? ZP_STALL_T_MAX
                                       : ZP_STALL_NONE;
}

/* the start at t = 0 (docs/model.md): at rest, the sensitivities 0; 0 to go on, 1 the run
   ended there (r filled), -1 it cannot be differentiated or computed (r's message) */
static int start(sens_loop *L, zp_sens_result *r) {
    zp_sim *s = L->c.sim;
    const zp_model *m = s->m;
    zp_chain ch;
    zp_state_start(m, s->course, &ch);
    const double zero_work[ZP_W_MAX] = {0};
    s->form->from_chain(m, &ch, zero_work, s->y);
    zp_sim_rhs_drive_start(s, s->y);
    zp_sim_events_start(s, &ch);
    int dir;
    if (m->stick && ch.v[0] == 0) {
        zp_result pr;
        memset(&pr, 0, sizeof pr);
        if (zp_sim_events_stick(s, 0, &pr, &dir)) {
            snprintf(r->message, sizeof r->message, "%s", pr.message);
            return -1;
        }
        if (s->stuck) {
            snprintf(r->message, sizeof r->message,
                     "the trolley is held by friction at the start: not differentiable");
            return -1;
        }
    } else {
        dir = zp_sim_events_departure(s, 0, s->y);
    }
    if (dir < 0) {
        memset(L->dt, 0, sizeof L->dt);
        memset(L->ya, 0, sizeof *L->ya * L->c.naug);
        memcpy(L->ya, s->y, sizeof *s->y * L->c.n);
        finish(L, r, 0, ZP_EVENT_ROLLBACK, 0);
        not_smooth(r, "rolled back at the start");
        return 1;
    }
    memset(L->ya, 0, sizeof *L->ya * L->c.naug);
    memcpy(L->ya, s->y, sizeof *s->y * L->c.n);
    zp_sens_peaks_restart(L->pk, 0, L->ya, NULL);
    return restart(L, 0) ? -1 : 0;
}

/* what a root at t means; 0 to go on, 1 the run ended, -1 it failed (r's message) */
static int on_root(sens_loop *L, zp_sens_result *r, double t) {
    zp_sim *s = L->c.sim;
    const zp_model *m = s->m;
    int link = 0, to = s->sec;
    zp_event ev = zp_events_classify(m, s->sec, L->roots, &link, &to);
    for (int i = 0; i < m->nlink; i++) {
        if (L->roots[ZP_ROOT_DEATH + m->nlink + i]) {
            margin_candidate(L, r, t, i, 0);
        }
    }
    if (ev == ZP_EVENT_NONE) {
        return 0;
    }
    if (ev == ZP_EVENT_DEATH || ev == ZP_EVENT_FINISH || ev == ZP_EVENT_ROLLBACK) {
        finish(L, r, t, ev, link);
        return 1;
    }
    if (ev == ZP_EVENT_REST) {
        not_smooth(r, "the trolley stopped under rolling resistance (stick or slip)");
        snprintf(r->message, sizeof r->message,
                 "the trolley stops under rolling resistance: not differentiable there");
        return -1;
    }
    time_shift_x(L);
    zp_sens_peaks_event(L->pk, t, L->dt);
    int kink = ev == ZP_EVENT_KINK, dir = to > s->sec ? 1 : -1;
    if (kink) {
        margin_all(L, r, t, 1); /* a corner: the impulse turns the joints' rates */
        zp_sens_peaks_kink(L->pk, t, L->ya, to, L->dt);
        r->ncross++;
    }
    if (jump(L, t, kink ? to : s->sec, ev)) {
        snprintf(r->message, sizeof r->message, "the mass matrix is not positive definite");
        return -1;
    }
    if (kink && (L->ya[s->w0 / 2] * dir <= 0 || r->ncross >= ZP_MAX_CROSSINGS)) {
        finish(L, r, t, ZP_EVENT_NONE, 0);
        r->stall = ZP_STALL_TRAPPED_AT_KINK;
        not_smooth(r, "trapped at a kink");
        return 1;
    }
    s->arc = zp_model_piece(m, s->sec, L->ya[0]);
    zp_sens_peaks_restart(L->pk, t, L->ya, L->dt);
    return restart(L, t) ? -1 : 0;
}

static int loop(sens_loop *L, zp_sens_result *r) {
    zp_sim *s = L->c.sim;
    const zp_model *m = s->m;
    double t = 0;
    int end = start(L, r);
    while (!end) {
        char err[256] = "";
        zp_adv adv = L->meth->advance(L->mwork, &t, L->ya, L->roots, err, sizeof err);
        count(L, r);
        if (adv == ZP_ADV_FAIL || r->steps > s->o.max_steps || !isfinite(L->ya[0])) {
            snprintf(r->message, sizeof r->message, "%s at t = %.9g s",
                     err[0] ? err : adv == ZP_ADV_FAIL ? "the integrator failed"
                                    : isfinite(L->ya[0]) ? "the step budget is spent"
                                                         : "the state is not finite",
                     t);
            return -1;
        }
        if (adv != ZP_ADV_ROOT && (L->ya[0] < m->xb[s->sec] || L->ya[0] > m->xb[s->sec + 1])) {
            /* a boundary passed without its root (masked at a restart on it) */
            memset(L->roots, 0, sizeof L->roots);
            L->roots[L->ya[0] < m->xb[s->sec] ? ZP_ROOT_LEFT : ZP_ROOT_RIGHT] = 1;
            not_smooth(r, "a boundary crossed at a step's end, not at its root");
            adv = ZP_ADV_ROOT;
        }
        zp_sens_peaks_step(L->pk, t, L->ya);
        if (adv == ZP_ADV_ROOT) {
            end = on_root(L, r, t);
        } else if (adv == ZP_ADV_STOP && t >= s->o.t_max) {
            finish(L, r, t, ZP_EVENT_NONE, 0);
            end = 1;
        } else if (adv == ZP_ADV_STOP) {
            /* a break of the schedule: the rates jump at a fixed time, the state does not */
            zp_sens_peaks_restart(L->pk, t, L->ya, NULL);
            end = restart(L, t) ? -1 : 0;
        }
    }
    return end;
}

static void loop_free(sens_loop *L) {
    zp_sim_free(L->c.sim);
    if (L->mwork) {
        L->meth->free(L->mwork);
    }
    free(L->ya);
    free(L->c.scratch);
    zp_sens_peaks_free(L->pk);
}

zp_status zp_sens_run(const zp_model *m, const zp_sim_opts *o, const zp_schedule *sched,
                      const zp_limits *lim, zp_sens_result *r) {
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    memset(r, 0, sizeof *r);
    r->smooth = 1;
    r->np = sched->np;
    sens_loop L;
    memset(&L, 0, sizeof L);
    zp_sim_opts plain = *o;
    plain.output_dt = 0;
    plain.peaks = 0;
    plain.track_loads = 0;
    zp_sens *c = &L.c;
    c->sim = zp_sim_create(m, &plain);
    c->sched = *sched;
    c->np = sched->np;
    L.meth = zp_method_get(o->method);
    if (c->sim) {
        zp_sim_rhs_pick(c->sim, m, &c->rhs, &c->root);
        c->sim->sched = &c->sched;
        c->sim->sec = 0;
        c->n = c->sim->n;
        c->naug = c->n * (1 + c->np);
        L.ya = calloc((size_t)c->naug + 4 * (size_t)c->n, sizeof *L.ya);
        c->scratch = calloc(4 * (size_t)c->n, sizeof *c->scratch);
        int dir[ZP_EVENTS_MAX];
        zp_events_directions(m, dir);
        zp_method_opts mo = {o->rtol, o->atol, o->max_steps, NULL, 0};
        L.mwork = L.ya && c->scratch ? L.meth->create(c->naug, c->sim->nroot, dir, zp_sens_rhs,
                                                     zp_sens_rhs_root, c, &mo)
                                     : NULL;
    }
    int nomem = 0;
    L.pk = L.mwork ? zp_sens_peaks_create(c, lim, L.meth, L.mwork, &nomem) : NULL;
    if (!L.mwork || nomem) {
        loop_free(&L);
        snprintf(r->message, sizeof r->message, "cannot create the sensitivity run");
        return ZP_ERR_NOMEM;
    }
    L.fm = L.ya + c->naug;
    L.fp = L.fm + c->n;
    L.u = L.fp + c->n;
    L.ym = L.u + c->n;
    L.nbreak = zp_drive_breaks(sched, L.breaks, ZP_SCHED_MAX_BREAKS);
    int end = loop(&L, r);
    r->rates = c->rates;
    if (end >= 0) {
        zp_sens_peaks_result(L.pk, &r->limits);
    }
    loop_free(&L);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    r->wall_s = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
    return end < 0 ? ZP_ERR_NUMERIC : ZP_OK;
}
