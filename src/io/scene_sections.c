/* The readers of the special keys of the original study's sections (scene_keys.def): the name,
   the course's sections, the body's lists, the drive's direction and forces, accuracy and the
   objective, each turning its key's raw text into zp_scene members with the key's rules. */
#include <stdio.h>
#include <string.h>

#include "course.h"
#include "text.h"
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
void zp_scene_sections_name(parse_ctx *c, zp_scene *sc, int k) {
    char name[ZP_NAME_MAX];
    int given = zp_scene_values_text(c, k, name, sizeof name);
    if (given > 0 && !plain_name(name)) {
        zp_scene_values_bad_key(c, k, "`%s` is not a plain folder name", shown(name));
    } else if (given > 0) {
        strcpy(sc->name, name);
    } else if (!given && !plain_name(sc->name) && c->need_name) {
        zp_scene_lines_bad(c, 0, "scene", "name",
                     "missing, and the file's name `%s` gives no plain folder name; expected %s",
                     shown(c->file), zp_scene_keys[k].expect);
    } else if (!given && !plain_name(sc->name)) {
        sc->name[0] = '\0'; /* no folder is made from it: the scene has no name */
    }
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
        zp_scene_lines_bad(c, line, "course", "section", "`%s` has no `:`; expected `x_end : f(x)`",
                     text);
        return 0;
    }
    *colon = '\0';
    char *expr = colon + 1;
    zp_text_trim(text);
    zp_text_trim(expr);
    int ok = 1;
    if (zp_text_number(text, &sc->x_end[k])) {
        zp_scene_lines_bad(c, line, "course", "section",
                     "x_end `%s` is not a number; expected `x_end : f(x)`", text);
        ok = 0;
    } else if (prev_ok && !(sc->x_end[k] > prev)) {
        zp_scene_lines_bad(c, line, "course", "section",
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
        zp_scene_lines_bad(c, line, "course", "section", "f(x) = `%s`: %s", expr, why);
    }
    if (st) {
        sc->expr[k][0] = '\0';
    }
    return ok;
}

/* every `section` line, in order: each must start where x_start (read before) or the previous
   section ends */
void zp_scene_sections_section(parse_ctx *c, zp_scene *sc, int k) {
    (void)k; /* the key repeats: its lines and values are kept apart (sect_line, sect_val) */
    sc->nsec = c->nsect < ZP_MAX_SECTIONS ? c->nsect : ZP_MAX_SECTIONS;
    int prev_ok = c->key_line[K_X_START] && !c->key_bad[K_X_START];
    double prev = sc->x_start;
    for (int i = 0; i < sc->nsec; i++) {
        /* y0 of section i: where section i - 1 ends, known when both its x_end and f are */
        double y0;
        int have_y0 = i > 0 && prev_ok && sc->expr[i - 1][0] &&
                      zp_scene_expr_end(sc->expr[i - 1], prev, &y0) == 0;
        int prev_bad = i > 0 && (!prev_ok || !sc->expr[i - 1][0]);
        prev_ok = read_section(c, sc, i, prev_ok, prev, have_y0 ? &y0 : NULL, prev_bad);
        prev = sc->x_end[i];
    }
}

/* lengths say how many links (nlink, 0 until they are accepted); the other lists follow them */
void zp_scene_sections_lengths(parse_ctx *c, zp_scene *sc, int k) {
    int nlen = zp_scene_values_list(c, k, R_POS, sc->lengths, ZP_MAX_LINKS);
    if (nlen > 0) {
        sc->nlink = nlen;
    }
}

void zp_scene_sections_masses(parse_ctx *c, zp_scene *sc, int k) {
    double tmp[ZP_MAX_LINKS];
    int nmass = zp_scene_values_list(c, k, R_POS, tmp, ZP_MAX_LINKS);
    if (nmass > 0 && sc->nlink > 0 && nmass != sc->nlink) {
        zp_scene_values_bad_count(c, k, nmass, "%d (one per link)", sc->nlink);
    } else if (nmass > 0) {
        memcpy(sc->masses, tmp, (size_t)nmass * sizeof *tmp);
    }
}

void zp_scene_sections_damping(parse_ctx *c, zp_scene *sc, int k) {
    double tmp[ZP_MAX_LINKS];
    int ndamp = zp_scene_values_list(c, k, R_NONNEG, tmp, ZP_MAX_LINKS);
    if (ndamp > 1 && sc->nlink > 0 && ndamp != sc->nlink) {
        zp_scene_values_bad_count(c, k, ndamp, "1 or %d (one per joint)", sc->nlink);
    } else if (ndamp > 0) {
        /* one value serves every joint; stored for each so readers need not branch */
        sc->ndamping = ndamp;
        for (int i = 0; i < ZP_MAX_LINKS; i++) {
            sc->damping[i] = ndamp == 1 ? tmp[0] : i < ndamp ? tmp[i] : 0;
        }
    }
}

/* one value for every joint or one per joint, each in (0, 360] */
void zp_scene_sections_death_angle(parse_ctx *c, zp_scene *sc, int k) {
    double tmp[ZP_MAX_LINKS];
    int ndeath = zp_scene_values_list(c, k, R_POS, tmp, ZP_MAX_LINKS);
    int fits = ndeath > 0;
    for (int i = 0; i < ndeath; i++) {
        if (tmp[i] > 360) {
            zp_scene_values_bad_key(c, k, "%g is out of range", tmp[i]);
            fits = 0;
            break;
        }
    }
    if (fits && ndeath > 1 && sc->nlink > 0 && ndeath != sc->nlink) {
        zp_scene_values_bad_count(c, k, ndeath, "1 or %d (one per joint)", sc->nlink);
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

int zp_scene_sections_parse_forces(parse_ctx *c, const zp_schedule *shape, zp_schedule *s) {
    if (!c->key_line[K_FORCES]) {
        return 0;
    }
    char why[LINE_CAP + 64];
    int rc = zp_drive_parse(shape, c->forces_val, s, why, sizeof why);
    if (rc == -2) {
        c->key_bad[K_FORCES] = 1;
        zp_scene_lines_bad(c, c->key_line[K_FORCES], "drive", zp_scene_keys[K_FORCES].name, "%s", why);
    } else if (rc) {
        zp_scene_values_bad_key(c, K_FORCES, "%s", why);
    }
    return rc ? -1 : 1;
}

void zp_scene_sections_set_forces(zp_scene *sc, const zp_schedule *s) {
    sc->nforce = s->np;
    memcpy(sc->forces, s->p, sizeof *s->p * (size_t)s->np);
}

/* the direction's name is the drive module's */
void zp_scene_sections_direction(parse_ctx *c, zp_scene *sc, int k) {
    if (zp_scene_values_text(c, k, sc->direction, sizeof sc->direction) >= 0 &&
        zp_drive_dir_find(sc->direction) < 0) {
        zp_scene_values_bad_key(c, k, "unknown direction `%s`", sc->direction);
    }
}

/* the kind's name is the drive module's */
void zp_scene_sections_kind(parse_ctx *c, zp_scene *sc, int k) {
    char name[16];
    if (zp_scene_values_text(c, k, name, sizeof name) > 0) {
        int kind = zp_drive_kind_find(name);
        if (kind < 0) {
            zp_scene_values_bad_key(c, k, "unknown kind `%s`", name);
        }
        sc->drive_kind = kind < 0 ? ZP_SCHED_SECTIONS : kind;
    }
}

/* knots shape a profile only, and every section's knots must fit the schedule */
void zp_scene_sections_knots(parse_ctx *c, zp_scene *sc, int k) {
    zp_scene_values_plain(c, sc, k);
    if (!c->key_line[k] || c->key_bad[k]) {
        return;
    }
    if (sc->drive_kind != ZP_SCHED_PROFILE) {
        zp_scene_values_bad_key(c, k, "given with kind = %s; expected kind = profile",
                         zp_drive_kind_name((zp_sched_kind)sc->drive_kind));
    } else if (c->nsect * sc->drive_knots > ZP_SCHED_MAX_PARAMS) {
        zp_scene_values_bad_key(c, k, "%d sections x %d knots = %d forces; expected at most %d",
                         c->nsect, sc->drive_knots, c->nsect * sc->drive_knots,
                         ZP_SCHED_MAX_PARAMS);
    }
}

/* the schedule's text is the drive module's to read, as the kind and knots shape it */
void zp_scene_sections_forces(parse_ctx *c, zp_scene *sc, int k) {
    (void)k; /* K_FORCES: the overlay of a schedule file reads it too (zp_scene_sections_parse_forces) */
    if (c->key_bad[K_KIND] || c->key_bad[K_KNOTS]) {
        return; /* the count they would set is unknown: one mistake, one message */
    }
    zp_schedule shape = zp_drive_of_scene(sc), sched;
    if (c->sec_line[S_CABLE]) { /* [cable] is read after [drive]: its sections counted here */
        shape.nsec = zp_scene_cable_nsec(c);
        shape.np = shape.nsec * (sc->drive_kind == ZP_SCHED_PROFILE ? sc->drive_knots : 1);
    }
    if (zp_scene_sections_parse_forces(c, &shape, &sched) > 0) {
        zp_scene_sections_set_forces(sc, &sched);
    }
}

/* accuracy asks zipopt to choose the tolerances: with rtol or atol beside it neither can be
   said to win, so both lines are named; a method beside it restricts the choice to it */
void zp_scene_sections_accuracy(parse_ctx *c, zp_scene *sc, int k) {
    zp_scene_values_plain(c, sc, k);
    const int tol[] = {K_RTOL, K_ATOL};
    for (int i = 0; i < 2 && c->key_line[k]; i++) {
        if (c->key_line[tol[i]]) {
            zp_scene_values_bad_key(c, k,
                             "given with %s on line %d; give one: accuracy (s on the finish "
                             "time) chooses the method's tolerances itself",
                             zp_scene_keys[tol[i]].name, c->key_line[tol[i]]);
        }
    }
}

void zp_scene_sections_objective(parse_ctx *c, zp_scene *sc, int k) {
    char objective[16];
    if (zp_scene_values_text(c, k, objective, sizeof objective) > 0) {
        if (strcmp(objective, "nominal") && strcmp(objective, "slowest")) {
            zp_scene_values_bad_key(c, k, "'%s' is not an objective", objective);
        } else {
            sc->objective_slowest = !strcmp(objective, "slowest");
        }
    }
}
