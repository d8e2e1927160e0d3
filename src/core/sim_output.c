/* What a run leaves: rows on the output grid, samples and still frames (at times, or where the
   trolley first reaches an x), each read off the dense output or the state at an event, and the
   result at the end or the failure. */
#include "sim_output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim_peaks.h"
#include "sim_rhs.h"

/* the next frame time, or INFINITY (none left, or frames at x) */
static double next_frame_t(const zp_input *in, const zp_sim_output_cursor *oc) {
    return !in->frame_at_x && oc->next_frame < in->nframe ? in->frame_at[oc->next_frame] : INFINITY;
}

/* the next output time (row, sample or frame), or INFINITY */
static double next_output(const zp_sim *s, const zp_input *in, const zp_sim_output_cursor *oc) {
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

void zp_sim_output_emit(zp_sim *s, const zp_input *in, double t_upto, int dense,
                        zp_sim_output_cursor *oc) {
    for (double to; (to = next_output(s, in, oc)) <= t_upto;) {
        const double *y = s->y;
        if (dense && s->meth->interpolate(s->mwork, to, s->yout) == 0) {
            y = s->yout;
        }
        if (next_frame_t(in, oc) == to) {
            /* before the row of the run: a frame leaves the load peaks alone */
            if (push_row(&s->frames, &s->nframes, &s->cap_frames, zp_sim_rhs_row(s, to, y))) {
                return;
            }
            oc->next_frame++;
        }
        int row = s->rows.n < s->rows.cap && oc->next_row == to;
        int sample = oc->next_sample < in->nsample && in->sample_t[oc->next_sample] == to;
        if (!row && !sample) {
            continue;
        }
        zp_row r = zp_sim_peaks_row(s, to, y);
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

void zp_sim_output_frames_in_step(zp_sim *s, const zp_input *in, double t,
                                  zp_sim_output_cursor *oc) {
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
        if (!y || push_row(&s->frames, &s->nframes, &s->cap_frames, zp_sim_rhs_row(s, tc, y))) {
            return;
        }
    }
    oc->t_prev = t;
}

void zp_sim_output_frames_here(zp_sim *s, const zp_input *in, double t, double reached,
                               zp_sim_output_cursor *oc) {
    for (; in->frame_at_x && oc->next_frame < in->nframe; oc->next_frame++) {
        if (!(in->frame_at[oc->next_frame] <= reached) ||
            push_row(&s->frames, &s->nframes, &s->cap_frames, zp_sim_rhs_row(s, t, s->y))) {
            break;
        }
    }
    oc->t_prev = t;
}

void zp_sim_output_finish(zp_sim *s, zp_result *r, double t, zp_outcome o, zp_stall st) {
    r->outcome = o;
    r->stall = st;
    r->time = t;
    zp_chain c = zp_sim_rhs_chain(s, s->y);
    r->x = c.q[0];
    r->v = hypot(c.v[0], c.v[1]);
    zp_energy e = zp_state_energy(s->m, &c);
    r->e_final = e.kinetic + e.potential;
    r->pi_final = zp_model_cable_energy(s->m, c.q[0]);
    r->x_min = fmin(r->x_min, r->x);
    r->x_max = fmax(r->x_max, r->x);
    r->w_drive = s->y[s->w0 + ZP_W_DRIVE];
    r->w_damp = s->y[s->w0 + ZP_W_DAMP];
    for (int k = ZP_W_EFFECTS; k < s->m->nwork; k++) {
        r->w_effect[k - ZP_W_EFFECTS] = s->y[s->w0 + k];
    }
    r->e_impulse = s->e_impulse;
    /* the last row shows the end state */
    if (s->rows.n < s->rows.cap &&
        (s->rows.n == 0 || zp_row_store_t(&s->rows, s->rows.n - 1) < t)) {
        zp_row last = zp_sim_peaks_row(s, t, s->y);
        zp_row_store_put(&s->rows, &last);
    }
    r->peaks = s->peaks; /* after the last row, whose loads count too */
    if (s->env.n) {
        zp_envelope_end(&s->env, t);
        memcpy(r->env_longest, s->env.longest, sizeof r->env_longest);
    }
}

void zp_sim_output_fail(zp_sim *s, zp_result *r, double t, const char *why) {
    if (isfinite(s->inconsistent_t)) {
        snprintf(r->message, sizeof r->message,
                 "rolling resistance has no consistent normal force at t = %.9g s, x = %.9g m "
                 "(Painleve's paradox: mu = %g is too large for this trolley and chain; the rigid "
                 "model of docs/model.md has no motion there)",
                 s->inconsistent_t, s->inconsistent_x, s->m->mu);
        return;
    }
    char where[64] = "";
    if (isfinite(s->y[0])) {
        snprintf(where, sizeof where, ", x = %.9g m (section %d)", s->y[0], s->sec + 1);
    }
    snprintf(r->message, sizeof r->message, "numerical failure at t = %.9g s%s: %.180s", t, where,
             why);
}
