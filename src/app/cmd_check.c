/* `zipopt check SCENE.ini` (docs/commands.md): validates a scene (docs/scene-file.md) as every
   command would and prints what it describes: course sections with exact derivatives, boundaries,
   body, settings. */
#include <stdio.h>

#include "cli.h"
#include "out_check.h"
#include "setup.h"

static void usage(FILE *f) {
    fputs("usage: zipopt check SCENE.ini [--json]\n"
          "\n"
          "Validates a scene file against every rule of docs/scene-file.md (all problems\n"
          "are listed on stderr as FILE:LINE: [section] key: what; expected, with exit\n"
          "status 2) and prints the scene: each course section with f(x) and f, f', f'' at\n"
          "its ends; each boundary between sections with its height, slope jump and whether\n"
          "it is a kink; the trolley and the body's links (length, mass, inertia, damping);\n"
          "the drive, solver and search settings; the [limits], [robust] and [physics]\n"
          "settings; every key zipopt added with its value. Warns on stderr when a force\n"
          "lies outside [min, max]. Writes no files.\n"
          "  --json   print the scene as one JSON object instead (keys: docs/commands.md)\n",
          f);
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

static const struct option options[] = {
    {"help", no_argument, NULL, 'h'},
    {"json", no_argument, NULL, ZP_OPT_FIRST},
    {NULL, 0, NULL, 0},
};

int zp_cmd_check(int argc, char **argv) {
    const char *path = NULL;
    int json = 0;
    zp_cli_opts_begin();
    for (int c; (c = zp_cli_opts_next("check", argc, argv, options)) != -1;) {
        if (c == 'h') {
            usage(stdout);
            return ZP_EXIT_OK;
        }
        if (c != ZP_OPT_FIRST) {
            return ZP_EXIT_USAGE;
        }
        json = 1;
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
    zp_out_check view = {&st.sc, st.m, &st.sched, &st.sim, st.max_evals};
    if (json) {
        zp_out_check_json(stdout, &view);
    } else {
        zp_out_check_text(stdout, &view);
    }
    warn_forces(&st);
    zp_setup_free(&st);
    return ZP_EXIT_OK;
}
