/* `zipopt check`'s description of a scene (out_check.h): the text, and the JSON object. */
#include "out_check.h"

#include <math.h>
#include <string.h>

#include "cable_text.h"
#include "formulation.h"
#include "method.h"
#include "out_json.h"
#include "scene_load.h"

static const char *method_doc(const char *name) {
    int i = zp_method_find(name);
    return i < 0 ? "" : zp_method_get(i)->doc;
}

static const char *formulation_doc(const char *name) {
    int i = zp_formulation_find(name);
    return i < 0 ? "" : zp_formulation_get(i)->doc;
}

/* the model decides what counts as a kink; check only reports it */
static void course_text(FILE *f, const zp_model *m) {
    fprintf(f, "course: %d section%s, x from %g to %g m\n", m->nsec, m->nsec == 1 ? "" : "s",
            m->xb[0], m->xb[m->nsec]);
    if (m->cable_paths) {
        for (int k = 0; k < m->nsec; k++) {
            fprintf(f, "  drive section %d: x in [%g, %g] m\n", k + 1, m->xb[k], m->xb[k + 1]);
        }
        fprintf(f, "  the path of the loaded cable: smooth, no kinks (below)\n");
        return;
    }
    for (int k = 0; k < m->nsec; k++) {
        fprintf(f, "  section %d: x in [%g, %g] m\n", k + 1, m->xb[k], m->xb[k + 1]);
        fprintf(f, "    f(x)   = %s\n", m->expr[k]);
        /* libmatheval's derivative text is unsimplified: its values at the ends say more */
        for (int end = 0; end < 2; end++) {
            zp_track t = zp_course_eval(m->course, k, m->xb[k + end]);
            fprintf(f, "    at x = %g: f = %.10g m, f' = %.10g, f'' = %.10g 1/m\n", m->xb[k + end],
                    t.f, t.fp, t.fpp);
        }
    }
    if (m->nsec == 1) {
        return;
    }
    fprintf(f, "boundaries:\n");
    for (int k = 1; k < m->nsec; k++) {
        double x = m->xb[k];
        zp_track l = zp_course_eval(m->course, k - 1, x), r = zp_course_eval(m->course, k, x);
        int kink = zp_model_is_kink(m, k - 1);
        /* 10 digits: typed back, the height is within the continuity tolerance 1e-9 (1 + |y|) */
        fprintf(f, "  x = %g m, y = %.10g m: slope %.6g -> %.6g (jump %+.6g, %.3g deg): %s\n", x,
                l.f, l.fp, r.fp, r.fp - l.fp, (atan(r.fp) - atan(l.fp)) * 180 / M_PI,
                kink ? "kink" : "smooth");
    }
    for (int i = 0; i < m->narc; i++) {
        const zp_arc *a = &m->arc[i];
        fprintf(f,
                "  arc %d (kink at x = %g m): radius %g m over x in [%.6g, %.6g] m, centre (%.6g, "
                "%.6g) m\n",
                i + 1, m->kink[a->kink].x, a->r, a->x1, a->x2, a->cx, a->cy);
    }
}

/* the [physics] effects the model carries */
static void physics_text(FILE *f, const zp_scene *sc, const zp_model *m) {
    if (!m->physics) {
        return;
    }
    fprintf(f, "physics:");
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        if (m->physics >> e & 1) {
            zp_effect_get(e)->describe(m, sc, f);
        }
    }
    fputc('\n', f);
}

static void body_text(FILE *f, const zp_scene *sc, const zp_model *m) {
    fprintf(f, "trolley: mass %g kg\n", m->m0);
    fprintf(f, "body: %d link%s, death angle %g deg%s\n", m->nlink, m->nlink == 1 ? "" : "s",
            sc->death_angle, sc->ndeath > 1 ? " at most (one per joint below)" : "");
    for (int i = 0; i < m->nlink; i++) {
        fprintf(f, "  link %d: length %g m, mass %g kg, inertia %.6g kg m^2, damping %g N m s/rad",
                i + 1, m->len[i], m->mass[i], m->inertia[i], m->damp[i]);
        if (sc->ndeath > 1) {
            fprintf(f, ", death angle %g deg", sc->death_angles[i]);
        }
        fputc('\n', f);
    }
}

/* the drive, the solver (with [solver] accuracy, the method and tolerances picked for it) and
   the search's settings */
static void settings_text(FILE *f, const zp_out_check *c) {
    const zp_scene *sc = c->sc;
    fprintf(f, "drive: %s; forces:", zp_drive_dir_name(c->m->drive));
    for (int k = 0; k < c->m->nsec; k++) {
        char label[64];
        zp_drive_section_label(c->sched, k, label, sizeof label);
        fprintf(f, "%s %s", k ? "," : "", label);
    }
    fprintf(f, "%s; search bounds [%g, %g] N", sc->nforce ? "" : " (none given)", sc->force_min,
            sc->force_max);
    if (c->m->ndrive) {
        fprintf(f, "; response %g s (the applied force lags the schedule)", c->m->drive_response);
    }
    fputc('\n', f);
    const char *method = zp_method_get(c->sim->method)->name;
    fprintf(f, "solver: method %s (%s); formulation %s (%s)\n", method, method_doc(method),
            sc->formulation, formulation_doc(sc->formulation));
    fprintf(f, "        rtol %g, atol %g, t_max %g s, output_dt %g s\n", c->sim->rtol, c->sim->atol,
            sc->t_max, sc->output_dt);
    if (sc->accuracy > 0) {
        fprintf(f,
                "        picked for accuracy %g s (work-precision table; simulate tightens it "
                "until its error estimate meets it)\n",
                sc->accuracy);
    }
    fprintf(f, "optimize: margin %g deg, max_evals %ld%s, seed %lu\n", sc->margin, c->max_evals,
            sc->line_max_evals ? "" : " (the search's default)", sc->seed);
}

void zp_out_check_text(FILE *f, const zp_out_check *c) {
    const zp_scene *sc = c->sc;
    fprintf(f, "scene: %s (%s)\n", sc->name, sc->path);
    fprintf(f, "gravity: %g m/s^2\n", c->m->g);
    course_text(f, c->m);
    body_text(f, sc, c->m);
    settings_text(f, c);
    zp_scene_show_optional(sc, f, 0, NULL, NULL);
    physics_text(f, sc, c->m);
    zp_cable_text_print(f, c->m, sc);
    fprintf(f, "added by zipopt (keys the file does not give, with the values taken):\n");
    zp_scene_show_added(sc, f, "  ");
}

/* "key": [v, ..], then sep */
static void key_list(FILE *f, const char *key, const double *v, int n, const char *sep) {
    fprintf(f, "\"%s\": ", key);
    zp_out_json_list(f, v, n, 1.0);
    fputs(sep, f);
}

/* the course at the end of section k at x, from the left or the right: a cable's is its
   nominal rider's path (the scene's expressions are a placeholder it never reads) */
static zp_track course_at(const zp_model *m, int k, double x) {
    if (m->cable_path) {
        double t[3];
        zp_cable_path_track(m->cable_path, x, t);
        return (zp_track){t[0], t[1], t[2]};
    }
    return zp_course_eval(m->course, k, x);
}

static void course_json(FILE *f, const zp_model *m) {
    fprintf(f, "\"sections\": [");
    for (int k = 0; k < m->nsec; k++) {
        fprintf(f, "%s{", k ? ", " : "");
        zp_out_json_key(f, "x_start", m->xb[k], ", ");
        zp_out_json_key(f, "x_end", m->xb[k + 1], ", ");
        if (m->cable_paths) { /* no expression: the course is the cable's path ("cable") */
            fputs("\"f\": null}", f);
        } else {
            zp_out_json_key_string(f, "f", m->expr[k], "}");
        }
    }
    fprintf(f, "], \"boundaries\": [");
    for (int k = 1; k < m->nsec; k++) {
        zp_track l = course_at(m, k - 1, m->xb[k]);
        zp_track r = course_at(m, k, m->xb[k]);
        fprintf(f, "%s{", k > 1 ? ", " : "");
        zp_out_json_key(f, "x", m->xb[k], ", ");
        zp_out_json_key(f, "y", l.f, ", ");
        zp_out_json_key(f, "slope_left", l.fp, ", ");
        zp_out_json_key(f, "slope_right", r.fp, ", ");
        fprintf(f, "\"kink\": %s}", zp_model_is_kink(m, k - 1) ? "true" : "false");
    }
    fprintf(f, "], ");
}

/* the cable's equilibria after its keys in check --json's "cable" */
static void cable_more(FILE *f, const char *section, int n, const void *user) {
    const zp_out_check *c = user;
    if (!strcmp(section, "cable")) {
        zp_cable_text_json(f, c->m, c->sc, n);
    }
}

void zp_out_check_json(FILE *f, const zp_out_check *c) {
    const zp_scene *sc = c->sc;
    const zp_model *m = c->m;
    fprintf(f, "{");
    zp_out_json_key_string(f, "scene", sc->name, ", ");
    zp_out_json_key_string(f, "path", sc->path, ", ");
    zp_out_json_key(f, "gravity", m->g, ", ");
    course_json(f, m);
    zp_out_json_key(f, "trolley_mass", m->m0, ", ");
    zp_out_json_key(f, "death_angle", sc->death_angle, ", ");
    key_list(f, "lengths", m->len, m->nlink, ", ");
    key_list(f, "masses", m->mass, m->nlink, ", ");
    key_list(f, "inertias", m->inertia, m->nlink, ", ");
    key_list(f, "damping", m->damp, m->nlink, ", ");
    zp_out_json_key_string(f, "drive", zp_drive_dir_name(m->drive), ", ");
    key_list(f, "forces", sc->forces, sc->nforce, ", ");
    zp_out_json_key(f, "force_min", sc->force_min, ", ");
    zp_out_json_key(f, "force_max", sc->force_max, ", ");
    zp_out_json_key_string(f, "method", zp_method_get(c->sim->method)->name, ", ");
    zp_out_json_key_string(f, "formulation", sc->formulation, ", ");
    zp_out_json_key(f, "rtol", c->sim->rtol, ", ");
    zp_out_json_key(f, "atol", c->sim->atol, ", ");
    zp_out_json_key(f, "accuracy", sc->accuracy > 0 ? sc->accuracy : NAN, ", ");
    zp_out_json_key(f, "t_max", sc->t_max, ", ");
    zp_out_json_key(f, "output_dt", sc->output_dt, ", ");
    zp_out_json_key(f, "margin", sc->margin, ", ");
    fprintf(f, "\"max_evals\": %ld, \"seed\": %lu, ", sc->max_evals, sc->seed);
    zp_scene_show_optional(sc, f, 1, cable_more, c);
    fprintf(f, "}\n");
}
