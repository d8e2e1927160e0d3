/* `zipopt tradeoff SCENE.ini [--levels P1,P2,..]`: the robust search at each force_error level
   (the scene's other [robust] ranges as given): what robustness costs; with `--power W1,..` the
   search at each drive power (W) against no cap: what a motor buys. The levels exchange
   their answers, so the costs never fall as the level grows past what the searches missed. */
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "report_tradeoff.h"
#include "setup.h"

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

/* set by the first Ctrl-C (the transaction's handler): the level under way stops cleanly */
static volatile sig_atomic_t interrupted;

/* the progress line inside a level: what its search is doing and its best so far */
typedef struct level_progress {
    const zp_tradeoff *T;
    int i;
    int tty;
} level_progress;

static void on_progress(void *user, const zp_search_progress *p, int improved) {
    (void)improved;
    const level_progress *lp = user;
    if (!lp->tty) {
        return;
    }
    fprintf(stderr,
            "\r\033[Ktradeoff: level %d of %d (%s%g %s): %s, round %d, %ld of %ld "
            "simulations, %.1f s",
            lp->i + 1, lp->T->n, lp->T->power ? "" : "+/-", lp->T->L[lp->i].p,
            lp->T->power ? "W" : "%", p->phase, p->round + 1, p->evals, p->budget, p->wall_s);
    if (p->found) {
        fprintf(stderr, ", best %.4f s", p->time);
    }
}

/* the levels: 0 first (the reference of the costs: no force error, or no cap), then the ones
   asked for in the order given */
static int parse_levels(const char *text, int power, double *lv) {
    double got[ZP_TRADEOFF_MAX_LEVELS];
    char why[128] = "";
    int n = text ? zp_cli_parse_list(text, got, ZP_TRADEOFF_MAX_LEVELS - 1, why, sizeof why) : 4;
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

/* the levels in order until one is stopped (Ctrl-C), those finished counted in T->ndone; 0, or
   -1 (said) */
static int solve_levels(zp_tradeoff *T, int tty) {
    char err[1200] = "";
    for (int i = 0; i < T->n && !interrupted; i++) {
        level_progress lp = {T, i, tty};
        zp_status st = zp_tradeoff_solve(T, i, on_progress, &lp, err, sizeof err);
        if (tty) {
            fputs("\r\033[K", stderr);
        }
        if (st) {
            zp_cli_error("tradeoff", "level %g %s: %s; nothing was written", T->L[i].p,
                         T->power ? "W" : "%", err);
            return -1;
        }
        if (!T->L[i].done) {
            break; /* stopped inside this level: it is not reported */
        }
        T->ndone = i + 1;
        fprintf(stderr, "tradeoff: %s%g %s: %s%.4f s\n", T->power ? "" : "+/-", T->L[i].p,
                T->power ? "W" : "%", T->L[i].found ? "" : "(none) ", T->L[i].time);
    }
    return 0;
}

/* the finished levels' files committed, then the summary; the exit status */
static int write_levels(zp_tx *t, const zp_tradeoff *T, int json) {
    char err[1400] = "";
    int missing = 0, complete = T->ndone == T->n;
    const char *scripts[] = {"tradeoff.gp"};
    if (zp_report_tradeoff_files(t, T, err, sizeof err)) {
        zp_tx_abort(t);
        zp_cli_error("tradeoff", "%s; nothing was written", err);
        return ZP_EXIT_FAIL;
    }
    if (zp_cli_out_draw_commit(t, "tradeoff", scripts, 1, &missing)) {
        return ZP_EXIT_FAIL;
    }
    for (int i = 1; i < T->ndone && !json; i++) {
        double cost = zp_tradeoff_cost(T, i);
        if (T->power) {
            printf("at %g W: %.4f s, %.3f s slower than no cap (%.1f %%)%s\n", T->L[i].p,
                   T->L[i].time, cost, 100 * cost / T->L[0].time,
                   T->L[i].found ? "" : ", NOT found");
        } else {
            printf("robust to +/-%g %%: %.4f s, costs %.3f s (%.1f %%)%s\n", T->L[i].p,
                   T->L[i].time, cost, 100 * cost / T->L[0].time,
                   T->L[i].found ? "" : ", NOT found");
        }
    }
    if (json) {
        zp_report_tradeoff_json(stdout, T);
    }
    char shown[4 * sizeof t->dir];
    fprintf(json ? stderr : stdout, "wrote in %s: %s%s\n",
            zp_cli_shown(t->dir, shown, sizeof shown), t->written,
            missing ? " (no gnuplot: tradeoff.gp without its image)" : "");
    if (!complete) {
        fprintf(stderr,
                "zipopt tradeoff: interrupted; wrote the %d level%s finished, marked "
                "incomplete\n",
                T->ndone, T->ndone == 1 ? "" : "s");
    }
    return complete ? ZP_EXIT_OK : ZP_EXIT_FAIL;
}

int zp_cmd_tradeoff(int argc, char **argv) {
    tradeoff_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    double lv[ZP_TRADEOFF_MAX_LEVELS];
    int n = parse_levels(a.levels, a.power, lv);
    static zp_problem su; /* large: kept off the stack */
    if (n < 1 || zp_setup_load("tradeoff", a.scene, &a.ov, &su)) {
        return ZP_EXIT_USAGE;
    }
    static zp_tradeoff T; /* large: kept off the stack */
    zp_tradeoff_init(&T, &su, lv, n, su.sc.nforce > 0 || a.ov.schedule || a.ov.force, a.power);
    T.max_time = a.max_time;
    T.stop = &interrupted;
    char err[1200] = "";
    int status = ZP_EXIT_FAIL;
    zp_tx t;
    if (zp_cli_out_begin(&t, "tradeoff", "tradeoff", a.out, &su.sc)) {
        goto done;
    }
    interrupted = 0;
    zp_tx_soft_interrupt(&t, &interrupted);
    if (solve_levels(&T, isatty(STDERR_FILENO))) {
        zp_tx_abort(&t);
    } else if (T.ndone == 0) {
        fputs("zipopt tradeoff: interrupted before a level was finished; nothing was written\n",
              stderr);
        zp_tx_abort(&t);
    } else if (zp_tradeoff_exchange(&T, err, sizeof err)) {
        zp_cli_error("tradeoff", "%s; nothing was written", err);
        zp_tx_abort(&t);
    } else {
        status = write_levels(&t, &T, a.json); /* the files commit or abort the transaction */
    }
done:
    zp_tradeoff_free(&T);
    zp_setup_free(&su);
    return status;
}
