/* `zipopt [SCENE.ini] [--out DIR]`: the search for the fastest survivable schedule, its
   verification and the best-forcing report. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "answer.h"
#include "cli.h"
#include "mpi_spread.h"
#include "tx.h"
#include "plot.h"
#include "report.h"
#include "report_files.h"
#include "report_text.h"
#include "robust.h"
#include "search.h"
#include "setup.h"

/* set by the first Ctrl-C (the transaction's handler): the search stops cleanly; a second
   one ends the run leaving nothing */
static volatile sig_atomic_t interrupted;

static void usage(FILE *f) {
    fputs("usage: zipopt [SCENE.ini] [--out DIR] [--algorithm NAME] [--seed N] [--max-evals N]\n"
          "              [--max-time S] [--no-plot] [--json]\n"
          "\n"
          "Searches for the fastest schedule of drive forces, one per course section within\n"
          "[drive] min, max, that brings the spy to the end alive with every relative joint\n"
          "angle at least [optimize] margin below death_angle. With no file: the built-in seed\n"
          "scene. Verifies the best schedule at a 100x tighter tolerance, measures its\n"
          "robustness to random changes of the forces (+/-p % and 2p %, p the scene's\n"
          "[robust] force_error; +/-2 % and 5 % without one), and writes report.md,\n"
          "report.html, schedule.ini, summary.json, trajectory.csv and the best run's figures\n"
          "(course, energy, angles, loads, along: PNG with their gnuplot scripts) to\n"
          "out/<scene name>/search/ (or DIR itself), all or nothing.\n"
          "While it runs, the best so far is kept in DIR/checkpoint.ini; Ctrl-C stops the\n"
          "search and writes the best so far, marked interrupted.\n"
          "  --out DIR         output folder\n"
          "  --algorithm NAME  the search strategy (below; default portfolio-cobyla on 4\n"
          "                    sections or more without [robust], scan-cobyla otherwise)\n"
          "  --seed N          overrides [optimize] seed\n"
          "  --max-evals N     overrides [optimize] max_evals (simulations; default 5000 per\n"
          "                    section)\n"
          "  --max-time S      stops the search after S seconds of wall time, keeping the best\n"
          "                    so far (then the answer depends on the machine's speed)\n"
          "  --no-plot         skip the figures\n"
          "  --json            print summary.json's object on stdout instead of the text\n"
          "                    summary (keys: docs/commands.md)\n"
          "\n"
          "Under `mpirun -np N zipopt SCENE.ini ..` rank 0 searches on its threads while the\n"
          "other ranks wait without spinning, then the N ranks share the robust verification's\n"
          "fresh scenarios; rank 0 alone prints and writes, bit for bit as without mpirun.\n"
          "\n"
          "strategies:\n",
          f);
    for (int i = 0; i < zp_search_algo_count(); i++) {
        const zp_search_algo *a = zp_search_algo_get(i);
        fprintf(f, "  %-14s %s\n", a->name, a->doc);
    }
}

typedef struct search_args {
    const char *scene, *out, *algo;
    int has_seed;
    unsigned long seed, max_evals; /* max_evals 0: from the scene */
    double max_time;               /* s, 0: no limit */
    int no_plot, json;
} search_args;

enum { O_OUT = ZP_OPT_FIRST, O_NO_PLOT, O_ALGORITHM, O_SEED, O_MAX_EVALS, O_MAX_TIME, O_JSON };
static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"json", no_argument, NULL, O_JSON},
    {"out", required_argument, NULL, O_OUT},
    {"no-plot", no_argument, NULL, O_NO_PLOT},
    {"algorithm", required_argument, NULL, O_ALGORITHM},
    {"seed", required_argument, NULL, O_SEED},
    {"max-evals", required_argument, NULL, O_MAX_EVALS},
    {"max-time", required_argument, NULL, O_MAX_TIME},
    {NULL, 0, NULL, 0},
};

/* 1: --help was shown; -1: a mistake (reported) */
static int parse_args(int argc, char **argv, search_args *a) {
    *a = (search_args){0};
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("", argc, argv, options)) != -1;) {
        switch (c) {
        case 'h':
            usage(stdout);
            return 1;
        case O_OUT:
            a->out = optarg;
            break;
        case O_NO_PLOT:
            a->no_plot = 1;
            break;
        case O_JSON:
            a->json = 1;
            break;
        case O_ALGORITHM:
            a->algo = optarg;
            break;
        case O_SEED:
            a->has_seed = 1;
            if (zp_cli_whole("", "--seed", optarg, 0, ULONG_MAX, &a->seed)) {
                return -1;
            }
            break;
        case O_MAX_EVALS:
            if (zp_cli_whole("", "--max-evals", optarg, 1, LONG_MAX, &a->max_evals)) {
                return -1;
            }
            break;
        case O_MAX_TIME:
            if (zp_cli_seconds("", "--max-time", optarg, &a->max_time)) {
                return -1;
            }
            break;
        default:
            return -1;
        }
    }
    if (zp_cli_scene_operand("", argc, argv, &a->scene) ||
        (a->out && zp_cli_path_ok("", "--out", a->out))) {
        return -1;
    }
    if (a->algo && zp_search_algo_find(a->algo) < 0) {
        const char *names[64];
        int n = 0;
        for (; n < zp_search_algo_count() && n < 64; n++) {
            names[n] = zp_search_algo_get(n)->name;
        }
        int near = zp_diag_nearest(a->algo, names, n);
        zp_cli_error("", "--algorithm '%s' is unknown%s%s%s (the list: zipopt SCENE --help)",
                     a->algo, near >= 0 ? "; did you mean '" : "", near >= 0 ? names[near] : "",
                     near >= 0 ? "'?" : "");
        return -1;
    }
    return 0;
}

typedef struct progress_ctx {
    const zp_scene *sc;
    const zp_schedule *shape; /* the kind and bounds the search's parameters fill */
    zp_tx *tx;
    const zp_search_progress *p; /* the improvement being checkpointed */
    int tty;      /* stderr is a terminal: show the progress line */
    int shown;    /* a progress line is on screen */
    struct timespec t0; /* start of the current phase */
    double last;  /* s into it at the last line shown */
    int plot;     /* the figures are asked for */
    int early;    /* ... and drawn while the answer's checks run */
    int drawn;    /* the figures: 1 drawn, 0 data and scripts only or none, -1 failed (said) */
    int said;     /* a failure that stopped the solve is said already */
    zp_gnuplot_job job;
    zp_plot_info info;
} progress_ctx;

static void phase_start(progress_ctx *c, const char *what) {
    clock_gettime(CLOCK_MONOTONIC, &c->t0);
    c->last = 0;
    if (c->tty) {
        fprintf(stderr, "%s%s", c->shown ? "\n" : "", what);
        c->shown = 1;
    }
}

static void write_checkpoint(FILE *f, void *user) {
    const progress_ctx *c = user;
    char note[160];
    snprintf(note, sizeof note, "search checkpoint: best so far, finish %.6f s after %ld "
             "simulations", c->p->time, c->p->evals);
    zp_schedule best = zp_drive_with(c->shape, c->p->force);
    zp_checkpoint_write_schedule(f, c->sc, &best, note);
}

/* the progress line, and the checkpoint of every improvement so a killed run loses nothing */
static void on_progress(void *user, const zp_search_progress *p, int improved) {
    progress_ctx *c = user;
    if (improved) {
        char err[1400];
        c->p = p;
        if (zp_tx_checkpoint(c->tx, "checkpoint.ini", write_checkpoint, c, err, sizeof err)) {
            fprintf(stderr, "%szipopt: %s\n", c->shown ? "\n" : "", err);
        }
    }
    if (c->tty) {
        /* the budget left at the rate so far: an upper bound, as a round may converge first */
        double rate = p->evals / fmax(p->wall_s, 1e-9);
        char again[64] = "";
        if (p->restart) { /* the robust search again, its adversary's scenarios added */
            snprintf(again, sizeof again, "restart %d (%d scenario%s added), ", p->restart,
                     p->restart, p->restart == 1 ? "" : "s");
        }
        fprintf(stderr, "\rsearch %sround %d, %s: %ld of %ld simulations, %.0f/s, best %s%.4f s, "
                "at most %.0f s left   ", again, p->round + 1, p->phase, p->evals, p->budget, rate,
                p->found ? "" : "(none survives) ", p->found ? p->time : 0.0,
                (p->budget - p->evals) / fmax(rate, 1e-9));
        c->shown = 1;
    }
}

/* the verification's progress line: its robustness runs done, and the time left at that pace */
static void on_verify(void *user, int done, int total) {
    progress_ctx *c = user;
    double el = zp_cli_since(&c->t0);
    if (c->tty && (done == total || el - c->last >= 0.25)) {
        c->last = el;
        fprintf(stderr, "\rrobustness: %d of %d runs and bisections, about %.0f s left   ", done,
                total, el / done * (total - done));
        c->shown = 1;
    }
}

/* the answer's figures into the transaction, started: 0, or -1 failed (said on stderr) */
static int figures_start(progress_ctx *c, const zp_answer *a, int procs) {
    const zp_problem *p = a->pb;
    zp_plot_opts po;
    zp_plot_opts_default(&po);
    po.procs = procs;
    po.margin = p->sc.margin * M_PI / 180;
    zp_schedule best = zp_drive_with(&p->sched, a->res.force);
    po.sched = &best;
    char err[1400];
    if (zp_plot_start(c->tx, p->m, a->best, a->v.run, &po, &c->info, &c->job, err, sizeof err)) {
        fprintf(stderr, "zipopt: figures: %s; nothing was written\n", err);
        c->said = 1;
        return -1;
    }
    return 0;
}

/* the figures finished: 1 drawn, 0 data and scripts only (no gnuplot), -1 failed (said) */
static int figures_finish(progress_ctx *c) {
    char err[1400];
    if (zp_plot_finish(c->tx, &c->job, &c->info, err, sizeof err)) {
        fprintf(stderr, "zipopt: figures: %s; nothing was written\n", err);
        return -1;
    }
    if (c->info.no_gnuplot) {
        fputs("zipopt: gnuplot is not installed (apt-get install gnuplot-nox): writing the "
              "figures' data and scripts, not the images\n",
              stderr);
    }
    return !c->info.no_gnuplot;
}

/* the solve's stages: the phase lines, and the figures of the answer, drawn while its checks
   run unless [solver] accuracy may still replace it */
static int on_stage(void *user, zp_answer_stage s, const zp_answer *a) {
    progress_ctx *c = user;
    if (s == ZP_ANSWER_RERUN && c->early) {
        /* half the cores draw while the checks have the other half: every gnuplot start-up
           costs about what drawing one figure does */
        int half = zp_gnuplot_cores() / 2;
        return figures_start(c, a, half > 1 ? half : 1);
    }
    if (s == ZP_ANSWER_CHECKING) {
        phase_start(c, "verification: the best schedule with [solver] and 100x tighter");
    } else if (s == ZP_ANSWER_CHECKED && c->shown) {
        fputc('\n', stderr);
        c->shown = 0;
    } else if (s == ZP_ANSWER_COMPARED && c->plot) {
        /* the figures before the report, so that it links only those drawn */
        phase_start(c, "figures: drawing the best run with gnuplot\n");
        c->shown = 0;
        if (!c->early && figures_start(c, a, 0)) {
            return -1;
        }
        c->drawn = figures_finish(c);
    } else if (s == ZP_ANSWER_DIAGNOSING) {
        phase_start(c, "diagnosis: the fresh scenarios the answer fails\n");
    }
    return 0;
}

/* the files of the answer committed and the summary printed; the exit status */
static int finish(zp_tx *tx, const search_args *args, const zp_answer *a, int drawn) {
    zp_report_place w = {args->scene, tx->dir, drawn > 0};
    char err[1400] = "";
    if (drawn < 0) {
        return ZP_EXIT_FAIL;
    }
    if (zp_report_files_write(tx, a, &w, err, sizeof err)) {
        fprintf(stderr, "zipopt: %s; nothing was written\n", err);
        return ZP_EXIT_FAIL;
    }
    if (zp_cli_out_commit(tx, "")) {
        return ZP_EXIT_FAIL;
    }
    if (args->json) {
        zp_summary_write_json(stdout, a); /* summary.json's object */
    } else {
        zp_report_text_write(stdout, a);
    }
    fprintf(args->json ? stderr : stdout, "wrote in %s: %s\n", tx->dir, tx->written);
    if (a->res.interrupted) {
        fputs("zipopt: interrupted; wrote the best schedule found so far\n", stderr);
        return ZP_EXIT_FAIL;
    }
    if (!a->found) {
        return ZP_EXIT_NONE; /* the closest candidate is written, marked */
    }
    if (interrupted) {
        fputs("zipopt: interrupted after the search had finished; the files are complete\n",
              stderr);
        return ZP_EXIT_FAIL;
    }
    return ZP_EXIT_OK;
}

/* the command on every rank of sp: rank 0 searches, prints and writes; every rank verifies
   its share of the robust scenarios */
static int search(int argc, char **argv, const zp_spread *sp) {
    search_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    static zp_problem st; /* large: kept off the stack */
    zp_overrides ov = {.has_seed = a.has_seed, .seed = a.seed, .max_evals = (long)a.max_evals};
    if (zp_setup_load("", a.scene, &ov, &st)) {
        return ZP_EXIT_USAGE;
    }
    zp_tx tx = {.dirfd = -1, .tmpfd = -1};
    int rank = sp->rank; /* ranks other than 0 write nothing, not even the folder */
    if (rank == 0 && zp_cli_out_begin(&tx, "", "search", a.out, &st.sc)) {
        zp_robust_release(sp);
        zp_setup_free(&st);
        return ZP_EXIT_FAIL;
    }
    if (rank == 0) {
        zp_tx_soft_interrupt(&tx, &interrupted);
    }
    progress_ctx pc = {.sc = &st.sc, .shape = &st.sched, .tx = &tx,
                       .tty = isatty(STDERR_FILENO), .plot = !a.no_plot,
                       .early = !a.no_plot && !(st.sc.accuracy > 0)};
    zp_answer_opts o = zp_answer_opts_of(&st, ZP_ANSWER_REPORTED);
    if (a.algo) {
        o.search.algo = zp_search_algo_find(a.algo);
    }
    o.search.max_time = a.max_time;
    o.search.stop = &interrupted;
    o.search.progress = on_progress;
    o.search.user = &pc;
    o.spread = sp;
    o.stage = on_stage;
    o.checked = on_verify;
    o.user = &pc;
    static zp_answer ans; /* large: kept off the stack */
    char err[512] = "";
    int status = ZP_EXIT_FAIL;
    if (zp_answer_solve(&st, &o, &ans, err, sizeof err)) {
        if (!pc.said) {
            fprintf(stderr, "zipopt: %s; nothing was written\n", err);
        }
    } else if (rank != 0) { /* its share of the verification is rank 0's too, which goes on */
        status = ZP_EXIT_OK;
    } else {
        status = finish(&tx, &a, &ans, pc.drawn);
    }
    zp_tx_abort(&tx); /* nothing of the run remains unless it was committed */
    zp_answer_free(&ans);
    zp_setup_free(&st);
    return status;
}

int zp_cmd_search(int argc, char **argv) {
    return zp_mpi_spread_main("search", search, argc, argv);
}
