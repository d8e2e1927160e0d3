/* The text of one simulation (out_text.h); angles in degrees, everything else SI. */
#include "out_text.h"

#include <math.h>

#include "cable_ride.h"

static void outcome_text(FILE *f, const zp_model *m, const zp_result *r) {
    fprintf(f, "outcome: %s", zp_sim_outcome_name(r->outcome));
    if (r->outcome == ZP_OUTCOME_DIED) {
        fprintf(f, " (joint of link %d looped)", r->died_link);
    } else if (r->outcome == ZP_OUTCOME_STALLED) {
        fprintf(f, " (%s)", zp_sim_stall_name(r->stall));
    }
    fprintf(f, "\ntime: %.9f s\nx: %.6f m\nspeed: %.4f m/s (%.2f km/h)\n", r->time, r->x, r->v,
            3.6 * r->v);
    fprintf(f, "largest |relative joint angle| (deg):");
    for (int i = 0; i < m->nlink; i++) {
        fprintf(f, " %.3f", r->max_rel_angle[i] * 180.0 / M_PI);
    }
    fprintf(f, "\nkink crossings: %d\n", r->ncross);
    int nwork = 0;
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        if (zp_effect_work_shown(m->physics, k)) {
            fprintf(f, "%s%s: %.6g J", nwork++ ? ", " : "", zp_effect_work_names(k)->words,
                    r->w_effect[k]);
        }
    }
    if (nwork) {
        fputc('\n', f);
    }
    fprintf(f, "energy audit residual: %.3g J\n", zp_estimate_energy_residual(r));
    fprintf(f, "steps: %ld (and %ld rejected), rhs evaluations: %ld, wall: %.4f s\n", r->steps,
            r->rejected, r->rhs_evals, r->wall_s);
}

/* with [cable]: what the line carried over the x the ride visited (simulate --json's `cable`) */
static void cable_text(FILE *f, const zp_model *m, const zp_result *r) {
    zp_cable_ride cr;
    char why[256];
    if (zp_cable_ride_over(zp_cable_paths_cable(m->cable_paths), m->g * m->mtot, r->x_min,
                           r->x_max, &cr, why, sizeof why) != ZP_OK) {
        fprintf(f, "cable: no equilibrium over the ride: %s\n", why);
        return;
    }
    fprintf(f,
            "cable: tension at most %.0f N at anchor A, %.0f N at anchor B, %.0f N at the "
            "trolley; lowest point %.3f m at x = %.2f m; sag %.3f m at mid-span\n",
            cr.ta_max, cr.tb_max, cr.trolley_max, cr.y_low, cr.x_low, cr.sag_mid);
}

/* each [limits] value set: reached against the limit; then the felt-g levels */
static void limits_text(FILE *f, const zp_model *m, const zp_result *r, const zp_limits *lim) {
    double v[ZP_LIMIT_COUNT];
    zp_limits_reached(m, r, v);
    for (int i = 0; i < ZP_LIMIT_COUNT && lim; i++) {
        if (lim->max[i] > 0 && !zp_limits_reached_in(r, i)) {
            fprintf(f, "limit %s: not reached (the trolley did not arrive)\n", zp_limits_name(i));
        } else if (lim->max[i] > 0) {
            fprintf(f, "limit %s: reached %.4g %s of %g (%s)\n", zp_limits_name(i), v[i],
                    zp_limits_unit(i), lim->max[i],
                    zp_limits_kept(i, v[i], lim->max[i]) ? "kept" : "BROKEN");
        }
    }
    for (int l = 0; l < m->nenv; l++) {
        fprintf(f, "  felt g above %g g: longest %.4g s at once, allowed %g s%s\n", m->env_g[l],
                r->env_longest[l], m->env_s[l],
                l == zp_limits_envelope_worst(m, r) ? " (the worst level)" : "");
    }
}

/* the state at each reached sample time, and the times never reached */
static void samples_text(FILE *f, const zp_model *m, const zp_result *r, const zp_sim *s,
                         const zp_run_meta *meta) {
    int n;
    const zp_row *smp = zp_sim_samples(s, &n);
    for (int k = 0; k < n; k++) {
        fprintf(f, "sample t = %g s: x = %.6f m, y = %.6f m, section %d, theta (deg):", smp[k].t,
                smp[k].c.q[0], smp[k].c.q[1], smp[k].sec + 1);
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, " %.3f", smp[k].c.q[2 + i] * 180.0 / M_PI);
        }
        fprintf(f, ", normal force %.3f N\n", smp[k].loads.normal);
    }
    for (int k = 0; k < meta->nunreached; k++) {
        fprintf(f, "sample t = %g s: not reached (the run ended at %.9f s)\n", meta->unreached[k],
                r->time);
    }
}

/* the error estimate beside the answer (docs/trade.md) */
static void estimate_text(FILE *f, const zp_result *r, const zp_estimate *e) {
    if (!e->ok) {
        fprintf(f, "time error estimate: unavailable, the run at rtol %.0e failed: %s\n", e->rtol,
                e->message);
    } else if (e->sensitive) {
        fprintf(f,
                "SENSITIVE: at rtol %.0e the outcome is %s at %.9f s instead of %s: the verdict "
                "depends on the tolerance\n",
                e->rtol, zp_sim_outcome_name(e->outcome), e->time, zp_sim_outcome_name(r->outcome));
    } else {
        fprintf(f, "time error estimate: %.2g s (difference from a run at rtol %.0e)\n",
                e->time_error, e->rtol);
    }
    if (e->ok && e->energy_large) {
        fprintf(f,
                "SUSPECT: the energy audit residual %.3g J is large against the energies of the "
                "run: the tolerances are too loose for this answer\n",
                e->energy_residual);
    }
}

/* what a request for accuracy met, and what it cost */
static void accuracy_text(FILE *f, const zp_accuracy *a) {
    fprintf(f, "accuracy: %.2g s requested, %.2g s met%s (%s at rtol %.0e, %d rerun%s)\n",
            a->requested, a->met, a->ok ? "" : " - NOT MET", zp_method_get(a->method)->name,
            a->rtol, a->reruns, a->reruns == 1 ? "" : "s");
}

static void gradient_text(FILE *f, const zp_schedule *sh, const zp_sens_result *g) {
    fprintf(f, "gradient (sensitivities), per %s:\n", zp_drive_unit(sh));
    for (int k = 0; k < g->np; k++) {
        char label[64];
        zp_drive_param_label(sh, k, label, sizeof label);
        fprintf(f, "  %-12s d time %+.9e s, d margin angle %+.9e deg\n", label, g->dtime[k],
                g->dmargin[k] * 180 / M_PI);
    }
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (!g->limits.set[i]) {
            continue;
        }
        fprintf(f, "  d %s (%s):", zp_limits_name(i), zp_limits_unit(i));
        for (int k = 0; g->limits.has[i] && k < g->np; k++) {
            fprintf(f, " %+.9e", g->limits.d[i][k]);
        }
        if (g->limits.has[i] && isfinite(g->limits.t[i])) {
            fprintf(f, "  (of %.9g at t = %.6g s)", g->limits.value[i], g->limits.t[i]);
        } else if (g->limits.has[i]) {
            fprintf(f, "  (of %.9g: nowhere reached, 0 nearby)", g->limits.value[i]);
        }
        fprintf(f, "%s%s\n", g->limits.why_not[i][0] ? "  not smooth: " : "",
                g->limits.why_not[i]);
    }
    if (!g->smooth) {
        fprintf(f, "  not smooth there: %s\n", g->why_not);
    }
}

void zp_out_text_result(FILE *f, const zp_model *m, const zp_result *r, const zp_sim *s,
                        const zp_run_meta *meta) {
    outcome_text(f, m, r);
    if (m->cable_paths) {
        cable_text(f, m, r);
    }
    limits_text(f, m, r, meta->lim);
    samples_text(f, m, r, s, meta);
    if (meta->estimate) {
        estimate_text(f, r, meta->estimate);
    }
    if (meta->accuracy) {
        accuracy_text(f, meta->accuracy);
    }
    if (meta->gradient) {
        gradient_text(f, meta->sched, meta->gradient);
    }
}
