/* `zipopt landscape`: the survival landscape: finish time or death over a
   constant push, and over a 2D slice of two parameters (sections' forces) through a base
   schedule. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "mpi_spread.h"
#include "report_landscape.h"
#include "setup.h"

#define MAX_1D 100001 /* points of the constant-push sweep */
#define MAX_2D 1001   /* points per axis of the slice */

static void usage(FILE *f) {
    fputs(
        "usage: zipopt landscape SCENE.ini [--force-range A:B:N] [--slice I,J]\n"
        "                        [--range A:B:N[,C:D:M]] [--force F1,..|--schedule FILE]\n"
        "                        [--out DIR] [--json]\n"
        "\n"
        "Runs many schedules in parallel (OpenMP; OMP_NUM_THREADS sets the threads) and\n"
        "draws the outcome over the forces:\n"
        "  landscape.csv, landscape.png   one constant push in every section, N points from\n"
        "                                 A to B N (--force-range; default [drive] min:max:201):\n"
        "                                 finish time, time of death, the survival windows\n"
        "  landscape_slice.csv, .png      with --slice I,J: the forces of sections I and J\n"
        "                                 (1-based) over --range (default min:max:41 for\n"
        "                                 both; A:B:N,C:D:M for each), the other sections at\n"
        "                                 the base schedule, which is marked\n"
        "  --force F1,..       the base schedule (default: the scene's [drive] forces)\n"
        "  --schedule FILE     the base schedule from a schedule file, e.g. the search's\n"
        "                      schedule.ini: the slice then passes through the best schedule\n"
        "  --out DIR           the output folder (default out/<scene name>/landscape/)\n"
        "  --json              print the result as one JSON object (keys: docs/commands.md)\n"
        "Each image comes with its gnuplot script (.gp); the CSV files are its data. Prints\n"
        "the survival windows of the constant push on stdout.\n"
        "\n"
        "Under `mpirun -np N zipopt landscape ..` the runs are dealt out over the N ranks\n"
        "(each on its OpenMP threads; e.g. -x OMP_NUM_THREADS=1 for one core per rank);\n"
        "rank 0 alone prints and writes, and the files are bit for bit those without mpirun.\n",
        f);
}

typedef zp_fig_axis range;

typedef struct land_args {
    const char *scene, *schedule, *out, *force_text, *range1_text, *slice_text, *range2_text;
    int json;
} land_args;

enum { O_FORCE_RANGE = ZP_OPT_FIRST, O_SLICE, O_RANGE, O_FORCE, O_SCHEDULE, O_OUT, O_JSON };
static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"force-range", required_argument, NULL, O_FORCE_RANGE},
    {"slice", required_argument, NULL, O_SLICE},
    {"range", required_argument, NULL, O_RANGE},
    {"force", required_argument, NULL, O_FORCE},
    {"schedule", required_argument, NULL, O_SCHEDULE},
    {"out", required_argument, NULL, O_OUT},
    {"json", no_argument, NULL, O_JSON},
    {NULL, 0, NULL, 0},
};

/* 1: --help was shown; -1: a mistake (reported) */
static int parse_args(int argc, char **argv, land_args *a) {
    memset(a, 0, sizeof *a);
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("landscape", argc, argv, options)) != -1;) {
        switch (c) {
        case 'h':
            usage(stdout);
            return 1;
        case O_FORCE_RANGE:
            a->range1_text = optarg;
            break;
        case O_SLICE:
            a->slice_text = optarg;
            break;
        case O_RANGE:
            a->range2_text = optarg;
            break;
        case O_FORCE:
            a->force_text = optarg;
            break;
        case O_SCHEDULE:
            a->schedule = optarg;
            break;
        case O_OUT:
            a->out = optarg;
            break;
        case O_JSON:
            a->json = 1;
            break;
        default:
            return -1;
        }
    }
    if (zp_cli_scene_operand("landscape", argc, argv, &a->scene) ||
        (a->out && zp_cli_path_ok("landscape", "--out", a->out)) ||
        (a->schedule && zp_cli_path_ok("landscape", "--schedule", a->schedule))) {
        return -1;
    }
    if (!a->scene) {
        zp_cli_error("landscape", "a scene file is required; see zipopt landscape --help");
        return -1;
    }
    if (a->range2_text && !a->slice_text) {
        zp_cli_error("landscape", "--range: needs --slice I,J; see zipopt landscape --help");
        return -1;
    }
    return 0;
}

/* N: the largest |force| drawn. gnuplot pads and ticks its axes in doubles and fails (inf)
   long before 1e308; no push on a zip line comes near this. */
#define FORCE_DRAWN_MAX 1e12

static int drawable(const range *r) {
    return fabs(r->a) <= FORCE_DRAWN_MAX && fabs(r->b) <= FORCE_DRAWN_MAX;
}

/* "A:B:N" at text; returns the characters read, or -1 */
static int parse_range(const char *text, range *r, int max) {
    int used = 0;
    if (sscanf(text, "%lf:%lf:%d%n", &r->a, &r->b, &r->n, &used) != 3 || !isfinite(r->a) ||
        !isfinite(r->b) || !(r->a < r->b) || !drawable(r) || r->n < 2 || r->n > max) {
        return -1;
    }
    return used;
}

/* the progress line on stderr, when it is a terminal */
typedef struct progress {
    struct timespec start, last;
    int ranks; /* > 1: the count is rank 0's share */
} progress;

static void show(void *user, int done, int total) {
    progress *p = user;
    if (zp_cli_since(&p->last) > 0.2 || done == total) {
        clock_gettime(CLOCK_MONOTONIC, &p->last);
        fprintf(stderr, "\rzipopt landscape: %d/%d runs%s, %.1f s", done, total,
                p->ranks > 1 ? " (rank 0's share)" : "", zp_cli_since(&p->start));
        if (done == total) {
            fputc('\n', stderr);
        }
    }
}

/* the options' ranges into plan, checked against the base schedule sh; 0, or -1 (said) */
static int plan_of(const land_args *a, const zp_scene *sc, const zp_schedule *sh,
                   zp_landscape_plan *plan) {
    double lo, hi;
    zp_drive_constant_bounds(sh, &lo, &hi);
    *plan = (zp_landscape_plan){.push = {lo, hi, 201}, .si = -1, .sj = -1};
    range *r1 = &plan->push, *rx = &plan->rx, *ry = &plan->ry;
    if (a->range1_text && parse_range(a->range1_text, r1, MAX_1D) != (int)strlen(a->range1_text)) {
        zp_cli_error("landscape",
                     "--force-range: '%s' is not A:B:N; expected forces A < B (N, within "
                     "+/-%g) and 2 to %d points",
                     a->range1_text, FORCE_DRAWN_MAX, MAX_1D);
        return -1;
    }
    *rx = *ry = (range){lo, hi, 41};
    if (a->slice_text) {
        int used = 0, si, sj, np = sh->np;
        if (sscanf(a->slice_text, "%d,%d%n", &si, &sj, &used) != 2 || a->slice_text[used] ||
            si < 1 || sj < 1 || si > np || sj > np || si == sj) {
            zp_cli_error("landscape",
                         "--slice: '%s' is not I,J; expected two different %s from 1 to %d",
                         a->slice_text, zp_drive_param_noun(sh, 1), np);
            return -1;
        }
        plan->si = --si;
        plan->sj = --sj;
        *rx = (range){sh->lo[si], sh->hi[si], 41};
        *ry = (range){sh->lo[sj], sh->hi[sj], 41};
    }
    if (a->range2_text) {
        const char *t = a->range2_text;
        int used = parse_range(t, rx, MAX_2D);
        *ry = *rx;
        if (used > 0 && t[used] == ',') {
            int more = parse_range(t + used + 1, ry, MAX_2D);
            used = more < 0 ? -1 : used + 1 + more;
        }
        if (used != (int)strlen(t)) {
            zp_cli_error("landscape",
                         "--range: '%s' is not A:B:N or A:B:N,C:D:M; expected forces A < B (N, "
                         "within +/-%g) and 2 to %d points per axis",
                         t, FORCE_DRAWN_MAX, MAX_2D);
            return -1;
        }
    }
    /* the scene's [drive] min:max, where no option replaced them */
    if (!drawable(r1) || !drawable(rx) || !drawable(ry)) {
        zp_cli_error("landscape",
                     "%s: [drive] min, max: forces beyond +/-%g N cannot be drawn; give "
                     "--force-range (and --range with --slice) within it",
                     sc->path, FORCE_DRAWN_MAX);
        return -1;
    }
    return 0;
}

/* rank 0: the files committed, then the windows or the JSON object; the exit status */
static int write_landscape(const land_args *a, const zp_report_landscape *L, double wall,
                           int ranks, const zp_scene *sc) {
    char err[1400];
    zp_tx t;
    if (zp_cli_out_begin(&t, "landscape", "landscape", a->out, sc)) {
        return ZP_EXIT_FAIL;
    }
    if (zp_report_landscape_files(&t, L, err, sizeof err)) {
        zp_tx_abort(&t);
        fprintf(stderr, "zipopt landscape: %s; nothing was written\n", err);
        return ZP_EXIT_FAIL;
    }
    const zp_landscape_plan *p = L->plan;
    int n1 = p->push.n, n2 = zp_landscape_slice_runs(p), missing;
    const char *scripts[] = {"landscape.gp", "landscape_slice.gp"};
    if (zp_cli_out_draw_commit(&t, "landscape", scripts, n2 ? 2 : 1, &missing)) {
        return ZP_EXIT_FAIL;
    }
    if (a->json) {
        zp_report_landscape_json(stdout, L, wall, t.dir, !missing);
    } else {
        zp_report_landscape_windows(stdout, L);
        printf("%d runs in %.2f s", n1 + n2, wall);
        if (ranks > 1) {
            printf(" on %d ranks", ranks);
        }
        printf("; wrote in %s: %s\n", t.dir, t.written);
    }
    FILE *say = a->json ? stderr : stdout; /* stdout carries only the JSON object */
    if (missing) {
        fprintf(stderr,
                "zipopt landscape: gnuplot is not installed (apt-get install gnuplot-nox): "
                "no images were drawn; the data and the .gp scripts are in %s, run "
                "`gnuplot landscape.gp` there once it is\n",
                t.dir);
        return ZP_EXIT_FAIL;
    }
    fprintf(say, "figures: landscape.png%s\n", n2 ? ", landscape_slice.png" : "");
    const double *base = L->base->p;
    int si = p->si, sj = p->sj;
    if (n2 && (base[si] < p->rx.a || base[si] > p->rx.b || base[sj] < p->ry.a ||
               base[sj] > p->ry.b)) {
        fprintf(say,
                "note: the base schedule (F%d = %g, F%d = %g %s) lies outside the slice and is "
                "not marked\n",
                si + 1, base[si], sj + 1, base[sj], zp_drive_unit(L->base));
    }
    return ZP_EXIT_OK;
}

/* the command on every rank of sp: each runs its share, rank 0 alone writes and prints */
static int landscape(int argc, char **argv, const zp_spread *sp) {
    land_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    static zp_problem st; /* large: kept off the stack */
    zp_overrides ov = {.schedule = a.schedule, .force = a.force_text};
    if (zp_setup_load("landscape", a.scene, &ov, &st)) {
        return ZP_EXIT_USAGE;
    }
    const zp_schedule *sh = &st.sched;
    zp_landscape_plan plan;
    int status = ZP_EXIT_USAGE;
    double *param = NULL;
    zp_landscape_point *pt = NULL;
    if (plan_of(&a, &st.sc, sh, &plan)) { /* every option checked before any run */
        goto done;
    }
    zp_sim_opts o = st.sim;
    o.output_dt = 0; /* outcomes only */
    zp_limits lim;
    zp_limits_from_scene(&st.sc, &lim);
    o.peaks = zp_limits_need_peaks(&lim);
    status = ZP_EXIT_FAIL;
    int n = plan.push.n + zp_landscape_slice_runs(&plan);
    param = zp_landscape_params(&plan, sh);
    pt = malloc(sizeof *pt * (size_t)n);
    if (!param || !pt) {
        fputs("zipopt landscape: out of memory; nothing was written\n", stderr);
        goto done;
    }
    progress pr = {.ranks = sp->size};
    clock_gettime(CLOCK_MONOTONIC, &pr.start);
    pr.last = pr.start;
    zp_status rc = zp_landscape_sweep(st.m, &o, sh, param, n, pt,
                                      isatty(STDERR_FILENO) ? show : NULL, &pr, sp);
    if (rc) {
        fprintf(stderr, "zipopt landscape: %s; nothing was written\n",
                rc == ZP_ERR_IO ? "the MPI ranks could not exchange their runs"
                                : "cannot create the simulators (out of memory)");
        goto done;
    }
    double wall = zp_cli_since(&pr.start);
    zp_report_landscape L = {st.sc.name, sh,
                             a.schedule     ? a.schedule
                             : a.force_text ? "--force"
                                            : "[drive] forces",
                             &plan, param, pt, st.limit, &lim};
    /* rank 0 holds every run too, and speaks for the job */
    status = sp->rank != 0 ? ZP_EXIT_OK : write_landscape(&a, &L, wall, sp->size, &st.sc);
done:
    free(param);
    free(pt);
    zp_setup_free(&st);
    return status;
}

int zp_cmd_landscape(int argc, char **argv) {
    return zp_mpi_spread_main("landscape", landscape, argc, argv);
}
