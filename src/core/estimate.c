/* An error estimate for every answer: the run again at a tolerance 100x tighter. Rejected:
   the spread between two methods, which costs as much and measures the looser of the two. */
#include "estimate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

double zp_estimate_energy_residual(const zp_result *r) {
    /* the effects' work is 0 without [physics]: the sum is then the plain audit's */
    double res = r->e_final - r->e_initial - r->w_drive + r->w_damp + r->e_impulse;
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        res += r->w_effect[k];
    }
    /* the cable's potential belongs to the system (docs/model.md); added only where it moved,
       so a scene without a cable keeps its residual bit for bit (-0 included) */
    double dpi = r->pi_final - r->pi_initial;
    return dpi != 0 ? res + dpi : res;
}

/* the energies the audit adds up: a residual is judged against their size */
static double energy_scale(const zp_result *r) {
    double scale = fabs(r->e_initial) + fabs(r->e_final) + fabs(r->w_drive) + fabs(r->w_damp) +
                   fabs(r->e_impulse);
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        scale += fabs(r->w_effect[k]);
    }
    double dpi = r->pi_final - r->pi_initial;
    return dpi != 0 ? scale + fabs(dpi) : scale;
}

zp_sim_opts zp_estimate_tighter(const zp_sim_opts *o) {
    zp_sim_opts ot = *o;
    /* both tighter: rtol down to round-off, atol by the whole factor (it has no such floor) */
    ot.rtol = fmax(o->rtol / ZP_ESTIMATE_FACTOR, ZP_ESTIMATE_RTOL_MIN);
    ot.atol = o->atol / ZP_ESTIMATE_FACTOR;
    ot.output_dt = 0;
    ot.track_loads = 0;
    return ot;
}

void zp_estimate_run(const zp_model *m, const zp_sim_opts *o, const zp_input *in,
                     const zp_result *r, zp_estimate *e) {
    zp_sim_opts ot = zp_estimate_tighter(o);
    zp_input it = {.sched = in->sched, .start = in->start};
    *e = (zp_estimate){.rtol = ot.rtol, .atol = ot.atol, .time_error = NAN};
    /* heap, not static: a library function keeps no state between calls (or threads) */
    zp_result *tight = malloc(sizeof *tight);
    zp_sim *s = tight ? zp_sim_create(m, &ot) : NULL;
    if (!s) {
        snprintf(e->message, sizeof e->message, "cannot create the simulator (out of memory)");
    } else if (zp_sim_run(m, s, &it, tight) != ZP_OK) {
        snprintf(e->message, sizeof e->message, "%s", tight->message);
    } else {
        e->ok = 1;
        e->outcome = tight->outcome;
        e->died_link = tight->died_link;
        e->time = tight->time;
        e->time_error = fabs(r->time - tight->time);
        e->sensitive = tight->outcome != r->outcome || tight->died_link != r->died_link ||
                       tight->stall != r->stall;
        e->energy_residual = zp_estimate_energy_residual(r);
        e->energy_large = fabs(e->energy_residual) > ZP_ESTIMATE_ENERGY_REL * energy_scale(r);
    }
    zp_sim_free(s);
    free(tight);
}
