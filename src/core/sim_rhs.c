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

/* a drive with a response time: the force applied is the state's F_a, on dn; where rate is
   not NULL, F_a's rate into it */
static void drive_lagged(const zp_sim *s, double t, const double *y, zp_drive_now *dn,
                         double *rate) {
    double applied = y[s->wd];
    if (rate) {
        zp_drive_state st =
            zp_drive_state_at(s->m->drive, t, y[0], y[s->w0 / 2], s->sec, dn->tr.fp);
        *rate = zp_drive_lag_rate(s->sched, s->m->drive_response, &st, applied);
    }
    zp_drive_split(s->m->drive, applied, dn->tr.fp, &dn->fx, &dn->fy);
}

/* the drive at time t and state y (the trolley's x and x', the drive's states) on the current
   section, the course there being tr; with a response time the drive's states' rates into
   rates (NULL: not wanted) */
static inline zp_drive_now drive_with(const zp_sim *s, zp_track tr, double t, const double *y,
                                      double *rates) {
    zp_drive_now dn = {tr, 0, 0, 0, 0, s->zone};
    if (s->m->ndrive) {
        drive_lagged(s, t, y, &dn, rates);
    } else {
        zp_drive_push(s->sched, s->m->drive, t, y[0], y[s->w0 / 2], s->sec, tr.fp, &dn.fx,
                      &dn.fy);
    }
    return dn;
}

/* course and drive at time t and state y on the current section; track a constant where
   inlined */
static inline zp_drive_now drive_at(const zp_sim *s, track_fn track, double t, const double *y,
                                    double *rates) {
    return drive_with(s, track(s->m, s->course, s->sec, y[0]), t, y, rates);
}

/* the drive on the course point tr with the simulator's hold and slide */
static inline zp_drive_now drive_held(const zp_sim *s, zp_track tr, double t, const double *y,
                                      double *rates) {
    zp_drive_now dn = drive_with(s, tr, t, y, rates);
    dn.hold = s->stuck;
    dn.slide = s->slide;
    return dn;
}

/* the drive now with the simulator's hold and slide, the course read on the piece the
   integrator restarted on (continued past its ends) as sim_rhs_provided reads it: read by x,
   f'' would jump at an arc's tangent point inside the step that crosses it, and its stages
   would mix two pieces' equations (under rolling resistance the finish time then moved by
   1e-8 with a schedule's last digits, and a load peak at the step's end read the next piece) */
static inline zp_drive_now drive_now(const zp_sim *s, double t, const double *y, double *rates) {
    zp_track tr = zp_model_track_piece(s->m, s->course, s->sec, s->arc, y[0]);
    return drive_held(s, tr, t, y, rates);
}

zp_drive_now zp_sim_rhs_drive_now(const zp_sim *s, double t, const double *y) {
    return drive_now(s, t, y, NULL);
}

zp_drive_now zp_sim_rhs_drive_on(const zp_sim *s, zp_track tr, double t, const double *y,
                                 double *ydot) {
    return drive_held(s, tr, t, y, ydot + s->wd);
}

void zp_sim_rhs_drive_start(const zp_sim *s, double *y) {
    for (int k = 0; k < s->m->ndrive; k++) {
        y[s->wd + k] = 0;
    }
}

int zp_sim_rhs_drive_settled(const zp_sim *s, double t, const double *y) {
    if (!s->m->ndrive) {
        return 1;
    }
    double rate;
    drive_now(s, t, y, &rate); /* the one drive state's rate */
    return fabs(rate * s->m->drive_response) <= ZP_FRICTION_SETTLED * s->m->mtot * s->m->g;
}

double zp_sim_rhs_drive_applied(const zp_sim *s, const zp_drive_state *st, const double *y) {
    return s->m->ndrive ? y[s->wd] : zp_drive_force(s->sched, st);
}

/* the equations of motion as the integrator sees them: on the plain course, or on the piece
   of an effect's course; the formulation's rates, then the drive's states' */
int zp_sim_rhs(double t, const double *y, double *ydot, void *user) {
    zp_sim *s = user;
    zp_drive_now dn = drive_at(s, plain_track, t, y, ydot + s->wd);
    return s->form->rhs(s->m, s->fwork, &dn, y, ydot, NULL);
}

static int sim_rhs_provided(double t, const double *y, double *ydot, void *user) {
    zp_sim *s = user;
    zp_track tr = zp_model_track_piece(s->m, s->course, s->sec, s->arc, y[0]);
    zp_drive_now dn = drive_with(s, tr, t, y, ydot + s->wd);
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
    zp_drive_now dn = drive_now(s, t, y, ydot + s->wd);
    int rc = s->form->rhs(s->m, s->fwork, &dn, y, ydot, NULL);
    if (s->stuck) {
        /* held, x'' is 0 exactly, not to round-off: a hold that lasts (a drive's force still
           growing) would drift past the start's boundary, a roll-back */
        ydot[s->w0 / 2] = 0;
    }
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
    r.f_applied = s->m->ndrive ? y[s->wd] : 0;
    s->form->rhs(s->m, s->fwork, &dn, y, s->ydot, &r.loads);
    return r;
}

void zp_sim_rhs_pick(zp_sim *s, const zp_model *m, zp_rhs_fn *rhs, zp_root_fn *root) {
    s->track = zp_model_track;
    *rhs = m->stick ? zp_sim_rhs_rolling : m->course_provider ? sim_rhs_provided : zp_sim_rhs;
    *root = m->stick ? sim_root_rolling : sim_root;
}
