/* The scene reader's rules that join keys of several sections (docs/scene-file.md): search bounds,
   margin against the death angle, the trajectory's size, drag against the body, the brake zone
   inside the course. A rule is judged only when every key it reads was accepted, so one
   mistake gives one message. */
#include <math.h>

#include "scene_parse.h"

/* 1 when none of the keys (up to 3, -1 for none) was refused */
static int all_good(const parse_ctx *c, int k1, int k2, int k3) {
    return !(k1 >= 0 && c->key_bad[k1]) && !(k2 >= 0 && c->key_bad[k2]) &&
           !(k3 >= 0 && c->key_bad[k3]);
}

static void force_bounds(parse_ctx *c, const zp_scene *sc) {
    if (all_good(c, K_MIN, K_MAX, -1) && sc->force_min > sc->force_max) {
        int k = c->key_line[K_MAX] ? K_MAX : K_MIN;
        zp_scene_lines_bad(c, c->key_line[k], "drive", zp_scene_keys[k].name,
                     "min %g > max %g; expected min <= max", sc->force_min, sc->force_max);
    }
}

/* the default margin obeys the same rule as a given one: it is named at death_angle; with a
   death angle per joint, the smallest judges */
static void margin_below_death(parse_ctx *c, const zp_scene *sc) {
    double least = sc->death_angles[0];
    for (int i = 1; i < sc->ndeath; i++) {
        least = fmin(least, sc->death_angles[i]);
    }
    if (!all_good(c, K_MARGIN, K_DEATH_ANGLE, -1) || sc->margin < least) {
        return;
    }
    if (c->key_line[K_MARGIN]) {
        zp_scene_values_bad_key(c, K_MARGIN, "%g is not below death_angle %g", sc->margin, least);
    } else {
        zp_scene_values_bad_key(c, K_DEATH_ANGLE,
                         "%g is not above the default [optimize] margin %g (give a smaller "
                         "margin)",
                         least, sc->margin);
    }
}

/* rows are kept in memory and written to trajectory.csv: refused before running, not cut */
static void row_count(parse_ctx *c, const zp_scene *sc) {
    double rows = floor(sc->t_max / sc->output_dt) + 1;
    if (!all_good(c, K_T_MAX, K_OUTPUT_DT, -1) || rows <= ZP_MAX_ROWS) {
        return;
    }
    int k = c->key_line[K_OUTPUT_DT] ? K_OUTPUT_DT : K_T_MAX;
    zp_scene_lines_bad(c, c->key_line[k], "solver", zp_scene_keys[k].name,
                 "t_max %g s / output_dt %g s asks for %.3g trajectory rows; expected at most %d "
                 "(a larger output_dt or a smaller t_max)",
                 sc->t_max, sc->output_dt, rows, ZP_MAX_ROWS);
}

static void drag(parse_ctx *c, const zp_scene *sc) {
    if (sc->ndrag && all_good(c, K_LENGTHS, -1, -1) && sc->nlink && sc->ndrag != sc->nlink + 1) {
        zp_scene_values_bad_count(c, K_DRAG_AREA, sc->ndrag, "%d (the trolley's, then one per link)",
                           sc->nlink + 1);
    }
    if (sc->ndrag && all_good(c, K_AIR_DENSITY, -1, -1) && !(sc->air_density > 0)) {
        int k = c->key_line[K_AIR_DENSITY] ? K_AIR_DENSITY : K_DRAG_AREA;
        zp_scene_lines_bad(c, c->key_line[k], "physics", zp_scene_keys[k].name,
                     "air_density %g with drag_area given; expected air_density > 0",
                     sc->air_density);
    }
}

/* wind acts on the bodies through their drag only: a range of it without drag changes nothing */
static void wind_needs_drag(parse_ctx *c, const zp_scene *sc) {
    if (sc->wind_varied && !sc->ndrag && all_good(c, K_DRAG_AREA, -1, -1)) {
        zp_scene_values_bad_key(c, K_WIND_RANGE, "given without [physics] drag_area, through which "
                                          "wind acts");
    }
}

/* the brake zone lies inside the course, start before end (end defaults to the course's end);
   its start is required once [brake] is given */
static void brake_zone(parse_ctx *c, zp_scene *sc) {
    if (!sc->brake) {
        return;
    }
    if (!c->key_line[K_BRAKE_START]) {
        zp_scene_values_missing(c, K_BRAKE_START, "where the brake zone begins (m)");
        return;
    }
    int course = all_good(c, K_X_START, K_SECTION, -1) && sc->nsec > 0;
    double lo = sc->x_start, hi = course ? sc->x_end[sc->nsec - 1] : INFINITY;
    if (!c->key_line[K_BRAKE_END] && course) {
        sc->brake_end = hi;
    }
    if (!course || !all_good(c, K_BRAKE_START, K_BRAKE_END, -1)) {
        return;
    }
    if (!(sc->brake_start >= lo && sc->brake_start < hi)) {
        zp_scene_values_bad_key(c, K_BRAKE_START, "%g is outside the course [%g, %g]",
                                sc->brake_start, lo, hi);
    } else if (!(sc->brake_end > sc->brake_start && sc->brake_end <= hi)) {
        int k = c->key_line[K_BRAKE_END] ? K_BRAKE_END : K_BRAKE_START;
        zp_scene_values_bad_key(c, k, "the zone [%g, %g] does not fit the course [%g, %g]",
                                sc->brake_start, sc->brake_end, lo, hi);
    }
}

void zp_scene_rules(parse_ctx *c, zp_scene *sc) {
    brake_zone(c, sc);
    wind_needs_drag(c, sc);
    force_bounds(c, sc);
    margin_below_death(c, sc);
    row_count(c, sc);
    drag(c, sc);
    zp_scene_cable_rules(c, sc);
}
