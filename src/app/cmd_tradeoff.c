/* `zipopt tradeoff SCENE.ini [--levels P1,P2,..]`: the robust search at each force_error level
   (the scene's other [robust] ranges as given): what robustness costs (CLI.md). */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "out_json.h"
#include "report.h"
#include "robust.h"
#include "setup.h"

#define MAX_LEVELS 16
#define KMH 3.6

static void usage(FILE *f) {
    fputs("usage: zipopt tradeoff SCENE.ini [--levels P1,P2,..] [--json] [--out DIR]\n"
          "Runs the robust search (zipopt SCENE.ini) at each force error level P (%, each\n"
          "section's force off by up to +/-P %; the scene's other [robust] ranges and [limits]\n"
          "as given) and writes tradeoff.csv, tradeoff.png (finish time and arrival speed\n"
          "against the level, the nominal optimum marked) and report.md (what each level\n"
          "costs against the nominal optimum) to out/<scene name>/tradeoff/ (or DIR).\n"
          "  --levels P1,..  force error levels in % (default 0,1,2,5,10), each in [0, 100)\n"
          "  --json          print the levels as one JSON object (keys: README)\n"
          "  --out DIR       output folder\n",
          f);
}

typedef struct level_out {
    double p;    /* % */
    int found;
    double time; /* s, nominal finish time of the answer */
    double arrival; /* km/h */
    double force[ZP_MAX_SECTIONS];
    int scenarios;
    zp_robust_check check;
} level_out;

/* "key": number, then sep */
static void json_num(FILE *f, const char *key, double v, const char *sep) {
    fprintf(f, "\"%s\": ", key);
    zp_out_json_number(f, v);
    fputs(sep, f);
}

/* the levels as one JSON object, the CSV's columns by name */
static void write_json(FILE *f, const zp_scene *sc, const level_out *L, int n, int nsec) {
    fputs("{\n  \"scene\": ", f);
    zp_out_json_string(f, sc->name);
    fputs(",\n  \"levels\": [", f);
    for (int i = 0; i < n; i++) {
        fprintf(f, "%s\n    {", i ? "," : "");
        json_num(f, "force_error_pct", L[i].p, ", ");
        fprintf(f, "\"found\": %s, ", L[i].found ? "true" : "false");
        json_num(f, "time", L[i].time, ", ");
        json_num(f, "cost", L[i].time - L[0].time, ", ");
        json_num(f, "cost_pct", 100 * (L[i].time - L[0].time) / L[0].time, ", ");
        json_num(f, "arrival_kmh", L[i].arrival, ", ");
        fputs("\"forces\": [", f);
        for (int k = 0; k < nsec; k++) {
            zp_out_json_number(f, L[i].force[k]);
            fputs(k + 1 < nsec ? ", " : "], ", f);
        }
        fprintf(f, "\"scenarios\": %d, \"verify\": {\"samples\": %d, \"survived\": %d, "
                   "\"margin_kept\": %d, \"all_kept\": %d, ",
                L[i].scenarios, L[i].check.samples, L[i].check.survived, L[i].check.margin_kept,
                L[i].check.all_kept);
        json_num(f, "lower_95", L[i].check.lower_95, "}, ");
        fputs("\"headroom\": ", f);
        zp_summary_headroom_json(f, &L[i].check.headroom);
        fputs("}", f);
    }
    fputs("\n  ]\n}\n", f);
}

/* the robust answer at force error p; its arrival speed from one nominal run */
static zp_status solve_level(const zp_setup *su, double p, level_out *out, char *err,
                             size_t errlen) {
    zp_scene sc = su->sc;
    const zp_model *m = su->m;
    sc.force_error = p;
    sc.robust = sc.robust || p > 0;
    static zp_robust_problem pb;
    zp_sim_opts fast;
    static zp_search_result res;
    static zp_result run;
    zp_status st = zp_robust_setup(&pb, &sc, m, su->limit, &su->sched, &su->sim, &su->search,
                                   &fast);
    zp_search_opts o = {.max_evals = su->max_evals, .seed = su->seed};
    if (!st) {
        st = zp_robust_solve(&pb, &sc, &fast, su->sched.lo, su->sched.hi, &o,
                             &res, err, errlen);
    }
    zp_sim *s = st ? NULL : zp_sim_create(m, &fast);
    zp_schedule sched = zp_schedule_with(&su->sched, res.force);
    zp_input in = {.sched = &sched};
    if (!st && (!s || zp_sim_run(m, s, &in, &run))) {
        snprintf(err, errlen, "the answer's run failed: %s", s ? run.message : "out of memory");
        st = ZP_ERR_NUMERIC;
    }
    if (!st) {
        *out = (level_out){.p = p, .found = res.found, .time = res.best.time,
                           .arrival = run.v * KMH, .scenarios = pb.robust ? pb.set.n : 0,
                           .check = pb.check};
        memcpy(out->force, res.force, sizeof out->force);
    }
    zp_sim_free(s);
    zp_robust_problem_free(&pb);
    return st;
}

static void write_csv(FILE *f, const level_out *L, int n, int nsec) {
    fputs("force_error_pct,found,time_s,cost_s,cost_pct,arrival_kmh,scenarios,verify_samples,"
          "verify_kept,lower_95,headroom_factor",
          f);
    for (int k = 0; k < nsec; k++) {
        fprintf(f, ",force_%d_N", k + 1);
    }
    fputc('\n', f);
    for (int i = 0; i < n; i++) {
        const zp_headroom_line *h = &L[i].check.headroom.line[ZP_HEADROOM_LINES - 1];
        fprintf(f, "%g,%d,%.9g,%.6g,%.4g,%.6g,%d,%d,%d,%.6g,%.6g", L[i].p, L[i].found, L[i].time,
                L[i].time - L[0].time, 100 * (L[i].time - L[0].time) / L[0].time, L[i].arrival,
                L[i].scenarios, L[i].check.samples, L[i].check.all_kept, L[i].check.lower_95,
                h->range >= 0 ? h->holds : NAN);
        for (int k = 0; k < nsec; k++) {
            fprintf(f, ",%.9g", L[i].force[k]);
        }
        fputc('\n', f);
    }
}

static void write_plot(FILE *f) {
    fputs("set terminal pngcairo size 900,500 enhanced font 'DejaVu Sans,11' linewidth 1.3\n"
          "set output 'tradeoff.png'\nset datafile separator ','\nset key top left\n"
          "set title 'What robustness costs'\nset xlabel 'force error held (+/- %)'\n"
          "set ylabel 'finish time (s)'\nset y2label 'arrival speed (km/h)'\n"
          "set ytics nomirror\nset y2tics\nset grid\n"
          "plot 'tradeoff.csv' every ::1 using 1:3 with linespoints pt 7 title 'finish time', \\\n"
          "     '' every ::1 using 1:6 axes x1y2 with linespoints pt 5 dt 2 title 'arrival speed', "
          "\\\n     '' every ::1::1 using 1:3 with points pt 6 ps 3 lc rgb 'black' "
          "title 'nominal optimum'\n",
          f);
}

static void write_md(FILE *f, const zp_scene *sc, const level_out *L, int n) {
    fprintf(f, "# What robustness costs: %s\n\nThe robust search at each force error level "
               "(every section's force off by up to +/-p %%, independently%s), against the "
               "nominal optimum (%.4f s).\n\n| +/-p | found | finish (s) | costs (s) | costs "
               "(%%) | arrival (km/h) | verified survivable |\n|---|---|---|---|---|---|---|\n",
            sc->name, sc->robust ? "; the scene's other [robust] ranges as given" : "",
            L[0].time);
    for (int i = 0; i < n; i++) {
        fprintf(f, "| %g %% | %s | %.4f | %.4f | %.1f | %.1f | ", L[i].p, L[i].found ? "yes" : "no",
                L[i].time, L[i].time - L[0].time, 100 * (L[i].time - L[0].time) / L[0].time,
                L[i].arrival);
        if (L[i].check.samples) {
            fprintf(f, "%d / %d (>= %.2f %%) |\n", L[i].check.all_kept, L[i].check.samples,
                    100 * L[i].check.lower_95);
        } else {
            fputs("- |\n", f);
        }
    }
    fputc('\n', f);
    for (int i = 1; i < n; i++) {
        if (L[i].found) {
            fprintf(f, "Robust to +/-%g %% costs %.3f s (%.1f %%).\n", L[i].p,
                    L[i].time - L[0].time, 100 * (L[i].time - L[0].time) / L[0].time);
        }
    }
    fputs("\n![finish time and arrival speed against the level](tradeoff.png)\n", f);
}

/* the levels: 0 first (the nominal optimum), then the ones asked for in the order given */
static int parse_levels(const char *text, double *lv) {
    double got[MAX_LEVELS];
    char why[128] = "";
    int n = text ? zp_cli_parse_list(text, got, MAX_LEVELS - 1, why, sizeof why) : 4;
    if (!text) {
        memcpy(got, (double[]){1, 2, 5, 10}, sizeof(double) * 4);
    }
    if (n < 1) {
        fprintf(stderr, "zipopt tradeoff: --levels '%s': %s; expected levels in %% such as "
                        "0,1,2,5,10; nothing was written\n", text, *why ? why : "bad list");
        return -1;
    }
    int m = 1;
    lv[0] = 0;
    for (int i = 0; i < n; i++) {
        if (!(got[i] >= 0 && got[i] < 100)) {
            fprintf(stderr, "zipopt tradeoff: --levels: %g is not a level; expected each in "
                            "[0, 100) %%; nothing was written\n", got[i]);
            return -1;
        }
        if (got[i] > 0) {
            lv[m++] = got[i];
        }
    }
    return m;
}

enum { O_LEVELS = ZP_OPT_FIRST, O_OUT, O_JSON };

static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"levels", required_argument, NULL, O_LEVELS},
    {"out", required_argument, NULL, O_OUT},
    {"json", no_argument, NULL, O_JSON},
    {NULL, 0, NULL, 0},
};

int zp_cmd_tradeoff(int argc, char **argv) {
    const char *scene = NULL, *out = NULL, *levels = NULL;
    int json = 0;
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("tradeoff", argc, argv, options)) != -1;) {
        if (c == 'h') {
            usage(stdout);
            return ZP_EXIT_OK;
        } else if (c == O_LEVELS) {
            levels = optarg;
        } else if (c == O_OUT) {
            out = optarg;
        } else if (c == O_JSON) {
            json = 1;
        } else {
            return ZP_EXIT_USAGE;
        }
    }
    if (zp_cli_scene_operand("tradeoff", argc, argv, &scene) ||
        (out && zp_cli_path_ok("tradeoff", "--out", out))) {
        return ZP_EXIT_USAGE;
    }
    if (!scene) {
        zp_cli_error("tradeoff", "a scene file is required; see zipopt tradeoff --help");
        return ZP_EXIT_USAGE;
    }
    double lv[MAX_LEVELS];
    int n = parse_levels(levels, lv);
    static zp_setup su; /* large: kept off the stack */
    if (n < 1 || zp_setup_load("tradeoff", scene, &ZP_OVERRIDES_NONE, &su)) {
        return ZP_EXIT_USAGE;
    }
    const zp_scene *sc = &su.sc;
    static level_out L[MAX_LEVELS];
    char err[1200] = "";
    int status = ZP_EXIT_FAIL;
    for (int i = 0; i < n; i++) {
        if (solve_level(&su, lv[i], &L[i], err, sizeof err)) {
            fprintf(stderr, "zipopt tradeoff: level %g %%: %s; nothing was written\n", lv[i], err);
            goto done;
        }
        fprintf(stderr, "tradeoff: +/-%g %%: %s %.4f s\n", lv[i], L[i].found ? "" : "(none)",
                L[i].time);
    }
    zp_tx t;
    if (zp_cli_out_begin(&t, "tradeoff", "tradeoff", out, sc)) {
        goto done;
    }
    FILE *csv = zp_tx_open(&t, "tradeoff.csv", err, sizeof err);
    FILE *gp = csv ? zp_tx_open(&t, "tradeoff.gp", err, sizeof err) : NULL;
    FILE *md = gp ? zp_tx_open(&t, "report.md", err, sizeof err) : NULL;
    int missing = 0;
    if (!md) {
        zp_tx_abort(&t);
        fprintf(stderr, "zipopt tradeoff: %s; nothing was written\n", err);
        goto done;
    }
    write_csv(csv, L, n, su.m->nsec);
    write_plot(gp);
    write_md(md, sc, L, n);
    const char *scripts[] = {"tradeoff.gp"};
    if (zp_cli_out_draw_commit(&t, "tradeoff", scripts, 1, &missing)) {
        goto done;
    }
    for (int i = 1; i < n && !json; i++) {
        printf("robust to +/-%g %%: %.4f s, costs %.3f s (%.1f %%)%s\n", L[i].p, L[i].time,
               L[i].time - L[0].time, 100 * (L[i].time - L[0].time) / L[0].time,
               L[i].found ? "" : ", NOT found");
    }
    if (json) {
        write_json(stdout, sc, L, n, su.m->nsec);
    }
    fprintf(json ? stderr : stdout, "wrote in %s: %s%s\n", t.dir, t.written,
           missing ? " (no gnuplot: tradeoff.gp without its image)" : "");
    status = ZP_EXIT_OK;
done:
    zp_setup_free(&su);
    return status;
}
