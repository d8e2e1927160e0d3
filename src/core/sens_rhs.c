/* The sensitivity equations s_k' = J s_k + df/dp_k and the derivative of the kink map.
 *
 * Design note: each product J s_k + df/dp_k is the derivative of the plain rates along the
 * direction (s_k, e_k) in (state, parameters), taken on the plain equations themselves (every
 * formulation, effect and course provider as the run has them) by the central difference
 * (F(h) - F(-h)) / 2h, two evaluations per parameter where the five-point stencil took four
 * (those evaluations are most of a sensitivity run's cost). With h a relative step of 1e-4 of
 * the state's scale its truncation, O(h^2), sits near 1e-8 of the rates, and so does its
 * round-off where the rates carry the cable's equilibrium solves (about 1e-12 of noise, over
 * h): a step of 1e-5 made the zipline's sensitivities rough enough to cost 26 % more steps.
 * tests/test_gradient.c measures the gradients against central differences of whole runs
 * (at worst 1.7e-7 relative off, where the five-point stencil was 2.2e-8). The kink map and the
 * peaks, differentiated a few times a run, keep the five-point stencil. The alternative, the
 * formulation's rates differentiated by hand or by dual numbers, would be exact to round-off
 * but written once per formulation and effect; the drive is linear in its parameters, so
 * df/dp_k carries no stencil error at all. */
#include <math.h>
#include <string.h>

#include "impulse.h"
#include "sens_int.h"
#include "sim_rhs.h"

/* the largest of r and |u_i| / max(|y_i|, 1) over the entries of the state that feed back
   into the rates: positions and rates, and the drive's states (not the work integrals) */
static double fed_back_ratio(const zp_sim *s, const double *y, const double *u, double r) {
    for (int i = 0; i < s->w0; i++) {
        r = fmax(r, fabs(u[i]) / fmax(fabs(y[i]), 1));
    }
    for (int i = s->wd; i < s->n; i++) {
        r = fmax(r, fabs(u[i]) / fmax(fabs(y[i]), 1));
    }
    return r;
}

/* the step along (s, e_k) that moves no entry of the state that feeds back nor p_k by more
   than ZP_SENS_CENTRAL_STEP of its scale */
static double step_along(const zp_sens *c, const double *y, const double *s, int k) {
    return ZP_SENS_CENTRAL_STEP / fed_back_ratio(c->sim, y, s, 1 / fmax(fabs(c->sched.p[k]), 1));
}

/* the plain rates at y: the course read on the piece the integrator restarted on (continued
   past its ends), whose f'' is smooth inside the stencil */
static int rates(zp_sens *c, double t, const double *y, double *f) {
    c->rates++;
    return c->rhs(t, y, f, c->sim);
}

int zp_sens_rhs_rates(zp_sens *c, double t, const double *y, double *f) {
    return rates(c, t, y, f);
}

/* the rates at y + a h s with p_k + a h, into f */
static int rates_at(zp_sens *c, double t, const double *y, const double *s, int k, double p_k,
                    double a, double h, double *f) {
    double *yp = c->scratch + 3 * c->n;
    for (int i = 0; i < c->n; i++) {
        yp[i] = y[i] + a * h * s[i];
    }
    c->sched.p[k] = p_k + a * h;
    return rates(c, t, yp, f);
}

int zp_sens_rhs_zero(const double *s, int n) {
    for (int i = 0; i < n; i++) {
        if (s[i] != 0) {
            return 0;
        }
    }
    return 1;
}

int zp_sens_rhs(double t, const double *ya, double *yd, void *user) {
    zp_sens *c = user;
    int n = c->n;
    int rc = rates(c, t, ya, yd);
    double *f1 = c->scratch + n, *g = c->scratch + 2 * n;
    for (int k = 0; k < c->np && !rc; k++) {
        const double *s = ya + n * (k + 1);
        double *ds = yd + n * (k + 1);
        if (zp_drive_param_section(&c->sched, k) != c->sim->sec && zp_sens_rhs_zero(s, n)) {
            /* a parameter of a section not reached yet: the rates do not move along (0, e_k),
               and the stencil would only add its round-off (measured: about a third of a
               3-section run's stencil work, two thirds of a 3-knot profile's) */
            memset(ds, 0, sizeof *ds * (size_t)n);
            continue;
        }
        double p_k = c->sched.p[k], h = step_along(c, ya, s, k);
        rc = rates_at(c, t, ya, s, k, p_k, 1, h, f1) || rates_at(c, t, ya, s, k, p_k, -1, h, g);
        for (int i = 0; i < n && !rc; i++) {
            ds[i] = (f1[i] - g[i]) / (2 * h);
        }
        c->sched.p[k] = p_k;
    }
    return rc;
}

int zp_sens_rhs_root(double t, const double *ya, double *g, void *user) {
    zp_sens *c = user;
    return c->root(t, ya, g, c->sim);
}

/* the chain across the kink into `to` from y_in, before (*in) and after (*out) the impulse */
static int kink_chains(zp_sens *c, const double *y_in, int to, zp_chain *in, zp_chain *out) {
    zp_sim *s = c->sim;
    const zp_model *m = s->m;
    double b = m->xb[to > s->sec ? to : s->sec];
    *in = zp_sim_rhs_chain(s, y_in);
    zp_chain ch = *in;
    zp_track entered = s->track(m, s->course, to, b);
    ch.q[0] = b;
    ch.q[1] = entered.f;
    zp_impulse imp;
    if (m->physics & ZP_PHYS_ROUNDED) {
        ch.v[1] = entered.fp * ch.v[0]; /* an arc has no kink: only onto the course at b */
    } else if (zp_impulse_apply(m, entered.fp, &ch, &imp)) {
        return 1;
    }
    *out = ch;
    return 0;
}

int zp_sens_rhs_kink_map(zp_sens *c, const double *y_in, int to, double *y_out) {
    zp_chain in, out;
    if (kink_chains(c, y_in, to, &in, &out)) {
        return 1;
    }
    zp_sim *s = c->sim;
    s->form->from_chain(s->m, &out, y_in + s->w0, y_out);
    memcpy(y_out + s->wd, y_in + s->wd, sizeof *y_out * (size_t)s->m->ndrive); /* continuous */
    return 0;
}

int zp_sens_rhs_kink_dv(zp_sens *c, const double *y_in, int to, double *dv) {
    zp_chain in, out;
    if (kink_chains(c, y_in, to, &in, &out)) {
        return 1;
    }
    *dv = hypot(out.v[0] - in.v[0], out.v[1] - in.v[1]); /* as the plain run's kink_dv */
    return 0;
}

double zp_sens_rhs_speed(zp_sens *c, const double *y) {
    zp_chain ch = zp_sim_rhs_chain(c->sim, y);
    return hypot(ch.v[0], ch.v[1]);
}

int zp_sens_rhs_histories(zp_sens *c, double t, const double *y, double *v, double *power) {
    zp_sim *s = c->sim;
    const zp_model *m = s->m;
    double *f = c->scratch + 2 * c->n;
    zp_track tr = zp_model_track_piece(m, s->course, s->sec, s->arc, y[0]);
    zp_drive_now dn = zp_sim_rhs_drive_on(s, tr, t, y, f);
    zp_drive_state st = zp_drive_state_at(m->drive, t, y[0], y[s->w0 / 2], s->sec, tr.fp);
    *power = fabs(zp_sim_rhs_drive_applied(s, &st, y) * st.v);
    if (!v) {
        return 0;
    }
    zp_loads loads;
    c->rates++;
    int rc = s->form->rhs(m, s->fwork, &dn, y, f, &loads);
    zp_row_loads(m, &loads, v + m->nlink, v);
    for (int q = 0; q < 2 * m->nlink; q++) {
        v[q] = isfinite(v[q]) ? v[q] : 0;
    }
    return rc;
}

int zp_sens_rhs_kink_deriv(zp_sens *c, const double *y, const double *u, int to, double *dh) {
    int n = c->n;
    double *yp = c->scratch + 3 * n, *hp = c->scratch, r = fed_back_ratio(c->sim, y, u, 0);
    memset(dh, 0, sizeof *dh * n);
    if (r == 0) {
        return 0;
    }
    double h = ZP_SENS_STEP / r;
    static const double at[4] = {2, 1, -1, -2}, wt[4] = {-1, 8, -8, 1};
    for (int j = 0; j < 4; j++) {
        for (int i = 0; i < n; i++) {
            yp[i] = y[i] + at[j] * h * u[i];
        }
        if (zp_sens_rhs_kink_map(c, yp, to, hp)) {
            return 1;
        }
        for (int i = 0; i < n; i++) {
            dh[i] += wt[j] * hp[i];
        }
    }
    for (int i = 0; i < n; i++) {
        dh[i] /= 12 * h;
    }
    return 0;
}
