/* The scene reader's second pass for the sections of the original study: one reader per INI
   section, each turning its keys' raw text into zp_scene fields with the per-key rules. */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "course.h"
#include "numtext.h"
#include "scene_parse.h"

/* a name that is one folder: letters, digits, `.`, `_`, `-`, no leading dot, not empty */
static int plain_name(const char *name) {
    return name[0] && name[0] != '.' &&
           strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") ==
               strlen(name);
}

/* text for a message, control bytes shown as `?` (static buffer: one use per message) */
static const char *shown(const char *text) {
    static char buf[256];
    size_t k = 0;
    for (; text[k] && k + 1 < sizeof buf; k++) {
        buf[k] = (unsigned char)text[k] < 0x20 || text[k] == 0x7f ? '?' : text[k];
    }
    buf[k] = '\0';
    return buf;
}

/* the name becomes a folder under out/, so it may not climb or nest; the default, the file's
   stem, obeys the same rule */
void zp_scene_read_scene(parse_ctx *c, zp_scene *sc) {
    char name[ZP_NAME_MAX];
    int given = zp_scene_get_text(c, K_NAME, name, sizeof name);
    if (given > 0 && !plain_name(name)) {
        zp_scene_bad_key(c, K_NAME, "`%s` is not a plain folder name", shown(name));
    } else if (given > 0) {
        strcpy(sc->name, name);
    } else if (!given && !plain_name(sc->name) && c->need_name) {
        zp_scene_bad(c, 0, "scene", "name",
                     "missing, and the file's name `%s` gives no plain folder name; expected %s",
                     shown(c->file), zp_scene_keys[K_NAME].expect);
    } else if (!given && !plain_name(sc->name)) {
        sc->name[0] = '\0'; /* no folder is made from it: the scene has no name */
    }
    zp_scene_get_number(c, K_GRAVITY, R_NONNEG, &sc->gravity);
}

/* one `section = x_end : f(x)` line (k, 0-based); prev is the x it must pass (prev_ok: known),
   y0 the previous section's end height (NULL: none known; prev_bad: that section is in error).
   1 when x_end is known. */
static int read_section(parse_ctx *c, zp_scene *sc, int k, int prev_ok, double prev,
                        const double *y0, int prev_bad) {
    int line = c->sect_line[k];
    char *text = c->sect_val[k];
    sc->sec_line[k] = line;
    char *colon = strchr(text, ':');
    if (!colon) {
        zp_scene_bad(c, line, "course", "section", "`%s` has no `:`; expected `x_end : f(x)`",
                     text);
        return 0;
    }
    *colon = '\0';
    char *expr = colon + 1;
    zp_text_trim(text);
    zp_text_trim(expr);
    int ok = 1;
    if (zp_text_number(text, &sc->x_end[k])) {
        zp_scene_bad(c, line, "course", "section",
                     "x_end `%s` is not a number; expected `x_end : f(x)`", text);
        ok = 0;
    } else if (prev_ok && !(sc->x_end[k] > prev)) {
        zp_scene_bad(c, line, "course", "section",
                     "x_end %g is not past %g; expected x_end to increase past x_start and the "
                     "previous section's x_end",
                     sc->x_end[k], prev);
    }
    char why[ZP_DIAG_TEXT / 2];
    int st = zp_scene_expr_subst(expr, k > 0, y0, sc->expr[k], ZP_EXPR_MAX, why, sizeof why);
    if (st == 0 && zp_course_check(sc->expr[k], why, sizeof why)) {
        st = -1;
    }
    /* y0 unknown after a previous section in error: that error is already reported */
    if (st == -1 || (st == -2 && !prev_bad)) {
        zp_scene_bad(c, line, "course", "section", "f(x) = `%s`: %s", expr, why);
    }
    if (st) {
        sc->expr[k][0] = '\0';
    }
    return ok;
}

void zp_scene_read_course(parse_ctx *c, zp_scene *sc) {
    int have_start = zp_scene_get_number(c, K_X_START, R_ANY, &sc->x_start);
    if (!have_start) {
        zp_scene_missing(c, K_X_START, "where the trolley starts (m)");
    }
    if (c->nsect == 0) {
        zp_scene_missing(c, K_SECTION, "at least one `section = x_end : f(x)` line");
    }
    sc->nsec = c->nsect < ZP_MAX_SECTIONS ? c->nsect : ZP_MAX_SECTIONS;
    int prev_ok = have_start > 0;
    double prev = sc->x_start;
    for (int k = 0; k < sc->nsec; k++) {
        /* y0 of section k: where section k - 1 ends, known when both its x_end and f are */
        double y0;
        int have_y0 = k > 0 && prev_ok && sc->expr[k - 1][0] &&
                      zp_scene_expr_end(sc->expr[k - 1], prev, &y0) == 0;
        int prev_bad = k > 0 && (!prev_ok || !sc->expr[k - 1][0]);
        prev_ok = read_section(c, sc, k, prev_ok, prev, have_y0 ? &y0 : NULL, prev_bad);
        prev = sc->x_end[k];
    }
}

void zp_scene_read_trolley(parse_ctx *c, zp_scene *sc) {
    if (!zp_scene_get_number(c, K_MASS, R_POS, &sc->trolley_mass)) {
        zp_scene_missing(c, K_MASS, "the trolley's mass (kg)");
    }
}

/* lengths say how many links; masses and damping follow them */
void zp_scene_read_body(parse_ctx *c, zp_scene *sc) {
    int nlen = zp_scene_get_list(c, K_LENGTHS, R_POS, sc->lengths, ZP_MAX_LINKS);
    if (nlen == 0) {
        zp_scene_missing(c, K_LENGTHS, "the links' lengths (m), 1 to 8 of them");
    } else if (nlen > 0) {
        sc->nlink = nlen;
    }
    double tmp[ZP_MAX_LINKS];
    int nmass = zp_scene_get_list(c, K_MASSES, R_POS, tmp, ZP_MAX_LINKS);
    if (nmass == 0) {
        zp_scene_missing(c, K_MASSES, "the links' masses (kg), one per link");
    } else if (nmass > 0 && nlen > 0 && nmass != nlen) {
        zp_scene_bad_count(c, K_MASSES, nmass, "%d (one per link)", nlen);
    } else if (nmass > 0) {
        memcpy(sc->masses, tmp, (size_t)nmass * sizeof *tmp);
    }
    int ndamp = zp_scene_get_list(c, K_DAMPING, R_NONNEG, tmp, ZP_MAX_LINKS);
    if (ndamp > 1 && nlen > 0 && ndamp != nlen) {
        zp_scene_bad_count(c, K_DAMPING, ndamp, "1 or %d (one per joint)", nlen);
    } else if (ndamp > 0) {
        /* one value serves every joint; stored for each so readers need not branch */
        sc->ndamping = ndamp;
        for (int i = 0; i < ZP_MAX_LINKS; i++) {
            sc->damping[i] = ndamp == 1 ? tmp[0] : i < ndamp ? tmp[i] : 0;
        }
    }
    /* one value for every joint or one per joint, each in (0, 360] */
    int ndeath = zp_scene_get_list(c, K_DEATH_ANGLE, R_POS, tmp, ZP_MAX_LINKS);
    int fits = ndeath > 0;
    for (int i = 0; i < ndeath; i++) {
        if (tmp[i] > 360) {
            zp_scene_bad_key(c, K_DEATH_ANGLE, "%g is out of range", tmp[i]);
            fits = 0;
            break;
        }
    }
    if (fits && ndeath > 1 && nlen > 0 && ndeath != nlen) {
        zp_scene_bad_count(c, K_DEATH_ANGLE, ndeath, "1 or %d (one per joint)", nlen);
    } else if (fits) {
        /* stored for each joint, as damping is; death_angle keeps the largest */
        sc->ndeath = ndeath;
        sc->death_angle = 0;
        for (int i = 0; i < ZP_MAX_LINKS; i++) {
            sc->death_angles[i] = i < ndeath ? tmp[i] : tmp[0];
        }
        for (int i = 0; i < ndeath; i++) {
            sc->death_angle = tmp[i] > sc->death_angle ? tmp[i] : sc->death_angle;
        }
    }
}

int zp_scene_read_forces(parse_ctx *c, int nsec, zp_schedule *s) {
    if (!c->key_line[K_FORCES]) {
        return 0;
    }
    char why[LINE_CAP + 64];
    int rc = zp_schedule_parse(c->forces_val, nsec, s, why, sizeof why);
    if (rc == -2) {
        c->key_bad[K_FORCES] = 1;
        zp_scene_bad(c, c->key_line[K_FORCES], "drive", zp_scene_keys[K_FORCES].name, "%s", why);
    } else if (rc) {
        zp_scene_bad_key(c, K_FORCES, "%s", why);
    }
    return rc ? -1 : 1;
}

void zp_scene_set_forces(zp_scene *sc, const zp_schedule *s) {
    sc->drive_kind = (int)s->kind;
    sc->nforce = s->np;
    memcpy(sc->forces, s->p, sizeof *s->p * (size_t)s->np);
}

/* the schedule's text is the drive module's to read */
void zp_scene_read_drive(parse_ctx *c, zp_scene *sc) {
    if (zp_scene_get_text(c, K_DIRECTION, sc->direction, sizeof sc->direction) >= 0 &&
        zp_drive_dir_find(sc->direction) < 0) {
        zp_scene_bad_key(c, K_DIRECTION, "unknown direction `%s`", sc->direction);
    }
    zp_schedule sched;
    if (zp_scene_read_forces(c, c->nsect, &sched) > 0) {
        zp_scene_set_forces(sc, &sched);
    }
    sc->line_forces = c->key_line[K_FORCES];
    zp_scene_get_number(c, K_MIN, R_ANY, &sc->force_min);
    zp_scene_get_number(c, K_MAX, R_ANY, &sc->force_max);
}

/* a tolerance in [lo, hi]: outside, the integrators either stall below round-off or answer
   nothing worth the name */
static void get_tolerance(parse_ctx *c, int k, double lo, double hi, double *out) {
    double v;
    if (zp_scene_get_number(c, k, R_POS, &v) > 0) {
        if (v < lo || v > hi) {
            zp_scene_bad_key(c, k, "%g is out of range", v);
        } else {
            *out = v;
        }
    }
}

/* accuracy asks zipopt to choose the tolerances: with rtol or atol beside it neither can be
   said to win, so both lines are named; a method beside it restricts the choice to it */
static void get_accuracy(parse_ctx *c, zp_scene *sc) {
    get_tolerance(c, K_ACCURACY, ZP_ACCURACY_MIN, ZP_ACCURACY_MAX, &sc->accuracy);
    const int tol[] = {K_RTOL, K_ATOL};
    for (int i = 0; i < 2 && c->key_line[K_ACCURACY]; i++) {
        if (c->key_line[tol[i]]) {
            zp_scene_bad_key(c, K_ACCURACY,
                             "given with %s on line %d; give one: accuracy (s on the finish "
                             "time) chooses the method's tolerances itself",
                             zp_scene_keys[tol[i]].name, c->key_line[tol[i]]);
        }
    }
}

/* method and formulation names are checked against their registries later */
void zp_scene_read_solver(parse_ctx *c, zp_scene *sc) {
    zp_scene_get_text(c, K_METHOD, sc->method, sizeof sc->method);
    zp_scene_get_text(c, K_FORMULATION, sc->formulation, sizeof sc->formulation);
    sc->line_method = c->key_line[K_METHOD];
    sc->line_formulation = c->key_line[K_FORMULATION];
    get_tolerance(c, K_RTOL, ZP_RTOL_MIN, ZP_RTOL_MAX, &sc->rtol);
    get_tolerance(c, K_ATOL, ZP_ATOL_MIN, ZP_ATOL_MAX, &sc->atol);
    get_accuracy(c, sc);
    double v;
    if (zp_scene_get_number(c, K_T_MAX, R_POS, &v) > 0) {
        if (v > ZP_T_MAX_MAX) {
            zp_scene_bad_key(c, K_T_MAX, "%g is out of range", v);
        } else {
            sc->t_max = v;
        }
    }
    zp_scene_get_number(c, K_OUTPUT_DT, R_POS, &sc->output_dt);
}

void zp_scene_read_optimize(parse_ctx *c, zp_scene *sc) {
    unsigned long u;
    zp_scene_get_number(c, K_MARGIN, R_NONNEG, &sc->margin);
    if (zp_scene_get_whole(c, K_MAX_EVALS, 1, LONG_MAX, &u) > 0) {
        sc->max_evals = (long)u;
        sc->line_max_evals = c->key_line[K_MAX_EVALS];
    }
    if (zp_scene_get_whole(c, K_SEED, 0, ULONG_MAX, &u) > 0) {
        sc->seed = u;
    }
    zp_scene_get_text(c, K_SEARCH_METHOD, sc->search_method, sizeof sc->search_method);
    char objective[16];
    if (zp_scene_get_text(c, K_OBJECTIVE, objective, sizeof objective) > 0) {
        if (strcmp(objective, "nominal") && strcmp(objective, "slowest")) {
            zp_scene_bad_key(c, K_OBJECTIVE, "'%s' is not an objective", objective);
        } else {
            sc->objective_slowest = !strcmp(objective, "slowest");
        }
    }
    sc->line_search_method = c->key_line[K_SEARCH_METHOD];
    get_tolerance(c, K_SEARCH_RTOL, ZP_RTOL_MIN, ZP_RTOL_MAX, &sc->search_rtol);
}
