/* `zipopt check SCENE.ini` (docs/commands.md): validates a scene (docs/scene-file.md) as every
   command would and prints what it describes: course sections with exact derivatives, boundaries,
   body, settings. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable_text.h"
#include "cli.h"
#include "formulation.h"
#include "method.h"
#include "out_json.h"
#include "scene_read.h"
#include "search.h"
#include "setup.h"
#include "sim.h"

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

static const char *method_doc(const char *name) {
    int i = zp_method_find(name);
    return i < 0 ? "" : zp_method_get(i)->doc;
}

static const char *formulation_doc(const char *name) {
    int i = zp_formulation_find(name);
    return i < 0 ? "" : zp_formulation_get(i)->doc;
}

/* the model decides what counts as a kink; check only reports it */
static void print_course(const zp_model *m) {
    printf("course: %d section%s, x from %g to %g m\n", m->nsec, m->nsec == 1 ? "" : "s", m->xb[0],
           m->xb[m->nsec]);
    if (m->cable_paths) {
        for (int k = 0; k < m->nsec; k++) {
            printf("  drive section %d: x in [%g, %g] m\n", k + 1, m->xb[k], m->xb[k + 1]);
        }
        printf("  the path of the loaded cable: smooth, no kinks (below)\n");
        return;
    }
    for (int k = 0; k < m->nsec; k++) {
        printf("  section %d: x in [%g, %g] m\n", k + 1, m->xb[k], m->xb[k + 1]);
        printf("    f(x)   = %s\n", m->expr[k]);
        /* libmatheval's derivative text is unsimplified: its values at the ends say more */
        for (int end = 0; end < 2; end++) {
            zp_track t = zp_course_eval(m->course, k, m->xb[k + end]);
            printf("    at x = %g: f = %.10g m, f' = %.10g, f'' = %.10g 1/m\n", m->xb[k + end], t.f,
                   t.fp, t.fpp);
        }
    }
    if (m->nsec == 1) {
        return;
    }
    printf("boundaries:\n");
    for (int k = 1; k < m->nsec; k++) {
        double x = m->xb[k];
        zp_track l = zp_course_eval(m->course, k - 1, x), r = zp_course_eval(m->course, k, x);
        int kink = zp_model_is_kink(m, k - 1);
        /* 10 digits: typed back, the height is within the continuity tolerance 1e-9 (1 + |y|) */
        printf("  x = %g m, y = %.10g m: slope %.6g -> %.6g (jump %+.6g, %.3g deg): %s\n", x, l.f,
               l.fp, r.fp, r.fp - l.fp, (atan(r.fp) - atan(l.fp)) * 180 / M_PI,
               kink ? "kink" : "smooth");
    }
    for (int i = 0; i < m->narc; i++) {
        const zp_arc *a = &m->arc[i];
        printf("  arc %d (kink at x = %g m): radius %g m over x in [%.6g, %.6g] m, centre (%.6g, "
               "%.6g) m\n",
               i + 1, m->kink[a->kink].x, a->r, a->x1, a->x2, a->cx, a->cy);
    }
}

/* the [physics] effects the model carries */
static void print_physics(const zp_scene *sc, const zp_model *m) {
    if (!m->physics) {
        return;
    }
    printf("physics:");
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        if (m->physics >> e & 1) {
            zp_effect_get(e)->describe(m, sc, stdout);
        }
    }
    putchar('\n');
}

static void print_scene(const zp_problem *st) {
    const zp_scene *sc = &st->sc;
    const zp_model *m = st->m;
    printf("scene: %s (%s)\n", sc->name, sc->path);
    printf("gravity: %g m/s^2\n", m->g);
    print_course(m);
    printf("trolley: mass %g kg\n", m->m0);
    printf("body: %d link%s, death angle %g deg%s\n", m->nlink, m->nlink == 1 ? "" : "s",
           sc->death_angle, sc->ndeath > 1 ? " at most (one per joint below)" : "");
    for (int i = 0; i < m->nlink; i++) {
        printf("  link %d: length %g m, mass %g kg, inertia %.6g kg m^2, damping %g N m s/rad",
               i + 1, m->len[i], m->mass[i], m->inertia[i], m->damp[i]);
        if (sc->ndeath > 1) {
            printf(", death angle %g deg", sc->death_angles[i]);
        }
        putchar('\n');
    }
    printf("drive: %s; forces:", zp_drive_dir_name(m->drive));
    for (int k = 0; k < m->nsec; k++) {
        char label[64];
        zp_schedule_label(&st->sched, k, label, sizeof label);
        printf("%s %s", k ? "," : "", label);
    }
    printf("%s; search bounds [%g, %g] N\n", sc->nforce ? "" : " (none given)", sc->force_min,
           sc->force_max);
    /* st->sim: with [solver] accuracy, the method and tolerances picked for it */
    const char *method = zp_method_get(st->sim.method)->name;
    printf("solver: method %s (%s); formulation %s (%s)\n", method, method_doc(method),
           sc->formulation, formulation_doc(sc->formulation));
    printf("        rtol %g, atol %g, t_max %g s, output_dt %g s\n", st->sim.rtol, st->sim.atol,
           sc->t_max, sc->output_dt);
    if (sc->accuracy > 0) {
        printf("        picked for accuracy %g s (work-precision table; simulate tightens it "
               "until its error estimate meets it)\n",
               sc->accuracy);
    }
    printf("optimize: margin %g deg, max_evals %ld%s, seed %lu\n", sc->margin,
           sc->line_max_evals ? sc->max_evals : zp_search_default_budget(st->sched.np),
           sc->line_max_evals ? "" : " (the search's default)", sc->seed);
    zp_scene_print_optional(sc, stdout, 0);
    print_physics(sc, m);
    zp_cable_text_print(stdout, m, sc);
    printf("added by zipopt (keys the file does not give, with the values taken):\n");
    zp_scene_print_added(sc, stdout, "  ");
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

static void json_list(const char *key, const double *v, int n, const char *sep) {
    printf("\"%s\": [", key);
    for (int i = 0; i < n; i++) {
        printf("%s", i ? ", " : "");
        zp_out_json_number(stdout, v[i]);
    }
    printf("]%s", sep);
}

static void json_num(const char *key, double v, const char *sep) {
    printf("\"%s\": ", key);
    zp_out_json_number(stdout, v);
    printf("%s", sep);
}

static void json_str(const char *key, const char *v, const char *sep) {
    printf("\"%s\": ", key);
    zp_out_json_string(stdout, v);
    printf("%s", sep);
}

/* --json: the scene as read (README "check --json"), one object on stdout */
static void print_json(const zp_problem *st) {
    const zp_scene *sc = &st->sc;
    const zp_model *m = st->m;
    printf("{");
    json_str("scene", sc->name, ", ");
    json_str("path", sc->path, ", ");
    json_num("gravity", m->g, ", ");
    printf("\"sections\": [");
    for (int k = 0; k < m->nsec; k++) {
        printf("%s{", k ? ", " : "");
        json_num("x_start", m->xb[k], ", ");
        json_num("x_end", m->xb[k + 1], ", ");
        json_str("f", m->expr[k], "}");
    }
    printf("], \"boundaries\": [");
    for (int k = 1; k < m->nsec; k++) {
        zp_track l = zp_course_eval(m->course, k - 1, m->xb[k]);
        zp_track r = zp_course_eval(m->course, k, m->xb[k]);
        printf("%s{", k > 1 ? ", " : "");
        json_num("x", m->xb[k], ", ");
        json_num("y", l.f, ", ");
        json_num("slope_left", l.fp, ", ");
        json_num("slope_right", r.fp, ", ");
        printf("\"kink\": %s}", zp_model_is_kink(m, k - 1) ? "true" : "false");
    }
    printf("], ");
    json_num("trolley_mass", m->m0, ", ");
    json_num("death_angle", sc->death_angle, ", ");
    json_list("lengths", m->len, m->nlink, ", ");
    json_list("masses", m->mass, m->nlink, ", ");
    json_list("inertias", m->inertia, m->nlink, ", ");
    json_list("damping", m->damp, m->nlink, ", ");
    json_str("drive", zp_drive_dir_name(m->drive), ", ");
    json_list("forces", sc->forces, sc->nforce, ", ");
    json_num("force_min", sc->force_min, ", ");
    json_num("force_max", sc->force_max, ", ");
    json_str("method", zp_method_get(st->sim.method)->name, ", ");
    json_str("formulation", sc->formulation, ", ");
    json_num("rtol", st->sim.rtol, ", ");
    json_num("atol", st->sim.atol, ", ");
    json_num("accuracy", sc->accuracy > 0 ? sc->accuracy : NAN, ", ");
    json_num("t_max", sc->t_max, ", ");
    json_num("output_dt", sc->output_dt, ", ");
    json_num("margin", sc->margin, ", ");
    printf("\"max_evals\": %ld, \"seed\": %lu, ", sc->max_evals, sc->seed);
    zp_scene_print_optional(sc, stdout, 1);
    printf("}\n");
}

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
    if (json) {
        print_json(&st);
    } else {
        print_scene(&st);
    }
    warn_forces(&st);
    zp_setup_free(&st);
    return ZP_EXIT_OK;
}
