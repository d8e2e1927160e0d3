/* `zipopt [SCENE.ini] [--out DIR]`: the search for the fastest survivable schedule, its
   verification and the best-forcing report. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "estimate.h"
#include "mpi_spread.h"
#include "out_csv.h"
#include "out_file.h"
#include "out_html.h"
#include "plot.h"
#include "report.h"
#include "robust.h"
#include "search.h"
#include "setup.h"
#include "verify.h"

#define NROBUST 200     /* robustness runs per perturbation level */

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
          "  --algorithm NAME  the search strategy (below; default scan-cobyla)\n"
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
    zp_schedule best = zp_schedule_with(c->shape, c->p->force);
    zp_report_write_schedule(f, c->sc, &best, note);
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
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    double el = (t.tv_sec - c->t0.tv_sec) + 1e-9 * (t.tv_nsec - c->t0.tv_nsec);
    if (c->tty && (done == total || el - c->last >= 0.25)) {
        c->last = el;
        fprintf(stderr, "\rrobustness: %d of %d runs and bisections, about %.0f s left   ", done,
                total, el / done * (total - done));
        c->shown = 1;
    }
}

/* The fresh scenarios the answer fails, when it fails any, told apart by what breaks and
   where: the verification's scenarios run again with its options, each verdict kept. 0, or -1
   without memory (then no diagnosis). */
static int diagnose(const zp_robust_problem *pb, const zp_scene *sc, const zp_sim_opts *fast,
                    const double *p, zp_diagnosis *d) {
    int n = pb->check.samples;
    zp_robust_worst *each = malloc(sizeof *each * (size_t)n);
    zp_sim_opts to = zp_estimate_tighter(fast); /* as zp_robust_solve verified */
    to.track_loads = 0;
    zp_robust_check c;
    int bad = !each || zp_robust_verify_each(&pb->ob, &pb->box, &to, p, n, sc->seed, 0, NULL,
                                             &c, each);
    if (!bad) {
        zp_diagnose(&pb->box, &pb->ob, each, n, d);
    }
    free(each);
    return bad ? -1 : 0;
}

/* report.md, report.html, schedule.ini, summary.json and trajectory.csv into the transaction */
static int write_outputs(zp_tx *t, const zp_report *r, zp_sim *best_sim) {
    char err[1400] = "", note[200];
    FILE *md = zp_tx_open(t, "report.md", err, sizeof err);
    FILE *ini = md ? zp_tx_open(t, "schedule.ini", err, sizeof err) : NULL;
    FILE *js = ini ? zp_tx_open(t, "summary.json", err, sizeof err) : NULL;
    FILE *csv = js ? zp_tx_open(t, "trajectory.csv", err, sizeof err) : NULL;
    if (!csv) {
        fprintf(stderr, "zipopt: %s; nothing was written\n", err);
        return -1;
    }
    zp_report_write_md(md, r);
    snprintf(note, sizeof note, "%s of the search%s: %s, %.6f s; rerun with zipopt "
             "simulate SCENE.ini --schedule this-file",
             r->res->found ? "best schedule" : "CLOSEST CANDIDATE (nothing met the constraints)",
             r->res->interrupted ? " (interrupted)" : "",
             zp_sim_outcome_name(r->v->run->outcome), r->v->run->time);
    zp_schedule best = zp_schedule_with(r->shape, r->res->force);
    zp_report_write_schedule(ini, r->sc, &best, note);
    zp_report_write_json(js, r);
    zp_out_csv_trajectory(csv, r->m, zp_sim_rows(best_sim));
    /* report.html: report.md as one page a person can share, its figures inside it */
    char title[300];
    snprintf(title, sizeof title, "zipopt: best forcing, %s", r->sc->name);
    if (zp_out_html_report(t, "report.md", "report.html", title, err, sizeof err)) {
        fprintf(stderr, "zipopt: %s; nothing was written\n", err);
        return -1;
    }
    return 0;
}

/* the best run's figures into the transaction, started: 0, or -1 failed (said on stderr) */
static int figures_start(zp_tx *t, const zp_model *m, const zp_scene *sc, const zp_schedule *shape,
                         const zp_search_result *res, const zp_verify *v, const zp_sim *best_sim,
                         int procs, zp_gnuplot_job *job, zp_plot_info *info) {
    zp_plot_opts po;
    zp_plot_opts_default(&po);
    po.procs = procs;
    po.margin = sc->margin * M_PI / 180;
    zp_schedule best = zp_schedule_with(shape, res->force);
    po.sched = &best;
    char err[1400];
    if (zp_plot_start(t, m, best_sim, v->run, &po, info, job, err, sizeof err)) {
        fprintf(stderr, "zipopt: figures: %s; nothing was written\n", err);
        return -1;
    }
    return 0;
}

/* the figures finished: 1 drawn, 0 data and scripts only (no gnuplot), -1 failed (said) */
static int figures_finish(zp_tx *t, zp_gnuplot_job *job, zp_plot_info *info) {
    char err[1400];
    if (zp_plot_finish(t, job, info, err, sizeof err)) {
        fprintf(stderr, "zipopt: figures: %s; nothing was written\n", err);
        return -1;
    }
    if (info->no_gnuplot) {
        fputs("zipopt: gnuplot is not installed (apt-get install gnuplot-nox): writing the "
              "figures' data and scripts, not the images\n",
              stderr);
    }
    return !info->no_gnuplot;
}

/* whether the answer holds when rerun with [solver] (v->run) and 100x tighter (v->tight): it
   finishes with the margin at both, at times that agree. The search ranks with [optimize]'s
   own, possibly much looser, tolerance. 0 with why in why. */
static int answer_holds(const zp_objective *ob, const zp_verify *v, char *why, size_t n) {
    int which;
    zp_breaks b = zp_limits_broken(ob->m, &ob->lim, ob->limit, v->run, &which);
    if (b == ZP_BREAKS_DEATH || b == ZP_BREAKS_STALL) {
        snprintf(why, n, "rerun with [solver] it %s at %.4f s",
                 zp_sim_outcome_name(v->run->outcome), v->run->time);
    } else if (b == ZP_BREAKS_MARGIN) {
        snprintf(why, n,
                 "rerun with [solver] its largest joint angle is %.2f deg, past the %.2f deg the "
                 "margin allows",
                 zp_model_angle_used(ob->m, v->run->max_rel_angle) * 180 / M_PI,
                 ob->limit * 180 / M_PI);
    } else if (b == ZP_BREAKS_LIMIT) {
        snprintf(why, n, "rerun with [solver] it breaks [limits] %s", zp_limit_name(which));
    } else if (!v->agree) {
        snprintf(why, n, "it is not verified at the tighter tolerance (rtol %.0e)", v->rtol);
    } else {
        return 1;
    }
    return 0;
}

static void print_summary(const zp_report *r, const char *unheld) {
    const zp_search_result *s = r->res;
    const zp_result *run = r->v->run;
    if (unheld[0]) {
        printf("no schedule found: the search's best (ranked with [optimize]'s tolerance) does not "
               "hold: %s; it is written as the closest candidate (tighten [optimize] rtol)\n",
               unheld);
    } else if (!s->found) {
        printf("no schedule keeps the margin%s: none of %ld simulations survived with it; the "
               "closest candidate is written, marked as such\n",
               r->box || zp_limits_any(r->lim) ? ", the [limits] and the [robust] scenarios" : "",
               s->evals);
    }
    printf("%sbest schedule (%s):", s->interrupted ? "interrupted; " : "", zp_drive_unit(r->shape));
    for (int k = 0; k < r->shape->np; k++) {
        printf(" %.4f", s->force[k]);
    }
    double angle = zp_model_angle_used(r->m, run->max_rel_angle);
    printf("\noutcome: %s, time %.4f s (+/- %.1e s), margin %.2f deg%s\n",
           zp_sim_outcome_name(run->outcome), run->time, fabs(run->time - r->v->tight->time),
           r->sc->death_angle - angle * 180 / M_PI,
           r->v->agree ? ", verified" : ", NOT verified at the tighter tolerance");
    if (s->base_found) {
        printf("best constant push: %.3f N, %.4f s\n", s->base_force, s->base.time);
    } else {
        printf("best constant push: none found that keeps the margin\n");
    }
    printf("search: %s, %ld simulations in %.2f s on %d threads\n", r->algo, s->evals,
           s->wall_s, s->nthreads);
    if (r->box) {
        const zp_robust_check *c = r->check;
        printf("robust: held to %d scenarios (%d added by the adversary); on %d fresh ones %d "
               "finished, %d kept the margin, %d every limit: P(survivable) >= %.4f (95 %%)\n",
               r->set->n, r->rinfo->added, c->samples, c->survived, c->margin_kept,
               c->limits_kept, c->lower_95);
        const zp_headroom_line *L = &c->headroom.line[ZP_HEADROOM_LINES - 1];
        if (L->range >= 0 && isfinite(L->breaks)) {
            printf("headroom: holds to %.4fx the stated ranges along the worst direction found, "
                   "breaks at %.4fx (%s)\n",
                   L->holds, L->breaks, L->limited_by);
        } else if (L->range >= 0) {
            printf("headroom: holds to %.4fx the stated ranges or more along the worst "
                   "direction found\n",
                   L->holds);
        }
    }
    char conv[512];
    zp_report_convergence(conv, sizeof conv, s);
    printf("convergence: %s\n", conv);
}

/* the command on every rank of sp: rank 0 searches, prints and writes; every rank verifies
   its share of the robust scenarios */
static int search(int argc, char **argv, const zp_spread *sp) {
    search_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    static zp_setup st; /* large: kept off the stack */
    zp_overrides ov = {.has_seed = a.has_seed, .seed = a.seed, .max_evals = (long)a.max_evals};
    if (zp_setup_load("", a.scene, &ov, &st)) {
        return ZP_EXIT_USAGE;
    }
    const zp_model *m = st.m;
    const zp_scene *sc = &st.sc;
    zp_tx tx = {.dirfd = -1, .tmpfd = -1};
    int rank = sp->rank; /* ranks other than 0 write nothing, not even the folder */
    if (rank == 0 && zp_cli_out_begin(&tx, "", "search", a.out, sc)) {
        zp_robust_release(sp);
        zp_setup_free(&st);
        return ZP_EXIT_FAIL;
    }
    if (rank == 0) {
        zp_tx_soft_interrupt(&tx, &interrupted);
    }

    zp_sim_opts fast;
    static zp_robust_problem pb; /* large: kept off the stack */
    if (zp_robust_setup(&pb, sc, m, st.limit, &st.sched, &st.sim, &st.search, &fast)) {
        fputs("zipopt: out of memory building the scenarios; nothing was written\n", stderr);
        if (rank == 0) {
            zp_robust_release(sp);
        }
        zp_robust_problem_free(&pb);
        zp_tx_abort(&tx);
        zp_setup_free(&st);
        return ZP_EXIT_FAIL;
    }
    progress_ctx pc = {.sc = sc, .shape = &st.sched, .tx = &tx, .tty = isatty(STDERR_FILENO)};
    zp_search_opts o = {.algo = a.algo ? zp_search_algo_find(a.algo) : 0,
                        .max_evals = st.max_evals, .max_time = a.max_time, .seed = st.seed,
                        .stop = &interrupted, .progress = on_progress, .user = &pc};
    static zp_search_result res;
    char err[512] = "";
    pb.spread = sp;
    zp_status rc = zp_robust_solve(&pb, sc, &fast, st.sched.lo, st.sched.hi, &o, &res,
                                   err, sizeof err);
    int status = ZP_EXIT_FAIL;
    zp_sim *best_sim = NULL, *study_sim = NULL;
    zp_verify v = {0};
    if (rc) {
        fprintf(stderr, "zipopt: %s; nothing was written\n", err);
        goto done;
    }
    if (rank != 0) { /* its share of the verification is rank 0's too, which goes on */
        status = ZP_EXIT_OK;
        goto done;
    }
    /* verification (always) and robustness (not after Ctrl-C: the user wants out), of the
       nominal scene: the scenarios were checked above */
    zp_objective ob = pb.ob;
    ob.set = NULL;
    zp_sim_opts solver = st.sim;
    solver.peaks = fast.peaks;
    /* the figures of the answer are drawn while its checks run, unless [solver] accuracy may
       still replace it */
    int early = !a.no_plot && !(sc->accuracy > 0), drawn = 0;
    zp_gnuplot_job job;
    zp_plot_info info;
    rc = zp_verify_begin(&ob, &solver, res.force, &best_sim, &v, err, sizeof err);
    /* half the cores draw while the checks have the other half: every gnuplot start-up costs
       about what drawing one figure does */
    int half = zp_gnuplot_cores() / 2;
    if (!rc && early &&
        figures_start(&tx, m, sc, &st.sched, &res, &v, best_sim, half > 1 ? half : 1, &job,
                      &info)) {
        goto done;
    }
    phase_start(&pc, "verification: the best schedule with [solver] and 100x tighter");
    if (sc->force_error > 0) { /* the level the scene holds the answer to, and twice it */
        v.level[0] = sc->force_error / 100;
        v.level[1] = fmin(2 * sc->force_error / 100, 0.99);
    }
    if (!rc) {
        rc = zp_verify_finish(&ob, &solver, res.force, st.seed, res.interrupted ? 0 : NROBUST, 0,
                              &v, on_verify, &pc, err, sizeof err);
    }
    zp_sim_opts answer = solver;
    zp_accuracy acc;
    if (!rc && sc->accuracy > 0) {
        rc = zp_verify_accuracy(&ob, &solver, res.force, sc->accuracy, &best_sim, &v, &answer, &acc,
                                err, sizeof err);
    }
    if (pc.shown) {
        fputc('\n', stderr);
        pc.shown = 0;
    }
    if (rc) {
        fprintf(stderr, "zipopt: %s; nothing was written\n", err);
        goto done;
    }
    /* not found unless it holds with [solver]: exit 3 with it as the closest candidate */
    char unheld[256] = "";
    if (res.found && !res.interrupted && !answer_holds(&ob, &v, unheld, sizeof unheld)) {
        res.found = 0;
    }
    /* the scene's own [drive] forces, judged as the search judges (peaks where limits need
       them), for the report's comparison */
    static zp_result study;
    int given = sc->nforce > 0;
    study_sim = given ? zp_sim_create(m, &fast) : NULL;
    zp_input in = {.sched = &st.sched};
    if (given && (!study_sim || zp_sim_run(m, study_sim, &in, &study))) {
        fprintf(stderr, "zipopt: the run of the scene's [drive] forces failed: %s; nothing was "
                        "written\n",
                study_sim ? study.message : "out of memory");
        goto done;
    }
    /* the figures before the report, so that it links only those drawn */
    if (!a.no_plot) {
        phase_start(&pc, "figures: drawing the best run with gnuplot\n");
        pc.shown = 0;
        if (!early && figures_start(&tx, m, sc, &st.sched, &res, &v, best_sim, 0, &job, &info)) {
            goto done;
        }
        drawn = figures_finish(&tx, &job, &info);
    }
    int robust = pb.robust;
    static zp_diagnosis diag;
    int failing = robust && pb.check.samples > 0 && pb.check.all_kept < pb.check.samples;
    if (failing) {
        phase_start(&pc, "diagnosis: the fresh scenarios the answer fails\n");
        failing = !diagnose(&pb, sc, &fast, res.force, &diag);
    }
    zp_report r = {sc, m, &res, &v, best_sim, given ? &study : NULL,
                   zp_search_algo_get(o.algo)->name, zp_method_get(st.sim.method)->name, a.scene,
                   tx.dir, drawn > 0, &fast, &answer, &st.sched, st.seed, st.max_evals,
                   .lim = &pb.ob.lim, .box = robust ? &pb.box : NULL,
                   .set = robust ? &pb.set : NULL, .rinfo = robust ? &pb.info : NULL,
                   .check = robust ? &pb.check : NULL, .acc = sc->accuracy > 0 ? &acc : NULL,
                   .diag = failing ? &diag : NULL};
    if (drawn < 0 || write_outputs(&tx, &r, best_sim) || zp_cli_out_commit(&tx, "")) {
        goto done;
    }
    if (a.json) {
        zp_report_write_json(stdout, &r); /* summary.json's object */
    } else {
        print_summary(&r, unheld);
    }
    fprintf(a.json ? stderr : stdout, "wrote in %s: %s\n", tx.dir, tx.written);
    status = ZP_EXIT_OK;
    if (res.interrupted) {
        fputs("zipopt: interrupted; wrote the best schedule found so far\n", stderr);
        status = ZP_EXIT_FAIL;
    } else if (!res.found) {
        status = ZP_EXIT_NONE; /* the closest candidate is written, marked */
    } else if (interrupted) {
        fputs("zipopt: interrupted after the search had finished; the files are complete\n",
              stderr);
        status = ZP_EXIT_FAIL;
    }
done:
    zp_tx_abort(&tx); /* nothing of the run remains unless it was committed */
    zp_verify_free(&v);
    zp_sim_free(best_sim);
    zp_sim_free(study_sim);
    zp_robust_problem_free(&pb);
    zp_setup_free(&st);
    return status;
}

int zp_cmd_search(int argc, char **argv) {
    return zp_mpi_spread_main("search", search, argc, argv);
}
