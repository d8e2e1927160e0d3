/* `zipopt tradeoff SCENE.ini [--levels P1,P2,..]`: the robust search at each force_error level
   (the scene's other [robust] ranges as given): what robustness costs; with `--power W1,..` the
   search at each drive power (W) against no cap: what a motor buys. The levels exchange their
   answers, so the costs never fall as the level grows past what the searches missed. */
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "answer.h"
#include "cli.h"
#include "out_json.h"
#include "report.h"
#include "setup.h"

#define MAX_LEVELS 16
#define KMH 3.6
#define FROM_GIVEN -1 /* an answer that is the schedule the scene or --schedule/--force gave */

static void usage(FILE *f) {
    fputs("usage: zipopt tradeoff SCENE.ini [--levels P1,P2,.. | --power W1,W2,..] [--max-evals N]\n"
          "                       [--max-time S] [--schedule FILE | --force F1,..] [--json]\n"
          "                       [--out DIR]\n"
          "\n"
          "Runs the robust search (zipopt SCENE.ini) at each force error level P (%, each\n"
          "section's force off by up to +/-P %; the scene's other [robust] ranges and [limits]\n"
          "as given) and writes tradeoff.csv, tradeoff.png (finish time and arrival speed\n"
          "against the level) and report.md (what each level costs against the 0 % level)\n"
          "to out/<scene name>/tradeoff/ (or DIR). An answer held to +/-P % is a candidate\n"
          "at every other level too: each level keeps the fastest candidate that survives its\n"
          "own scenarios, so a level never reports a slower answer than a wider one found.\n"
          "Ctrl-C stops the level under way and writes the levels finished, marked\n"
          "incomplete.\n"
          "  --levels P1,..      force error levels in % (default 0,1,2,5,10), each in [0, 100)\n"
          "  --power W1,..       drive powers in W instead (each > 0): the search at each, the\n"
          "                      drive's force capped at W / speed, against no cap (the first\n"
          "                      level, 0): finish time against drive power, what a motor buys\n"
          "  --max-evals N       simulations each level's search may spend (default: the\n"
          "                      scene's [optimize] max_evals)\n"
          "  --max-time S        stops each level's search after S seconds of wall time,\n"
          "                      keeping its best (the answer then depends on the machine)\n"
          "  --schedule FILE     a schedule ([drive] forces) held as one more candidate at\n"
          "  --force F1,..       every level\n"
          "  --json              print the levels as one JSON object (keys: docs/commands.md)\n"
          "  --out DIR           output folder\n",
          f);
}

typedef struct level_out {
    double p; /* %, or with --power W (0: no cap) */
    int found;
    int done;       /* 1: its search finished; 0: stopped by Ctrl-C or never started */
    int from;       /* the level whose search found this answer, or FROM_GIVEN */
    double time;    /* s, nominal finish time of the answer */
    double arrival; /* km/h */
    double force[ZP_SCHED_MAX_PARAMS];
    int scenarios;
    zp_robust_check check;
} level_out;

/* what every level shares, and each level's problem and answer kept for the exchange */
typedef struct tradeoff {
    const zp_problem *su;
    zp_problem pb[MAX_LEVELS]; /* su with the level's force error, its model su's (borrowed) */
    zp_answer ans[MAX_LEVELS];
    level_out L[MAX_LEVELS];
    int n;     /* levels asked for */
    int ndone; /* levels whose search ran to its end */
    int given; /* the scene or --schedule/--force gave a schedule to hold as a candidate */
    int tty;
    int power; /* the levels are drive powers (W), not force errors */
    double max_time;
} tradeoff;

/* the levels' name in the CSV and JSON, and in words */
static const char *level_key(int power) {
    return power ? "power_W" : "force_error_pct";
}

/* set by the first Ctrl-C (the transaction's handler): the level under way stops cleanly */
static volatile sig_atomic_t interrupted;

/* "key": number, then sep */
static void json_num(FILE *f, const char *key, double v, const char *sep) {
    fprintf(f, "\"%s\": ", key);
    zp_out_json_number(f, v);
    fputs(sep, f);
}

/* the cost of level i against the 0 % level: never negative once the answers are exchanged */
static double cost(const level_out *L, int i) {
    return L[i].time - L[0].time;
}

/* the levels as one JSON object, the CSV's columns by name */
static void write_json(FILE *f, const zp_scene *sc, const level_out *L, int n, int np,
                       int complete, int power) {
    fputs("{\n  \"scene\": ", f);
    zp_out_json_string(f, sc->name);
    fprintf(f, ",\n  \"complete\": %s,\n  \"levels\": [", complete ? "true" : "false");
    for (int i = 0; i < n; i++) {
        fprintf(f, "%s\n    {", i ? "," : "");
        json_num(f, level_key(power), L[i].p, ", ");
        fprintf(f, "\"found\": %s, \"from_level_%s\": ", L[i].found ? "true" : "false",
                power ? "W" : "pct");
        zp_out_json_number(f, L[i].from == FROM_GIVEN ? NAN : L[L[i].from].p);
        fputs(", ", f);
        json_num(f, "time", L[i].time, ", ");
        json_num(f, "cost", cost(L, i), ", ");
        json_num(f, "cost_pct", 100 * cost(L, i) / L[0].time, ", ");
        json_num(f, "arrival_kmh", L[i].arrival, ", ");
        fputs("\"forces\": [", f);
        for (int k = 0; k < np; k++) {
            zp_out_json_number(f, L[i].force[k]);
            fputs(k + 1 < np ? ", " : "], ", f);
        }
        fprintf(f,
                "\"scenarios\": %d, \"verify\": {\"samples\": %d, \"survived\": %d, "
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

/* the progress line inside a level: what its search is doing and its best so far */
typedef struct level_progress {
    const tradeoff *T;
    int i;
} level_progress;

static void on_progress(void *user, const zp_search_progress *p, int improved) {
    (void)improved;
    const level_progress *lp = user;
    if (!lp->T->tty) {
        return;
    }
    fprintf(stderr,
            "\r\033[Ktradeoff: level %d of %d (+/-%g %%): %s, round %d, %ld of %ld "
            "simulations, %.1f s",
            lp->i + 1, lp->T->n, lp->T->L[lp->i].p, p->phase, p->round + 1, p->evals, p->budget,
            p->wall_s);
    if (p->found) {
        fprintf(stderr, ", best %.4f s", p->time);
    }
}

/* the answer's arrival speed: one nominal run at the search's tolerance */
static int arrival_of(const tradeoff *T, int i, double *kmh, char *err, size_t errlen) {
    const zp_problem *su = T->su;
    zp_sim *s = zp_sim_create(su->m, &T->pb[i].search);
    zp_schedule sched = zp_schedule_with(&T->pb[i].sched, T->L[i].force);
    zp_input in = {.sched = &sched};
    static zp_result run;
    int bad = !s || zp_sim_run(su->m, s, &in, &run);
    if (bad) {
        snprintf(err, errlen, "the answer's run failed: %s", s ? run.message : "out of memory");
    } else {
        *kmh = run.v * KMH;
    }
    zp_sim_free(s);
    return bad ? -1 : 0;
}

/* the robust answer at force error L[i].p, its problem and answer kept in T */
static zp_status solve_level(tradeoff *T, int i, char *err, size_t errlen) {
    level_out *out = &T->L[i];
    zp_problem *pb = &T->pb[i];
    *pb = *T->su;
    if (T->power) {
        pb->sc.drive_power = out->p;
        pb->sched.power = out->p;
    } else {
        pb->sc.force_error = out->p;
        pb->sc.robust = pb->sc.robust || out->p > 0;
    }
    level_progress lp = {T, i};
    zp_answer_opts o = zp_answer_opts_of(pb, ZP_ANSWER_SEARCHED);
    o.search.max_time = T->max_time;
    o.search.stop = &interrupted;
    o.search.progress = on_progress;
    o.search.user = &lp;
    zp_status st = zp_answer_solve(pb, &o, &T->ans[i], err, errlen);
    if (T->tty) {
        fputs("\r\033[K", stderr);
    }
    if (st) {
        return st;
    }
    const zp_search_result *res = &T->ans[i].res;
    out->found = res->found;
    out->done = !res->interrupted;
    out->from = i;
    out->time = res->best.time;
    out->scenarios = zp_answer_scenarios(&T->ans[i]);
    out->check = T->ans[i].rp.check;
    memcpy(out->force, res->force, sizeof out->force);
    return arrival_of(T, i, &out->arrival, err, errlen) ? ZP_ERR_NUMERIC : ZP_OK;
}

/* Each level keeps the fastest of its own answer and the others' (and the schedule given)
   that survives its own held scenarios: an answer robust to +/-5 % is as good a candidate at
   +/-2 % as the +/-2 % search's, which may have stopped in a slower island. An adopted answer
   is checked again on the level's fresh scenarios. */
static int exchange_answers(tradeoff *T, char *err, size_t errlen) {
    const zp_problem *su = T->su;
    for (int i = 0; i < T->ndone; i++) {
        level_out *L = &T->L[i];
        zp_robust_problem *rp = &T->ans[i].rp;
        zp_sim *s = zp_sim_create(su->m, &T->pb[i].search);
        if (!s) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        int adopted = 0;
        for (int j = -1; j < T->ndone; j++) { /* -1: the schedule the scene or user gave */
            if (j < 0 ? !T->given
                      : j == i || !T->L[j].found || (L->found && T->L[j].time >= L->time)) {
                continue;
            }
            const double *p = j < 0 ? su->sched.p : T->L[j].force;
            zp_eval e;
            static zp_result r;
            zp_objective_eval(&rp->ob, s, p, &e, &r);
            if (zp_objective_feasible(&e) && (!L->found || e.time < L->time)) {
                memcpy(L->force, p, sizeof *p * (size_t)su->sched.np);
                L->time = e.time;
                L->found = adopted = 1;
                L->from = j < 0 ? FROM_GIVEN : T->L[j].from;
            }
        }
        zp_sim_free(s);
        if (!adopted) {
            continue;
        }
        if (rp->robust) {
            if (zp_robust_verify(&rp->ob, &rp->box, &T->pb[i].verify, L->force,
                                 su->sc.verify_samples, su->seed, 0, NULL, &L->check)) {
                snprintf(err, errlen, "out of memory verifying the scenarios");
                return -1;
            }
        }
        if (arrival_of(T, i, &L->arrival, err, errlen)) {
            return -1;
        }
    }
    return 0;
}

static void write_csv(FILE *f, const level_out *L, int n, int np, int power) {
    fprintf(f,
            "%s,found,time_s,cost_s,cost_pct,arrival_kmh,scenarios,verify_samples,"
            "verify_kept,lower_95,from_level_%s,headroom_factor",
            level_key(power), power ? "W" : "pct");
    for (int k = 0; k < np; k++) {
        fprintf(f, ",force_%d_N", k + 1);
    }
    fputc('\n', f);
    for (int i = 0; i < n; i++) {
        const zp_headroom_line *h = &L[i].check.headroom.line[ZP_HEADROOM_LINES - 1];
        fprintf(f, "%g,%d,%.9g,%.6g,%.4g,%.6g,%d,%d,%d,%.6g,", L[i].p, L[i].found, L[i].time,
                cost(L, i), 100 * cost(L, i) / L[0].time, L[i].arrival, L[i].scenarios,
                L[i].check.samples, L[i].check.all_kept, L[i].check.lower_95);
        if (L[i].from != FROM_GIVEN) {
            fprintf(f, "%g", L[L[i].from].p);
        }
        fprintf(f, ",%.6g", h->range >= 0 ? h->holds : NAN);
        for (int k = 0; k < np; k++) {
            fprintf(f, ",%.9g", L[i].force[k]);
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
static void write_md_power(FILE *f, const level_out *L, int n) {
    fprintf(f,
            "The search at each drive power (the applied force capped at power / speed; the "
            "scene's [robust] and [limits] as given), against no cap (%.4f s). Each level keeps "
            "the fastest answer any level found that holds at its own power (\"from\").\n\n"
            "| power (W) | found | finish (s) | slower (s) | slower (%%) | arrival (km/h) | from "
            "|\n|---|---|---|---|---|---|---|\n",
            L[0].time);
    for (int i = 0; i < n; i++) {
        char power[32] = "no cap";
        if (i) {
            snprintf(power, sizeof power, "%g", L[i].p);
        }
        fprintf(f, "| %s | %s | %.4f | %.4f | %.1f | %.1f | ", power, L[i].found ? "yes" : "no",
                L[i].time, cost(L, i), 100 * cost(L, i) / L[0].time, L[i].arrival);
        if (L[i].from == FROM_GIVEN) {
            fputs("the given schedule |\n", f);
        } else if (L[i].from == 0) {
            fputs("no cap |\n", f);
        } else {
            fprintf(f, "%g W |\n", L[L[i].from].p);
        }
    }
    fputs("\n![finish time and arrival speed against drive power](tradeoff.png)\n", f);
}

static void write_md(FILE *f, const zp_scene *sc, const level_out *L, int n, int complete,
                     int power) {
    fprintf(f, "# %s: %s\n\n", power ? "What a motor buys" : "What robustness costs", sc->name);
    if (!complete) {
        fputs("**Incomplete**: stopped (Ctrl-C) before every level was searched; the levels "
              "below are those finished.\n\n",
              f);
    }
    if (power) {
        write_md_power(f, L, n);
        return;
    }
    fprintf(f,
            "The robust search at each force error level (every section's force off by up to "
            "+/-p %%, independently%s), against the 0 %% level (%.4f s). Each level keeps the "
            "fastest answer any level found that survives its own scenarios (\"from\").\n\n"
            "| +/-p | found | finish (s) | costs (s) | costs (%%) | arrival (km/h) | verified "
            "survivable | from |\n|---|---|---|---|---|---|---|---|\n",
            sc->robust ? "; the scene's other [robust] ranges as given" : "", L[0].time);
    for (int i = 0; i < n; i++) {
        fprintf(f, "| %g %% | %s | %.4f | %.4f | %.1f | %.1f | ", L[i].p, L[i].found ? "yes" : "no",
                L[i].time, cost(L, i), 100 * cost(L, i) / L[0].time, L[i].arrival);
        if (L[i].check.samples) {
            fprintf(f, "%d / %d (>= %.2f %%) | ", L[i].check.all_kept, L[i].check.samples,
                    100 * L[i].check.lower_95);
        } else {
            fputs("- | ", f);
        }
        if (L[i].from == FROM_GIVEN) {
            fputs("the given schedule |\n", f);
        } else {
            fprintf(f, "%s%g %% |\n", L[i].from == i ? "" : "the search at ", L[L[i].from].p);
        }
    }
    fputc('\n', f);
    for (int i = 1; i < n; i++) {
        if (L[i].found) {
            fprintf(f, "Robust to +/-%g %% costs %.3f s (%.1f %%).\n", L[i].p, cost(L, i),
                    100 * cost(L, i) / L[0].time);
        }
    }
    fputs("\n![finish time and arrival speed against the level](tradeoff.png)\n", f);
}

/* the levels: 0 first (the reference of the costs: no force error, or no cap), then the ones
   asked for in the order given */
static int parse_levels(const char *text, int power, double *lv) {
    double got[MAX_LEVELS];
    char why[128] = "";
    int n = text ? zp_cli_parse_list(text, got, MAX_LEVELS - 1, why, sizeof why) : 4;
    if (!text) {
        memcpy(got, (double[]){1, 2, 5, 10}, sizeof(double) * 4);
    }
    if (power && n < 1) {
        zp_cli_error("tradeoff",
                     "--power '%s': %s; expected powers in W such as 2000,5000,10000; nothing "
                     "was written",
                     text, *why ? why : "bad list");
        return -1;
    }
    if (n < 1) {
        zp_cli_error("tradeoff",
                     "--levels '%s': %s; expected levels in %% such as 0,1,2,5,10; nothing was "
                     "written",
                     text, *why ? why : "bad list");
        return -1;
    }
    int m = 1;
    lv[0] = 0;
    for (int i = 0; i < n; i++) {
        if (power && !(got[i] > 0 && isfinite(got[i]))) {
            zp_cli_error("tradeoff",
                         "--power: %g is not a power; expected each > 0 (W); nothing was written",
                         got[i]);
            return -1;
        }
        if (!(got[i] >= 0 && got[i] < 100) && !power) {
            zp_cli_error("tradeoff",
                         "--levels: %g is not a level; expected each in [0, 100) %%; nothing was "
                         "written",
                         got[i]);
            return -1;
        }
        if (got[i] > 0) {
            lv[m++] = got[i];
        }
    }
    return m;
}

enum { O_LEVELS = ZP_OPT_FIRST, O_POWER, O_OUT, O_JSON, O_MAX_EVALS, O_MAX_TIME, O_SCHEDULE, O_FORCE };

static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"levels", required_argument, NULL, O_LEVELS},
    {"power", required_argument, NULL, O_POWER},
    {"out", required_argument, NULL, O_OUT},
    {"json", no_argument, NULL, O_JSON},
    {"max-evals", required_argument, NULL, O_MAX_EVALS},
    {"max-time", required_argument, NULL, O_MAX_TIME},
    {"schedule", required_argument, NULL, O_SCHEDULE},
    {"force", required_argument, NULL, O_FORCE},
    {NULL, 0, NULL, 0},
};

typedef struct tradeoff_args {
    const char *scene, *out, *levels;
    int json;
    int power; /* --power: the levels are drive powers */
    double max_time;
    zp_overrides ov;
} tradeoff_args;

/* 1: --help was shown; -1: a mistake (reported); 0: go on */
static int parse_args(int argc, char **argv, tradeoff_args *a) {
    *a = (tradeoff_args){.ov = ZP_OVERRIDES_NONE};
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("tradeoff", argc, argv, options)) != -1;) {
        unsigned long evals;
        switch (c) {
        case 'h':
            usage(stdout);
            return 1;
        case O_LEVELS:
        case O_POWER:
            if (a->levels && a->power != (c == O_POWER)) {
                zp_cli_error("tradeoff", "--levels and --power: give one; nothing was written");
                return -1;
            }
            a->levels = optarg;
            a->power = c == O_POWER;
            break;
        case O_OUT:
            a->out = optarg;
            break;
        case O_JSON:
            a->json = 1;
            break;
        case O_MAX_EVALS:
            if (zp_cli_whole("tradeoff", "--max-evals", optarg, 1, LONG_MAX, &evals)) {
                return -1;
            }
            a->ov.max_evals = (long)evals;
            break;
        case O_MAX_TIME:
            if (zp_cli_seconds("tradeoff", "--max-time", optarg, &a->max_time)) {
                return -1;
            }
            break;
        case O_SCHEDULE:
            a->ov.schedule = optarg;
            break;
        case O_FORCE:
            a->ov.force = optarg;
            break;
        default:
            return -1;
        }
    }
    if (zp_cli_scene_operand("tradeoff", argc, argv, &a->scene) ||
        (a->out && zp_cli_path_ok("tradeoff", "--out", a->out))) {
        return -1;
    }
    if (!a->scene) {
        zp_cli_error("tradeoff", "a scene file is required; see zipopt tradeoff --help");
        return -1;
    }
    return 0;
}

/* the finished levels' files, all or nothing; 0, or -1 (said) */
static int write_files(zp_tx *t, const tradeoff *T, int complete) {
    char err[1400] = "";
    const zp_scene *sc = &T->su->sc;
    FILE *csv = zp_tx_open(t, "tradeoff.csv", err, sizeof err);
    FILE *gp = csv ? zp_tx_open(t, "tradeoff.gp", err, sizeof err) : NULL;
    FILE *md = gp ? zp_tx_open(t, "report.md", err, sizeof err) : NULL;
    if (!md) {
        zp_tx_abort(t);
        zp_cli_error("tradeoff", "%s; nothing was written", err);
        return -1;
    }
    write_csv(csv, T->L, T->ndone, T->su->sched.np, T->power);
    write_plot(gp, T->power);
    write_md(md, sc, T->L, T->ndone, complete, T->power);
    return 0;
}

/* the levels in order until one is stopped (Ctrl-C), those finished counted in T->ndone; 0, or
   -1 (said) */
static int solve_levels(tradeoff *T) {
    char err[1200] = "";
    for (int i = 0; i < T->n && !interrupted; i++) {
        if (solve_level(T, i, err, sizeof err)) {
            zp_cli_error("tradeoff", "level %g %s: %s; nothing was written", T->L[i].p,
                         T->power ? "W" : "%", err);
            return -1;
        }
        if (!T->L[i].done) {
            break; /* stopped inside this level: it is not reported */
        }
        T->ndone = i + 1;
        if (T->power) {
            fprintf(stderr, "tradeoff: %g W: %s%.4f s\n", T->L[i].p,
                    T->L[i].found ? "" : "(none) ", T->L[i].time);
        } else {
            fprintf(stderr, "tradeoff: +/-%g %%: %s%.4f s\n", T->L[i].p,
                    T->L[i].found ? "" : "(none) ", T->L[i].time);
        }
    }
    return 0;
}

int zp_cmd_tradeoff(int argc, char **argv) {
    tradeoff_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    double lv[MAX_LEVELS];
    int n = parse_levels(a.levels, a.power, lv);
    static zp_problem su; /* large: kept off the stack */
    if (n < 1 || zp_setup_load("tradeoff", a.scene, &a.ov, &su)) {
        return ZP_EXIT_USAGE;
    }
    const zp_scene *sc = &su.sc;
    static tradeoff T; /* large: kept off the stack */
    T = (tradeoff){.su = &su,
                   .n = n,
                   .tty = isatty(STDERR_FILENO),
                   .power = a.power,
                   .max_time = a.max_time,
                   .given = sc->nforce > 0 || a.ov.schedule || a.ov.force};
    for (int i = 0; i < n; i++) {
        T.L[i].p = lv[i];
    }
    char err[1200] = "";
    int status = ZP_EXIT_FAIL, begun = 0;
    zp_tx t;
    if (zp_cli_out_begin(&t, "tradeoff", "tradeoff", a.out, sc)) {
        goto done;
    }
    begun = 1;
    interrupted = 0;
    zp_tx_soft_interrupt(&t, &interrupted);
    if (solve_levels(&T)) {
        goto done;
    }
    int complete = T.ndone == n;
    if (T.ndone == 0) {
        fputs("zipopt tradeoff: interrupted before a level was finished; nothing was written\n",
              stderr);
        goto done;
    }
    if (exchange_answers(&T, err, sizeof err)) {
        zp_cli_error("tradeoff", "%s; nothing was written", err);
        goto done;
    }
    int missing = 0;
    const char *scripts[] = {"tradeoff.gp"};
    begun = 0; /* the files commit or abort the transaction */
    if (write_files(&t, &T, complete) ||
        zp_cli_out_draw_commit(&t, "tradeoff", scripts, 1, &missing)) {
        goto done;
    }
    for (int i = 1; i < T.ndone && !a.json && a.power; i++) {
        printf("at %g W: %.4f s, %.3f s slower than no cap (%.1f %%)%s\n", T.L[i].p, T.L[i].time,
               cost(T.L, i), 100 * cost(T.L, i) / T.L[0].time, T.L[i].found ? "" : ", NOT found");
    }
    for (int i = 1; i < T.ndone && !a.json && !a.power; i++) {
        printf("robust to +/-%g %%: %.4f s, costs %.3f s (%.1f %%)%s\n", T.L[i].p, T.L[i].time,
               cost(T.L, i), 100 * cost(T.L, i) / T.L[0].time, T.L[i].found ? "" : ", NOT found");
    }
    if (a.json) {
        write_json(stdout, sc, T.L, T.ndone, su.sched.np, complete, a.power);
    }
    char shown[4 * sizeof t.dir];
    fprintf(a.json ? stderr : stdout, "wrote in %s: %s%s\n",
            zp_cli_shown(t.dir, shown, sizeof shown), t.written,
            missing ? " (no gnuplot: tradeoff.gp without its image)" : "");
    status = complete ? ZP_EXIT_OK : ZP_EXIT_FAIL;
    if (!complete) {
        fprintf(stderr,
                "zipopt tradeoff: interrupted; wrote the %d level%s finished, marked "
                "incomplete\n",
                T.ndone, T.ndone == 1 ? "" : "s");
    }
done:
    if (begun) {
        zp_tx_abort(&t);
    }
    for (int i = 0; i < n; i++) {
        zp_answer_free(&T.ans[i]);
    }
    zp_setup_free(&su);
    return status;
}
