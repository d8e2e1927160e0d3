/* Handling a run's events: the kink impulse with its Zeno and trapped tests, the restart past an
   arc's tangent point or a brake zone's end, stops and releases under rolling resistance or a
   friction brake (the stick rule), and the run's end at a death, the finish or a roll-back. */
#include "sim_events.h"

#include <math.h>
#include <string.h>

#include "effect_brake.h"
#include "friction.h"
#include "impulse.h"
#include "sim_peaks.h"
#include "sim_rhs.h"

/* ZP_ZENO_RUN crossings of one kink in a row, each closer than ZP_ZENO_DT (s) to the one
   before, mean the trolley has come to rest in it (an accumulation of ever smaller bounces).
   One close pair is not enough: a stiff chain can knock a light trolley straight back across */
#define ZP_ZENO_DT 1e-6
#define ZP_ZENO_RUN 4

int zp_sim_events_departure(zp_sim *s, double t, const double *y) {
    zp_row r = zp_sim_peaks_row(s, t, y);
    double v = r.c.v[0] != 0 ? r.c.v[0] : r.loads.acc[0][0];
    return (v > 0) - (v < 0);
}

/* crosses the boundary into section `to` at time t: snap onto the boundary, apply the
   impulse, record it; returns 0, or 1 if the trolley is trapped at the kink */
static int cross_kink(zp_sim *s, double t, zp_result *r, int to) {
    const zp_model *m = s->m;
    double b = m->xb[to > s->sec ? to : s->sec];
    zp_chain c = zp_sim_rhs_chain(s, s->y);
    zp_track entered = s->track(m, s->course, to, b);
    c.q[0] = b;
    c.q[1] = entered.f;
    zp_impulse imp = {0, 0};
    double v_in[2] = {c.v[0], c.v[1]};
    if (m->physics & (ZP_PHYS_ROUNDED | ZP_PHYS_CABLE)) {
        c.v[1] = entered.fp * c.v[0]; /* an arc or a cable has no kink: only onto the course */
    } else if (zp_impulse_apply(m, entered.fp, &c, &imp)) {
        return -1;
    }
    s->peaks.kink_dv = fmax(s->peaks.kink_dv, hypot(c.v[0] - v_in[0], c.v[1] - v_in[1]));
    double wk[ZP_W_MAX];
    memcpy(wk, s->y + s->w0, sizeof *wk * m->nwork);
    s->form->from_chain(m, &c, wk, s->y);
    s->e_impulse += imp.energy_lost;
    int from = s->sec;
    s->sec = to;
    if (m->physics & ZP_PHYS_CABLE) {
        return 0; /* a drive section's end on a cable is no kink: not listed, nothing traps */
    }
    if (s->ncross < ZP_MAX_CROSSINGS) {
        s->cross[s->ncross++] = (zp_crossing){t, b, from, to, imp.lambda, imp.energy_lost};
    }
    r->ncross++;
    /* the last ZP_ZENO_RUN crossings: all at this kink, each close after the one before */
    int zeno = r->ncross >= ZP_ZENO_RUN && r->ncross <= ZP_MAX_CROSSINGS;
    for (int i = r->ncross - 1; zeno && i > r->ncross - ZP_ZENO_RUN; i--) {
        const zp_crossing *p = &s->cross[i], *q = &s->cross[i - 1];
        zeno = p->x == q->x && p->t - q->t < ZP_ZENO_DT;
    }
    int dir = to > from ? 1 : -1;
    return zeno || r->ncross >= ZP_MAX_CROSSINGS || zp_sim_events_departure(s, t, s->y) * dir < 0;
}

/* the trolley put at rest exactly, the chain keeping its rates: a residual x' of a root's
   tolerance would set the friction against the wrong way and bring the root straight back */
static void snap_rest(zp_sim *s) {
    zp_chain rest = zp_sim_rhs_chain(s, s->y);
    rest.v[0] = rest.v[1] = 0;
    double wk[ZP_W_MAX];
    memcpy(wk, s->y + s->w0, sizeof *wk * s->m->nwork);
    s->form->from_chain(s->m, &rest, wk, s->y);
}

void zp_sim_events_held(zp_sim *s, zp_result *r, double t) {
    zp_sim_output_finish(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_HELD_BY_FRICTION);
    r->time = s->hold_t;
}

int zp_sim_events_settled(zp_sim *s, double t) {
    zp_chain c = zp_sim_rhs_chain(s, s->y);
    return zp_friction_settled(s->m, &c) && zp_sim_rhs_drive_settled(s, t, s->y);
}

/* the hold at the current state, at rest at t; 0, or the rhs's nonzero status */
static int hold_now(zp_sim *s, double t, zp_friction_hold *h) {
    return zp_friction_hold_at(s->m, s->form, s->fwork, zp_sim_rhs_drive_now(s, t, s->y), s->y,
                               s->ydot, h);
}

int zp_sim_events_stick(zp_sim *s, double t, zp_result *r, int *dir) {
    s->stuck = 0;
    snap_rest(s);
    zp_friction_hold h;
    if (hold_now(s, t, &h)) {
        zp_sim_output_fail(s, r, t, "the forces at rest cannot be computed");
        return -1;
    }
    s->stuck = h.margin >= 0;
    *dir = s->stuck ? 0 : h.tangential > 0 ? -1 : 1;
    if (s->stuck) {
        s->hold_t = t;
        if (zp_sim_events_settled(s, t)) {
            zp_sim_events_held(s, r, t);
            return 1;
        }
        return 0;
    }
    /* sliding off: friction needs a consistent normal force here, and must leave the trolley
       going that way (Painleve's regime can turn it round) */
    s->slide = *dir;
    int rc = zp_sim_rhs_rolling(t, s->y, s->ydot, s);
    int turned = rc == 0 && s->ydot[s->w0 / 2] * *dir < 0;
    if (turned) {
        s->inconsistent_t = t;
        s->inconsistent_x = s->y[0];
    }
    if (rc || turned) {
        /* or Painleve's paradox, which the message then names */
        zp_sim_output_fail(s, r, t, "the forces at rest cannot be computed");
        return -1;
    }
    return 0;
}

int zp_sim_events_kink(zp_sim *s, const zp_input *in, zp_result *r, double t, int to,
                       zp_sim_output_cursor *oc) {
    int trapped = cross_kink(s, t, r, to);
    if (trapped < 0) {
        zp_sim_output_fail(s, r, t, "the mass matrix is not positive definite at the kink");
        return -1;
    }
    zp_sim_output_emit(s, in, t + ZP_EVENT_TIME_EPS, 0, oc);
    zp_sim_output_frames_here(s, in, t, s->y[0], oc);
    if (trapped) {
        zp_sim_output_finish(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_TRAPPED_AT_KINK);
        return 1;
    }
    /* friction now opposes the way it leaves the kink */
    s->slide = zp_sim_events_departure(s, t, s->y);
    return 0;
}

void zp_sim_events_tangent(zp_sim *s) {
    /* f'' jumps at an arc's tangent point: a step across it would lose the method's order, so
       the integrator restarts there as at a section's end, the trolley put one bit past the
       point the way it moves: a root left a hair short would fire again at once, and the
       restart's rates must be those of the side it enters */
    const zp_model *m = s->m;
    zp_chain c = zp_sim_rhs_chain(s, s->y);
    int it = zp_events_tangent(m), lo = m->arc_at[s->sec], hi = m->arc_at[s->sec + 1];
    c.q[0] =
        nextafter(s->roots[it] ? m->arc[lo].x2 : m->arc[hi].x1, c.v[0] < 0 ? -INFINITY : INFINITY);
    c.q[1] = s->track(m, s->course, s->sec, c.q[0]).f;
    double wk[ZP_W_MAX];
    memcpy(wk, s->y + s->w0, sizeof *wk * m->nwork);
    s->form->from_chain(m, &c, wk, s->y);
}

void zp_sim_events_place(zp_sim *s, double x, double xd) {
    s->arc = zp_model_piece(s->m, s->sec, x);
    s->zone = s->m->physics & ZP_PHYS_BRAKE && zp_effect_brake_entered(s->m, x, xd);
}

void zp_sim_events_start(zp_sim *s, const zp_chain *c) {
    s->stuck = 0;
    s->slide = (c->v[0] > 0) - (c->v[0] < 0);
    zp_sim_events_place(s, c->q[0], c->v[0]); /* the stick rule's and outputs' rates read it */
    s->inconsistent_t = NAN;
}

void zp_sim_events_zone(zp_sim *s) {
    /* the brake's force starts or stops here: restarted as at an arc's tangent point */
    const zp_model *m = s->m;
    zp_chain c = zp_sim_rhs_chain(s, s->y);
    double edge = m->brake_zone[s->roots[zp_events_zone(m)] ? 0 : 1];
    c.q[0] = nextafter(edge, c.v[0] < 0 ? -INFINITY : INFINITY);
    c.q[1] = s->track(m, s->course, s->sec, c.q[0]).f;
    double wk[ZP_W_MAX];
    memcpy(wk, s->y + s->w0, sizeof *wk * m->nwork);
    s->form->from_chain(m, &c, wk, s->y);
}

int zp_sim_events_rest(zp_sim *s, double t, zp_result *r) {
    /* a release (the hold's margin reached 0): off toward -F_t from rest; a stop: the stick
       rule. Either way the equations change and the integrator restarts */
    if (!s->stuck) {
        int dir;
        return zp_sim_events_stick(s, t, r, &dir);
    }
    zp_friction_hold h;
    s->stuck = 0;
    snap_rest(s);
    if (hold_now(s, t, &h)) {
        zp_sim_output_fail(s, r, t, "the forces at rest cannot be computed");
        return -1;
    }
    s->slide = h.tangential > 0 ? -1 : 1;
    return 0;
}

int zp_sim_events_end(zp_sim *s, const zp_input *in, zp_result *r, double t, zp_event ev, int link,
                      zp_sim_output_cursor *oc) {
    if (ev == ZP_EVENT_FINISH) {
        zp_sim_output_frames_here(s, in, t, s->m->xb[s->m->nsec], oc);
    }
    r->died_link = ev == ZP_EVENT_DEATH ? link + 1 : 0;
    zp_sim_output_finish(s, r, t,
                         ev == ZP_EVENT_DEATH    ? ZP_OUTCOME_DIED
                         : ev == ZP_EVENT_FINISH ? ZP_OUTCOME_FINISHED
                                                 : ZP_OUTCOME_STALLED,
                         ev == ZP_EVENT_ROLLBACK ? ZP_STALL_ROLLED_BACK : ZP_STALL_NONE);
    return 1;
}
