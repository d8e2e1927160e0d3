/* `zipopt sweep`: a design study over a grid of scene values (docs/commands.md). Under mpirun the
   points are spread over the ranks; rank 0 checkpoints each row as it comes and writes the outputs.
 */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "mpi_queue.h"
#include "mpi_spread.h"
#include "report_sweep.h"
#include "scene_load.h"
#include "sweep_csv.h"

#define MAX_ARGS_VARY                                                                              \
    16 /* --vary options kept for checking; more than ZP_SWEEP_MAX_VARY is an error */

static void usage(FILE *f) {
    fputs("usage: zipopt sweep SCENE.ini --vary SECTION.KEY=A:B:N [--vary ..]\n"
          "                    [--run search|simulate] [--out DIR] [--resume] [--json]\n"
          "                    [--grid-schedule | --no-grid-schedule] [--max-evals N]\n"
          "                    [--max-time S] [--schedule FILE | --force F1,..]\n"
          "\n"
          "A design study: the scene at every point of the grid of the varied keys (N values\n"
          "from A to B for each --vary, the first varying fastest; up to 4 keys). A list key\n"
          "(body.masses, body.lengths, body.damping, drive.forces, ..) is scaled as a whole:\n"
          "A and B are factors, e.g. body.masses=0.8:1.2:5. Every point is checked by every\n"
          "rule of the scene file before anything runs. At each point:\n"
          "  --run search      the search for the fastest schedule that keeps the limits,\n"
          "                    its answer re-run at the scene's tolerance (default)\n"
          "  --run simulate    one run of the scene's [drive] forces\n"
          "Writes sweep.csv (one row per point: the varied values, found, outcome, finish\n"
          "time, margin, the binding limit of the margin and [limits], peak g, peak joint\n"
          "force, arrival speed, kink dv, forces; a failed point says why and the study goes\n"
          "on), sweep.png with its gnuplot script (a line for one key, a heat map for two,\n"
          "points without a schedule marked) and summary.json to out/<scene name>/sweep/ (or\n"
          "DIR), and prints the summary. Each finished row is appended to checkpoint.csv there\n"
          "at once; after Ctrl-C or a killed job, --resume skips every finished point.\n"
          "  --json            print summary.json on stdout instead of the text\n"
          "  --max-evals N     overrides [optimize] max_evals at every point\n"
          "  --max-time S      stops each point's search after S seconds (the rows then\n"
          "                    depend on the machine's speed)\n"
          "  --schedule FILE   a schedule ([drive] forces) laid over the scene: what\n"
          "  --force F1,..     --run simulate runs at every point\n"
          "Besides, the schedule that survives across the whole grid: the search for the\n"
          "fastest schedule at the middle point that keeps the limits at every corner of the\n"
          "grid (each corner's scene as it is, with its [robust] scenarios when the scene has\n"
          "them), then checked at every point (one run each). Corners need not bound\n"
          "survival: the points the answer breaks join the corners and the search runs\n"
          "again, warm from its answer, until every point survives or 4 searches ran (at\n"
          "most 16 points added a round, those broken most). In the summary and\n"
          "summary.json. On by default with --run search; --no-grid-schedule skips it,\n"
          "--grid-schedule adds it to a --run simulate study.\n"
          "\n"
          "Under `mpirun -np N zipopt sweep ..` the points go to the N ranks by a work queue\n"
          "(each rank with its OpenMP threads); the results are the same bits as without.\n",
          f);
}

typedef struct sweep_args {
    const char *scene, *out, *run;
    const char *force, *schedule, *max_evals; /* laid over the scene before the grid */
    double max_time;                          /* s per point's search, 0: no limit */
    int resume, json, nvary;
    int grid; /* the grid schedule: 1 on, 0 off, -1 as --run decides */
    const char *vary[MAX_ARGS_VARY];
} sweep_args;

enum {
    O_VARY = ZP_OPT_FIRST,
    O_RUN,
    O_OUT,
    O_RESUME,
    O_JSON,
    O_GRID,
    O_NO_GRID,
    O_MAX_EVALS,
    O_MAX_TIME,
    O_SCHEDULE,
    O_FORCE
};
static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"vary", required_argument, NULL, O_VARY},
    {"run", required_argument, NULL, O_RUN},
    {"out", required_argument, NULL, O_OUT},
    {"resume", no_argument, NULL, O_RESUME},
    {"json", no_argument, NULL, O_JSON},
    {"grid-schedule", no_argument, NULL, O_GRID},
    {"no-grid-schedule", no_argument, NULL, O_NO_GRID},
    {"max-evals", required_argument, NULL, O_MAX_EVALS},
    {"max-time", required_argument, NULL, O_MAX_TIME},
    {"schedule", required_argument, NULL, O_SCHEDULE},
    {"force", required_argument, NULL, O_FORCE},
    {NULL, 0, NULL, 0},
};

/* 0, 1 (--help shown) or -1 (reported) */
static int parse_args(int argc, char **argv, sweep_args *a) {
    memset(a, 0, sizeof *a);
    a->run = "search";
    a->grid = -1;
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("sweep", argc, argv, options)) != -1;) {
        switch (c) {
        case 'h':
            usage(stdout);
            return 1;
        case O_VARY:
            if (a->nvary < MAX_ARGS_VARY) {
                a->vary[a->nvary] = optarg;
            }
            a->nvary++;
            break;
        case O_RUN:
            a->run = optarg;
            break;
        case O_OUT:
            a->out = optarg;
            break;
        case O_RESUME:
            a->resume = 1;
            break;
        case O_JSON:
            a->json = 1;
            break;
        case O_GRID:
        case O_NO_GRID:
            a->grid = c == O_GRID;
            break;
        case O_MAX_EVALS: {
            unsigned long n;
            if (zp_cli_whole("sweep", "--max-evals", optarg, 1, LONG_MAX, &n)) {
                return -1;
            }
            a->max_evals = optarg;
            break;
        }
        case O_MAX_TIME:
            if (zp_cli_seconds("sweep", "--max-time", optarg, &a->max_time)) {
                return -1;
            }
            break;
        case O_SCHEDULE:
            a->schedule = optarg;
            break;
        case O_FORCE:
            a->force = optarg;
            break;
        default:
            return -1;
        }
    }
    if (zp_cli_scene_operand("sweep", argc, argv, &a->scene) ||
        (a->out && zp_cli_path_ok("sweep", "--out", a->out))) {
        return -1;
    }
    const char *miss = !a->scene ? "a scene file" : !a->nvary ? "at least one --vary" : NULL;
    if (miss) {
        zp_cli_error("sweep", "%s is required; see zipopt sweep --help", miss);
        return -1;
    }
    return 0;
}

/* The study as it runs; rows, done and the checkpoint live on rank 0 only. */
typedef struct study {
    const zp_sweep *s;
    const char *base, *path; /* the scene text and its file name */
    char name[ZP_NAME_MAX];  /* the scene's name */
    int np; /* parameters of the schedule */
    zp_scene *sc;        /* owned: scratch for the point being computed */
    zp_study_row *rows;  /* owned, npoint */
    unsigned char *done; /* owned, npoint */
    int ndone, nresumed;
    int grid;             /* the grid schedule is wanted: the queue's item npoint */
    int grid_done, grid_resumed;
    zp_grid_result *grid_res; /* owned, rank 0 */
    zp_sweep_checkpoint cp;
    int cp_failed;   /* a row could not be appended to the checkpoint */
    /* the fault a test injects (README): after fault_after rows are appended (0: never),
       rank 0 is killed hard as a lost node is, or with fault_hang hangs as a stuck node does
       (until a signal ends the job) */
    int fault_after, fault_hang;
    int appended;
    int tty;
    int lines; /* rank 0 under mpirun, its stderr no terminal: a progress line per point */
    double max_time; /* s per point's search, 0: no limit */
    struct timespec start;
} study;

/* what an item of the queue comes to: a point's row, or the grid schedule (item npoint) */
typedef union item_result {
    zp_study_row row;
    zp_grid_result grid;
} item_result;

static void work(void *user, int p, void *result) {
    study *st = user;
    if (p == st->s->npoint) {
        zp_grid_run(st->s, st->base, st->path, &((item_result *)result)->grid);
        return;
    }
    zp_study_row *row = result;
    zp_diag d;
    zp_diag_init(&d);
    if (zp_sweep_point_scene(st->s, st->base, st->path, p, st->sc, &d)) {
        memset(row, 0, sizeof *row);
        row->failed = 1;
        row->np = st->np;
        snprintf(row->message, sizeof row->message, "%.*s", (int)sizeof row->message - 1,
                 d.n ? d.text[0] : "bad scene");
        return;
    }
    zp_study_run(st->sc, st->s->kind, st->max_time, row);
}

/* rank 0 dies (or hangs) at once: no handler runs, nothing more is written */
static void inject_fault(const study *st) {
    fflush(stdout);
    while (st->fault_hang) {
        pause();
    }
    raise(SIGKILL);
}

static void done(void *user, int p, const void *result) {
    study *st = user;
    int grid = p == st->s->npoint;
    if (grid) {
        *st->grid_res = ((const item_result *)result)->grid;
        st->grid_done = 1;
    } else {
        st->rows[p] = *(const zp_study_row *)result;
        st->ndone += !st->done[p];
        st->done[p] = 1;
    }
    if (!st->cp_failed && (grid ? zp_sweep_csv_checkpoint_add_grid(&st->cp, st->s, st->grid_res)
                                : zp_sweep_csv_checkpoint_add(&st->cp, st->s, p, &st->rows[p]))) {
        st->cp_failed = 1;
        fputc('\n', stderr);
        zp_cli_error("sweep",
                     "cannot append to %s; the study goes on, but a rerun would start afresh",
                     st->cp.path);
    }
    if (!grid && !st->cp_failed && st->fault_after > 0 && ++st->appended >= st->fault_after) {
        inject_fault(st);
    }
    if (st->tty || st->lines) {
        fprintf(stderr, "%szipopt sweep: %d/%d points, %.1f s%s", st->tty ? "\r" : "",
                st->ndone, st->s->npoint, zp_cli_since(&st->start), st->tty ? "   " : "\n");
    }
}

/* every point checked by every rule of the scene file before anything runs; 0 or -1 (said) */
static int check_points(study *st) {
    zp_diag d;
    int p = zp_sweep_check_points(st->s, st->base, st->path, st->sc, &d);
    if (p < 0) {
        return 0;
    }
    char at[512];
    zp_sweep_describe(st->s, p, at, sizeof at);
    zp_cli_error("sweep", "the scene at point %d (%s) is not valid:", p, at);
    zp_diag_print(&d, stderr);
    fputs("zipopt sweep: nothing was written\n", stderr);
    return -1;
}

/* sweep.csv, summary.json and the figure into the transaction t, committed as a set */
static int write_outputs(zp_tx *t, const zp_report_sweep *o, const char *summary,
                         int *no_gnuplot) {
    char err[1300];
    if (zp_report_sweep_files(t, o, summary, err, sizeof err)) {
        zp_tx_abort(t);
        zp_cli_error("sweep", "%s; nothing was written", err);
        return -1;
    }
    const char *scripts[] = {"sweep.gp"};
    *no_gnuplot = 0;
    return zp_cli_out_draw_commit(t, "sweep", scripts, zp_report_sweep_has_figure(o), no_gnuplot);
}

/* rank 0, once every point is done: the files, then the summary on stdout */
static int finish(study *st, const sweep_args *a, zp_tx *t, int ranks) {
    zp_report_sweep o = {st->s, st->rows, st->name, st->np, st->grid ? st->grid_res : NULL};
    char summary[4096];
    zp_report_sweep_summary(&o, summary, sizeof summary);
    int no_gnuplot = 0;
    if (write_outputs(t, &o, summary, &no_gnuplot)) {
        zp_cli_error("sweep", "the finished rows stay in %s; rerun with --resume", st->cp.path);
        return ZP_EXIT_FAIL;
    }
    zp_sweep_csv_checkpoint_close(&st->cp, 1); /* sweep.csv holds every row */
    if (a->json) {
        zp_report_sweep_json(stdout, &o, summary);
    } else {
        char shown[4 * sizeof t->dir];
        printf("%s\n%d points (%d from the checkpoint)%s in %.2f s on %d rank%s; wrote "
               "%s/sweep.csv, summary.json%s\n",
               summary, st->s->npoint, st->nresumed,
               !st->grid           ? ""
               : st->grid_resumed ? " and the grid schedule (from the checkpoint)"
                                   : " and the grid schedule",
               zp_cli_since(&st->start), ranks,
               ranks == 1 ? "" : "s", zp_cli_shown(t->dir, shown, sizeof shown),
               !zp_report_sweep_has_figure(&o) ? " (no figure for more than two keys)"
               : no_gnuplot                 ? ", sweep.gp (gnuplot is not installed: no image)"
                                            : ", sweep.png");
    }
    return ZP_EXIT_OK;
}

/* --schedule, --force and --max-evals laid over the scene's text, so that every point, the
   grid schedule and the checkpoint's identity see them as scene lines; 0, or -1 (said) */
static int overlay(const sweep_args *a, study *st, char **base) {
    char value[ZP_SWEEP_LINE_MAX] = "", why[256];
    zp_diag d;
    zp_diag_init(&d);
    if (a->schedule && zp_scene_load_overlay_schedule(a->schedule, st->sc, &d) == ZP_OK) {
        zp_schedule sh = zp_drive_of_scene(st->sc);
        zp_drive_format(&sh, value, sizeof value);
    }
    if (a->force) {
        zp_schedule sh = zp_drive_of_scene(st->sc);
        if (zp_drive_parse(&sh, a->force, &sh, why, sizeof why)) {
            zp_diag_add(&d, NULL, 0, NULL, NULL, "zipopt sweep: --force: %s", why);
        } else {
            zp_drive_format(&sh, value, sizeof value);
        }
    }
    zp_diag_print(&d, stderr);
    if (d.n) {
        return -1;
    }
    const char *sec[] = {"drive", "optimize"}, *key[] = {"forces", "max_evals"};
    const char *val[] = {value[0] ? value : NULL, a->max_evals};
    for (int i = 0; i < 2; i++) {
        char *next = val[i] ? zp_sweep_set_text(*base, sec[i], key[i], val[i]) : *base;
        if (!next) {
            fputs("zipopt sweep: out of memory; nothing was written\n", stderr);
            return -1;
        }
        if (next != *base) {
            free(*base);
            *base = next;
        }
    }
    st->base = *base;
    return 0;
}

/* the scene, the grid and every point checked; 0, or the exit status */
static int prepare(const sweep_args *a, zp_sweep *s, study *st, char **base) {
    size_t len;
    zp_diag d;
    zp_diag_init(&d);
    /* the reader every command uses: capped, and a NUL byte refused with its line (the
       points' scenes are made from this text as a string) */
    *base = zp_scene_load_read_file(a->scene, &len, &d);
    st->base = *base;
    st->path = a->scene;
    zp_model *m = NULL;
    int read = *base && zp_scene_load_text(*base, len, a->scene, 1, st->sc, &d) == ZP_OK;
    if (read && (a->force || a->schedule || a->max_evals)) {
        zp_diag_print(&d, stderr);
        zp_diag_init(&d);
        if (overlay(a, st, base)) {
            return ZP_EXIT_USAGE;
        }
        read = zp_scene_load_text(*base, strlen(*base), a->scene, 1, st->sc, &d) == ZP_OK;
    }
    if (read) {
        m = zp_model_build(st->sc, &d);
    }
    zp_diag_print(&d, stderr);
    zp_model_free(m);
    if (!m) {
        zp_cli_error("sweep", "%s is not a valid scene; nothing was written", a->scene);
        return ZP_EXIT_USAGE;
    }
    snprintf(st->name, sizeof st->name, "%s", st->sc->name);
    st->np = zp_drive_of_scene(st->sc).np;
    int kind = zp_study_kind_find(a->run);
    if (kind < 0) {
        zp_cli_error("sweep", "--run '%s': expected search or simulate", a->run);
        return ZP_EXIT_USAGE;
    }
    s->kind = (zp_study_kind)kind;
    st->max_time = a->max_time;
    st->grid = a->grid >= 0 ? a->grid : s->kind == ZP_STUDY_SEARCH;
    for (int i = 0; i < a->nvary; i++) {
        char why[1200];
        zp_sweep_vary v;
        if (i < MAX_ARGS_VARY && !zp_sweep_vary_parse(a->vary[i], &v, why, sizeof why) &&
            (a->force || a->schedule) && !strcmp(v.section, "drive") && !strcmp(v.key, "forces")) {
            snprintf(why, sizeof why, "varies the forces --force or --schedule fixes; give one");
            fprintf(stderr, "zipopt sweep: --vary %s: %s; nothing was written\n", a->vary[i], why);
            return ZP_EXIT_USAGE;
        }
        if (i >= MAX_ARGS_VARY || zp_sweep_vary_parse(a->vary[i], &v, why, sizeof why) ||
            zp_sweep_add(s, &v, why, sizeof why)) {
            zp_cli_error("sweep", "--vary %s: %s; nothing was written",
                         i < MAX_ARGS_VARY ? a->vary[i] : "", i < MAX_ARGS_VARY ? why : "too many");
            return ZP_EXIT_USAGE;
        }
    }
    zp_sweep_note_base(s, *base);
    st->s = s;
    return check_points(st) ? ZP_EXIT_USAGE : 0;
}

/* rank 0: the checkpoint (resumed or fresh) and the points left to do; 0 or the exit status */
static int open_study(study *st, const sweep_args *a, zp_tx *t, int **todo, int *ntodo) {
    int n = st->s->npoint;
    st->rows = calloc((size_t)n, sizeof *st->rows);
    st->done = calloc((size_t)n, 1);
    st->grid_res = calloc(1, sizeof *st->grid_res);
    *todo = malloc(sizeof **todo * (size_t)(n + 1));
    if (!st->rows || !st->done || !st->grid_res || !*todo) {
        fputs("zipopt sweep: out of memory; nothing was written\n", stderr);
        return ZP_EXIT_FAIL;
    }
    char err[1300];
    if (zp_cli_out_begin(t, "sweep", "sweep", a->out, st->sc)) {
        return ZP_EXIT_FAIL;
    }
    zp_status rc = zp_sweep_csv_checkpoint_open(&st->cp, t->dirfd, t->dir, st->s, st->base, st->np,
                                            a->resume, st->rows, st->done, &st->ndone,
                                            st->grid_res, &st->grid_done, err, sizeof err);
    if (rc) {
        zp_cli_error("sweep", "%s; nothing was written", err);
        return rc == ZP_ERR_INPUT ? ZP_EXIT_USAGE : ZP_EXIT_FAIL;
    }
    st->nresumed = st->ndone;
    st->grid_resumed = st->grid_done;
    const char *fault = getenv("ZIPOPT_SWEEP_FAULT_AFTER"), *how = getenv("ZIPOPT_SWEEP_FAULT");
    st->fault_after = fault ? atoi(fault) : 0;
    st->fault_hang = how && !strcmp(how, "hang");
    *ntodo = 0;
    if (st->grid && !st->grid_done) {
        (*todo)[(*ntodo)++] = n; /* the costliest item first: it overlaps the points */
    }
    for (int p = 0; p < n; p++) {
        if (!st->done[p]) {
            (*todo)[(*ntodo)++] = p;
        }
    }
    return 0;
}

static int sweep(int argc, char **argv, int rank) {
    sweep_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    zp_sweep s = {0};
    study st = {.tty = rank == 0 && isatty(STDERR_FILENO), .cp = {.dirfd = -1}};
    st.lines = rank == 0 && !st.tty && zp_mpi_queue_size() > 1;
    clock_gettime(CLOCK_MONOTONIC, &st.start);
    char *base = NULL;
    int *todo = NULL, ntodo = 0;
    st.sc = malloc(sizeof *st.sc);
    int status = st.sc ? prepare(&a, &s, &st, &base) : ZP_EXIT_FAIL;
    if (status) {
        goto done; /* every rank saw the same input and stops here alike */
    }
    /* rank 0 alone keeps the rows and writes (its transaction: the output folder, the
       checkpoint in it); when it cannot start, the others are sent home at once */
    zp_tx t = {.dirfd = -1, .tmpfd = -1};
    status = rank == 0 ? open_study(&st, &a, &t, &todo, &ntodo) : 0;
    char err[256];
    if (zp_mpi_queue_run(todo, status ? 0 : ntodo, sizeof(item_result), work, done, &st, err,
                         sizeof err)) {
        zp_cli_error("sweep", "%s", err);
        status = ZP_EXIT_FAIL;
    }
    if (st.tty && ntodo) {
        fputc('\n', stderr);
    }
    if (rank == 0 && !status) {
        status = finish(&st, &a, &t, zp_mpi_queue_size());
    }
    zp_sweep_csv_checkpoint_close(&st.cp, 0);
    zp_tx_abort(&t); /* ended already when committed; the checkpoint is not the transaction's */
done:
    free(base);
    free(todo);
    free(st.rows);
    free(st.done);
    free(st.grid_res);
    free(st.sc);
    return status;
}

/* every rank runs the study; rank 0 speaks for it and writes */
static int sweep_on_rank(int argc, char **argv, const zp_spread *sp) {
    return sweep(argc, argv, sp->rank);
}

int zp_cmd_sweep(int argc, char **argv) {
    return zp_mpi_spread_main("sweep", sweep_on_rank, argc, argv);
}
