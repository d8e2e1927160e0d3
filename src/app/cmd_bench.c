/* `zipopt bench trade [SCENE]`: the work-precision study (docs/trade.md). Every method over a
   tolerance sweep on three cases of one scene; the error of what users read against a
   reference run by two methods that agree, against wall time and rhs evaluations; a CSV, a
   gnuplot script and its log-log plot in out/<scene name>/bench/; the results as text or, with
   --json, one JSON object. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "out_trade.h"
#include "setup.h"

typedef struct trade_args {
    const char *scene, *out;
    int repeats, json;
} trade_args;

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

/* the reference runs of case c and how well they agree, as the study goes */
static void on_reference(void *user, const zp_trade_study *st, int c) {
    (void)user;
    const zp_trade_case *tc = &zp_trade_cases[c];
    const zp_trade_reading *ref = &st->ref[c];
    const zp_trade_errors *agree = &st->agree[c];
    fprintf(stderr, "%s: reference %s at %.9f s by %s and %s, which agree to %.1e s (time), "
                    "%.1e N s (impulses), %.1e deg (angles), %.1e m (x)\n",
            tc->name, zp_sim_outcome_name(ref->outcome), ref->time,
            zp_method_get(ZP_METHOD_GSL_RK8PD)->name, zp_method_get(tc->ref_cvode)->name,
            agree->time, agree->impulse, agree->angle, agree->x);
}

/* every case of the study on the scene; 0, or -1 (said on stderr) */
static int run_study(const zp_scene *sc, int repeats, zp_trade_study *st) {
    for (int c = 0; c < ZP_TRADE_NCASE; c++) {
        zp_diag d;
        zp_diag_init(&d);
        zp_status rc = zp_trade_run(sc, c, repeats, st, on_reference, NULL, &d);
        if (rc == ZP_ERR_INPUT) {
            zp_diag_print(&d, stderr);
            return -1;
        }
        if (rc) {
            fprintf(stderr, "zipopt bench trade: %s: the reference runs disagree on the "
                            "outcome; nothing was written\n",
                    zp_trade_cases[c].name);
            return -1;
        }
    }
    return 0;
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
    static zp_trade_study st; /* large: kept off the stack */
    zp_trade_init(&st);
    zp_tx set;
    if (zp_cli_out_begin(&set, "bench trade", "bench", a.out, &base.sc)) {
        return ZP_EXIT_FAIL;
    }
    char err[1400] = "";
    const char *names[] = {"trade.csv", "trade.gp"};
    FILE *f[2];
    if (zp_tx_open_set(&set, names, f, 2, err, sizeof err)) {
        zp_tx_abort(&set);
        fprintf(stderr, "zipopt bench trade: %s; nothing was written\n", err);
        return ZP_EXIT_FAIL;
    }
    if (run_study(&base.sc, a.repeats, &st)) {
        zp_tx_abort(&set);
        return ZP_EXIT_FAIL;
    }
    zp_out_trade_csv(f[0], &st);
    zp_out_trade_gnuplot(f[1]);
    int missing;
    if (zp_cli_out_draw_commit(&set, "bench trade", &names[1], 1, &missing)) {
        return ZP_EXIT_FAIL;
    }
    if (a.json) {
        zp_out_trade_json(stdout, &st, base.sc.name, a.repeats);
    } else {
        zp_out_trade_text(stdout, &st);
    }
    fprintf(a.json ? stderr : stdout, "%swrote in %s: %s%s\n", a.json ? "" : "\n", set.dir,
            set.written,
            missing ? " (gnuplot is not installed: no plot; apt-get install gnuplot-nox)" : "");
    return ZP_EXIT_OK;
}
