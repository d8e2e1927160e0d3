/* One run of docs/model.md: advance to the next event or output time, classify the event, apply the
   kink impulse and restart the integrator; fills zp_result. Formulation- and method-agnostic. */
#include "sim.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "accuracy.h"
#include "events.h"
#include "friction.h"
#include "graze.h"
#include "impulse.h"
#include "envelope.h"
#include "peaks.h"

/* ZP_ZENO_RUN crossings of one kink in a row, each closer than ZP_ZENO_DT (s) to the one
   before, mean the trolley has come to rest in it (an accumulation of ever smaller bounces).
   One close pair is not enough: a stiff chain can knock a light trolley straight back across */
#define ZP_ZENO_DT 1e-6
#define ZP_ZENO_RUN 4
/* an output time this close (s) to an event shows the state after the event */
#define ZP_EVENT_TIME_EPS 1e-9
/* this many steps in a row, each refused a trial stage for want of a consistent friction (or
   one such step that no longer advances the time), mean the run is closing in on Painleve's
   boundary, where it would crawl for ever */
#define ZP_PAINLEVE_STEPS 10

typedef zp_track (*track_fn)(const zp_model *m, const zp_course *c, int sec, double x);

struct zp_sim {
    const zp_model *m; /* borrowed */
    zp_sim_opts o;
    const zp_formulation *form;
    void *fwork; /* owned */
    const zp_method *meth;
    void *mwork;       /* owned */
    zp_course *course; /* owned: this workspace's own evaluators */
    int n, nroot;
    double *y, *ydot, *yout; /* owned, n: state, rates scratch, dense output scratch */
    int *roots;       /* owned, nroot */

    /* the run under way */
    const zp_schedule *sched; /* borrowed */
    zp_schedule scaled;       /* the run's schedule times zp_input.force_scale, when given */
    double breaks[ZP_SCHED_MAX_BREAKS]; /* s, where the force jumps in time */
    int nbreak;
    int sec;
    double e_impulse; /* J, cumulative */
    zp_row_store rows; /* owned; cap 0 without a trajectory */
    zp_row *samples; /* owned, cap_samples */
    int nsamples, cap_samples;
    zp_row *frames; /* owned, cap_frames */
    int nframes, cap_frames;
    zp_load_peaks peaks; /* so far; every evaluation of the loads updates them */

    zp_crossing *cross;  /* owned, ZP_MAX_CROSSINGS */
    int ncross;          /* kept in cross (the result counts all) */
    zp_peaks *pk;        /* owned when o.peaks */
    zp_envelope env;     /* felt g against [limits] g_envelope (o.peaks; env.n 0: none) */

    /* [physics] */
    track_fn track; /* the course with its arcs, or the plain course (chosen at create) */
    int stuck;      /* rolling resistance: 1 while static friction holds the trolley */
    int slide;      /* +1, -1: the way it slides since the last stop, kink or start */
    double hold_t;  /* s, when that hold began */
    double inconsistent_t, inconsistent_x; /* s, m: the last evaluation since the last step
                                              where friction had no solution (NaN: none) */
    int inconsistent_steps; /* steps in a row that met such an evaluation */
    int w0;         /* index of the first work integral in the state */
    zp_arc_peaks arc_peaks[ZP_MAX_SECTIONS]; /* load peaks on each arc */
    int arc; /* the piece the integrator reads since its last restart: an arc, or -1 the plain
                course (zp_model_track_piece) */
};

static zp_track plain_track(const zp_model *m, const zp_course *c, int sec, double x) {
    (void)m;
    return zp_course_eval(c, sec, x);
}

/* the drive at time t and state y (the trolley's x and x') on the current section, the course
   there being tr */
static inline zp_drive_now drive_with(const zp_sim *s, zp_track tr, double t, const double *y) {
    zp_drive_now dn = {tr, 0, 0, 0, 0};
    zp_drive_push(s->sched, s->m->drive, t, y[0], y[s->w0 / 2], s->sec, tr.fp, &dn.fx, &dn.fy);
    return dn;
}

/* course and drive at time t and state y on the current section; track a constant where
   inlined */
static inline zp_drive_now drive_at(const zp_sim *s, track_fn track, double t, const double *y) {
    return drive_with(s, track(s->m, s->course, s->sec, y[0]), t, y);
}

/* the drive now, for outputs and decisions: held, the trolley's rates and loads at rest */
static zp_drive_now drive_now(const zp_sim *s, double t, const double *y) {
    zp_drive_now dn = drive_at(s, s->track, t, y);
    dn.hold = s->stuck;
    dn.slide = s->slide;
    return dn;
}

/* the equations of motion as the integrator sees them: on the plain course, or with arcs */
int zp_sim_rhs(double t, const double *y, double *ydot, void *user);
int zp_sim_rhs(double t, const double *y, double *ydot, void *user) {
    zp_sim *s = user;
    zp_drive_now dn = drive_at(s, plain_track, t, y);
    return s->form->rhs(s->m, s->fwork, &dn, y, ydot, NULL);
}

static int sim_rhs_rounded(double t, const double *y, double *ydot, void *user) {
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

/* with rolling resistance: held or sliding as the stick rule says, and where the friction
   has no consistent solution noted for the failure's message */
static int sim_rhs_rolling(double t, const double *y, double *ydot, void *user) {
    zp_sim *s = user;
    zp_drive_now dn = drive_now(s, t, y);
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
        zp_friction_hold_at(s->m, s->form, s->fwork, drive_now(s, t, y), y, s->ydot, &h);
    }
    *rest = s->stuck ? h.margin : y[s->w0 / 2];
    return 0;
}

void zp_sim_free(zp_sim *s) {
    if (!s) {
        return;
    }
    if (s->form) {
        s->form->free(s->fwork);
    }
    if (s->meth) {
        s->meth->free(s->mwork);
    }
    zp_course_free(s->course);
    free(s->y);
    free(s->ydot);
    free(s->yout);
    free(s->roots);
    zp_row_store_free(&s->rows);
    free(s->samples);
    free(s->frames);
    free(s->cross);
    zp_peaks_free(s->pk);
    free(s);
}

zp_sim *zp_sim_create(const zp_model *m, const zp_sim_opts *o) {
    zp_sim *s = calloc(1, sizeof *s);
    if (!s) {
        return NULL;
    }
    s->m = m;
    s->o = *o;
    s->form = zp_formulation_get(o->formulation);
    s->meth = zp_method_get(o->method);
    if (!s->form || !s->meth) {
        zp_sim_free(s);
        return NULL;
    }
    zp_course_err ce;
    s->course = zp_model_course(m, &ce);
    s->n = s->form->nstate(m);
    s->w0 = s->n - m->nwork;
    s->track = m->physics & ZP_PHYS_ROUNDED ? zp_model_track : plain_track;
    s->nroot = zp_events_count(m);
    s->fwork = s->form->create(m);
    s->y = calloc(s->n, sizeof *s->y);
    s->ydot = calloc(s->n, sizeof *s->ydot);
    s->yout = calloc(s->n, sizeof *s->yout);
    s->roots = calloc(s->nroot, sizeof *s->roots);
    s->cross = malloc(sizeof *s->cross * ZP_MAX_CROSSINGS);
    int dir[ZP_EVENTS_MAX];
    zp_events_directions(m, dir);
    int state_only[ZP_EVENTS_MAX];
    zp_events_state_only(m, state_only);
    zp_method_opts mo = {o->rtol, o->atol, o->max_steps, state_only, s->w0 / 2};
    zp_rhs_fn rhs = m->physics & ZP_PHYS_ROLLING   ? sim_rhs_rolling
                    : m->physics & ZP_PHYS_ROUNDED ? sim_rhs_rounded
                                                   : zp_sim_rhs;
    s->mwork = s->meth->create(s->n, s->nroot, dir, rhs,
                               m->physics & ZP_PHYS_ROLLING ? sim_root_rolling : sim_root, s,
                               &mo);
    if (o->peaks) {
        s->pk = zp_peaks_create(2 * m->nlink);
    }
    int rows_failed =
        o->output_dt > 0 &&
        zp_row_store_init(&s->rows, m, (int)fmin(o->t_max / o->output_dt + 2, ZP_MAX_ROWS + 2));
    if (!s->course || !s->fwork || !s->y || !s->ydot || !s->yout || !s->roots || !s->cross ||
        !s->mwork || rows_failed || (o->peaks && !s->pk)) {
        zp_sim_free(s);
        return NULL;
    }
    return s;
}

static zp_chain chain_of(const zp_sim *s, const double *y) {
    zp_chain c;
    zp_track tr = s->track(s->m, s->course, s->sec, y[0]);
    s->form->to_chain(s->m, &tr, y, &c);
    return c;
}

/* the row at (t, y), touching nothing of the run */
static zp_row row_at(zp_sim *s, double t, const double *y) {
    zp_drive_now dn = drive_now(s, t, y); /* its course point serves the chain too */
    zp_row r = {.t = t, .sec = s->sec};
    s->form->to_chain(s->m, &dn.tr, y, &r.c);
    r.w_drive = y[s->w0 + ZP_W_DRIVE];
    r.w_damp = y[s->w0 + ZP_W_DAMP];
    if (s->m->nwork > ZP_W_DRAG) {
        r.w_drag = y[s->w0 + ZP_W_DRAG];
        r.w_fric = y[s->w0 + ZP_W_FRICTION];
    }
    r.e_impulse = s->e_impulse;
    s->form->rhs(s->m, s->fwork, &dn, y, s->ydot, &r.loads);
    return r;
}

/* the row at (t, y), its loads counted in the run's peaks */
static zp_row row_of(zp_sim *s, double t, const double *y) {
    zp_row r = row_at(s, t, y);
    zp_load_peaks *p = &s->peaks;
    p->normal_min = fmin(p->normal_min, r.loads.normal);
    p->normal_max = fmax(p->normal_max, r.loads.normal);
    zp_row_loads_max(s->m, &r.loads, p->joint, p->acc_g);
    for (int a = 0; a < s->m->narc; a++) {
        zp_arc_peaks *ap = &s->arc_peaks[a];
        if (r.c.q[0] >= s->m->arc[a].x1 && r.c.q[0] <= s->m->arc[a].x2) {
            double joint[ZP_MAX_LINKS], acc_g[ZP_MAX_LINKS];
            zp_row_loads(s->m, &r.loads, joint, acc_g);
            ap->normal_min = ap->visited ? fmin(ap->normal_min, r.loads.normal) : r.loads.normal;
            ap->normal_max = ap->visited ? fmax(ap->normal_max, r.loads.normal) : r.loads.normal;
            for (int i = 0; i < s->m->nlink; i++) {
                ap->acc_g = fmax(ap->acc_g, acc_g[i]);
            }
            ap->visited = 1;
        }
    }
    return r;
}

/* every load history at state y: felt acceleration per link (g), then force per joint (N);
   the peaks take them in as a side effect */
static void load_values(zp_sim *s, double t, const double *y, double *v) {
    zp_row r = row_of(s, t, y);
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

/* the integrator (re)starts at (t, s->y): the peak locator starts a new interval there, and
   felt g may have jumped (an impulse) */
static void peaks_restart(zp_sim *s, double t) {
    double v[ZP_PEAKS_MAX];
    load_values(s, t, s->y, v);
    zp_peaks_restart(s->pk, t, v);
    if (s->env.n) {
        zp_envelope_jump(&s->env, t, judged_g(s->m, v));
    }
}

/* which way the trolley leaves x: its velocity, or from rest its acceleration */
static int departure(zp_sim *s, double t, const double *y) {
    zp_row r = row_of(s, t, y);
    double v = r.c.v[0] != 0 ? r.c.v[0] : r.loads.acc[0][0];
    return (v > 0) - (v < 0);
}

/* where the outputs of a run stand: the next row's time, the next sample and frame */
typedef struct out_cursor {
    double next_row; /* s */
    int next_sample, next_frame;
    double t_prev; /* s: where the last step (or restart) ended */
} out_cursor;

/* the next frame time, or INFINITY (none left, or frames at x) */
static double next_frame_t(const zp_input *in, const out_cursor *oc) {
    return !in->frame_at_x && oc->next_frame < in->nframe ? in->frame_at[oc->next_frame]
                                                          : INFINITY;
}

/* the next output time (row, sample or frame), or INFINITY */
static double next_output(const zp_sim *s, const zp_input *in, const out_cursor *oc) {
    double t = s->rows.n < s->rows.cap ? oc->next_row : INFINITY;
    t = fmin(t, next_frame_t(in, oc));
    return oc->next_sample < in->nsample ? fmin(t, in->sample_t[oc->next_sample]) : t;
}

/* r appended to the growing list *v (n used, cap allocated); -1 out of memory */
static int push_row(zp_row **v, int *n, int *cap, zp_row r) {
    if (*n == *cap) {
        int grown_cap = *cap ? 2 * *cap : 16;
        zp_row *grown = realloc(*v, sizeof *grown * grown_cap);
        if (!grown) {
            return -1;
        }
        *v = grown;
        *cap = grown_cap;
    }
    (*v)[(*n)++] = r;
    return 0;
}

/* rows of the output grid, samples and frames due by time t_upto. dense: take each from the
   integrator's dense output at its own time; else all show the current state s->y (at an
   event, within ZP_EVENT_TIME_EPS of it) */
static void emit_outputs(zp_sim *s, const zp_input *in, double t_upto, int dense,
                         out_cursor *oc) {
    for (double to; (to = next_output(s, in, oc)) <= t_upto;) {
        const double *y = s->y;
        if (dense && s->meth->interpolate(s->mwork, to, s->yout) == 0) {
            y = s->yout;
        }
        if (next_frame_t(in, oc) == to) {
            /* before the row of the run: a frame leaves the load peaks alone */
            if (push_row(&s->frames, &s->nframes, &s->cap_frames, row_at(s, to, y))) {
                return;
            }
            oc->next_frame++;
        }
        int row = s->rows.n < s->rows.cap && oc->next_row == to;
        int sample = oc->next_sample < in->nsample && in->sample_t[oc->next_sample] == to;
        if (!row && !sample) {
            continue;
        }
        zp_row r = row_of(s, to, y);
        if (row) {
            zp_row_store_put(&s->rows, &r);
            oc->next_row = s->rows.n * s->o.output_dt;
        }
        if (sample) {
            if (push_row(&s->samples, &s->nsamples, &s->cap_samples, r)) {
                return;
            }
            oc->next_sample++;
        }
    }
}

/* frames at x the trolley has reached by the step that ended at (t, s->y): each where the
   dense output first crosses it, those at or past the section's right end left to the kink
   (shown after its impulse) or the finish */
static void frames_at_x_in_step(zp_sim *s, const zp_input *in, double t, out_cursor *oc) {
    double x = s->y[0], x_right = s->m->xb[s->sec + 1]; /* crossed by now, not past the kink */
    for (; in->frame_at_x && oc->next_frame < in->nframe; oc->next_frame++) {
        double at = in->frame_at[oc->next_frame], tc;
        if (!(at <= x && at < x_right)) {
            break;
        }
        const double *y = s->yout;
        if (zp_method_dense_crossing(s->meth, s->mwork, 0, at, oc->t_prev, t, &tc, s->yout)) {
            y = tc == t ? s->y : NULL; /* the interpolant misses it: the nearer end */
        }
        if (!y && s->meth->interpolate(s->mwork, tc, s->yout) == 0) {
            y = s->yout;
        }
        if (!y || push_row(&s->frames, &s->nframes, &s->cap_frames, row_at(s, tc, y))) {
            return;
        }
    }
    oc->t_prev = t;
}

/* frames at x up to `reached` (the start, a kink just crossed, the finish line; a root's x
   may fall short of it by the root's tolerance): they show the state s->y at t */
static void frames_at_x_here(zp_sim *s, const zp_input *in, double t, double reached,
                             out_cursor *oc) {
    for (; in->frame_at_x && oc->next_frame < in->nframe; oc->next_frame++) {
        if (!(in->frame_at[oc->next_frame] <= reached) ||
            push_row(&s->frames, &s->nframes, &s->cap_frames, row_at(s, t, s->y))) {
            break;
        }
    }
    oc->t_prev = t;
}

static void track_extremes(zp_sim *s, double t, const double *y, zp_result *r) {
    double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
    s->form->relative(s->m, y, phi, w);
    for (int i = 0; i < s->m->nlink; i++) {
        r->max_rel_angle[i] = fmax(r->max_rel_angle[i], fabs(phi[i]));
    }
    /* load and speed peaks, when asked for, are sampled at every step (one more rhs call) */
    if (s->o.track_loads) {
        zp_chain c = row_of(s, t, y).c;
        r->max_speed = fmax(r->max_speed, hypot(c.v[0], c.v[1]));
    }
    if (s->form->constraint_residual) {
        zp_track tr = s->track(s->m, s->course, s->sec, y[0]);
        r->constraint_residual =
            fmax(r->constraint_residual, s->form->constraint_residual(s->m, &tr, y));
    }
}

static int first_non_finite(const double *y, int n) {
    for (int i = 0; i < n; i++) {
        if (!isfinite(y[i])) {
            return i;
        }
    }
    return -1;
}

/* crosses the boundary into section `to` at time t: snap onto the boundary, apply the
   impulse, record it; returns 0, or 1 if the trolley is trapped at the kink */
static int cross_kink(zp_sim *s, double t, zp_result *r, int to) {
    const zp_model *m = s->m;
    double b = m->xb[to > s->sec ? to : s->sec];
    zp_chain c = chain_of(s, s->y);
    zp_track entered = s->track(m, s->course, to, b);
    c.q[0] = b;
    c.q[1] = entered.f;
    zp_impulse imp = {0, 0};
    double v_in[2] = {c.v[0], c.v[1]};
    if (m->physics & ZP_PHYS_ROUNDED) {
        c.v[1] = entered.fp * c.v[0]; /* an arc has no kink: only onto the course at b */
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
    return zeno || r->ncross >= ZP_MAX_CROSSINGS || departure(s, t, s->y) * dir < 0;
}

static void finish_result(zp_sim *s, zp_result *r, double t, zp_outcome o, zp_stall st) {
    r->outcome = o;
    r->stall = st;
    r->time = t;
    zp_chain c = chain_of(s, s->y);
    r->x = c.q[0];
    r->v = hypot(c.v[0], c.v[1]);
    zp_energy e = zp_state_energy(s->m, &c);
    r->e_final = e.kinetic + e.potential;
    r->w_drive = s->y[s->w0 + ZP_W_DRIVE];
    r->w_damp = s->y[s->w0 + ZP_W_DAMP];
    if (s->m->nwork > ZP_W_DRAG) {
        r->w_drag = s->y[s->w0 + ZP_W_DRAG];
        r->w_fric = s->y[s->w0 + ZP_W_FRICTION];
    }
    r->e_impulse = s->e_impulse;
    /* the last row shows the end state */
    if (s->rows.n < s->rows.cap &&
        (s->rows.n == 0 || zp_row_store_t(&s->rows, s->rows.n - 1) < t)) {
        zp_row last = row_of(s, t, s->y);
        zp_row_store_put(&s->rows, &last);
    }
    r->peaks = s->peaks; /* after the last row, whose loads count too */
    if (s->env.n) {
        zp_envelope_end(&s->env, t);
        memcpy(r->env_longest, s->env.longest, sizeof r->env_longest);
    }
}

static zp_status fail(zp_sim *s, zp_result *r, double t, const char *why) {
    if (isfinite(s->inconsistent_t)) {
        snprintf(r->message, sizeof r->message,
                 "rolling resistance has no consistent normal force at t = %.9g s, x = %.9g m "
                 "(Painleve's paradox: mu = %g is too large for this trolley and chain; the rigid "
                 "model of docs/model.md has no motion there)",
                 s->inconsistent_t, s->inconsistent_x, s->m->mu);
        return ZP_ERR_NUMERIC;
    }
    char where[64] = "";
    if (isfinite(s->y[0])) {
        snprintf(where, sizeof where, ", x = %.9g m (section %d)", s->y[0], s->sec + 1);
    }
    snprintf(r->message, sizeof r->message, "numerical failure at t = %.9g s%s: %.180s", t, where,
             why);
    return ZP_ERR_NUMERIC;
}

/* the trolley put at rest exactly, the chain keeping its rates: a residual x' of a root's
   tolerance would set the friction against the wrong way and bring the root straight back */
static void snap_rest(zp_sim *s) {
    zp_chain rest = chain_of(s, s->y);
    rest.v[0] = rest.v[1] = 0;
    double wk[ZP_W_MAX];
    memcpy(wk, s->y + s->w0, sizeof *wk * s->m->nwork);
    s->form->from_chain(s->m, &rest, wk, s->y);
}

/* a hold that lasted: stalled, held_by_friction, at the time the hold began (docs/model.md) */
static void finish_held(zp_sim *s, zp_result *r, double t) {
    finish_result(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_HELD_BY_FRICTION);
    r->time = s->hold_t;
}

/* whether the chain under the held trolley has settled, which ends the hold */
static int hold_settled(zp_sim *s) {
    zp_chain c = chain_of(s, s->y);
    return zp_friction_settled(s->m, &c);
}

/* the hold at the current state, at rest at t; 0, or the rhs's nonzero status */
static int hold_now(zp_sim *s, double t, zp_friction_hold *h) {
    return zp_friction_hold_at(s->m, s->form, s->fwork, drive_now(s, t, s->y), s->y, s->ydot,
                               h);
}

/* docs/model.md's stick rule for the trolley at rest at t (the start, a stop, a jump of the drive
   while held): held (|F_t| <= mu |N|), it stays while the chain swings on (s->stuck) and the
   run ends at once when the chain has settled; otherwise it slides off toward -F_t, *dir.
   Returns 1 when the run ended (r filled), -1 when it failed (r's message: the forces cannot
   be computed, or sliding friction has no consistent motion there, Painleve), 0 to go on. */
static int stick_rule(zp_sim *s, double t, zp_result *r, int *dir) {
    s->stuck = 0;
    snap_rest(s);
    zp_friction_hold h;
    if (hold_now(s, t, &h)) {
        fail(s, r, t, "the forces at rest cannot be computed");
        return -1;
    }
    s->stuck = h.margin >= 0;
    *dir = s->stuck ? 0 : h.tangential > 0 ? -1 : 1;
    if (s->stuck) {
        s->hold_t = t;
        if (hold_settled(s)) {
            finish_held(s, r, t);
            return 1;
        }
        return 0;
    }
    /* sliding off: friction needs a consistent normal force here, and must leave the trolley
       going that way (Painleve's regime can turn it round) */
    s->slide = *dir;
    int rc = sim_rhs_rolling(t, s->y, s->ydot, s);
    int turned = rc == 0 && s->ydot[s->w0 / 2] * *dir < 0;
    if (turned) {
        s->inconsistent_t = t;
        s->inconsistent_x = s->y[0];
    }
    if (rc || turned) {
        fail(s, r, t, "the forces at rest cannot be computed"); /* or Painleve's, said */
        return -1;
    }
    return 0;
}

/* the run's status after the stick rule ended it (end != 0) */
static zp_status stick_end(int end) {
    return end < 0 ? ZP_ERR_NUMERIC : ZP_OK;
}

static void add_stats(zp_sim *s, zp_result *r) {
    long steps = 0, evals = 0, rejected = 0;
    s->meth->stats(s->mwork, &steps, &evals);
    if (s->meth->rejections) {
        s->meth->rejections(s->mwork, &rejected);
    }
    r->steps += steps;
    r->rhs_evals += evals;
    r->rejected += rejected;
}

/* where the integrator stops next: the schedule's next break after t, or t_max */
static double stop_after(const zp_sim *s, double t) {
    for (int i = 0; i < s->nbreak; i++) {
        if (s->breaks[i] > t) {
            return fmin(s->breaks[i], s->o.t_max);
        }
    }
    return s->o.t_max;
}

/* the integrator (re)started at (t, s->y), reading the course piece the trolley is on; the
   peak locator (o.peaks) starts a new interval there */
static int restart(zp_sim *s, double t) {
    if (s->m->physics & ZP_PHYS_ROUNDED) {
        s->arc = zp_model_track_arc(s->m, s->sec, s->y[0]);
    }
    if (s->meth->reset(s->mwork, t, s->y, stop_after(s, t))) {
        return 1;
    }
    if (s->o.peaks) {
        peaks_restart(s, t);
    }
    return 0;
}

/* whether the advance ended on a located death root; if not, a joint found past the death
   angle there (at an extremum) grazed it inside the step, and zp_graze_locate ends the run */
static int died_at_root(const zp_model *m, const int *roots, zp_adv adv) {
    for (int i = 0; adv == ZP_ADV_ROOT && i < m->nlink; i++) {
        if (roots[ZP_ROOT_DEATH + i]) {
            return 1;
        }
    }
    return 0;
}

static zp_status run(const zp_model *m, zp_sim *s, const zp_input *in, zp_result *r) {
    zp_chain c;
    if (in->start) {
        c = *in->start;
    } else {
        zp_state_start(m, s->course, &c);
    }
    const double zero_work[ZP_W_MAX] = {0};
    s->form->from_chain(m, &c, zero_work, s->y);
    zp_energy e0 = zp_state_energy(m, &c);
    r->e_initial = e0.kinetic + e0.potential;

    double t = 0;
    out_cursor oc = {0};
    s->stuck = 0;
    s->slide = (c.v[0] > 0) - (c.v[0] < 0);
    s->inconsistent_t = NAN;
    s->inconsistent_steps = 0;
    emit_outputs(s, in, t, 0, &oc);
    frames_at_x_here(s, in, t, s->y[0], &oc);
    int dir;
    if (m->physics & ZP_PHYS_ROLLING && c.v[0] == 0) {
        int end = stick_rule(s, t, r, &dir);
        if (end) {
            return stick_end(end);
        }
    } else {
        dir = departure(s, t, s->y);
    }
    /* a root finder ignores a root at t0: a start that rolls back at once is caught here */
    if (dir < 0) {
        finish_result(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_ROLLED_BACK);
        return ZP_OK;
    }
    if (s->o.peaks) {
        zp_peaks_reset(s->pk);
        if (m->nenv > 0) {
            zp_envelope_start(&s->env, m->nenv, m->env_g, t, 0);
        }
    }
    if (restart(s, t)) {
        return fail(s, r, t, "the integrator could not start");
    }
    for (;;) {
        char err[256] = "";
        double t_before = t;
        zp_adv adv = s->meth->advance(s->mwork, &t, s->y, s->roots, err, sizeof err);
        int bad = first_non_finite(s->y, s->n);
        long steps_now = 0, evals_now = 0;
        s->meth->stats(s->mwork, &steps_now, &evals_now);
        if (adv == ZP_ADV_FAIL || bad >= 0 || r->steps + steps_now > s->o.max_steps) {
            add_stats(s, r);
            if (bad >= 0) {
                snprintf(err, sizeof err, "state component %d of %d (%s) is not finite", bad,
                         s->n, bad == 0 ? "trolley x" : "see the formulation's layout");
            } else if (adv != ZP_ADV_FAIL) {
                snprintf(err, sizeof err, "the run's budget of %ld steps is exhausted",
                         s->o.max_steps);
            }
            return fail(s, r, t, err);
        }
        /* closing in on Painleve's boundary: steps that each meet it, or no longer advance */
        s->inconsistent_steps = isfinite(s->inconsistent_t) ? s->inconsistent_steps + 1 : 0;
        if (s->inconsistent_steps >= ZP_PAINLEVE_STEPS ||
            (s->inconsistent_steps > 0 && !(t > t_before))) {
            add_stats(s, r);
            return fail(s, r, t, "");
        }
        s->inconsistent_t = NAN; /* a step was taken: what a trial stage met is past */
        if (!died_at_root(m, s->roots, adv)) {
            int link;
            if (zp_graze_locate(m, s->form, s->meth, s->mwork, t_before, t, s->y, s->n, &t,
                                s->yout, &link)) {
                memcpy(s->y, s->yout, sizeof *s->y * s->n);
                memset(s->roots, 0, sizeof *s->roots * s->nroot);
                s->roots[ZP_ROOT_DEATH + link] = 1;
                adv = ZP_ADV_ROOT;
            }
        }
        track_extremes(s, t, s->y, r);
        frames_at_x_in_step(s, in, t, &oc);
        if (s->o.peaks) {
            double vb[ZP_PEAKS_MAX];
            load_values(s, t, s->y, vb);
            /* a root inside a step is landed, off the step's dense output by its error: the
               interval is read on the one polynomial, or that gap shows as a false maximum */
            if (adv == ZP_ADV_ROOT) {
                dense_load_values(t, 0, vb, s);
            }
            zp_peaks_interval(s->pk, t, vb, dense_load_values, s);
            if (s->env.n) {
                zp_envelope_interval(&s->env, t, judged_g(m, vb), dense_judged_g, s);
            }
        }
        if (adv != ZP_ADV_ROOT) {
            emit_outputs(s, in, t, 1, &oc);
            if (s->stuck && hold_settled(s)) {
                add_stats(s, r);
                finish_held(s, r, t);
                return ZP_OK;
            }
            /* a boundary passed without a root (one masked at a restart) is crossed here */
            if (s->y[0] < m->xb[s->sec] || s->y[0] > m->xb[s->sec + 1]) {
                memset(s->roots, 0, sizeof *s->roots * s->nroot);
                s->roots[s->y[0] < m->xb[s->sec] ? ZP_ROOT_LEFT : ZP_ROOT_RIGHT] = 1;
            } else if (adv == ZP_ADV_STOP && s->nbreak > 0 && t < s->o.t_max) {
                /* a break of the schedule: the force jumps (a held trolley is judged again),
                   the integrator starts afresh */
                add_stats(s, r);
                int end = s->stuck ? stick_rule(s, t, r, &dir) : 0;
                if (end) {
                    return stick_end(end);
                }
                if (restart(s, t)) {
                    return fail(s, r, t, "the integrator could not restart at a break");
                }
                continue;
            } else if (adv == ZP_ADV_STOP) {
                add_stats(s, r);
                if (s->stuck) {
                    finish_held(s, r, t);
                } else {
                    finish_result(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_T_MAX);
                }
                return ZP_OK;
            } else {
                continue;
            }
        }
        int link = 0, to = 0;
        zp_event ev = zp_events_classify(m, s->sec, s->roots, &link, &to);
        /* outputs up to the event from the dense output; one on a kink shows the state after */
        emit_outputs(s, in, ev == ZP_EVENT_KINK ? t - ZP_EVENT_TIME_EPS : t, 1, &oc);
        if (ev == ZP_EVENT_NONE) {
            continue;
        }
        add_stats(s, r);
        if (ev == ZP_EVENT_TANGENT) {
            /* f'' jumps at an arc's tangent point: a step across it would lose the method's
               order, so the integrator restarts there as at a section's end, the trolley put
               one bit past the point the way it moves: a root left a hair short would fire
               again at once, and the restart's rates must be those of the side it enters */
            zp_chain c = chain_of(s, s->y);
            int it = zp_events_tangent(m), lo = m->arc_at[s->sec], hi = m->arc_at[s->sec + 1];
            c.q[0] = nextafter(s->roots[it] ? m->arc[lo].x2 : m->arc[hi].x1,
                               c.v[0] < 0 ? -INFINITY : INFINITY);
            c.q[1] = s->track(m, s->course, s->sec, c.q[0]).f;
            double wk[ZP_W_MAX];
            memcpy(wk, s->y + s->w0, sizeof *wk * m->nwork);
            s->form->from_chain(m, &c, wk, s->y);
            if (restart(s, t)) {
                return fail(s, r, t, "the integrator could not restart at an arc's end");
            }
            continue;
        }
        if (ev == ZP_EVENT_REST) {
            /* a release (the hold's margin reached 0): off toward -F_t from rest; a stop: the
               stick rule. Either way the equations change and the integrator restarts */
            zp_friction_hold h;
            if (s->stuck) {
                s->stuck = 0;
                snap_rest(s);
                if (hold_now(s, t, &h)) {
                    return fail(s, r, t, "the forces at rest cannot be computed");
                }
                s->slide = h.tangential > 0 ? -1 : 1;
            } else {
                int end = stick_rule(s, t, r, &dir);
                if (end) {
                    return stick_end(end);
                }
            }
            if (restart(s, t)) {
                return fail(s, r, t, "the integrator could not restart at rest");
            }
            continue;
        }
        if (ev == ZP_EVENT_FINISH) {
            frames_at_x_here(s, in, t, m->xb[m->nsec], &oc);
        }
        if (ev != ZP_EVENT_KINK) {
            r->died_link = ev == ZP_EVENT_DEATH ? link + 1 : 0;
            finish_result(s, r, t,
                          ev == ZP_EVENT_DEATH    ? ZP_OUTCOME_DIED
                          : ev == ZP_EVENT_FINISH ? ZP_OUTCOME_FINISHED
                                                  : ZP_OUTCOME_STALLED,
                          ev == ZP_EVENT_ROLLBACK ? ZP_STALL_ROLLED_BACK : ZP_STALL_NONE);
            return ZP_OK;
        }
        int trapped = cross_kink(s, t, r, to);
        if (trapped < 0) {
            return fail(s, r, t, "the mass matrix is not positive definite at the kink");
        }
        emit_outputs(s, in, t + ZP_EVENT_TIME_EPS, 0, &oc);
        frames_at_x_here(s, in, t, s->y[0], &oc);
        if (trapped) {
            finish_result(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_TRAPPED_AT_KINK);
            return ZP_OK;
        }
        /* friction now opposes the way it leaves the kink */
        s->slide = departure(s, t, s->y);
        if (restart(s, t)) {
            return fail(s, r, t, "the integrator could not restart after the kink");
        }
    }
}

zp_status zp_sim_run(const zp_model *m, zp_sim *s, const zp_input *in, zp_result *r) {
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    memset(r, 0, sizeof *r);
    s->m = m;
    /* a scaled drive is a schedule of its own, made once per run, not a factor per evaluation */
    if (in->force_scale) {
        s->scaled = zp_schedule_scaled(in->sched, in->force_scale);
        s->sched = &s->scaled;
    } else {
        s->sched = in->sched;
    }
    s->nbreak = zp_schedule_breaks(in->sched, s->breaks, ZP_SCHED_MAX_BREAKS);
    s->sec = 0;
    s->e_impulse = 0;
    s->rows.n = s->nsamples = s->nframes = s->ncross = 0;
    s->peaks = (zp_load_peaks){.normal_min = INFINITY, .normal_max = -INFINITY};
    s->env.n = 0;
    memset(s->arc_peaks, 0, sizeof s->arc_peaks);
    zp_status st = run(m, s, in, r);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    r->wall_s = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
    return st;
}

const zp_row_store *zp_sim_rows(const zp_sim *s) {
    return &s->rows;
}

const zp_row *zp_sim_samples(const zp_sim *s, int *n) {
    *n = s->nsamples;
    return s->samples;
}

const zp_row *zp_sim_frames(const zp_sim *s, int *n) {
    *n = s->nframes;
    return s->frames;
}

const zp_crossing *zp_sim_crossings(const zp_sim *s, int *n) {
    *n = s->ncross;
    return s->cross;
}

const zp_arc_peaks *zp_sim_arc_peaks(const zp_sim *s, int *n) {
    *n = s->m->narc;
    return s->arc_peaks;
}

static const char *const outcome_names[ZP_OUTCOME_COUNT] = {"finished", "died", "stalled"};
static const char *const stall_names[ZP_STALL_COUNT] = {"none", "t_max", "rolled_back",
                                                        "trapped_at_kink", "held_by_friction"};

const char *zp_sim_outcome_name(zp_outcome o) { return outcome_names[o]; }
const char *zp_sim_stall_name(zp_stall s) { return stall_names[s]; }

zp_status zp_sim_opts_from_scene(const zp_scene *sc, zp_sim_opts *o, zp_diag *d) {
    *o = (zp_sim_opts){.rtol = sc->rtol,
                       .atol = sc->atol,
                       .t_max = sc->t_max,
                       .output_dt = sc->output_dt,
                       .max_steps = 2000000,
                       .track_loads = 1};
    o->method = zp_method_find(sc->method);
    o->formulation = zp_formulation_find(sc->formulation);
    if (o->method < 0) {
        zp_diag_add(d, sc->path, sc->line_method, "solver", "method",
                    "unknown method '%s'; expected one of those listed by zipopt --help",
                    sc->method);
    }
    if (o->formulation < 0) {
        zp_diag_add(d, sc->path, sc->line_formulation, "solver", "formulation",
                    "unknown formulation '%s'; expected one of those listed by zipopt --help",
                    sc->formulation);
    }
    if (sc->accuracy > 0 && o->method >= 0) {
        /* a method given beside accuracy restricts the pick to it */
        zp_accuracy_pick(sc->accuracy, sc->line_method ? o->method : -1, zp_accuracy_stiff(sc), o);
    }
    return o->method < 0 || o->formulation < 0 ? ZP_ERR_INPUT : ZP_OK;
}
