/* `zipopt bench trade [SCENE]`: the work-precision study (docs/trade.md). Every method over a
   tolerance sweep on three cases of one scene; the error of what users read against a
   reference run by two methods that agree, against wall time and rhs evaluations; a CSV, a
   gnuplot script and its log-log plot in out/<scene name>/bench/; the results as text or, with
   --json, one JSON object. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "out_json.h"
#include "setup.h"
#include "sim.h"
#include "sim_opts.h"

#define NTOL 10          /* rtol 1e-3 .. 1e-12 */
#define REF_RTOL 1e-13   /* the reference runs' tolerance: tighter than the sweep */
#define ATOL_RATIO 1e-2  /* atol = rtol / 100, the scene default's ratio */
#define MAX_IMPULSES 64  /* kink impulses compared per run */
#define REPEAT_BUDGET 1.0 /* s: wall time the repeats of one configuration may take */
#define NTARGET 3

static const double targets[NTARGET] = {1e-3, 1e-6, 1e-9}; /* s, on the finish/death time */

/* the seed scene at a surviving schedule, a dying one, and a stiff copy (heavy damping) */
typedef struct trade_case {
    const char *name;
    double force;   /* N, every section */
    double damping; /* N m s/rad, every joint; < 0: the scene's */
    int ref_cvode;  /* the CVODE method of the reference pair, with gsl-rk8pd */
} trade_case;

static const trade_case cases[] = {
    {"survive", 10, -1, ZP_METHOD_CVODE_ADAMS},
    {"die", 100, -1, ZP_METHOD_CVODE_ADAMS},
    {"stiff", 100, 1e4, ZP_METHOD_CVODE_BDF},
};
#define NCASE ((int)(sizeof cases / sizeof cases[0]))

/* what a user reads from one run, plus its cost */
typedef struct reading {
    int ok; /* 0: numerical failure */
    zp_outcome outcome;
    int died_link;
    double time, x, v;            /* s, m, m/s */
    int nimp;                     /* kink crossings */
    double impulse[MAX_IMPULSES]; /* N s */
    double angle[ZP_MAX_LINKS];   /* deg, largest |relative joint angle| */
    double wall;                  /* s, median over repeats */
    long evals, steps, rejected;
    int repeats;
} reading;

/* errors against the reference; infinite when the outcome or the kinks crossed differ */
typedef struct errors {
    double time, impulse, angle, x, v; /* s, N s, deg, m, m/s */
} errors;

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static reading read_result(const zp_model *m, const zp_result *r, const zp_sim *s) {
    reading d = {.ok = 1, .outcome = r->outcome, .died_link = r->died_link, .time = r->time,
                 .x = r->x, .v = r->v, .evals = r->rhs_evals, .steps = r->steps,
                 .rejected = r->rejected};
    int n;
    const zp_crossing *cross = zp_sim_crossings(s, &n);
    d.nimp = r->ncross;
    for (int k = 0; k < n && k < MAX_IMPULSES; k++) {
        d.impulse[k] = cross[k].impulse;
    }
    for (int i = 0; i < m->nlink; i++) {
        d.angle[i] = r->max_rel_angle[i] * 180 / M_PI;
    }
    return d;
}

/* one configuration: runs repeated within REPEAT_BUDGET (at most max_rep), median wall */
static reading measure(const zp_model *m, zp_sim_opts o, const zp_schedule *sched, int max_rep) {
    zp_result r;
    reading d = {0};
    zp_sim *s = zp_sim_create(m, &o);
    if (!s) {
        return d;
    }
    zp_input in = {.sched = sched};
    double walls[64];
    int n = 0;
    for (double spent = 0; n < max_rep && n < 64 && (n == 0 || spent < REPEAT_BUDGET); n++) {
        if (zp_sim_run(m, s, &in, &r) != ZP_OK) {
            zp_sim_free(s);
            return d;
        }
        walls[n] = r.wall_s;
        spent += r.wall_s;
    }
    d = read_result(m, &r, s);
    qsort(walls, n, sizeof *walls, cmp_double);
    d.wall = n % 2 ? walls[n / 2] : 0.5 * (walls[n / 2 - 1] + walls[n / 2]);
    d.repeats = n;
    zp_sim_free(s);
    return d;
}

static errors compare(const zp_model *m, const reading *a, const reading *ref) {
    errors e = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
    if (!a->ok || a->outcome != ref->outcome || a->died_link != ref->died_link) {
        return e;
    }
    e.time = fabs(a->time - ref->time);
    e.x = fabs(a->x - ref->x);
    e.v = fabs(a->v - ref->v);
    e.angle = 0;
    for (int i = 0; i < m->nlink; i++) {
        e.angle = fmax(e.angle, fabs(a->angle[i] - ref->angle[i]));
    }
    if (a->nimp == ref->nimp) {
        e.impulse = 0;
        for (int k = 0; k < a->nimp && k < MAX_IMPULSES; k++) {
            e.impulse = fmax(e.impulse, fabs(a->impulse[k] - ref->impulse[k]));
        }
    }
    return e;
}

static double worst(errors e) {
    return fmax(fmax(e.time, e.impulse), fmax(fmax(e.angle, e.x), e.v));
}

typedef struct trade_args {
    const char *scene, *out;
    int repeats, json;
} trade_args;

/* the whole study: per case its reference, then every method at every tolerance */
typedef struct trade_study {
    double tols[NTOL];
    reading ref[NCASE];
    errors agree[NCASE]; /* the second reference method against the first */
    reading runs[NCASE][ZP_METHOD_COUNT][NTOL];
    errors errs[NCASE][ZP_METHOD_COUNT][NTOL];
} trade_study;

static void usage(FILE *f) {
    fputs("usage: zipopt bench trade [SCENE.ini] [--repeats N] [--json] [--out DIR]\n"
          "\n"
          "Work-precision study: every method at rtol 1e-3 .. 1e-12 (atol = rtol/100) on the\n"
          "scene (default: the built-in seed) at 10 N everywhere (survives), 100 N (dies) and\n"
          "100 N with joint damping 1e4 N m s/rad (stiff). Errors of the finish/death time,\n"
          "kink impulses, largest joint angles and final x/speed against a reference at rtol\n"
          "1e-13 by two methods that agree; cost as the median wall time of up to N runs\n"
          "(default 5) and rhs evaluations. Writes trade.csv, trade.gp and trade.png in DIR\n"
          "(default out/<scene name>/bench/) and prints the fastest method and tolerance\n"
          "reaching a finish or death time error of 1e-3, 1e-6 and 1e-9 s; with --json, one\n"
          "JSON object instead (keys: docs/commands.md).\n",
          f);
}

enum { O_OUT = ZP_OPT_FIRST, O_REPEATS, O_JSON };
static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"json", no_argument, NULL, O_JSON},
    {"out", required_argument, NULL, O_OUT},
    {"repeats", required_argument, NULL, O_REPEATS},
    {NULL, 0, NULL, 0},
};

/* 1: --help was shown; -1: a mistake (reported) */
static int parse_args(int argc, char **argv, trade_args *a) {
    *a = (trade_args){.repeats = 5};
    if (argc < 2 || strcmp(argv[1], "trade")) {
        if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
            usage(stdout);
            return 1;
        }
        zp_cli_error("bench", "expected a study name: trade; see zipopt bench --help");
        return -1;
    }
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("bench trade", argc - 1, argv + 1, options)) != -1;) {
        unsigned long n;
        switch (c) {
        case 'h':
            usage(stdout);
            return 1;
        case O_OUT:
            a->out = optarg;
            break;
        case O_JSON:
            a->json = 1;
            break;
        case O_REPEATS:
            if (zp_cli_whole("bench trade", "--repeats", optarg, 1, 64, &n)) {
                return -1;
            }
            a->repeats = (int)n;
            break;
        default:
            return -1;
        }
    }
    return zp_cli_scene_operand("bench trade", argc - 1, argv + 1, &a->scene) ||
                   zp_cli_path_ok("bench trade", "--out", a->out)
               ? -1
               : 0;
}

/* the plot: error of the finish/death time against wall time, one panel per case, one line
   per method, read straight from the CSV; a zero error is drawn at the 1e-16 floor */
static void write_gnuplot(FILE *f) {
    fputs("# written by zipopt bench trade: work-precision plot from trade.csv\n"
          "set datafile separator ','\n"
          "set terminal pngcairo size 1500,520 noenhanced\n"
          "set output 'trade.png'\n"
          "set logscale xy\nset format x '%.0e'\nset format y '%.0e'\n"
          "set xlabel 'wall time per run (s, median)'\n"
          "set ylabel '|finish/death time - reference| (s)'\n"
          "set key bottom left\nset grid\n"
          "lo(e) = e < 1e-16 ? 1e-16 : e\n"
          "set multiplot layout 1,3\n",
          f);
    for (int c = 0; c < NCASE; c++) {
        fprintf(f, "set title '%s: %g N%s'\nplot ", cases[c].name, cases[c].force,
                cases[c].damping >= 0 ? ", damping 1e4 N m s/rad" : "");
        for (int k = 0; k < ZP_METHOD_COUNT; k++) {
            const char *name = zp_method_get(k)->name;
            fprintf(f,
                    "%s'trade.csv' using (strcol(1) eq '%s' && strcol(2) eq '%s' ? $12 : NaN)"
                    ":(lo($6)) with linespoints title '%s'",
                    k ? ", \\\n     " : "", cases[c].name, name, name);
        }
        fputs("\n", f);
    }
    fputs("unset multiplot\n", f);
}

static void print_error(const char *label, double e) {
    if (isfinite(e)) {
        printf("%s %.1e", label, e);
    } else {
        printf("%s  wrong  ", label);
    }
}

/* the model and options of case c on the scene base, at its schedule (sched); NULL on a bad
   scene (said on stderr) */
static zp_model *case_model(const zp_scene *base, int c, zp_sim_opts *o, zp_schedule *sched) {
    const trade_case *tc = &cases[c];
    zp_scene sc = *base;
    zp_schedule shape = zp_schedule_of_scene(&sc);
    *sched = zp_drive_constant(&shape, tc->force);
    if (tc->damping >= 0) {
        sc.ndamping = 1;
        sc.damping[0] = tc->damping;
    }
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = zp_model_build(&sc, &d);
    if (!m || zp_sim_opts_from_scene(&sc, o, &d)) {
        zp_diag_print(&d, stderr);
        zp_model_free(m);
        return NULL;
    }
    o->output_dt = 0; /* integration and events only, as the search runs */
    o->track_loads = 0;
    return m;
}

/* case c of the study: its reference, then every configuration, each a line of the CSV;
   0, or -1 (said on stderr) */
static int run_case(const zp_scene *base, int c, int repeats, trade_study *st, FILE *csv) {
    const trade_case *tc = &cases[c];
    zp_sim_opts o;
    zp_schedule sched;
    zp_model *m = case_model(base, c, &o, &sched);
    if (!m) {
        return -1;
    }
    /* the reference: gsl-rk8pd and a CVODE method at REF_RTOL, and how well they agree */
    o.rtol = REF_RTOL;
    o.atol = REF_RTOL * ATOL_RATIO;
    o.method = ZP_METHOD_GSL_RK8PD;
    reading ref = st->ref[c] = measure(m, o, &sched, 1);
    o.method = tc->ref_cvode;
    reading ref2 = measure(m, o, &sched, 1);
    errors agree = st->agree[c] = compare(m, &ref2, &ref);
    fprintf(stderr, "%s: reference %s at %.9f s by %s and %s, which agree to %.1e s (time), "
                    "%.1e N s (impulses), %.1e deg (angles), %.1e m (x)\n",
            tc->name, zp_sim_outcome_name(ref.outcome), ref.time,
            zp_method_get(ZP_METHOD_GSL_RK8PD)->name, zp_method_get(tc->ref_cvode)->name,
            agree.time, agree.impulse, agree.angle, agree.x);
    if (!ref.ok || !isfinite(worst(agree))) {
        fprintf(stderr, "zipopt bench trade: %s: the reference runs disagree on the "
                        "outcome; nothing was written\n",
                tc->name);
        zp_model_free(m);
        return -1;
    }
    for (int k = 0; k < ZP_METHOD_COUNT; k++) {
        for (int t = 0; t < NTOL; t++) {
            o.method = k;
            o.rtol = st->tols[t];
            o.atol = st->tols[t] * ATOL_RATIO;
            reading *r = &st->runs[c][k][t];
            *r = measure(m, o, &sched, repeats);
            st->errs[c][k][t] = compare(m, r, &ref);
            const errors *e = &st->errs[c][k][t];
            fprintf(csv, "%s,%s,%.0e,%s,%.12g,%.3e,%.3e,%.3e,%.3e,%.3e,%ld,%.6e,%ld,%d,%ld\n",
                    tc->name, zp_method_get(k)->name, st->tols[t],
                    r->ok ? zp_sim_outcome_name(r->outcome) : "failed", r->time, e->time,
                    e->impulse, e->angle, e->x, e->v, r->evals, r->wall, r->steps, r->repeats,
                    r->rejected);
        }
    }
    zp_model_free(m);
    return 0;
}

/* the fastest configuration (*bk method, *bt tolerance, total median wall returned) whose
   finish/death time error is within target on case c, or on all of them (c == NCASE);
   *bk < 0 when none is */
static double fastest(const trade_study *st, double target, int c, int *bk, int *bt) {
    double best = INFINITY;
    *bk = *bt = -1;
    int c0 = c == NCASE ? 0 : c, c1 = c == NCASE ? NCASE : c + 1;
    for (int k = 0; k < ZP_METHOD_COUNT; k++) {
        for (int t = 0; t < NTOL; t++) {
            double e = 0, w = 0;
            for (int cc = c0; cc < c1; cc++) {
                e = fmax(e, st->errs[cc][k][t].time);
                w += st->runs[cc][k][t].wall;
            }
            if (e <= target && w < best) {
                best = w;
                *bk = k;
                *bt = t;
            }
        }
    }
    return best;
}

static void print_text(const trade_study *st) {
    /* the table: time error and cost of every configuration */
    for (int c = 0; c < NCASE; c++) {
        printf("\n%s (%g N%s): error of the %s time (s) / median wall (ms) / rhs evals / "
               "rejected steps\n",
               cases[c].name, cases[c].force, cases[c].damping >= 0 ? ", c = 1e4" : "",
               st->runs[c][0][0].outcome == ZP_OUTCOME_DIED ? "death" : "finish");
        printf("%-7s", "rtol");
        for (int k = 0; k < ZP_METHOD_COUNT; k++) {
            printf(" | %-31s", zp_method_get(k)->name);
        }
        printf("\n");
        for (int t = 0; t < NTOL; t++) {
            printf("%-7.0e", st->tols[t]);
            for (int k = 0; k < ZP_METHOD_COUNT; k++) {
                const reading *r = &st->runs[c][k][t];
                printf(" | ");
                print_error("", st->errs[c][k][t].time);
                printf(" %8.2f %7ld %4ld", 1e3 * r->wall, r->evals, r->rejected);
            }
            printf("\n");
        }
    }
    /* the fastest configuration reaching each target, per case and over all three */
    printf("\nfastest to reach a finish/death time error (method, rtol, median wall):\n");
    for (int g = 0; g < NTARGET; g++) {
        printf("  <= %.0e s:", targets[g]);
        for (int c = 0; c <= NCASE; c++) {
            int bk, bt;
            double best = fastest(st, targets[g], c, &bk, &bt);
            printf("  %s: ", c == NCASE ? "all three" : cases[c].name);
            if (bk < 0) {
                printf("none");
            } else {
                printf("%s %.0e (%.2f ms)", zp_method_get(bk)->name, st->tols[bt], 1e3 * best);
            }
            fputs(c < NCASE ? ";" : "\n", stdout);
        }
    }
}

/* "key": number, then sep */
static void json_num(const char *key, double v, const char *sep) {
    printf("\"%s\": ", key);
    zp_out_json_number(stdout, v);
    fputs(sep, stdout);
}

/* one errors object: null where the outcome or the kinks crossed differ */
static void json_errors(const errors *e) {
    fputs("{", stdout);
    json_num("time", e->time, ", ");
    json_num("impulse", e->impulse, ", ");
    json_num("angle", e->angle, ", ");
    json_num("x", e->x, ", ");
    json_num("speed", e->v, "}");
}

static void json_case(const trade_study *st, int c) {
    const trade_case *tc = &cases[c];
    const reading *ref = &st->ref[c];
    printf("    {\"name\": \"%s\", ", tc->name);
    json_num("force", tc->force, ", ");
    json_num("damping", tc->damping >= 0 ? tc->damping : NAN, ",\n");
    printf("     \"reference\": {\"methods\": [\"%s\", \"%s\"], \"outcome\": \"%s\", ",
           zp_method_get(ZP_METHOD_GSL_RK8PD)->name, zp_method_get(tc->ref_cvode)->name,
           zp_sim_outcome_name(ref->outcome));
    json_num("time", ref->time, ", ");
    fputs("\"agreement\": ", stdout);
    json_errors(&st->agree[c]);
    fputs("},\n     \"runs\": [", stdout);
    for (int k = 0; k < ZP_METHOD_COUNT; k++) {
        for (int t = 0; t < NTOL; t++) {
            const reading *r = &st->runs[c][k][t];
            printf("%s\n      {\"method\": \"%s\", ", k || t ? "," : "", zp_method_get(k)->name);
            json_num("rtol", st->tols[t], ", ");
            json_num("atol", st->tols[t] * ATOL_RATIO, ", ");
            printf("\"outcome\": \"%s\", ", r->ok ? zp_sim_outcome_name(r->outcome) : "failed");
            json_num("time", r->ok ? r->time : NAN, ", ");
            fputs("\"error\": ", stdout);
            json_errors(&st->errs[c][k][t]);
            printf(", \"rhs_evals\": %ld, \"steps\": %ld, \"rejected_steps\": %ld, ", r->evals,
                   r->steps, r->rejected);
            json_num("wall_s", r->wall, ", ");
            printf("\"repeats\": %d}", r->repeats);
        }
    }
    printf("\n     ]}%s\n", c + 1 < NCASE ? "," : "");
}

/* the study as one JSON object (README "zipopt bench trade --json") */
static void print_json(const trade_study *st, const char *scene, int repeats) {
    fputs("{\n  \"study\": \"trade\",\n  \"scene\": ", stdout);
    zp_out_json_string(stdout, scene);
    printf(",\n  \"repeats\": %d,\n  ", repeats);
    json_num("reference_rtol", REF_RTOL, ",\n  ");
    json_num("atol_per_rtol", ATOL_RATIO, ",\n  \"cases\": [\n");
    for (int c = 0; c < NCASE; c++) {
        json_case(st, c);
    }
    fputs("  ],\n  \"fastest\": [", stdout);
    for (int g = 0; g < NTARGET; g++) {
        printf("%s\n    {", g ? "," : "");
        json_num("time_error", targets[g], "");
        for (int c = 0; c <= NCASE; c++) {
            int bk, bt;
            double best = fastest(st, targets[g], c, &bk, &bt);
            printf(", \"%s\": ", c == NCASE ? "all" : cases[c].name);
            if (bk < 0) {
                fputs("null", stdout);
                continue;
            }
            printf("{\"method\": \"%s\", ", zp_method_get(bk)->name);
            json_num("rtol", st->tols[bt], ", ");
            json_num("wall_s", best, "}");
        }
        fputs("}", stdout);
    }
    fputs("\n  ]\n}\n", stdout);
}

int zp_cmd_bench(int argc, char **argv) {
    trade_args a;
    int pa = parse_args(argc, argv, &a);
    if (pa) {
        return pa > 0 ? ZP_EXIT_OK : ZP_EXIT_USAGE;
    }
    static zp_problem base; /* large: kept off the stack */
    zp_overrides none = ZP_OVERRIDES_NONE;
    if (zp_setup_load("bench trade", a.scene, &none, &base)) {
        return ZP_EXIT_USAGE;
    }
    zp_setup_free(&base);

    static trade_study st;
    for (int t = 0; t < NTOL; t++) {
        st.tols[t] = pow(10, -3 - t);
    }
    zp_tx set;
    if (zp_cli_out_begin(&set, "bench trade", "bench", a.out, &base.sc)) {
        return ZP_EXIT_FAIL;
    }
    char err[1400] = "";
    FILE *csv = zp_tx_open(&set, "trade.csv", err, sizeof err);
    FILE *gp = csv ? zp_tx_open(&set, "trade.gp", err, sizeof err) : NULL;
    if (!gp) {
        zp_tx_abort(&set);
        fprintf(stderr, "zipopt bench trade: %s; nothing was written\n", err);
        return ZP_EXIT_FAIL;
    }
    fputs("case,method,rtol,outcome,time_s,err_time_s,err_impulse_Ns,err_angle_deg,err_x_m,"
          "err_speed_mps,rhs_evals,wall_s,steps,repeats,rejected\n",
          csv);
    for (int c = 0; c < NCASE; c++) {
        if (run_case(&base.sc, c, a.repeats, &st, csv)) {
            zp_tx_abort(&set);
            return ZP_EXIT_FAIL;
        }
    }
    write_gnuplot(gp);
    const char *script = "trade.gp";
    int missing;
    if (zp_cli_out_draw_commit(&set, "bench trade", &script, 1, &missing)) {
        return ZP_EXIT_FAIL;
    }
    if (a.json) {
        print_json(&st, base.sc.name, a.repeats);
    } else {
        print_text(&st);
    }
    fprintf(a.json ? stderr : stdout, "%swrote in %s: %s%s\n", a.json ? "" : "\n", set.dir,
            set.written,
            missing ? " (gnuplot is not installed: no plot; apt-get install gnuplot-nox)" : "");
    return ZP_EXIT_OK;
}
