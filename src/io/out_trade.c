/* The work-precision study's files, text and JSON (out_trade.h). */
#include "out_trade.h"

#include <math.h>

#include "out_json.h"

void zp_out_trade_csv(FILE *f, const zp_trade_study *st) {
    fputs("case,method,rtol,outcome,time_s,err_time_s,err_impulse_Ns,err_angle_deg,err_x_m,"
          "err_speed_mps,rhs_evals,wall_s,steps,repeats,rejected\n",
          f);
    for (int c = 0; c < ZP_TRADE_NCASE; c++) {
        for (int k = 0; k < ZP_METHOD_COUNT; k++) {
            for (int t = 0; t < ZP_TRADE_NTOL; t++) {
                const zp_trade_reading *r = &st->runs[c][k][t];
                const zp_trade_errors *e = &st->errs[c][k][t];
                fprintf(f, "%s,%s,%.0e,%s,%.12g,%.3e,%.3e,%.3e,%.3e,%.3e,%ld,%.6e,%ld,%d,%ld\n",
                        zp_trade_cases[c].name, zp_method_get(k)->name, st->tols[t],
                        r->ok ? zp_sim_outcome_name(r->outcome) : "failed", r->time, e->time,
                        e->impulse, e->angle, e->x, e->v, r->evals, r->wall, r->steps, r->repeats,
                        r->rejected);
            }
        }
    }
}

/* a zero error is drawn at the 1e-16 floor */
void zp_out_trade_gnuplot(FILE *f) {
    fputs("# written by zipopt bench trade: work-precision plot from trade.csv\n"
          "set datafile separator ','\n"
          "set terminal pngcairo size 1500,520 noenhanced\n"
          "set output 'trade.png'\n"
          "set logscale xy\nset format x '%.0e'\nset format y '%.0e'\n"
          "set xlabel 'wall time per run (s, median)'\n"
          "set ylabel '|finish/death time - reference| (s)'\n"
          "set key bottom left\nset grid\n"
          "lo(e) = e < 1e-16 ? 1e-16 : e\n"
          "set multiplot layout 1,3\n",
          f);
    for (int c = 0; c < ZP_TRADE_NCASE; c++) {
        const zp_trade_case *tc = &zp_trade_cases[c];
        fprintf(f, "set title '%s: %g N%s'\nplot ", tc->name, tc->force,
                tc->damping >= 0 ? ", damping 1e4 N m s/rad" : "");
        for (int k = 0; k < ZP_METHOD_COUNT; k++) {
            const char *name = zp_method_get(k)->name;
            fprintf(f,
                    "%s'trade.csv' using (strcol(1) eq '%s' && strcol(2) eq '%s' ? $12 : NaN)"
                    ":(lo($6)) with linespoints title '%s'",
                    k ? ", \\\n     " : "", tc->name, name, name);
        }
        fputs("\n", f);
    }
    fputs("unset multiplot\n", f);
}

static void error_text(FILE *f, double e) {
    if (isfinite(e)) {
        fprintf(f, " %.1e", e);
    } else {
        fprintf(f, "  wrong  ");
    }
}

/* case c's table: time error and cost of every configuration */
static void case_text(FILE *f, const zp_trade_study *st, int c) {
    const zp_trade_case *tc = &zp_trade_cases[c];
    fprintf(f,
            "\n%s (%g N%s): error of the %s time (s) / median wall (ms) / rhs evals / "
            "rejected steps\n",
            tc->name, tc->force, tc->damping >= 0 ? ", c = 1e4" : "",
            st->runs[c][0][0].outcome == ZP_OUTCOME_DIED ? "death" : "finish");
    fprintf(f, "%-7s", "rtol");
    for (int k = 0; k < ZP_METHOD_COUNT; k++) {
        fprintf(f, " | %-31s", zp_method_get(k)->name);
    }
    fprintf(f, "\n");
    for (int t = 0; t < ZP_TRADE_NTOL; t++) {
        fprintf(f, "%-7.0e", st->tols[t]);
        for (int k = 0; k < ZP_METHOD_COUNT; k++) {
            const zp_trade_reading *r = &st->runs[c][k][t];
            fprintf(f, " | ");
            error_text(f, st->errs[c][k][t].time);
            fprintf(f, " %8.2f %7ld %4ld", 1e3 * r->wall, r->evals, r->rejected);
        }
        fprintf(f, "\n");
    }
}

void zp_out_trade_text(FILE *f, const zp_trade_study *st) {
    for (int c = 0; c < ZP_TRADE_NCASE; c++) {
        case_text(f, st, c);
    }
    fprintf(f, "\nfastest to reach a finish/death time error (method, rtol, median wall):\n");
    for (int g = 0; g < ZP_TRADE_NTARGET; g++) {
        fprintf(f, "  <= %.0e s:", zp_trade_targets[g]);
        for (int c = 0; c <= ZP_TRADE_NCASE; c++) {
            int bk, bt;
            double best = zp_trade_fastest(st, zp_trade_targets[g], c, &bk, &bt);
            fprintf(f, "  %s: ", c == ZP_TRADE_NCASE ? "all three" : zp_trade_cases[c].name);
            if (bk < 0) {
                fprintf(f, "none");
            } else {
                fprintf(f, "%s %.0e (%.2f ms)", zp_method_get(bk)->name, st->tols[bt], 1e3 * best);
            }
            fputs(c < ZP_TRADE_NCASE ? ";" : "\n", f);
        }
    }
}

/* one errors object: null where the outcome or the kinks crossed differ */
static void errors_json(FILE *f, const zp_trade_errors *e) {
    fputs("{", f);
    zp_out_json_key(f, "time", e->time, ", ");
    zp_out_json_key(f, "impulse", e->impulse, ", ");
    zp_out_json_key(f, "angle", e->angle, ", ");
    zp_out_json_key(f, "x", e->x, ", ");
    zp_out_json_key(f, "speed", e->v, "}");
}

static void run_json(FILE *f, const zp_trade_study *st, int c, int k, int t) {
    const zp_trade_reading *r = &st->runs[c][k][t];
    fprintf(f, "%s\n      {\"method\": \"%s\", ", k || t ? "," : "", zp_method_get(k)->name);
    zp_out_json_key(f, "rtol", st->tols[t], ", ");
    zp_out_json_key(f, "atol", st->tols[t] * ZP_TRADE_ATOL_RATIO, ", ");
    fprintf(f, "\"outcome\": \"%s\", ", r->ok ? zp_sim_outcome_name(r->outcome) : "failed");
    zp_out_json_key(f, "time", r->ok ? r->time : NAN, ", ");
    fputs("\"error\": ", f);
    errors_json(f, &st->errs[c][k][t]);
    fprintf(f, ", \"rhs_evals\": %ld, \"steps\": %ld, \"rejected_steps\": %ld, ", r->evals,
            r->steps, r->rejected);
    zp_out_json_key(f, "wall_s", r->wall, ", ");
    fprintf(f, "\"repeats\": %d}", r->repeats);
}

static void case_json(FILE *f, const zp_trade_study *st, int c) {
    const zp_trade_case *tc = &zp_trade_cases[c];
    fprintf(f, "    {\"name\": \"%s\", ", tc->name);
    zp_out_json_key(f, "force", tc->force, ", ");
    zp_out_json_key(f, "damping", tc->damping >= 0 ? tc->damping : NAN, ",\n");
    fprintf(f, "     \"reference\": {\"methods\": [\"%s\", \"%s\"], \"outcome\": \"%s\", ",
            zp_method_get(ZP_METHOD_GSL_RK8PD)->name, zp_method_get(tc->ref_cvode)->name,
            zp_sim_outcome_name(st->ref[c].outcome));
    zp_out_json_key(f, "time", st->ref[c].time, ", ");
    fputs("\"agreement\": ", f);
    errors_json(f, &st->agree[c]);
    fputs("},\n     \"runs\": [", f);
    for (int k = 0; k < ZP_METHOD_COUNT; k++) {
        for (int t = 0; t < ZP_TRADE_NTOL; t++) {
            run_json(f, st, c, k, t);
        }
    }
    fprintf(f, "\n     ]}%s\n", c + 1 < ZP_TRADE_NCASE ? "," : "");
}

/* the fastest configuration reaching target g, per case and over all */
static void fastest_json(FILE *f, const zp_trade_study *st, int g) {
    zp_out_json_key(f, "time_error", zp_trade_targets[g], "");
    for (int c = 0; c <= ZP_TRADE_NCASE; c++) {
        int bk, bt;
        double best = zp_trade_fastest(st, zp_trade_targets[g], c, &bk, &bt);
        fprintf(f, ", \"%s\": ", c == ZP_TRADE_NCASE ? "all" : zp_trade_cases[c].name);
        if (bk < 0) {
            fputs("null", f);
            continue;
        }
        fprintf(f, "{\"method\": \"%s\", ", zp_method_get(bk)->name);
        zp_out_json_key(f, "rtol", st->tols[bt], ", ");
        zp_out_json_key(f, "wall_s", best, "}");
    }
}

void zp_out_trade_json(FILE *f, const zp_trade_study *st, const char *scene, int repeats) {
    fputs("{\n  \"study\": \"trade\",\n  \"scene\": ", f);
    zp_out_json_string(f, scene);
    fprintf(f, ",\n  \"repeats\": %d,\n  ", repeats);
    zp_out_json_key(f, "reference_rtol", ZP_TRADE_REF_RTOL, ",\n  ");
    zp_out_json_key(f, "atol_per_rtol", ZP_TRADE_ATOL_RATIO, ",\n  \"cases\": [\n");
    for (int c = 0; c < ZP_TRADE_NCASE; c++) {
        case_json(f, st, c);
    }
    fputs("  ],\n  \"fastest\": [", f);
    for (int g = 0; g < ZP_TRADE_NTARGET; g++) {
        fprintf(f, "%s\n    {", g ? "," : "");
        fastest_json(f, st, g);
        fputs("}", f);
    }
    fputs("\n  ]\n}\n", f);
}
