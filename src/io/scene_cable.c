/* The [cable] section (docs/scene-file.md, docs/model.md "A cable that sags"): the anchors, the
   drive sections as stretches of x, and the rules that make a cable hang and a ride fit it.
   The reader fills x_start and the sections (nsec, x_end) as [course] would, so the drive, the
   search and every output read a cable scene's sections as any other's. */
#include <math.h>
#include <stdio.h>

#include "cable.h"
#include "text.h"
#include "scene_parse.h"

void zp_scene_cable_anchor(parse_ctx *c, zp_scene *sc, int k) {
    double v[2];
    int n = zp_scene_values_list(c, k, R_ANY, v, 2);
    if (n > 0 && n != 2) {
        zp_scene_values_bad_count(c, k, n, "2 (x, y)");
    } else if (n == 2) {
        double *anchor = k == K_CABLE_START ? sc->cable_a : sc->cable_b;
        anchor[0] = v[0];
        anchor[1] = v[1];
    }
}

void zp_scene_cable_sections(parse_ctx *c, zp_scene *sc, int k) {
    int n = zp_scene_values_list(c, k, R_ANY, sc->x_end, ZP_MAX_SECTIONS);
    if (n > 0) {
        sc->nsec = n;
    }
}

int zp_scene_cable_nsec(const parse_ctx *c) {
    double v[ZP_MAX_SECTIONS];
    char why[64];
    int n = c->key_line[K_CABLE_SECTIONS]
                ? zp_text_items(c->val[K_CABLE_SECTIONS], v, ZP_MAX_SECTIONS, why, sizeof why)
                : 0;
    return n > 0 ? n : 0;
}

/* 1 when key k is given and was accepted */
static int good(const parse_ctx *c, int k) {
    return c->key_line[k] && !c->key_bad[k];
}

/* what cannot stand beside a cable: [course], whose place it takes, and kink_radius (a cable has
   no kinks); and the one key that needs a cable */
static void alone(parse_ctx *c, const zp_scene *sc) {
    if (!sc->cable && c->key_line[K_MAX_CABLE_TENSION]) {
        zp_scene_values_bad_key(c, K_MAX_CABLE_TENSION,
                                "given without [cable]; expected only on a cable scene (the "
                                "tension at the cable's anchors)");
    }
    if (sc->cable && c->sec_line[S_COURSE]) {
        zp_scene_lines_bad(c, c->sec_line[S_COURSE], "course", NULL,
                     "given with [cable] on line %d; expected [course] or [cable], not both (the "
                     "cable lays the course)",
                     c->sec_line[S_CABLE]);
    }
    if (sc->cable && c->key_line[K_KINK_RADIUS]) {
        zp_scene_values_bad_key(c, K_KINK_RADIUS, "given with [cable], whose path has no kinks to round");
    }
}

/* length or tension, and a cable that hangs between the anchors with them */
static void hangs(parse_ctx *c, const zp_scene *sc) {
    int has_len = c->key_line[K_CABLE_LENGTH] != 0, has_ten = c->key_line[K_CABLE_TENSION] != 0;
    if (has_len && has_ten) {
        zp_scene_values_bad_key(c, K_CABLE_TENSION, "given with length on line %d",
                         c->key_line[K_CABLE_LENGTH]);
        return;
    }
    if (!has_len && !has_ten) {
        zp_scene_values_missing(c, K_CABLE_LENGTH,
                         "the cable's unstretched length (m), or `tension` (N) to derive it");
        return;
    }
    int k = has_len ? K_CABLE_LENGTH : K_CABLE_TENSION;
    if (!good(c, k) || !good(c, K_CABLE_START) || !good(c, K_CABLE_END) ||
        c->key_bad[K_CABLE_WEIGHT] || c->key_bad[K_CABLE_EA] || !(sc->cable_a[0] < sc->cable_b[0])) {
        return;
    }
    zp_cable_def def = zp_cable_def_of_scene(sc);
    zp_cable cable;
    char why[256];
    if (zp_cable_build(&def, &cable, why, sizeof why) != ZP_OK) {
        zp_scene_values_bad_key(c, k, "the cable does not hang: %s", why);
    }
}

/* the ride inside the span: x_start (default x_A + 1 % of the span) past anchor A, the
   sections' ends increasing past it and short of anchor B */
static void ride_fits(parse_ctx *c, zp_scene *sc) {
    double xa = sc->cable_a[0], xb = sc->cable_b[0];
    if (!c->key_line[K_CABLE_X_START]) {
        sc->x_start = xa + 0.01 * (xb - xa);
    } else if (!c->key_bad[K_CABLE_X_START] && !(sc->x_start > xa && sc->x_start < xb)) {
        zp_scene_values_bad_key(c, K_CABLE_X_START, "%g is not between the anchors (%g, %g)",
                         sc->x_start, xa, xb);
        return;
    }
    if (!good(c, K_CABLE_SECTIONS) || c->key_bad[K_CABLE_X_START]) {
        return;
    }
    double prev = sc->x_start;
    for (int i = 0; i < sc->nsec; i++) {
        if (!(sc->x_end[i] > prev) || !(sc->x_end[i] < xb)) {
            zp_scene_values_bad_key(c, K_CABLE_SECTIONS,
                             "item %d (%g) is not past %g and short of anchor B at %g", i + 1,
                             sc->x_end[i], prev, xb);
            return;
        }
        prev = sc->x_end[i];
    }
}

/* the keys a cable needs (required with [cable] only, so not REQUIRED in the table) */
static int given_all(parse_ctx *c) {
    static const struct {
        int k;
        const char *what;
    } need[] = {
        {K_CABLE_START, "anchor A (x, y) in m, where the ride starts"},
        {K_CABLE_END, "anchor B (x, y) in m, where the ride ends"},
        {K_CABLE_SECTIONS, "the x at which each drive section ends (m); the last is where the "
                           "ride ends"},
    };
    int all = 1;
    for (size_t i = 0; i < sizeof need / sizeof *need; i++) {
        if (!c->key_line[need[i].k]) {
            zp_scene_values_missing(c, need[i].k, need[i].what);
            all = 0;
        }
    }
    return all;
}

void zp_scene_cable_rules(parse_ctx *c, zp_scene *sc) {
    alone(c, sc);
    if (!sc->cable || !given_all(c)) {
        return;
    }
    if (good(c, K_CABLE_START) && good(c, K_CABLE_END) && !(sc->cable_a[0] < sc->cable_b[0])) {
        zp_scene_values_bad_key(c, K_CABLE_END, "x = %g is not past anchor A's x = %g", sc->cable_b[0],
                         sc->cable_a[0]);
        return;
    }
    hangs(c, sc);
    if (good(c, K_CABLE_START) && good(c, K_CABLE_END)) {
        ride_fits(c, sc);
    }
}
