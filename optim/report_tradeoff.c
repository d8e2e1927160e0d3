/* The files and JSON of what robustness costs (report_tradeoff.h). */
#include "report_tradeoff.h"

#include <math.h>

#include "out_json.h"
#include "report.h"

/* level i's cost in % of the 0 % level's time */
static double cost_pct(const zp_tradeoff *T, int i) {
    return 100 * zp_tradeoff_cost(T, i) / T->L[0].time;
}

/* the levels' name in the CSV and JSON */
static const char *level_key(const zp_tradeoff *T) {
    return T->power ? "power_W" : "force_error_pct";
}

static const char *from_key(const zp_tradeoff *T) {
    return T->power ? "from_level_W" : "from_level_pct";
}

static double from_pct(const zp_tradeoff *T, int i) {
    return T->L[i].from == ZP_TRADEOFF_GIVEN ? NAN : T->L[T->L[i].from].p;
}

static void level_json(FILE *f, const zp_tradeoff *T, int i) {
    const zp_tradeoff_level *L = &T->L[i];
    zp_out_json_key(f, level_key(T), L->p, ", ");
    fprintf(f, "\"found\": %s, ", L->found ? "true" : "false");
    zp_out_json_key(f, from_key(T), from_pct(T, i), ", ");
    zp_out_json_key(f, "time", L->time, ", ");
    zp_out_json_key(f, "cost", zp_tradeoff_cost(T, i), ", ");
    zp_out_json_key(f, "cost_pct", cost_pct(T, i), ", ");
    zp_out_json_key(f, "arrival_kmh", L->arrival, ", ");
    fputs("\"forces\": ", f);
    zp_out_json_list(f, L->force, T->su->sched.np, 1.0);
    fprintf(f,
            ", \"scenarios\": %d, \"verify\": {\"samples\": %d, \"survived\": %d, "
            "\"margin_kept\": %d, \"all_kept\": %d, ",
            L->scenarios, L->check.samples, L->check.survived, L->check.margin_kept,
            L->check.all_kept);
    zp_out_json_key(f, "lower_95", L->check.lower_95, "}, ");
    fputs("\"headroom\": ", f);
    zp_summary_headroom_json(f, &L->check.headroom);
    fputs("}", f);
}

void zp_report_tradeoff_json(FILE *f, const zp_tradeoff *T) {
    fputs("{\n  \"scene\": ", f);
    zp_out_json_string(f, T->su->sc.name);
    fprintf(f, ",\n  \"complete\": %s,\n  \"levels\": [", T->ndone == T->n ? "true" : "false");
    for (int i = 0; i < T->ndone; i++) {
        fprintf(f, "%s\n    {", i ? "," : "");
        level_json(f, T, i);
    }
    fputs("\n  ]\n}\n", f);
}

static void write_csv(FILE *f, const zp_tradeoff *T) {
    int np = T->su->sched.np;
    fprintf(f,
            "%s,found,time_s,cost_s,cost_pct,arrival_kmh,scenarios,verify_samples,"
            "verify_kept,lower_95,%s,headroom_factor",
            level_key(T), from_key(T));
    for (int k = 0; k < np; k++) {
        fprintf(f, ",force_%d_N", k + 1);
    }
    fputc('\n', f);
    for (int i = 0; i < T->ndone; i++) {
        const zp_tradeoff_level *L = &T->L[i];
        const zp_headroom_line *h = &L->check.headroom.line[ZP_HEADROOM_LINES - 1];
        fprintf(f, "%g,%d,%.9g,%.6g,%.4g,%.6g,%d,%d,%d,%.6g,", L->p, L->found, L->time,
                zp_tradeoff_cost(T, i), cost_pct(T, i), L->arrival, L->scenarios, L->check.samples,
                L->check.all_kept, L->check.lower_95);
        if (L->from != ZP_TRADEOFF_GIVEN) {
            fprintf(f, "%g", T->L[L->from].p);
        }
        fprintf(f, ",%.6g", h->range >= 0 ? h->holds : NAN);
        for (int k = 0; k < np; k++) {
            fprintf(f, ",%.9g", L->force[k]);
        }
        fputc('\n', f);
    }
}

static void write_plot(FILE *f, int power) {
    fputs("set terminal pngcairo size 900,500 enhanced font 'DejaVu Sans,11' linewidth 1.3\n"
          "set output 'tradeoff.png'\nset datafile separator ','\nset key top left\n",
          f);
    if (power) {
        /* the no-cap level (0 W) is the reference, drawn as a line: it has no place on the
           power axis */
        fputs("set title 'What a motor buys'\nset xlabel 'drive power (W)'\n"
              "stats 'tradeoff.csv' every ::1::1 using 3 nooutput name 'free'\n",
              f);
    } else {
        fputs("set title 'What robustness costs'\nset xlabel 'force error held (+/- %)'\n", f);
    }
    fputs("set ylabel 'finish time (s)'\nset y2label 'arrival speed (km/h)'\n"
          "set ytics nomirror\nset y2tics\nset grid\n",
          f);
    fprintf(f,
            "plot 'tradeoff.csv' every ::%d using 1:3 with linespoints pt 7 title 'finish time', "
            "\\\n     '' every ::%d using 1:6 axes x1y2 with linespoints pt 5 dt 2 title "
            "'arrival speed', \\\n",
            power ? 2 : 1, power ? 2 : 1);
    fputs(power ? "     free_min with lines dt 3 lc rgb 'black' title 'no cap'\n"
                : "     '' every ::1::1 using 1:3 with points pt 6 ps 3 lc rgb 'black' "
                  "title 'the 0 % level'\n",
          f);
}

/* the levels of a power tradeoff: finish time against drive power, against no cap */
static void write_md_power(FILE *f, const zp_tradeoff *T) {
    fprintf(f,
            "The search at each drive power (the applied force capped at power / speed; the "
            "scene's [robust] and [limits] as given), against no cap (%.4f s). Each level keeps "
            "the fastest answer any level found that holds at its own power (\"from\").\n\n"
            "| power (W) | found | finish (s) | slower (s) | slower (%%) | arrival (km/h) | from "
            "|\n|---|---|---|---|---|---|---|\n",
            T->L[0].time);
    for (int i = 0; i < T->ndone; i++) {
        const zp_tradeoff_level *L = &T->L[i];
        char power[32] = "no cap";
        if (i) {
            snprintf(power, sizeof power, "%g", L->p);
        }
        fprintf(f, "| %s | %s | %.4f | %.4f | %.1f | %.1f | ", power, L->found ? "yes" : "no",
                L->time, zp_tradeoff_cost(T, i), cost_pct(T, i), L->arrival);
        if (L->from == ZP_TRADEOFF_GIVEN) {
            fputs("the given schedule |\n", f);
        } else if (L->from == 0) {
            fputs("no cap |\n", f);
        } else {
            fprintf(f, "%g W |\n", T->L[L->from].p);
        }
    }
    fputs("\n![finish time and arrival speed against drive power](tradeoff.png)\n", f);
}

/* the table's row of level i */
static void md_row(FILE *f, const zp_tradeoff *T, int i) {
    const zp_tradeoff_level *L = &T->L[i];
    fprintf(f, "| %g %% | %s | %.4f | %.4f | %.1f | %.1f | ", L->p, L->found ? "yes" : "no",
            L->time, zp_tradeoff_cost(T, i), cost_pct(T, i), L->arrival);
    if (L->check.samples) {
        fprintf(f, "%d / %d (>= %.2f %%) | ", L->check.all_kept, L->check.samples,
                100 * L->check.lower_95);
    } else {
        fputs("- | ", f);
    }
    if (L->from == ZP_TRADEOFF_GIVEN) {
        fputs("the given schedule |\n", f);
    } else {
        fprintf(f, "%s%g %% |\n", L->from == i ? "" : "the search at ", T->L[L->from].p);
    }
}

static void write_md(FILE *f, const zp_tradeoff *T) {
    const zp_scene *sc = &T->su->sc;
    fprintf(f, "# %s: %s\n\n", T->power ? "What a motor buys" : "What robustness costs",
            sc->name);
    if (T->ndone < T->n) {
        fputs("**Incomplete**: stopped (Ctrl-C) before every level was searched; the levels "
              "below are those finished.\n\n",
              f);
    }
    if (T->power) {
        write_md_power(f, T);
        return;
    }
    fprintf(f,
            "The robust search at each force error level (every section's force off by up to "
            "+/-p %%, independently%s), against the 0 %% level (%.4f s). Each level keeps the "
            "fastest answer any level found that survives its own scenarios (\"from\").\n\n"
            "| +/-p | found | finish (s) | costs (s) | costs (%%) | arrival (km/h) | verified "
            "survivable | from |\n|---|---|---|---|---|---|---|---|\n",
            sc->robust ? "; the scene's other [robust] ranges as given" : "", T->L[0].time);
    for (int i = 0; i < T->ndone; i++) {
        md_row(f, T, i);
    }
    fputc('\n', f);
    for (int i = 1; i < T->ndone; i++) {
        if (T->L[i].found) {
            fprintf(f, "Robust to +/-%g %% costs %.3f s (%.1f %%).\n", T->L[i].p,
                    zp_tradeoff_cost(T, i), cost_pct(T, i));
        }
    }
    fputs("\n![finish time and arrival speed against the level](tradeoff.png)\n", f);
}

int zp_report_tradeoff_files(zp_tx *t, const zp_tradeoff *T, char *err, size_t errlen) {
    const char *names[] = {"tradeoff.csv", "tradeoff.gp", "report.md"};
    FILE *f[3];
    if (zp_tx_open_set(t, names, f, 3, err, errlen)) {
        return -1;
    }
    write_csv(f[0], T);
    write_plot(f[1], T->power);
    write_md(f[2], T);
    return 0;
}
