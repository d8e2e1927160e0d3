/* The equations of a run at one state: the drive at (t, x), the rates and event functions for
   the integrator (plain course, arcs, rolling resistance), and the state as a row. */
#include "sim_rhs.h"

#include <math.h>

#include "events.h"
#include "friction.h"

static zp_track plain_track(const zp_model *m, const zp_course *c, int sec, double x) {
    (void)m;
    return zp_course_eval(c, sec, x);
}

/* the drive at time t and state y (the trolley's x and x') on the current section, the course
   there being tr */
static inline zp_drive_now drive_with(const zp_sim *s, zp_track tr, double t, const double *y) {
    zp_drive_now dn = {tr, 0, 0, 0, 0, s->zone};
    zp_drive_push(s->sched, s->m->drive, t, y[0], y[s->w0 / 2], s->sec, tr.fp, &dn.fx, &dn.fy);
    return dn;
}

/* course and drive at time t and state y on the current section; track a constant where
   inlined */
static inline zp_drive_now drive_at(const zp_sim *s, track_fn track, double t, const double *y) {
    return drive_with(s, track(s->m, s->course, s->sec, y[0]), t, y);
}

zp_drive_now zp_sim_rhs_drive_now(const zp_sim *s, double t, const double *y) {
    zp_drive_now dn = drive_at(s, s->track, t, y);
    dn.hold = s->stuck;
    dn.slide = s->slide;
    return dn;
}

/* the equations of motion as the integrator sees them: on the plain course, or on the piece
   of an effect's course */
int zp_sim_rhs(double t, const double *y, double *ydot, void *user) {
    zp_sim *s = user;
    zp_drive_now dn = drive_at(s, plain_track, t, y);
    return s->form->rhs(s->m, s->fwork, &dn, y, ydot, NULL);
}

static int sim_rhs_provided(double t, const double *y, double *ydot, void *user) {
    zp_sim *s = user;
    zp_track tr = zp_model_track_piece(s->m, s->course, s->sec, s->arc, y[0]);
    zp_drive_now dn = drive_with(s, tr, t, y);
    return s->form->rhs(s->m, s->fwork, &dn, y, ydot, NULL);
}

static int sim_root(double t, const double *y, double *g, void *user) {
    zp_sim *s = user;
    double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
    (void)t;
    s->form->relative(s->m, y, phi, w);
    zp_events_eval(s->m, s->sec, y[0], phi, w, g);
    return 0;
}

int zp_sim_rhs_rolling(double t, const double *y, double *ydot, void *user) {
    zp_sim *s = user;
    zp_drive_now dn = zp_sim_rhs_drive_now(s, t, y);
    int rc = s->form->rhs(s->m, s->fwork, &dn, y, ydot, NULL);
    if (rc == ZP_RHS_FRICTION_INCONSISTENT) {
        s->inconsistent_t = t;
        s->inconsistent_x = y[0];
    }
    return rc;
}

/* with rolling resistance also the trolley's x' (the state contract puts it at w0 / 2): a
   stop; held, instead the hold's margin mu |N| - |F_t|: a release */
static int sim_root_rolling(double t, const double *y, double *g, void *user) {
    zp_sim *s = user;
    sim_root(t, y, g, user);
    double *rest = &g[zp_events_rest(s->m)];
    zp_friction_hold h = {.margin = 1}; /* where it cannot be computed the rates fail too */
    if (s->stuck) {
        zp_friction_hold_at(s->m, s->form, s->fwork, zp_sim_rhs_drive_now(s, t, y), y, s->ydot,
                            &h);
    }
    *rest = s->stuck ? h.margin : y[s->w0 / 2];
    return 0;
}

zp_chain zp_sim_rhs_chain(const zp_sim *s, const double *y) {
    zp_chain c;
    zp_track tr = s->track(s->m, s->course, s->sec, y[0]);
    s->form->to_chain(s->m, &tr, y, &c);
    return c;
}

zp_row zp_sim_rhs_row(zp_sim *s, double t, const double *y) {
    zp_drive_now dn = zp_sim_rhs_drive_now(s, t, y); /* its course point serves the chain too */
    zp_row r = {.t = t, .sec = s->sec};
    s->form->to_chain(s->m, &dn.tr, y, &r.c);
    r.w_drive = y[s->w0 + ZP_W_DRIVE];
    r.w_damp = y[s->w0 + ZP_W_DAMP];
    for (int k = ZP_W_EFFECTS; k < s->m->nwork; k++) {
        r.w_effect[k - ZP_W_EFFECTS] = y[s->w0 + k];
    }
    r.e_impulse = s->e_impulse;
    s->form->rhs(s->m, s->fwork, &dn, y, s->ydot, &r.loads);
    return r;
}

void zp_sim_rhs_pick(zp_sim *s, const zp_model *m, zp_rhs_fn *rhs, zp_root_fn *root) {
    s->track = zp_model_track;
    *rhs = m->stick ? zp_sim_rhs_rolling : m->course_provider ? sim_rhs_provided : zp_sim_rhs;
    *root = m->stick ? sim_root_rolling : sim_root;
}
