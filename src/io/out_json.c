/* docs/commands.md's JSON object of one run; angles in degrees, everything else SI. */
#include "out_json.h"

#include <math.h>

#include "cable_ride.h"
#include "estimate.h"

#define DEG (180.0 / M_PI)

void zp_out_json_number(FILE *f, double v) {
    if (isfinite(v)) {
        fprintf(f, "%.17g", v);
    } else {
        fputs("null", f);
    }
}

void zp_out_json_string(FILE *f, const char *s) {
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\') {
            fprintf(f, "\\%c", *s);
        } else if ((unsigned char)*s < 0x20) {
            fprintf(f, "\\u%04x", (unsigned char)*s);
        } else {
            fputc(*s, f);
        }
    }
    fputc('"', f);
}

static void key_num(FILE *f, const char *key, double v, const char *sep) {
    fprintf(f, "\"%s\": ", key);
    zp_out_json_number(f, v);
    fputs(sep, f);
}

static void num_list(FILE *f, const double *v, int n, double scale) {
    fputc('[', f);
    for (int i = 0; i < n; i++) {
        zp_out_json_number(f, v[i] * scale);
        fputs(i + 1 < n ? ", " : "", f);
    }
    fputc(']', f);
}

static void write_samples(FILE *f, const zp_model *m, const zp_row *s, int n) {
    fputs("  \"samples\": [", f);
    for (int k = 0; k < n; k++) {
        fputs(k ? ",\n    {" : "\n    {", f);
        key_num(f, "t", s[k].t, ", ");
        key_num(f, "x", s[k].c.q[0], ", ");
        key_num(f, "y", s[k].c.q[1], ", ");
        fprintf(f, "\"section\": %d, \"theta\": ", s[k].sec + 1);
        num_list(f, s[k].c.q + 2, m->nlink, DEG);
        fputs(", \"omega\": ", f);
        num_list(f, s[k].c.v + 2, m->nlink, DEG);
        fputs(", ", f);
        key_num(f, "normal_force", s[k].loads.normal, "}");
    }
    fputs(n ? "\n  ],\n" : "],\n", f);
}

void zp_out_json_limits(FILE *f, const zp_model *m, const zp_result *r, const zp_limits *lim) {
    double v[ZP_LIMIT_COUNT];
    zp_limits_reached(m, r, v);
    fputs("{", f);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        double max = lim ? lim->max[i] : 0;
        if (i == ZP_LIMIT_G_ENVELOPE) {
            /* docs/commands.md: per level {g, allowed_s, longest_s} */
            fprintf(f, "\"%s\": [", zp_limit_name(i));
            for (int l = 0; l < m->nenv; l++) {
                fputs(l ? ", {" : "{", f);
                key_num(f, "g", m->env_g[l], ", ");
                key_num(f, "allowed_s", m->env_s[l], ", ");
                key_num(f, "longest_s", r->env_longest[l], "}");
            }
            fputs(i + 1 < ZP_LIMIT_COUNT ? "], " : "]}", f);
            continue;
        }
        fprintf(f, "\"%s\": {", zp_limit_name(i));
        if (!zp_limit_reached_in(r, i)) { /* never measured: neither kept nor broken */
            fputs("\"reached\": null, ", f);
            key_num(f, "limit", max > 0 ? max : NAN, max > 0 ? ", \"kept\": null}" : "}");
            fputs(i + 1 < ZP_LIMIT_COUNT ? ", " : "}", f);
            continue;
        }
        key_num(f, "reached", v[i], ", ");
        if (max > 0) {
            key_num(f, "limit", max, "");
            fprintf(f, ", \"kept\": %s}", zp_limits_kept(i, v[i], max) ? "true" : "false");
        } else {
            fputs("\"limit\": null}", f);
        }
        fputs(i + 1 < ZP_LIMIT_COUNT ? ", " : "}", f);
    }
}

/* the cable over the x the ride visited (CLI.md `cable`) */
static void write_cable(FILE *f, const zp_model *m, const zp_result *r) {
    zp_cable_ride cr;
    char why[256];
    const zp_cable *c = zp_cable_paths_cable(m->cable_paths);
    int ok = zp_cable_ride_over(c, m->g * m->mtot, r->x_min, r->x_max, &cr, why, sizeof why) ==
             ZP_OK;
    fputs("\"cable\": {", f);
    key_num(f, "anchor_tension_max", ok ? fmax(cr.ta_max, cr.tb_max) : NAN, ", ");
    key_num(f, "trolley_tension_max", ok ? cr.trolley_max : NAN, ", ");
    key_num(f, "lowest_y", ok ? cr.y_low : NAN, ", ");
    key_num(f, "sag_mid", ok ? cr.sag_mid : NAN, "},\n  ");
}

void zp_out_json_result(FILE *f, const zp_model *m, const zp_result *r, const zp_sim *s,
                        const zp_run_meta *meta) {
    int nsamples, nk;
    const zp_row *samples = zp_sim_samples(s, &nsamples);
    const zp_crossing *cross = zp_sim_crossings(s, &nk);
    fputs("{\n  \"scene\": ", f);
    zp_out_json_string(f, meta->scene);
    fprintf(f, ",\n  \"method\": \"%s\",\n  \"formulation\": \"%s\",\n  ", meta->method,
            meta->formulation);
    key_num(f, "rtol", meta->rtol, ", ");
    key_num(f, "atol", meta->atol, ",\n");
    fputs("  \"forces\": ", f);
    num_list(f, meta->sched->p, meta->sched->np, 1.0);
    fprintf(f, ",\n  \"outcome\": \"%s\",\n  ", zp_sim_outcome_name(r->outcome));
    key_num(f, "time", r->time, ",\n  ");
    key_num(f, "x", r->x, ",\n  ");
    key_num(f, "speed", r->v, ",\n");
    if (meta->estimate) {
        /* null when the tighter run failed: no estimate, no verdict */
        const zp_estimate *e = meta->estimate;
        fputs("  ", f);
        key_num(f, "time_error", e->ok ? e->time_error : NAN, ", ");
        key_num(f, "time_error_rtol", e->rtol, ", ");
        fprintf(f, "\"sensitive\": %s,\n", !e->ok ? "null" : e->sensitive ? "true" : "false");
    }
    if (meta->accuracy) {
        const zp_accuracy *a = meta->accuracy;
        fputs("  \"accuracy\": {", f);
        key_num(f, "requested", a->requested, ", ");
        key_num(f, "met", a->met, ", ");
        fprintf(f, "\"ok\": %s, \"method\": \"%s\", ", a->ok ? "true" : "false",
                zp_method_get(a->method)->name);
        key_num(f, "rtol", a->rtol, ", ");
        fprintf(f, "\"reruns\": %d},\n", a->reruns);
    }
    if (r->died_link) {
        fprintf(f, "  \"died_link\": %d,\n", r->died_link);
    } else {
        fputs("  \"died_link\": null,\n", f);
    }
    if (r->outcome == ZP_OUTCOME_STALLED) {
        fprintf(f, "  \"stall_reason\": \"%s\",\n", zp_sim_stall_name(r->stall));
    } else {
        fputs("  \"stall_reason\": null,\n", f);
    }
    fputs("  \"kinks\": [", f);
    for (int k = 0; k < nk; k++) {
        const zp_crossing *c = &cross[k];
        fputs(k ? ",\n    {" : "\n    {", f);
        key_num(f, "t", c->t, ", ");
        key_num(f, "x", c->x, ", ");
        fprintf(f, "\"from_section\": %d, \"to_section\": %d, ", c->from + 1, c->to + 1);
        key_num(f, "impulse", c->impulse, ", ");
        key_num(f, "energy_lost", c->energy_lost, m->narc ? ", \"rounded\": true}" : "}");
    }
    fputs(nk ? "\n  ],\n" : "],\n", f);
    fprintf(f, "  \"kink_crossings\": %d,\n  \"max_rel_angle\": ", r->ncross);
    num_list(f, r->max_rel_angle, m->nlink, DEG);
    fputs(",\n  \"energy\": {", f);
    key_num(f, "initial", r->e_initial, ", ");
    key_num(f, "final", r->e_final, ", ");
    key_num(f, "drive_work", r->w_drive, ", ");
    key_num(f, "damper_work", r->w_damp, ", ");
    key_num(f, "impulse_loss", r->e_impulse, ", ");
    for (int k = 0; zp_effect_work_shown(m->physics) && k < ZP_EFFECT_NWORK; k++) {
        key_num(f, zp_effect_work_names(k)->column, r->w_effect[k], ", ");
    }
    if (m->cable_paths) {
        fputs("\"cable_potential\": {", f);
        key_num(f, "initial", r->pi_initial, ", ");
        key_num(f, "final", r->pi_final, "}, ");
    }
    key_num(f, "residual", zp_estimate_energy_residual(r), "},\n  ");
    if (m->cable_paths) {
        write_cable(f, m, r);
    }
    key_num(f, "constraint_residual", r->constraint_residual, ",\n");
    fputs("  \"loads\": {\"joint_peak\": ", f);
    num_list(f, r->peaks.joint, m->nlink, 1.0);
    fputs(", ", f);
    key_num(f, "normal_min", r->peaks.normal_min, ", ");
    key_num(f, "normal_max", r->peaks.normal_max, ", ");
    fputs("\"acc_peak_g\": ", f);
    num_list(f, r->peaks.acc_g, m->nlink, 1.0);
    fputs("},\n", f);
    fputs("  \"limits\": ", f);
    zp_out_json_limits(f, m, r, meta->lim);
    fputs(",\n", f);
    write_samples(f, m, samples, nsamples);
    fputs("  \"samples_not_reached\": ", f);
    num_list(f, meta->unreached, meta->nunreached, 1.0);
    fputs(",\n", f);
    fprintf(f, "  \"stats\": {\"steps\": %ld, \"rejected_steps\": %ld, \"rhs_evals\": %ld, ",
            r->steps, r->rejected, r->rhs_evals);
    key_num(f, "wall_s", r->wall_s, "}\n}\n");
}
