/* `zipopt simulate`: one schedule through the simulator; results to stdout, files to the
   output folder (docs/commands.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "out_csv.h"
#include "tx.h"
#include "out_json.h"
#include "out_text.h"
#include "plot.h"
#include "setup.h"
#include "sim.h"

#define MAX_SAMPLES 10000
#define MAX_ANIM_FRAMES 20000 /* run.gif: 13 min at 25 fps */

static void usage(FILE *f) {
    fputs("usage: zipopt simulate SCENE.ini [--force F1,F2,..] [--schedule FILE] [--json]\n"
          "                       [--sample-times T1,T2,..] [--gradient] [--out DIR]\n"
          "                       [--plot] [--frames-at x=X1,.. | t=T1,..] [--animate]\n"
          "                       [--fps N] [--size WxH] [--speedup S]\n"
          "\n"
          "Runs one schedule of drive forces (one per course section, N) through the\n"
          "simulator and reports the outcome: finished (finish time), died (time, x, link)\n"
          "or stalled (why).\n"
          "  --force F1,..       the schedule, overriding [drive] forces\n"
          "  --schedule FILE     a schedule file ([drive] forces) laid over the scene\n"
          "  --json              print the result as one JSON object (keys: docs/commands.md)\n"
          "  --sample-times T,.. also report the state at these times (s)\n"
          "  --gradient          also the derivatives of the time and the margin angle with\n"
          "                      respect to each schedule parameter (exact: sensitivities)\n"
          "  --out DIR           write trajectory.csv and summary.json in DIR itself\n"
          "                      (default out/<scene name>/simulate/)\n"
          "  --plot              also draw the run with gnuplot into the same folder:\n"
          "                      course.png (course, sections, kinks, every centre-of-mass\n"
          "                      path), energy.png, angles.png (death angle and search\n"
          "                      margin), loads.png, along.png (angles, felt g and loads\n"
          "                      against distance), drive.png (the applied force against\n"
          "                      distance and speed); each with its .gp script and data\n"
          "  --frames-at x=X,..|t=T,..\n"
          "                      still frames of the body: frame_x<X>.png where the trolley\n"
          "                      first reaches x = X (m), or frame_t<T>.png at time T (s)\n"
          "  --animate           run.gif (and run.mp4 when ffmpeg is installed)\n"
          "  --fps N             animation frames per second, 1..100 (default 25)\n"
          "  --size WxH          animation size in px (default 960 wide, height to fit)\n"
          "  --speedup S         simulated seconds per second of animation (default 1)\n"
          "\n"
          "--frames-at and --animate imply --plot.\n",
          f);
}

typedef struct sim_args {
    const char *scene, *schedule, *out;
    const char *force_text, *sample_text;
    int json, gradient;
    int plot, animate; /* --frames-at and --animate imply --plot */
    const char *frames_text, *fps_text, *size_text, *speedup_text;
} sim_args;

enum {
    O_JSON = ZP_OPT_FIRST,
    O_FORCE,
    O_SCHEDULE,
    O_SAMPLES,
    O_OUT,
    O_PLOT,
    O_ANIMATE,
    O_FRAMES,
    O_FPS,
    O_SIZE,
    O_SPEEDUP,
    O_GRADIENT
};
static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"json", no_argument, NULL, O_JSON},
    {"force", required_argument, NULL, O_FORCE},
    {"schedule", required_argument, NULL, O_SCHEDULE},
    {"sample-times", required_argument, NULL, O_SAMPLES},
    {"out", required_argument, NULL, O_OUT},
    {"plot", no_argument, NULL, O_PLOT},
    {"animate", no_argument, NULL, O_ANIMATE},
    {"frames-at", required_argument, NULL, O_FRAMES},
    {"fps", required_argument, NULL, O_FPS},
    {"size", required_argument, NULL, O_SIZE},
    {"speedup", required_argument, NULL, O_SPEEDUP},
    {"gradient", no_argument, NULL, O_GRADIENT},
    {NULL, 0, NULL, 0},
};

/* 1: --help was shown; -1: a mistake (reported) */
static int parse_args(int argc, char **argv, sim_args *a) {
    memset(a, 0, sizeof *a);
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("simulate", argc, argv, options)) != -1;) {
        switch (c) {
        case 'h':
            usage(stdout);
            return 1;
        case O_JSON:
            a->json = 1;
            break;
        case O_FORCE:
            a->force_text = optarg;
            break;
        case O_SCHEDULE:
            a->schedule = optarg;
            break;
        case O_SAMPLES:
            a->sample_text = optarg;
            break;
        case O_OUT:
            a->out = optarg;
            break;
        case O_PLOT:
            a->plot = 1;
            break;
        case O_ANIMATE:
            a->plot = a->animate = 1;
            break;
        case O_FRAMES:
            a->plot = 1;
            a->frames_text = optarg;
            break;
        case O_FPS:
            a->fps_text = optarg;
            break;
        case O_SIZE:
            a->size_text = optarg;
            break;
        case O_SPEEDUP:
            a->speedup_text = optarg;
            break;
        case O_GRADIENT:
            a->gradient = 1;
            break;
        default:
            return -1;
        }
    }
    if (zp_cli_scene_operand("simulate", argc, argv, &a->scene) ||
        (a->out && zp_cli_path_ok("simulate", "--out", a->out)) ||
        (a->schedule && zp_cli_path_ok("simulate", "--schedule", a->schedule))) {
        return -1;
    }
    if (!a->scene) {
        zp_cli_error("simulate", "a scene file is required; see zipopt simulate --help");
        return -1;
    }
    return 0;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* trajectory.csv and summary.json into the command's transaction */
static int write_files(zp_tx *t, const zp_model *m, zp_sim *s, const zp_result *r,
                       const zp_run_meta *meta) {
    char err[1400] = "";
    FILE *csv = zp_tx_open(t, "trajectory.csv", err, sizeof err);
    FILE *js = csv ? zp_tx_open(t, "summary.json", err, sizeof err) : NULL;
    if (!js) {
        fprintf(stderr, "zipopt simulate: %s; nothing was written\n", err);
        return -1;
    }
    zp_out_csv_trajectory(csv, m, zp_sim_rows(s));
    zp_out_json_result(js, m, r, s, meta);
    return 0;
}

/* the --plot options, checked before the run; 0, or -1 with the message printed */
static int plot_opts(const sim_args *a, const zp_problem *st, zp_plot_opts *po) {
    const zp_model *m = st->m;
    const zp_scene *sc = &st->sc;
    zp_plot_opts_default(po);
    po->margin = sc->margin * M_PI / 180;
    po->sched = &st->sched;
    po->animate = a->animate;
    char why[256] = "", expect[128] = "";
    const char *opt = NULL;
    if (a->plot && !(st->sim.output_dt > 0)) {
        opt = "--plot";
        snprintf(why, sizeof why, "[solver] output_dt = %g gives no trajectory", st->sim.output_dt);
        snprintf(expect, sizeof expect, "output_dt > 0 in the scene");
    } else if (a->frames_text &&
               zp_plot_opts_parse_frames(m, a->frames_text, po, why, sizeof why)) {
        opt = "--frames-at";
        snprintf(expect, sizeof expect, "x=X1,X2,.. (m, on the course) or t=T1,T2,.. (s)");
    } else if (a->size_text && zp_plot_opts_parse_size(a->size_text, po, why, sizeof why)) {
        opt = "--size";
        snprintf(expect, sizeof expect, "e.g. 960x400");
    } else if (a->fps_text && (zp_cli_parse_list(a->fps_text, &po->fps, 1, why, sizeof why) != 1 ||
                               !(po->fps >= 1 && po->fps <= 100))) {
        opt = "--fps";
        snprintf(expect, sizeof expect, "one number of frames per second from 1 to 100");
    } else if (a->speedup_text &&
               (zp_cli_parse_list(a->speedup_text, &po->speedup, 1, why, sizeof why) != 1 ||
                !(po->speedup > 0 && po->speedup <= 1000))) {
        opt = "--speedup";
        snprintf(expect, sizeof expect, "one number above 0 and at most 1000");
    }
    if (opt) {
        zp_cli_error("simulate", "%s: %s%s%s; nothing was written", opt, *why ? why : "bad value",
                     *why ? "; expected " : ", expected ", expect);
        return -1;
    }
    return 0;
}

/* run.gif's frame count, known once the run's length is: within MAX_ANIM_FRAMES or refused
   (bad input: the options ask for too many) before anything is written */
static int anim_fits(const zp_result *r, const zp_plot_opts *po) {
    double frames = floor(r->time * po->fps / po->speedup) + 2;
    if (!po->animate || frames <= MAX_ANIM_FRAMES) {
        return 1;
    }
    zp_cli_error("simulate",
                 "--animate: the run of %.3f s at --speedup %g and --fps %g needs %.3g frames; "
                 "at most %d are drawn (use --speedup %.3g or more); nothing was written",
                 r->time, po->speedup, po->fps, frames, MAX_ANIM_FRAMES,
                 r->time * po->fps / (MAX_ANIM_FRAMES - 2));
    return 0;
}

/* the figures of the run into the transaction; 0, or -1 with why on stderr */
static int draw(zp_tx *t, const zp_model *m, zp_sim *s, const zp_result *r,
                const zp_plot_opts *po, zp_plot_info *info) {
    char err[1400];
    if (zp_plot_run(t, m, s, r, po, info, err, sizeof err)) {
        fprintf(stderr, "zipopt simulate: figures: %s; nothing was written\n", err);
        return -1;
    }
    if (info->nskipped) {
        fprintf(stderr, "zipopt simulate: %d of the still frames asked for lie beyond the end of "
                        "the run (t = %.2f s, x = %.2f m) and were not drawn\n",
                info->nskipped, r->time, r->x);
    }
    return 0;
}

/* what the figures came to, once committed */
static int say_figures(const char *dir, const zp_plot_opts *po, const zp_plot_info *info,
                       FILE *say) {
    if (info->no_gnuplot) {
        fprintf(stderr, "zipopt simulate: gnuplot is not installed (apt-get install gnuplot-nox): "
                        "no images were drawn; the plot data and the .gp scripts are in %s, run "
                        "`gnuplot course.gp` (and the other scripts) there once it is\n",
                dir);
        return ZP_EXIT_FAIL;
    }
    fprintf(say,
            "figures in %s: course.png (and .svg) energy.png angles.png loads.png along.png "
            "drive.png%s",
            dir,
            info->envelope ? " envelope.png" : "");
    if (info->nframe) {
        fprintf(say, ", %d still frame%s", info->nframe, info->nframe == 1 ? "" : "s");
    }
    if (po->animate) {
        fprintf(say, ", run.gif (%d frames)%s", info->anim_frames, info->mp4 ? ", run.mp4" : "");
    }
    fprintf(say, "\n");
    return ZP_EXIT_OK;
}

/* the answer's run and its error estimate; with [solver] accuracy, tightened until it is met */
/* the gradient's lines of the text summary */
static zp_status run_answer(const zp_model *m, double accuracy, zp_sim_opts *o,
                            const zp_input *in, zp_sim **s, zp_result *r, zp_estimate *e,
                            zp_accuracy *a) {
    if (accuracy > 0) {
        return zp_accuracy_run(m, o, in, accuracy, s, r, e, a);
    }
    *s = zp_sim_create(m, o);
    if (!*s) {
        snprintf(r->message, sizeof r->message, "cannot create the simulator (out of memory)");
        return ZP_ERR_NOMEM;
    }
    zp_status st = zp_sim_run(m, *s, in, r);
    if (st == ZP_OK) {
        zp_estimate_run(m, o, in, r, e);
    }
    return st;
}

/* --sample-times, sorted, into *samples (malloc'd, NULL when none are asked for); their count,
   or -1 (said) */
static int parse_samples(const char *text, double **samples) {
    *samples = NULL;
    if (!text) {
        return 0;
    }
    char why[256] = "out of memory";
    *samples = malloc(sizeof **samples * MAX_SAMPLES);
    int n = *samples ? zp_cli_parse_list(text, *samples, MAX_SAMPLES, why, sizeof why) : -1;
    for (int i = 0; i < n; i++) {
        if ((*samples)[i] < 0) {
            snprintf(why, sizeof why, "%g is negative", (*samples)[i]);
            n = -1;
        }
    }
    if (n < 0) {
        zp_cli_error("simulate", "--sample-times: %s; expected times >= 0 in s", why);
        return -1;
    }
    qsort(*samples, n, sizeof **samples, cmp_double);
    return n;
}

/* the run's files (and figures) committed, then the result printed; the exit status */
static int write_run(const sim_args *a, const zp_problem *st, zp_sim *s, const zp_result *r,
                     const zp_run_meta *meta, const zp_plot_opts *po) {
    zp_tx t;
    zp_plot_info info;
    if (zp_cli_out_begin(&t, "simulate", "simulate", a->out, &st->sc)) {
        return ZP_EXIT_FAIL;
    }
    if (write_files(&t, st->m, s, r, meta) || (a->plot && draw(&t, st->m, s, r, po, &info)) ||
        zp_cli_out_commit(&t, "simulate")) {
        zp_tx_abort(&t);
        return ZP_EXIT_FAIL;
    }
    if (a->json) {
        zp_out_json_result(stdout, st->m, r, s, meta);
    } else {
        zp_out_text_result(stdout, st->m, r, s, meta);
    }
    fprintf(a->json ? stderr : stdout, "wrote in %s: %s\n", t.dir, t.written);
    return a->plot ? say_figures(t.dir, po, &info, a->json ? stderr : stdout) : ZP_EXIT_OK;
}

int zp_cmd_simulate(int argc, char **argv) {
    sim_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    static zp_problem st; /* large: kept off the stack */
    zp_overrides ov = {.schedule = a.schedule, .force = a.force_text};
    if (zp_setup_load("simulate", a.scene, &ov, &st)) {
        return ZP_EXIT_USAGE;
    }
    zp_sim_opts o = st.sim;
    int status = ZP_EXIT_USAGE;
    zp_sim *s = NULL;
    double *samples;
    int nsample = parse_samples(a.sample_text, &samples);
    zp_plot_opts po;
    if (nsample < 0 || plot_opts(&a, &st, &po)) {
        goto done;
    }
    status = ZP_EXIT_FAIL;
    zp_limits lim;
    zp_limits_from_scene(&st.sc, &lim);
    o.peaks = zp_limits_need_peaks(&lim);
    zp_result r;
    zp_estimate est;
    zp_accuracy acc;
    zp_input in = {.sched = &st.sched, .sample_t = samples, .nsample = nsample};
    zp_plot_opts_frames_input(&po, &in);
    if (run_answer(st.m, st.sc.accuracy, &o, &in, &s, &r, &est, &acc)) {
        fprintf(stderr, "zipopt simulate: %s; nothing was written\n", r.message);
        goto done;
    }
    if (!anim_fits(&r, &po)) {
        status = ZP_EXIT_USAGE;
        goto done;
    }
    zp_sens_result grad;
    if (a.gradient && zp_sens_run(st.m, &o, &st.sched, &lim, &grad)) {
        fprintf(stderr, "zipopt simulate: --gradient: %s; nothing was written\n", grad.message);
        goto done;
    }
    int nsmp;
    zp_sim_samples(s, &nsmp); /* the times reached; the rest were not */
    zp_run_meta meta = {st.sc.name, zp_method_get(o.method)->name,
                        zp_formulation_get(o.formulation)->name, o.rtol, o.atol, &st.sched, &est,
                        samples + nsmp, nsample - nsmp, &lim,
                        st.sc.accuracy > 0 ? &acc : NULL, a.gradient ? &grad : NULL};
    status = write_run(&a, &st, s, &r, &meta, &po);
done:
    free(samples);
    zp_sim_free(s);
    zp_setup_free(&st);
    return status;
}
