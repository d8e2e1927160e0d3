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
#include "fig_landscape.h"
#include "landscape.h"
#include "mpi_spread.h"
#include "out_json.h"
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

static double at(const range *r, int k) {
    return r->a + (r->b - r->a) * k / (r->n - 1);
}

/* the progress line on stderr, when it is a terminal */
typedef struct progress {
    struct timespec start, last;
    int ranks; /* > 1: the count is rank 0's share */
} progress;

static double since(const struct timespec *a) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - a->tv_sec) + 1e-9 * (double)(now.tv_nsec - a->tv_nsec);
}

static void show(void *user, int done, int total) {
    progress *p = user;
    if (since(&p->last) > 0.2 || done == total) {
        clock_gettime(CLOCK_MONOTONIC, &p->last);
        fprintf(stderr, "\rzipopt landscape: %d/%d runs%s, %.1f s", done, total,
                p->ranks > 1 ? " (rank 0's share)" : "", since(&p->start));
        if (done == total) {
            fputc('\n', stderr);
        }
    }
}

static const char *outcome_name(const zp_landscape_point *p) {
    return p->failed ? "failed" : zp_sim_outcome_name(p->outcome);
}

/* what keeps p from being survivable: "" when it finished with the margin (limit, rad) and
   every [limits] value kept; else its outcome, "margin", or the limit it exceeds most */
static const char *binding(const zp_landscape_point *p, double limit, const zp_limits *lim) {
    if (p->failed || p->outcome != ZP_OUTCOME_FINISHED) {
        return outcome_name(p);
    }
    if (p->max_rel_angle > limit) {
        return "margin";
    }
    int worst;
    double excess = zp_limits_excess_of(lim, p->reached, &worst);
    return worst >= 0 && excess > 0 ? zp_limit_name(worst) : "";
}

/* the result columns' header: the outcome, then what the run reached of each limit set */
static void write_header(FILE *f, const zp_limits *lim) {
    fputs("outcome,stall_reason,time,x,died_link,max_rel_angle_deg,kept,binding", f);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (lim->max[i] > 0) {
            fprintf(f, ",%s_reached_", zp_limit_name(i));
            for (const char *u = zp_limit_unit(i); *u; u++) { /* km/h -> km_h: a plain name */
                fputc(*u == '/' || *u == ' ' ? '_' : *u, f);
            }
        }
    }
    fputc('\n', f);
}

/* one CSV row's result columns */
static void write_point(FILE *f, const zp_landscape_point *p, double limit, const zp_limits *lim) {
    const char *why = binding(p, limit, lim);
    fprintf(f, ",%s,%s,%.9g,%.9g,%d,%.6g,%d,%s", outcome_name(p),
            p->failed || p->outcome != ZP_OUTCOME_STALLED ? "" : zp_sim_stall_name(p->stall),
            p->time, p->x, p->died_link, p->max_rel_angle * 180 / M_PI, !*why, why);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (lim->max[i] > 0) {
            fprintf(f, ",%.9g", p->failed ? NAN : p->reached[i]);
        }
    }
    fputc('\n', f);
}
/* one window, points i..j: listed as the points it is, since pushes between two sampled
   points were never run */
static void print_window(const range *r, int i, int j, int first) {
    printf("%s %g", first ? "" : ";", at(r, i));
    if (j == i + 1) {
        printf(", %g", at(r, j));
    } else if (j > i + 1) {
        printf(", %g, .., %g", at(r, i + 1), at(r, j));
    }
    printf(" N");
    if (j > i + 1) {
        printf(" (%d points)", j - i + 1);
    }
}

static int finishes(const zp_landscape_point *p) {
    return !p->failed && p->outcome == ZP_OUTCOME_FINISHED;
}

/* the survival windows are runs of consecutive finishing pushes: where one starts, ends */
static int window_starts(const zp_landscape_point *p, int k) {
    return finishes(&p[k]) && (k == 0 || !finishes(&p[k - 1]));
}

static int window_ends(const range *r, const zp_landscape_point *p, int k) {
    return finishes(&p[k]) && (k == r->n - 1 || !finishes(&p[k + 1]));
}

/* the fastest push that finishes (survivable: that also keeps the margin, limit in rad, and
   every [limits] value), or -1 */
static int fastest(const range *r, const zp_landscape_point *p, int survivable, double limit,
                   const zp_limits *lim) {
    int best = -1;
    for (int k = 0; k < r->n; k++) {
        if (finishes(&p[k]) && (!survivable || !*binding(&p[k], limit, lim)) &&
            (best < 0 || p[k].time < p[best].time)) {
            best = k;
        }
    }
    return best;
}

/* the survival windows of the constant push on stdout: runs of consecutive sampled pushes
   that finish, each listed as the points it is */
static void print_windows(const range *r, const zp_landscape_point *p, double limit,
                          const zp_limits *lim) {
    int nwin = 0, start = 0, best = fastest(r, p, 1, limit, lim), quick = fastest(r, p, 0, 0, lim);
    printf("constant push from %g to %g N (%d runs, every %g N): finishes at", r->a, r->b, r->n,
           (r->b - r->a) / (r->n - 1));
    for (int k = 0; k < r->n; k++) {
        start = window_starts(p, k) ? k : start;
        if (window_ends(r, p, k)) {
            print_window(r, start, k, !nwin++);
        }
    }
    printf("%s\n", quick < 0 ? " no push in the range" : "");
    if (best < 0) {
        printf("fastest: no push in the range keeps the margin%s\n",
               zp_limits_any(lim) ? " and every [limits] value" : "");
    } else {
        printf("fastest: %g N, finished in %.3f s, keeping the margin%s\n", at(r, best),
               p[best].time, zp_limits_any(lim) ? " and every [limits] value" : "");
    }
    if (quick >= 0 && quick != best) {
        printf("fastest finishing push: %g N, %.3f s, breaks %s\n", at(r, quick), p[quick].time,
               binding(&p[quick], limit, lim));
    }
}

/* --json: the run as one object on stdout (README "landscape --json") */
static void print_json(const zp_scene *sc, const zp_schedule *sh, const range *r,
                       const zp_landscape_point *p, int si, int sj, int n2, double wall,
                       const char *dir, int figures, double limit, const zp_limits *lim) {
    printf("{\"scene\": ");
    zp_out_json_string(stdout, sc->name);
    printf(", \"force_from\": %.17g, \"force_to\": %.17g, \"points\": %d, \"windows\": [", r->a,
           r->b, r->n);
    for (int k = 0, nwin = 0; k < r->n; k++) {
        if (window_starts(p, k)) {
            printf("%s[%.17g, ", nwin++ ? ", " : "", at(r, k));
        }
        if (window_ends(r, p, k)) {
            printf("%.17g]", at(r, k));
        }
    }
    int best = fastest(r, p, 1, limit, lim), quick = fastest(r, p, 0, 0, lim);
    if (best < 0) {
        printf("], \"fastest\": null");
    } else {
        printf("], \"fastest\": {\"force\": %.17g, \"time\": ", at(r, best));
        zp_out_json_number(stdout, p[best].time);
        printf("}");
    }
    if (quick < 0) {
        printf(", \"fastest_finish\": null");
    } else {
        printf(", \"fastest_finish\": {\"force\": %.17g, \"time\": ", at(r, quick));
        zp_out_json_number(stdout, p[quick].time);
        printf(", \"breaks\": ");
        zp_out_json_string(stdout, binding(&p[quick], limit, lim));
        printf("}");
    }
    if (n2) {
        printf(", \"slice\": {\"%s\": [%d, %d], \"points\": %d}", zp_drive_param_noun(sh, 1),
               si + 1, sj + 1, n2);
    } else {
        printf(", \"slice\": null");
    }
    printf(", \"runs\": %d, \"wall_s\": %.6g, \"out_dir\": ", r->n + n2, wall);
    zp_out_json_string(stdout, dir);
    printf(", \"figures\": %s}\n", figures ? "true" : "false");
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
    const zp_model *m = st.m;
    const zp_scene *sc = &st.sc;
    const zp_schedule *sh = &st.sched;
    const double *base = sh->p; /* the base schedule's parameters */
    int np = sh->np, status = ZP_EXIT_USAGE;
    double *force = NULL;
    zp_landscape_point *pt = NULL;
    /* every option checked before any run */
    double lo, hi;
    zp_drive_constant_bounds(sh, &lo, &hi);
    range r1 = {lo, hi, 201};
    if (a.range1_text && parse_range(a.range1_text, &r1, MAX_1D) != (int)strlen(a.range1_text)) {
        zp_cli_error("landscape",
                     "--force-range: '%s' is not A:B:N; expected forces A < B (N, within "
                     "+/-%g) and 2 to %d points",
                     a.range1_text, FORCE_DRAWN_MAX, MAX_1D);
        goto done;
    }
    int si = -1, sj = -1;
    range rx = {lo, hi, 41}, ry = rx;
    if (a.slice_text) {
        int used = 0;
        if (sscanf(a.slice_text, "%d,%d%n", &si, &sj, &used) != 2 || a.slice_text[used] || si < 1 ||
            sj < 1 || si > np || sj > np || si == sj) {
            zp_cli_error("landscape",
                         "--slice: '%s' is not I,J; expected two different %s from 1 to %d",
                         a.slice_text, zp_drive_param_noun(sh, 1), np);
            goto done;
        }
        si--;
        sj--;
        rx = (range){sh->lo[si], sh->hi[si], 41};
        ry = (range){sh->lo[sj], sh->hi[sj], 41};
    }
    if (a.range2_text) {
        const char *t = a.range2_text;
        int used = parse_range(t, &rx, MAX_2D);
        ry = rx;
        if (used > 0 && t[used] == ',') {
            int more = parse_range(t + used + 1, &ry, MAX_2D);
            used = more < 0 ? -1 : used + 1 + more;
        }
        if (used != (int)strlen(t)) {
            zp_cli_error("landscape",
                         "--range: '%s' is not A:B:N or A:B:N,C:D:M; expected forces A < B (N, "
                         "within +/-%g) and 2 to %d points per axis",
                         t, FORCE_DRAWN_MAX, MAX_2D);
            goto done;
        }
    }
    /* the scene's [drive] min:max, where no option replaced them */
    if (!drawable(&r1) || !drawable(&rx) || !drawable(&ry)) {
        zp_cli_error("landscape",
                     "%s: [drive] min, max: forces beyond +/-%g N cannot be drawn; give "
                     "--force-range (and --range with --slice) within it",
                     sc->path, FORCE_DRAWN_MAX);
        goto done;
    }
    zp_sim_opts o = st.sim;
    o.output_dt = 0; /* outcomes only */
    zp_limits lim;
    zp_limits_from_scene(sc, &lim);
    o.peaks = zp_limits_need_peaks(&lim);

    /* the schedules: the constant pushes, then the slice */
    status = ZP_EXIT_FAIL;
    int n1 = r1.n, n2 = si >= 0 ? rx.n * ry.n : 0;
    force = malloc(sizeof *force * (size_t)(n1 + n2) * (size_t)np);
    pt = malloc(sizeof *pt * (size_t)(n1 + n2));
    if (!force || !pt) {
        fputs("zipopt landscape: out of memory; nothing was written\n", stderr);
        goto done;
    }
    for (int k = 0; k < n1; k++) {
        zp_schedule push = zp_drive_constant(sh, at(&r1, k));
        memcpy(force + (size_t)k * np, push.p, sizeof *force * (size_t)np);
    }
    for (int k = 0; k < n2; k++) {
        double *f = force + (size_t)(n1 + k) * np;
        memcpy(f, base, sizeof *f * (size_t)np);
        f[si] = at(&rx, k % rx.n);
        f[sj] = at(&ry, k / rx.n);
    }
    progress pr = {.ranks = sp->size};
    clock_gettime(CLOCK_MONOTONIC, &pr.start);
    pr.last = pr.start;
    zp_status rc = zp_landscape_sweep(m, &o, sh, force, n1 + n2, pt,
                                      isatty(STDERR_FILENO) ? show : NULL, &pr, sp);
    if (rc) {
        fprintf(stderr, "zipopt landscape: %s; nothing was written\n",
                rc == ZP_ERR_IO ? "the MPI ranks could not exchange their runs"
                                : "cannot create the simulators (out of memory)");
        goto done;
    }
    double wall = since(&pr.start);
    if (sp->rank != 0) { /* rank 0 holds every run too, and speaks for the job */
        status = ZP_EXIT_OK;
        goto done;
    }

    /* the files, all or nothing */
    char err[1400];
    zp_tx t;
    if (zp_cli_out_begin(&t, "landscape", "landscape", a.out, sc)) {
        goto done;
    }
    FILE *csv = zp_tx_open(&t, "landscape.csv", err, sizeof err);
    FILE *gp = csv ? zp_tx_open(&t, "landscape.gp", err, sizeof err) : NULL;
    FILE *csv2 = gp && n2 ? zp_tx_open(&t, "landscape_slice.csv", err, sizeof err) : gp;
    FILE *gp2 = csv2 && n2 ? zp_tx_open(&t, "landscape_slice.gp", err, sizeof err) : csv2;
    if (!gp2) {
        zp_tx_abort(&t);
        fprintf(stderr, "zipopt landscape: %s; nothing was written\n", err);
        goto done;
    }
    fputs("force,", csv);
    write_header(csv, &lim);
    for (int k = 0; k < n1; k++) {
        fprintf(csv, "%.9g", at(&r1, k));
        write_point(csv, &pt[k], st.limit, &lim);
    }
    zp_fig_landscape_1d(gp, sc->name, &r1);
    if (n2) {
        fprintf(csv2, "f%d,f%d,", si + 1, sj + 1);
        write_header(csv2, &lim);
        for (int k = 0; k < n2; k++) {
            const double *f = force + (size_t)(n1 + k) * np;
            fprintf(csv2, "%.9g,%.9g", f[si], f[sj]);
            write_point(csv2, &pt[n1 + k], st.limit, &lim);
        }
        zp_fig_landscape_2d(gp2, sc->name, sh, si, sj, &rx, &ry,
                            a.schedule     ? a.schedule
                            : a.force_text ? "--force"
                                           : "[drive] forces");
    }
    const char *scripts[] = {"landscape.gp", "landscape_slice.gp"};
    int missing;
    if (zp_cli_out_draw_commit(&t, "landscape", scripts, n2 ? 2 : 1, &missing)) {
        goto done;
    }
    if (a.json) {
        print_json(sc, sh, &r1, pt, si, sj, n2, wall, t.dir, !missing, st.limit, &lim);
    } else {
        print_windows(&r1, pt, st.limit, &lim);
        printf("%d runs in %.2f s", n1 + n2, wall);
        if (sp->size > 1) {
            printf(" on %d ranks", sp->size);
        }
        printf("; wrote in %s: %s\n", t.dir, t.written);
    }
    FILE *say = a.json ? stderr : stdout; /* stdout carries only the JSON object */
    if (missing) {
        fprintf(stderr,
                "zipopt landscape: gnuplot is not installed (apt-get install gnuplot-nox): "
                "no images were drawn; the data and the .gp scripts are in %s, run "
                "`gnuplot landscape.gp` there once it is\n",
                t.dir);
        goto done;
    }
    fprintf(say, "figures: landscape.png%s\n", n2 ? ", landscape_slice.png" : "");
    if (n2 && (base[si] < rx.a || base[si] > rx.b || base[sj] < ry.a || base[sj] > ry.b)) {
        fprintf(say,
                "note: the base schedule (F%d = %g, F%d = %g %s) lies outside the slice and is "
                "not marked\n",
                si + 1, base[si], sj + 1, base[sj], zp_drive_unit(sh));
    }
    status = ZP_EXIT_OK;
done:
    free(force);
    free(pt);
    zp_setup_free(&st);
    return status;
}

int zp_cmd_landscape(int argc, char **argv) {
    return zp_mpi_spread_main("landscape", landscape, argc, argv);
}
