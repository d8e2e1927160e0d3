/* One run of docs/model.md, and the workspace it runs in. Each step of the loop reads
   advance -> check -> outputs -> classify -> handle: the integrator takes a step, a death between
   its ends is looked for, the step's outputs and peaks are taken, what it ended on is classified
   and handled (a kink's impulse, a stop, the end), and the integrator restarts where the
   equations change. Formulation- and method-agnostic; the parts are sim_*.c. */
#include "sim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "graze.h"
#include "sim_events.h"
#include "sim_peaks.h"
#include "sim_rhs.h"

/* this many steps in a row, each refused a trial stage for want of a consistent friction (or
   one such step that no longer advances the time), mean the run is closing in on Painleve's
   boundary, where it would crawl for ever */
#define ZP_PAINLEVE_STEPS 10

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
    s->wd = s->form->nstate(m);
    s->n = s->wd + m->ndrive;
    s->w0 = s->wd - m->nwork;
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
    zp_rhs_fn rhs;
    zp_root_fn root;
    zp_sim_rhs_pick(s, m, &rhs, &root);
    s->mwork = s->meth->create(s->n, s->nroot, dir, rhs, root, s, &mo);
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

const zp_arc_peaks *zp_sim_zone_peaks(const zp_sim *s) {
    return &s->zone_peaks;
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

/* the run failed at t, why in r's message: -1, as the handlers say it */
static int failed(zp_sim *s, zp_result *r, double t, const char *why) {
    zp_sim_output_fail(s, r, t, why);
    return -1;
}

static int first_non_finite(const double *y, int n) {
    for (int i = 0; i < n; i++) {
        if (!isfinite(y[i])) {
            return i;
        }
    }
    return -1;
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

/* the trolley's speed and the felt g as it first enters the brake zone (at its start or later),
   the brake's force already on */
static void zone_entered(zp_sim *s, zp_result *r, double t) {
    zp_row row = zp_sim_rhs_row(s, t, s->y);
    double joint[ZP_MAX_LINKS], acc_g[ZP_MAX_LINKS];
    zp_row_loads(s->m, &row.loads, joint, acc_g);
    r->brake_speed_in = hypot(row.c.v[0], row.c.v[1]);
    for (int i = 0; i < s->m->nlink; i++) {
        r->brake_g_in = fmax(r->brake_g_in, acc_g[i]);
    }
}

/* the integrator (re)started at (t, s->y), reading the course piece the trolley is on; the
   peak locator (o.peaks) starts a new interval there */
static int restart(zp_sim *s, zp_result *r, double t) {
    zp_sim_events_place(s, s->y[0], s->y[s->w0 / 2]);
    if (s->zone && r->brake_speed_in == 0) {
        zone_entered(s, r, t);
    }
    if (s->meth->reset(s->mwork, t, s->y, stop_after(s, t))) {
        return 1;
    }
    if (s->o.peaks) {
        zp_sim_peaks_restart(s, t);
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

/* the run's start at t = 0: the state, the outputs there, the way the trolley leaves (from rest
   under rolling resistance, the stick rule), the peaks and the integrator; 0 to go on, or the
   run ended there (1, r filled) or failed (-1, r's message) */
static int start(zp_sim *s, const zp_input *in, zp_result *r, zp_sim_output_cursor *oc) {
    const zp_model *m = s->m;
    zp_chain c;
    if (in->start) {
        c = *in->start;
    } else {
        zp_state_start(m, s->course, &c);
    }
    const double zero_work[ZP_W_MAX] = {0};
    s->form->from_chain(m, &c, zero_work, s->y);
    zp_sim_rhs_drive_start(s, s->y);
    zp_energy e0 = zp_state_energy(m, &c);
    r->e_initial = e0.kinetic + e0.potential;
    r->pi_initial = zp_model_cable_energy(m, c.q[0]);
    r->x_min = r->x_max = c.q[0];

    double t = 0;
    zp_sim_events_start(s, &c);
    s->inconsistent_steps = 0;
    zp_sim_peaks_drive_start(s, t, s->y, r);
    zp_sim_output_emit(s, in, t, 0, oc);
    zp_sim_output_frames_here(s, in, t, s->y[0], oc);
    int dir;
    if (m->stick && c.v[0] == 0) {
        int end = zp_sim_events_stick(s, t, r, &dir);
        if (end) {
            return end;
        }
    } else {
        dir = zp_sim_events_departure(s, t, s->y);
    }
    /* a root finder ignores a root at t0: a start that rolls back at once is caught here */
    if (dir < 0) {
        zp_sim_output_finish(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_ROLLED_BACK);
        return 1;
    }
    if (s->o.peaks) {
        zp_sim_peaks_start(s, t);
    }
    return restart(s, r, t) ? failed(s, r, t, "the integrator could not start") : 0;
}

/* advance: one step of the integrator from *t; 0, or -1 when the run failed there (r's
   message): the integrator failed, the state is not finite, the run's step budget is spent, or
   the run closes in on Painleve's boundary */
static int advance(zp_sim *s, zp_result *r, double *t, zp_adv *adv) {
    char err[256] = "";
    double t_before = *t;
    *adv = s->meth->advance(s->mwork, t, s->y, s->roots, err, sizeof err);
    int bad = first_non_finite(s->y, s->n);
    long steps_now = 0, evals_now = 0;
    s->meth->stats(s->mwork, &steps_now, &evals_now);
    if (*adv == ZP_ADV_FAIL || bad >= 0 || r->steps + steps_now > s->o.max_steps) {
        add_stats(s, r);
        if (bad >= 0) {
            snprintf(err, sizeof err, "state component %d of %d (%s) is not finite", bad, s->n,
                     bad == 0 ? "trolley x" : "see the formulation's layout");
        } else if (*adv != ZP_ADV_FAIL) {
            snprintf(err, sizeof err, "the run's budget of %ld steps is exhausted", s->o.max_steps);
        }
        return failed(s, r, *t, err);
    }
    /* closing in on Painleve's boundary: steps that each meet it, or no longer advance */
    s->inconsistent_steps = isfinite(s->inconsistent_t) ? s->inconsistent_steps + 1 : 0;
    if (s->inconsistent_steps >= ZP_PAINLEVE_STEPS ||
        (s->inconsistent_steps > 0 && !(*t > t_before))) {
        add_stats(s, r);
        return failed(s, r, *t, "");
    }
    s->inconsistent_t = NAN; /* a step was taken: what a trial stage met is past */
    return 0;
}

/* check: a death the step's ends miss. Unless the step ended on a located death root, a joint
   found past the death angle inside it grazed that angle: the run is put there, on that
   death's root (zp_graze_locate) */
static zp_adv check(zp_sim *s, double t_before, double *t, zp_adv adv) {
    int link;
    if (!died_at_root(s->m, s->roots, adv) &&
        zp_graze_locate(s->m, s->form, s->meth, s->mwork, t_before, *t, s->y, s->n, t, s->yout,
                        &link)) {
        memcpy(s->y, s->yout, sizeof *s->y * s->n);
        memset(s->roots, 0, sizeof *s->roots * s->nroot);
        s->roots[ZP_ROOT_DEATH + link] = 1;
        adv = ZP_ADV_ROOT;
    }
    return adv;
}

/* outputs: the step's extremes and load peaks, the frames at x it passed, and unless it ended
   on a root (whose outputs wait for its event) the rows, samples and frames due by its end */
static void outputs(zp_sim *s, const zp_input *in, zp_result *r, double t, zp_adv adv,
                    zp_sim_output_cursor *oc) {
    zp_sim_peaks_extremes(s, t, s->y, r);
    if (in->frame_at_x) {
        zp_sim_output_frames_in_step(s, in, t, oc);
    }
    if (s->o.peaks) {
        zp_sim_peaks_step(s, t, adv);
    }
    if (adv != ZP_ADV_ROOT) {
        zp_sim_output_emit(s, in, t, 1, oc);
    }
}

/* What a step ended on: a root's event (ZP_EVENT_NONE: only extrema of joint angles), or with
   no root nothing, a hold whose chain has settled, a break of the schedule, or t_max. */
typedef enum { STEP_ON, STEP_EVENT, STEP_SETTLED, STEP_BREAK, STEP_T_MAX } step_kind;
typedef struct step_end {
    step_kind kind;
    zp_event ev;  /* STEP_EVENT */
    int link, to; /* the dead link (0-based), the entered section (zp_events_classify) */
} step_end;

/* classify: what the step that ended at t on adv ended on */
static step_end classify(zp_sim *s, double t, zp_adv adv) {
    const zp_model *m = s->m;
    step_end e = {STEP_EVENT, ZP_EVENT_NONE, 0, 0};
    if (adv != ZP_ADV_ROOT) {
        if (s->stuck && zp_sim_events_settled(s, t)) {
            e.kind = STEP_SETTLED;
            return e;
        }
        /* a boundary passed without a root (one masked at a restart) is crossed here */
        if (s->y[0] < m->xb[s->sec] || s->y[0] > m->xb[s->sec + 1]) {
            memset(s->roots, 0, sizeof *s->roots * s->nroot);
            s->roots[s->y[0] < m->xb[s->sec] ? ZP_ROOT_LEFT : ZP_ROOT_RIGHT] = 1;
        } else {
            e.kind = adv != ZP_ADV_STOP                ? STEP_ON
                     : s->nbreak > 0 && t < s->o.t_max ? STEP_BREAK
                                                       : STEP_T_MAX;
            return e;
        }
    }
    e.ev = zp_events_classify(m, s->sec, s->roots, &e.link, &e.to);
    return e;
}

/* handle: what the step ended on at t; 0 to go on (the integrator restarted where the equations
   change), or the run ended (1, r filled) or failed (-1, r's message) */
static int handle(zp_sim *s, const zp_input *in, zp_result *r, double t, step_end e,
                  zp_sim_output_cursor *oc) {
    if (e.kind == STEP_ON) {
        return 0;
    }
    if (e.kind == STEP_EVENT) {
        /* outputs up to the event from the dense output; one on a kink shows the state after */
        zp_sim_output_emit(s, in, e.ev == ZP_EVENT_KINK ? t - ZP_EVENT_TIME_EPS : t, 1, oc);
        if (e.ev == ZP_EVENT_NONE) {
            return 0;
        }
    }
    add_stats(s, r);
    if (e.kind == STEP_SETTLED || (e.kind == STEP_T_MAX && s->stuck)) {
        zp_sim_events_held(s, r, t);
        return 1;
    }
    if (e.kind == STEP_T_MAX) {
        zp_sim_output_finish(s, r, t, ZP_OUTCOME_STALLED, ZP_STALL_T_MAX);
        return 1;
    }
    int end = 0, dir;
    const char *cannot; /* why the restart that follows could fail */
    if (e.kind == STEP_BREAK) {
        /* a break of the schedule: the force jumps (a held trolley is judged again), the
           integrator starts afresh */
        end = s->stuck ? zp_sim_events_stick(s, t, r, &dir) : 0;
        cannot = "the integrator could not restart at a break";
    } else if (e.ev == ZP_EVENT_TANGENT) {
        zp_sim_events_tangent(s);
        cannot = "the integrator could not restart at an arc's end";
    } else if (e.ev == ZP_EVENT_ZONE) {
        zp_sim_events_zone(s);
        cannot = "the integrator could not restart at the brake zone";
    } else if (e.ev == ZP_EVENT_REST) {
        end = zp_sim_events_rest(s, t, r);
        cannot = "the integrator could not restart at rest";
    } else if (e.ev == ZP_EVENT_KINK) {
        end = zp_sim_events_kink(s, in, r, t, e.to, oc);
        cannot = "the integrator could not restart after the kink";
    } else {
        return zp_sim_events_end(s, in, r, t, e.ev, e.link, oc);
    }
    if (end) {
        return end;
    }
    return restart(s, r, t) ? failed(s, r, t, cannot) : 0;
}

/* the run: its start, then step after step until it ends or fails */
static zp_status run(zp_sim *s, const zp_input *in, zp_result *r) {
    zp_sim_output_cursor oc = {0};
    double t = 0;
    int end = start(s, in, r, &oc);
    while (!end) {
        double t_before = t;
        zp_adv adv;
        end = advance(s, r, &t, &adv);
        if (end) {
            break;
        }
        adv = check(s, t_before, &t, adv);
        outputs(s, in, r, t, adv, &oc);
        end = handle(s, in, r, t, classify(s, t, adv), &oc);
    }
    return end < 0 ? ZP_ERR_NUMERIC : ZP_OK;
}

zp_status zp_sim_run(const zp_model *m, zp_sim *s, const zp_input *in, zp_result *r) {
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    memset(r, 0, sizeof *r);
    s->m = m;
    /* a scaled drive is a schedule of its own, made once per run, not a factor per evaluation */
    if (in->force_scale) {
        s->scaled = zp_drive_scaled(in->sched, in->force_scale);
        s->sched = &s->scaled;
    } else {
        s->sched = in->sched;
    }
    s->nbreak = zp_drive_breaks(in->sched, s->breaks, ZP_SCHED_MAX_BREAKS);
    s->sec = 0;
    s->e_impulse = 0;
    s->rows.n = s->nsamples = s->nframes = s->ncross = 0;
    s->peaks = (zp_load_peaks){.normal_min = INFINITY, .normal_max = -INFINITY};
    s->env.n = 0;
    memset(s->arc_peaks, 0, sizeof s->arc_peaks);
    memset(&s->zone_peaks, 0, sizeof s->zone_peaks);
    zp_status st = run(s, in, r);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    r->wall_s = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
    return st;
}
