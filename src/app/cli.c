/* What the commands share (CLI.md): the scene argument, the output folder, number lists, and
   the usage text with the method and formulation registries. */
#include "cli.h"

#include "formulation.h"
#include "method.h"
#include "numtext.h"

int zp_cli_parse_list(const char *text, double *out, int max, char *why, size_t whylen) {
    return zp_text_list(text, out, max, why, whylen);
}

int zp_cli_scene_arg(const char *cmd, const char *arg, const char **scene) {
    const char *sp = *cmd ? " " : "";
    if (arg[0] == '-' || *scene) {
        fprintf(stderr, "zipopt%s%s: %s '%s'%s; see zipopt%s%s --help\n", sp, cmd,
                arg[0] == '-' ? "unknown option or missing value" : "unexpected argument", arg,
                arg[0] == '-' ? "" : " (one scene file only)", sp, cmd);
        return -1;
    }
    *scene = arg;
    return 0;
}

void zp_cli_out_dir(const char *out, const zp_scene *sc, char *dir, size_t cap) {
    if (out) {
        snprintf(dir, cap, "%s", out);
    } else {
        snprintf(dir, cap, "out/%s", sc->name);
    }
}

void zp_cli_print_registries(FILE *f) {
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
    fputs("usage:\n"
          "  zipopt [SCENE.ini] [--out DIR] [--algorithm NAME] [--seed N] [--max-evals N]\n"
          "         [--no-plot]\n"
          "      Search for the fastest survivable schedule of drive forces (one per course\n"
          "      section), verify it 100x tighter and write report.md, schedule.ini,\n"
          "      summary.json, the best run's trajectory and figures to out/<scene name>/\n"
          "      (or DIR). With no file: the built-in seed scene. See zipopt SCENE --help.\n"
          "  zipopt simulate SCENE.ini [--force F1,F2,..] [--schedule FILE] [--json]\n"
          "                  [--sample-times T1,T2,..] [--out DIR]\n"
          "      Run one schedule through the simulator: --force or --schedule replace the\n"
          "      scene's [drive] forces (N); --json prints the result as JSON; --sample-times\n"
          "      also reports the state at those times (s). Writes trajectory.csv and\n"
          "      summary.json; --plot [--frames-at ..] [--animate] also draws the run with\n"
          "      gnuplot (course, energy, angles, loads, still frames, run.gif). See zipopt\n"
          "      simulate --help.\n"
          "  zipopt check SCENE.ini\n"
          "      Validate a scene file and print its course (sections, derivatives, kinks),\n"
          "      body, drive, solver and search settings. Writes nothing.\n"
          "  zipopt tradeoff SCENE.ini [--levels P1,P2,..] [--out DIR]\n"
          "      The robust search at each force error level (%, default 0,1,2,5,10): what\n"
          "      robustness costs; writes tradeoff.csv, tradeoff.png and report.md.\n"
          "  zipopt bench trade [SCENE.ini] [--repeats N] [--out DIR]\n"
          "      Work-precision study of every method over rtol 1e-3..1e-12; writes\n"
          "      out/bench/trade.csv, trade.gp and trade.png. See zipopt bench --help.\n"
          "  zipopt landscape SCENE.ini [--force-range A:B:N] [--slice I,J [--range ..]]\n"
          "                  [--force F1,..|--schedule FILE] [--out DIR]\n"
          "      The survival landscape: finish time or death over a constant push, and over\n"
          "      two sections' forces through a base schedule (run in parallel); writes\n"
          "      landscape.csv/.png (and landscape_slice.*). See zipopt landscape --help.\n"
          "  zipopt --help | --version\n"
          "\n"
          "Exit status: 0 done (a spy that dies is a result, not an error); 2 bad input\n"
          "(command line or scene file, with FILE:LINE: [section] key: messages on stderr);\n"
          "1 anything else. Scene files: see CONFIG.md; config/ holds examples.\n"
          "\n",
          f);
    zp_cli_print_registries(f);
}
