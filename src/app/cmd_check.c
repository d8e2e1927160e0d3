/* `zipopt check SCENE.ini` (docs/commands.md): validates a scene (docs/scene-file.md) as every
   command would and prints what it describes: course sections with exact derivatives, boundaries,
   body, settings; with --plot, a cable scene's paths as a figure. */
#include <stdio.h>

#include "cli.h"
#include "fig_cable.h"
#include "out_check.h"
#include "setup.h"

static void usage(FILE *f) {
    fputs("usage: zipopt check SCENE.ini [--json] [--plot [--out DIR]]\n"
          "\n"
          "Validates a scene file against every rule of docs/scene-file.md (all problems\n"
          "are listed on stderr as FILE:LINE: [section] key: what; expected, with exit\n"
          "status 2) and prints the scene: each course section with f(x) and f, f', f'' at\n"
          "its ends; each boundary between sections with its height, slope jump and whether\n"
          "it is a kink; the trolley and the body's links (length, mass, inertia, damping);\n"
          "the drive, solver and search settings; the [limits], [robust] and [physics]\n"
          "settings; every key zipopt added with its value. Warns on stderr when a force\n"
          "lies outside [min, max]. Writes no files, but with --plot.\n"
          "  --json     print the scene as one JSON object instead (keys: docs/commands.md)\n"
          "  --plot     a [cable] scene: also draw cable.png (the rope alone and each rider's\n"
          "             loaded path between the anchors) with cable.gp and cable.dat in\n"
          "             out/<scene name>/check/ (or DIR)\n"
          "  --out DIR  the figure's folder\n",
          f);
}

/* cable.png and its files, committed as one transaction; the exit status (a failure said on
   stderr) */
static int plot(const zp_problem *st, const char *out, int json) {
    zp_tx t;
    char err[1400];
    int missing;
    if (zp_cli_out_begin(&t, "check", "check", out, &st->sc)) {
        return ZP_EXIT_FAIL;
    }
    if (zp_fig_cable_write(&t, st->m, &st->sc, err, sizeof err)) {
        zp_tx_abort(&t);
        fprintf(stderr, "zipopt check: %s; nothing was written\n", err);
        return ZP_EXIT_FAIL;
    }
    const char *scripts[] = {"cable.gp"};
    if (zp_cli_out_draw_commit(&t, "check", scripts, 1, &missing)) {
        return ZP_EXIT_FAIL;
    }
    /* stdout carries only the JSON object with --json */
    fprintf(json ? stderr : stdout, "wrote in %s: %s%s\n", t.dir, t.written,
            missing ? " (gnuplot is not installed: no cable.png)" : "");
    return ZP_EXIT_OK;
}

/* forces the search could never pick: legal for `simulate`, but worth a word */
static void warn_forces(const zp_problem *st) {
    const zp_schedule *sh = &st->sched;
    for (int i = 0; i < st->sc.nforce && i < sh->np; i++) {
        if (sh->p[i] < sh->lo[i] || sh->p[i] > sh->hi[i]) {
            fprintf(stderr,
                    "%s:%d: [drive] forces: warning: item %d (%g) is outside [min, max] = "
                    "[%g, %g], the search's bounds\n",
                    st->sc.path, st->sc.line_forces, i + 1, sh->p[i], sh->lo[i], sh->hi[i]);
        }
    }
}

enum { O_JSON = ZP_OPT_FIRST, O_PLOT, O_OUT };
static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"json", no_argument, NULL, O_JSON},
    {"plot", no_argument, NULL, O_PLOT},
    {"out", required_argument, NULL, O_OUT},
    {NULL, 0, NULL, 0},
};

int zp_cmd_check(int argc, char **argv) {
    const char *path = NULL, *out = NULL;
    int json = 0, want_plot = 0;
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("check", argc, argv, options)) != -1;) {
        if (c == 'h') {
            usage(stdout);
            return ZP_EXIT_OK;
        }
        if (c == O_JSON || c == O_PLOT) {
            json |= c == O_JSON;
            want_plot |= c == O_PLOT;
        } else if (c == O_OUT && !zp_cli_path_ok("check", "--out", optarg)) {
            out = optarg;
        } else {
            return ZP_EXIT_USAGE;
        }
    }
    if (out && !want_plot) {
        zp_cli_error("check", "--out names the figure's folder: it needs --plot");
        return ZP_EXIT_USAGE;
    }
    if (zp_cli_scene_operand("check", argc, argv, &path)) {
        return ZP_EXIT_USAGE;
    }
    if (!path) {
        zp_cli_error("check", "a scene file is required; see zipopt check --help");
        return ZP_EXIT_USAGE;
    }
    /* judged exactly as every command judges it, registry names included */
    static zp_problem st; /* large: kept off the stack */
    zp_overrides none = ZP_OVERRIDES_NONE;
    if (zp_setup_load("check", path, &none, &st)) {
        return ZP_EXIT_USAGE;
    }
    if (want_plot && !st.m->cable_paths) {
        zp_cli_error("check", "--plot: %s has no [cable]; a course's figure is `zipopt simulate "
                              "--plot`'s course.png",
                     st.sc.path);
        zp_setup_free(&st);
        return ZP_EXIT_USAGE;
    }
    zp_out_check view = {&st.sc, st.m, &st.sched, &st.sim, st.max_evals};
    if (json) {
        zp_out_check_json(stdout, &view);
    } else {
        zp_out_check_text(stdout, &view);
    }
    warn_forces(&st);
    int status = want_plot ? plot(&st, out, json) : ZP_EXIT_OK;
    zp_setup_free(&st);
    return status;
}
