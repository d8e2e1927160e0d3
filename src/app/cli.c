/* What the commands share (docs/commands.md): options by getopt_long with one message per
   mistake, the scene operand, the output folder, number lists, the usage text with the
   registries. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "formulation.h"
#include "gnuplot.h"
#include "method.h"
#include "text.h"

int zp_cli_parse_list(const char *text, double *out, int max, char *why, size_t whylen) {
    return zp_text_list(text, out, max, why, whylen);
}

void zp_cli_error(const char *cmd, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char *text = n >= 0 ? malloc((size_t)n + 1) : NULL;
    fprintf(stderr, "zipopt%s%s: ", *cmd ? " " : "", cmd);
    if (text) {
        va_start(ap, fmt);
        vsnprintf(text, (size_t)n + 1, fmt, ap);
        va_end(ap);
        zp_diag_put_escaped(stderr, text);
    } else {
        fputs(fmt, stderr);
    }
    fputc('\n', stderr);
    free(text);
}

const char *zp_cli_shown(const char *text, char *buf, size_t len) {
    FILE *f = fmemopen(buf, len, "w");
    if (!f) {
        snprintf(buf, len, "?");
        return buf;
    }
    setvbuf(f, NULL, _IONBF, 0); /* what fits stays when the text is longer than buf */
    zp_diag_put_escaped(f, text);
    fclose(f);
    buf[len - 1] = '\0';
    return buf;
}

void zp_cli_opts_begin(void) {
    optind = 0; /* glibc: 0 starts a fresh scan */
    opterr = 0; /* the messages are ours: one per mistake */
}

static const struct option *opt_by_val(const struct option *opts, int val) {
    for (; opts->name; opts++) {
        if (opts->val == val) {
            return opts;
        }
    }
    return NULL;
}

/* `--name` or `--name=value` that getopt_long refused: unknown or ambiguous */
static void bad_long(const char *cmd, const char *arg, const struct option *opts) {
    size_t len = strcspn(arg + 2, "=");
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)(len < 63 ? len : 63), arg + 2);
    char list[512] = "";
    int nprefix = 0, n = 0;
    const char *names[64];
    for (const struct option *o = opts; o->name && n < 64; o++) {
        names[n++] = o->name;
        if (!strncmp(o->name, name, len)) {
            size_t used = strlen(list);
            snprintf(list + used, sizeof list - used, "%s--%s", nprefix++ ? ", " : "", o->name);
        }
    }
    if (nprefix > 1) {
        zp_cli_error(cmd, "option '--%s' is ambiguous: %s; see zipopt%s%s --help", name, list,
                     *cmd ? " " : "", cmd);
        return;
    }
    int near = zp_diag_nearest(name, names, n);
    if (near >= 0) {
        zp_cli_error(cmd, "unknown option '--%s'; did you mean '--%s'? (see zipopt%s%s --help)",
                     name, names[near], *cmd ? " " : "", cmd);
    } else {
        zp_cli_error(cmd, "unknown option '--%s'; see zipopt%s%s --help", name, *cmd ? " " : "",
                     cmd);
    }
}

int zp_cli_opts_next(const char *cmd, int argc, char **argv, const struct option *opts) {
    int c = getopt_long(argc, argv, ":h", opts, NULL);
    if (c != '?' && c != ':') {
        return c;
    }
    const char *sp = *cmd ? " " : "";
    const char *arg = argv[optind - 1];
    const struct option *o = opt_by_val(opts, optopt);
    if (c == ':') {
        zp_cli_error(cmd, "option '--%s' requires an argument; see zipopt%s%s --help",
                     o ? o->name : arg + 2, sp, cmd);
    } else if (o && !strncmp(arg, "--", 2)) {
        zp_cli_error(cmd, "option '--%s' takes no value; see zipopt%s%s --help", o->name, sp, cmd);
    } else if (optopt == 0 && !strncmp(arg, "--", 2)) {
        bad_long(cmd, arg, opts);
    } else {
        zp_cli_error(cmd, "unknown option '-%c'; see zipopt%s%s --help", optopt, sp, cmd);
    }
    return '?';
}

int zp_cli_path_ok(const char *cmd, const char *opt, const char *path) {
    size_t n = strlen(path);
    if (n == 0) { /* '' would be the current folder, or no file at all */
        zp_cli_error(cmd, "%s%san empty path; expected a name", opt, *opt ? ": " : "");
        return -1;
    }
    if (n > ZP_CLI_PATH_MAX) {
        zp_cli_error(cmd, "%s%sthe path is %zu characters long; at most %d are supported", opt,
                     *opt ? ": " : "", n, ZP_CLI_PATH_MAX);
        return -1;
    }
    return 0;
}

int zp_cli_scene_operand(const char *cmd, int argc, char **argv, const char **scene) {
    const char *sp = *cmd ? " " : "";
    if (optind < argc && zp_cli_path_ok(cmd, "the scene file", argv[optind])) {
        return -1;
    }
    if (optind + 1 < argc) {
        zp_cli_error(cmd, "unexpected argument '%s' (one scene file only); see zipopt%s%s --help",
                     argv[optind + 1], sp, cmd);
        return -1;
    }
    if (optind < argc) {
        *scene = argv[optind];
    }
    return 0;
}

int zp_cli_whole(const char *cmd, const char *opt, const char *text, unsigned long lo,
                 unsigned long hi, unsigned long *out) {
    errno = 0;
    unsigned long v = strtoul(text, NULL, 10);
    int digits = *text && strspn(text, "0123456789") == strlen(text);
    if (!digits || errno || v < lo || v > hi) {
        zp_cli_error(cmd, "%s: '%s' is %s; expected a whole number from %lu to %lu", opt, text,
                     digits ? "out of range" : "not a whole number", lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int zp_cli_seconds(const char *cmd, const char *opt, const char *text, double *out) {
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end || !(v > 0) || !isfinite(v)) {
        zp_cli_error(cmd, "%s: '%s' is not a time; expected seconds > 0", opt, text);
        return -1;
    }
    *out = v;
    return 0;
}

int zp_cli_out_begin(zp_tx *t, const char *cmd, const char *folder, const char *out,
                     const zp_scene *sc) {
    char sub[2 * ZP_NAME_MAX], err[1400];
    snprintf(sub, sizeof sub, "%s/%s", sc->name, folder);
    if (zp_tx_begin(t, out ? out : "out", out ? NULL : sub, err, sizeof err)) {
        fprintf(stderr, "zipopt%s%s: %s; nothing was written\n", *cmd ? " " : "", cmd, err);
        return -1;
    }
    return 0;
}

int zp_cli_out_commit(zp_tx *t, const char *cmd) {
    char err[1400];
    if (zp_tx_commit(t, err, sizeof err)) {
        fprintf(stderr, "zipopt%s%s: %s; nothing was written\n", *cmd ? " " : "", cmd, err);
        return -1;
    }
    return 0;
}

int zp_cli_out_draw_commit(zp_tx *t, const char *cmd, const char *const *scripts, int n,
                           int *missing) {
    char err[1400];
    if (zp_gnuplot_run(t, scripts, n, missing, err, sizeof err)) {
        zp_tx_abort(t);
        fprintf(stderr, "zipopt %s: %s; nothing was written\n", cmd, err);
        return -1;
    }
    return zp_cli_out_commit(t, cmd);
}

double zp_cli_since(const struct timespec *t0) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - t0->tv_sec) + 1e-9 * (double)(now.tv_nsec - t0->tv_nsec);
}

static void zp_cli_print_registries(FILE *f) {
    fprintf(f, "methods ([solver] method):\n");
    for (int i = 0; i < ZP_METHOD_COUNT; i++) {
        const zp_method *me = zp_method_get(i);
        fprintf(f, "  %-18s %s\n", me->name, me->doc);
    }
    fprintf(f, "formulations ([solver] formulation):\n");
    for (int i = 0; i < ZP_FORM_COUNT; i++) {
        const zp_formulation *fo = zp_formulation_get(i);
        fprintf(f, "  %-18s %s\n", fo->name, fo->doc);
    }
}

void zp_cli_usage(FILE *f) {
    fputs("Usage: zipopt [SCENE.ini] [OPTION]...\n"
          "  or:  zipopt simulate SCENE.ini [OPTION]...\n"
          "  or:  zipopt check SCENE.ini [--json] [--plot [--out DIR]]\n"
          "  or:  zipopt landscape SCENE.ini [OPTION]...\n"
          "  or:  zipopt tradeoff SCENE.ini [--levels P1,P2,..] [OPTION]...\n"
          "  or:  zipopt sweep SCENE.ini --vary SECTION.KEY=A:B:N [OPTION]...\n"
          "  or:  zipopt bench trade [SCENE.ini] [OPTION]...\n"
          "  or:  zipopt --help | --help-all | --version\n"
          "Simulates a trolley on a zipline course carrying a hanging chain of links (the\n"
          "spy) and searches for the fastest survivable schedule of drive forces.\n"
          "\n"
          "Commands:\n"
          "  (none)      Search for the fastest survivable schedule of drive forces (one per\n"
          "              course section), verify it 100x tighter and write report.md,\n"
          "              schedule.ini, summary.json, the best run's trajectory and figures to\n"
          "              out/<scene name>/search/ (or DIR). With no file: the built-in seed scene.\n"
          "  simulate    Run one schedule through the simulator: --force or --schedule\n"
          "              replace the scene's [drive] forces (N); --json prints the result as\n"
          "              JSON. Writes trajectory.csv and summary.json; --plot also draws the\n"
          "              run with gnuplot (course, energy, angles, loads, frames, run.gif).\n"
          "  check       Validate a scene file and print its course (sections, derivatives,\n"
          "              kinks), body, drive, solver and search settings. Writes nothing;\n"
          "              --plot draws a [cable] scene's paths (cable.png).\n"
          "  landscape   The survival landscape: finish time or death over a constant push,\n"
          "              and over two sections' forces through a base schedule (run in\n"
          "              parallel); writes landscape.csv/.png (and landscape_slice.*).\n"
          "  tradeoff    The robust search at each force error level (%, default\n"
          "              0,1,2,5,10): what robustness costs; writes tradeoff.csv,\n"
          "              tradeoff.png and report.md.\n"
          "  sweep       A design study: the search (or one run) at every point of a grid of\n"
          "              scene values; sweep.csv, sweep.png, summary.json in\n"
          "              out/<scene name>/sweep/. Under `mpirun -np N` the points are spread\n"
          "              over the ranks.\n"
          "  bench       bench trade: work-precision study of every method over rtol\n"
          "              1e-3..1e-12; writes out/<scene name>/bench/trade.*.\n"
          "Each command's options: zipopt COMMAND --help (the search's: zipopt SCENE --help);\n"
          "all of them: zipopt --help-all (the text of the man page zipopt(1)). Options take\n"
          "--name VALUE or --name=VALUE, before or after the scene file; -- ends them.\n"
          "\n"
          "Exit status: 0 done (a spy that dies is a result, not an error); 2 bad input\n"
          "(command line or scene file, with FILE:LINE: [section] key: messages on stderr);\n"
          "3 the search found no schedule that keeps the margin, the [limits] and the\n"
          "[robust] scenarios (the closest candidate is still written, marked); 1 anything\n"
          "else.\n"
          "Documentation: docs/model.md (the physics), docs/scene-file.md (every scene key),\n"
          "docs/commands.md (commands, files, JSON keys), installed in share/doc/zipopt/;\n"
          "example scenes in config/ (installed: share/zipopt/scenes/).\n"
          "\n",
          f);
    zp_cli_print_registries(f);
}
