/* docs/commands.md's JSON object of one run; angles in degrees, everything else SI. */
#include "out_json.h"

#include <math.h>

#include "cable_ride.h"
#include "estimate.h"
#include "out_columns.h"

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

void zp_out_json_key(FILE *f, const char *key, double v, const char *sep) {
    fprintf(f, "\"%s\": ", key);
    zp_out_json_number(f, v);
    fputs(sep, f);
}

void zp_out_json_key_string(FILE *f, const char *key, const char *s, const char *sep) {
    fprintf(f, "\"%s\": ", key);
    zp_out_json_string(f, s);
    fputs(sep, f);
}

void zp_out_json_list(FILE *f, const double *v, int n, double scale) {
    fputc('[', f);
    for (int i = 0; i < n; i++) {
        zp_out_json_number(f, v[i] * scale);
        fputs(i + 1 < n ? ", " : "", f);
    }
    fputc(']', f);
}

/* the keys of a sample, in their order: each a quantity of the trajectory's table, its value
   and unit the table's; list: one per link, as a list */
static const struct {
    const char *key;
    zp_out_quantity q;
    int list;
} sample_key[] = {
    {"t", ZP_OUT_Q_T, 0},           {"x", ZP_OUT_Q_X, 0},         {"y", ZP_OUT_Q_Y, 0},
    {"section", ZP_OUT_Q_SECTION, 0}, {"theta", ZP_OUT_Q_THETA, 1}, {"omega", ZP_OUT_Q_OMEGA, 1},
    {"normal_force", ZP_OUT_Q_NORMAL, 0},
};
#define NSAMPLE_KEY ((int)(sizeof sample_key / sizeof *sample_key))

static void write_sample(FILE *f, const zp_model *m, const zp_row *s, const zp_out_column *col) {
    double v[ZP_OUT_COLUMNS_MAX];
    zp_out_columns_values(m, s, v);
    for (int i = 0; i < NSAMPLE_KEY; i++) {
        int n, j = zp_out_columns_find(m, sample_key[i].q, &n);
        const char *sep = i + 1 < NSAMPLE_KEY ? ", " : "}";
        if (sample_key[i].list) {
            fprintf(f, "\"%s\": ", sample_key[i].key);
            zp_out_json_list(f, v + j, n, col[j].csv_scale);
            fputs(sep, f);
        } else {
            zp_out_json_key(f, sample_key[i].key, v[j] * col[j].csv_scale, sep);
        }
    }
}

static void write_samples(FILE *f, const zp_model *m, const zp_row *s, int n) {
    zp_out_column col[ZP_OUT_COLUMNS_MAX];
    zp_out_columns(m, col);
    fputs("  \"samples\": [", f);
    for (int k = 0; k < n; k++) {
        fputs(k ? ",\n    {" : "\n    {", f);
        write_sample(f, m, &s[k], col);
    }
    fputs(n ? "\n  ],\n" : "],\n", f);
}

void zp_out_json_limits(FILE *f, const zp_model *m, const zp_result *r, const zp_limits *lim) {
    double v[ZP_LIMIT_COUNT];
    zp_limits_reached(m, r, v);
    fputs("{", f);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        double max = lim ? lim->max[i] : 0;
        /* the drive's power shows in "drive", the anchor tension in "cable"; here only as
           limits set */
        if ((i == ZP_LIMIT_DRIVE_POWER || i == ZP_LIMIT_CABLE_TENSION) && !(max > 0)) {
            continue;
        }
        fputs(i ? ", " : "", f);
        if (i == ZP_LIMIT_G_ENVELOPE) {
            /* docs/commands.md: per level {g, allowed_s, longest_s} */
            fprintf(f, "\"%s\": [", zp_limits_name(i));
            for (int l = 0; l < m->nenv; l++) {
                fputs(l ? ", {" : "{", f);
                zp_out_json_key(f, "g", m->env_g[l], ", ");
                zp_out_json_key(f, "allowed_s", m->env_s[l], ", ");
                zp_out_json_key(f, "longest_s", r->env_longest[l], "}");
            }
            fputs("]", f);
            continue;
        }
        fprintf(f, "\"%s\": {", zp_limits_name(i));
        if (!zp_limits_reached_in(r, i)) { /* never measured: neither kept nor broken */
            fputs("\"reached\": null, ", f);
            zp_out_json_key(f, "limit", max > 0 ? max : NAN, max > 0 ? ", \"kept\": null}" : "}");
            continue;
        }
        zp_out_json_key(f, "reached", v[i], ", ");
        if (max > 0) {
            zp_out_json_key(f, "limit", max, "");
            fprintf(f, ", \"kept\": %s}", zp_limits_kept(i, v[i], max) ? "true" : "false");
        } else {
            fputs("\"limit\": null}", f);
        }
    }
    fputs("}", f);
}

/* the "gradient" object (docs/commands.md): per schedule parameter, the derivatives of the
   time, of the largest joint angle (deg) and of each [limits] value the scene sets (its unit) */
static void write_gradient(FILE *f, const zp_schedule *sh, const zp_sens_result *g) {
    fputs("  \"gradient\": {\"parameters\": [", f);
    for (int k = 0; k < sh->np; k++) {
        char label[64];
        zp_drive_param_label(sh, k, label, sizeof label);
        fputs(k ? ", " : "", f);
        zp_out_json_string(f, label);
    }
    fputs("], \"time\": ", f);
    zp_out_json_list(f, g->dtime, g->np, 1.0);
    fputs(", \"margin_angle\": ", f);
    zp_out_json_list(f, g->dmargin, g->np, DEG);
    fputs(", \"limits\": {", f);
    const char *sep = "";
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (g->limits.set[i]) {
            fprintf(f, "%s\"%s\": ", sep, zp_limits_name(i));
            if (g->limits.has[i]) {
                zp_out_json_list(f, g->limits.d[i], g->np, 1.0);
            } else {
                fputs("null", f);
            }
            sep = ", ";
        }
    }
    /* why a limit's derivatives are missing or not smooth there; only those */
    fputs("}, \"limits_not_smooth\": {", f);
    sep = "";
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (g->limits.set[i] && g->limits.why_not[i][0]) {
            fprintf(f, "%s\"%s\": ", sep, zp_limits_name(i));
            zp_out_json_string(f, g->limits.why_not[i]);
            sep = ", ";
        }
    }
    fprintf(f, "}, \"smooth\": %s, \"not_smooth_because\": ", g->smooth ? "true" : "false");
    if (g->smooth) {
        fputs("null", f);
    } else {
        zp_out_json_string(f, g->why_not);
    }
    fputs("},\n", f);
}

/* the cable over the x the ride visited (CLI.md `cable`) */
static void write_cable(FILE *f, const zp_model *m, const zp_result *r) {
    zp_cable_ride cr;
    char why[256];
    const zp_cable *c = zp_cable_paths_cable(m->cable_paths);
    int ok = zp_cable_ride_over(c, m->g * m->mtot, r->x_min, r->x_max, &cr, why, sizeof why) ==
             ZP_OK;
    fputs("\"cable\": {", f);
    zp_out_json_key(f, "anchor_tension_max", ok ? fmax(cr.ta_max, cr.tb_max) : NAN, ", ");
    zp_out_json_key(f, "trolley_tension_max", ok ? cr.trolley_max : NAN, ", ");
    zp_out_json_key(f, "lowest_y", ok ? cr.y_low : NAN, ", ");
    zp_out_json_key(f, "sag_mid", ok ? cr.sag_mid : NAN, "},\n  ");
}

/* the error estimate and the accuracy met, when the run has them */
static void checks_json(FILE *f, const zp_run_meta *meta) {
    if (meta->estimate) {
        /* null when the tighter run failed: no estimate, no verdict */
        const zp_estimate *e = meta->estimate;
        fputs("  ", f);
        zp_out_json_key(f, "time_error", e->ok ? e->time_error : NAN, ", ");
        zp_out_json_key(f, "time_error_rtol", e->rtol, ", ");
        fprintf(f, "\"sensitive\": %s,\n", !e->ok ? "null" : e->sensitive ? "true" : "false");
    }
    if (meta->accuracy) {
        const zp_accuracy *a = meta->accuracy;
        fputs("  \"accuracy\": {", f);
        zp_out_json_key(f, "requested", a->requested, ", ");
        zp_out_json_key(f, "met", a->met, ", ");
        fprintf(f, "\"ok\": %s, \"method\": \"%s\", ", a->ok ? "true" : "false",
                zp_method_get(a->method)->name);
        zp_out_json_key(f, "rtol", a->rtol, ", ");
        fprintf(f, "\"reruns\": %d},\n", a->reruns);
    }
}

static void kinks_json(FILE *f, const zp_model *m, const zp_sim *s) {
    int nk;
    const zp_crossing *cross = zp_sim_crossings(s, &nk);
    fputs("  \"kinks\": [", f);
    for (int k = 0; k < nk; k++) {
        const zp_crossing *c = &cross[k];
        fputs(k ? ",\n    {" : "\n    {", f);
        zp_out_json_key(f, "t", c->t, ", ");
        zp_out_json_key(f, "x", c->x, ", ");
        fprintf(f, "\"from_section\": %d, \"to_section\": %d, ", c->from + 1, c->to + 1);
        zp_out_json_key(f, "impulse", c->impulse, ", ");
        zp_out_json_key(f, "energy_lost", c->energy_lost, m->narc ? ", \"rounded\": true}" : "}");
    }
    fputs(nk ? "\n  ],\n" : "],\n", f);
}

/* the energy audit, the cable and the drive, closing the energy object */
static void energy_json(FILE *f, const zp_model *m, const zp_result *r, const zp_run_meta *meta) {
    fputs(",\n  \"energy\": {", f);
    zp_out_json_key(f, "initial", r->e_initial, ", ");
    zp_out_json_key(f, "final", r->e_final, ", ");
    zp_out_json_key(f, "drive_work", r->w_drive, ", ");
    zp_out_json_key(f, "damper_work", r->w_damp, ", ");
    zp_out_json_key(f, "impulse_loss", r->e_impulse, ", ");
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        if (zp_effect_work_shown(m->physics, k)) {
            zp_out_json_key(f, zp_effect_work_names(k)->column, r->w_effect[k], ", ");
        }
    }
    if (m->cable_paths) {
        fputs("\"cable_potential\": {", f);
        zp_out_json_key(f, "initial", r->pi_initial, ", ");
        zp_out_json_key(f, "final", r->pi_final, "}, ");
    }
    zp_out_json_key(f, "residual", zp_estimate_energy_residual(r), "},\n  ");
    if (m->cable_paths) {
        write_cable(f, m, r);
    }
    zp_out_json_key(f, "constraint_residual", r->constraint_residual, ",\n");
    if (!zp_drive_plain(meta->sched) || m->ndrive ||
        (meta->lim && meta->lim->max[ZP_LIMIT_DRIVE_POWER] > 0)) {
        fputs("  \"drive\": {", f);
        zp_out_json_key(f, "peak_power", r->drive_peak_power, ", ");
        zp_out_json_key(f, "energy", r->w_drive, ", ");
        zp_out_json_key(f, "time_at_cap", r->drive_time_at_cap, "},\n");
    }
}

void zp_out_json_result(FILE *f, const zp_model *m, const zp_result *r, const zp_sim *s,
                        const zp_run_meta *meta) {
    int nsamples;
    const zp_row *samples = zp_sim_samples(s, &nsamples);
    fputs("{\n  \"scene\": ", f);
    zp_out_json_string(f, meta->scene);
    fprintf(f, ",\n  \"method\": \"%s\",\n  \"formulation\": \"%s\",\n  ", meta->method,
            meta->formulation);
    zp_out_json_key(f, "rtol", meta->rtol, ", ");
    zp_out_json_key(f, "atol", meta->atol, ",\n");
    fputs("  \"forces\": ", f);
    zp_out_json_list(f, meta->sched->p, meta->sched->np, 1.0);
    fprintf(f, ",\n  \"outcome\": \"%s\",\n  ", zp_sim_outcome_name(r->outcome));
    zp_out_json_key(f, "time", r->time, ",\n  ");
    zp_out_json_key(f, "x", r->x, ",\n  ");
    zp_out_json_key(f, "speed", r->v, ",\n");
    checks_json(f, meta);
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
    kinks_json(f, m, s);
    fprintf(f, "  \"kink_crossings\": %d,\n  \"max_rel_angle\": ", r->ncross);
    zp_out_json_list(f, r->max_rel_angle, m->nlink, DEG);
    energy_json(f, m, r, meta);
    fputs("  \"loads\": {\"joint_peak\": ", f);
    zp_out_json_list(f, r->peaks.joint, m->nlink, 1.0);
    fputs(", ", f);
    zp_out_json_key(f, "normal_min", r->peaks.normal_min, ", ");
    zp_out_json_key(f, "normal_max", r->peaks.normal_max, ", ");
    fputs("\"acc_peak_g\": ", f);
    zp_out_json_list(f, r->peaks.acc_g, m->nlink, 1.0);
    fputs("},\n", f);
    fputs("  \"limits\": ", f);
    zp_out_json_limits(f, m, r, meta->lim);
    fputs(",\n", f);
    if (meta->gradient) {
        write_gradient(f, meta->sched, meta->gradient);
    }
    write_samples(f, m, samples, nsamples);
    fputs("  \"samples_not_reached\": ", f);
    zp_out_json_list(f, meta->unreached, meta->nunreached, 1.0);
    fputs(",\n", f);
    fprintf(f, "  \"stats\": {\"steps\": %ld, \"rejected_steps\": %ld, \"rhs_evals\": %ld, ",
            r->steps, r->rejected, r->rhs_evals);
    zp_out_json_key(f, "wall_s", r->wall_s, "}\n}\n");
}
