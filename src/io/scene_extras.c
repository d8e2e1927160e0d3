/* The scene reader's second pass for the optional sections (docs/scene-file.md [limits], [robust],
   [physics]): each key off unless given, each refusal naming the key and what it expects. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parse.h"

/* key k as link numbers 1..nlink: a mask (bit i: link i + 1), 0 when absent or bad */
static unsigned read_links(parse_ctx *c, int k, int nlink) {
    double links[ZP_MAX_LINKS];
    int n = zp_scene_get_list(c, k, R_POS, links, ZP_MAX_LINKS);
    unsigned mask = 0;
    for (int i = 0; i < n; i++) {
        if (links[i] != floor(links[i]) || links[i] > nlink) {
            zp_scene_bad_key(c, k, "item %d (%g) is not a link number from 1 to %d", i + 1,
                             links[i], nlink);
            return 0;
        }
        mask |= 1u << ((int)links[i] - 1);
    }
    return mask;
}

/* g_envelope: comma-separated pairs g:s, each number finite and > 0 */
static void read_envelope(parse_ctx *c, zp_scene *sc) {
    if (!c->key_line[K_G_ENVELOPE]) {
        return;
    }
    char text[LINE_CAP];
    snprintf(text, sizeof text, "%s", c->val[K_G_ENVELOPE]);
    int n = 0;
    for (char *save = NULL, *item = strtok_r(text, ",", &save); item;
         item = strtok_r(NULL, ",", &save)) {
        char *colon = strchr(item, ':'), *end1, *end2;
        if (!colon) {
            zp_scene_bad_key(c, K_G_ENVELOPE, "item %d ('%s') is not g:s", n + 1, item);
            return;
        }
        *colon = '\0';
        double g = strtod(item, &end1), s = strtod(colon + 1, &end2);
        while (*end1 == ' ') {
            end1++;
        }
        while (*end2 == ' ') {
            end2++;
        }
        if (end1 == item || *end1 || end2 == colon + 1 || *end2 || !isfinite(g) ||
            !isfinite(s) || !(g > 0) || !(s > 0)) {
            zp_scene_bad_key(c, K_G_ENVELOPE, "item %d is not two numbers > 0", n + 1);
            return;
        }
        if (n == 8) {
            zp_scene_bad_key(c, K_G_ENVELOPE, "more than 8 levels");
            return;
        }
        sc->env_g[n] = g;
        sc->env_s[n++] = s;
    }
    if (n == 0) {
        zp_scene_bad_key(c, K_G_ENVELOPE, "no levels");
        return;
    }
    sc->nenv = n;
}

/* every limit is a positive ceiling: 0 would forbid any ride and means "off" inside */
void zp_scene_read_limits(parse_ctx *c, zp_scene *sc) {
    zp_scene_get_number(c, K_MAX_G, R_POS, &sc->max_g);
    zp_scene_get_number(c, K_MAX_JOINT_FORCE, R_POS, &sc->max_joint_force);
    zp_scene_get_number(c, K_MAX_ARRIVAL_SPEED, R_POS, &sc->max_arrival_speed);
    zp_scene_get_number(c, K_MAX_KINK_DV, R_POS, &sc->max_kink_dv);
    zp_scene_get_number(c, K_MIN_ARRIVAL_SPEED, R_POS, &sc->min_arrival_speed);
    read_envelope(c, sc);
    sc->g_links = read_links(c, K_G_LINKS, sc->nlink);
}

/* key k as `lo, hi` percentages with 0 < lo <= hi */
static void get_range(parse_ctx *c, int k, double out[2]) {
    double v[2];
    int n = zp_scene_get_list(c, k, R_POS, v, 2);
    if (n == 1) {
        zp_scene_bad_count(c, k, n, "2 (lo, hi)");
    } else if (n == 2 && v[0] > v[1]) {
        zp_scene_bad_key(c, k, "the range %g, %g is reversed", v[0], v[1]);
    } else if (n == 2) {
        memcpy(out, v, sizeof v);
    }
}

/* key k as a number in [0, below) */
static void get_below(parse_ctx *c, int k, double below, double *out) {
    double v;
    if (zp_scene_get_number(c, k, R_NONNEG, &v) > 0) {
        if (v >= below) {
            zp_scene_bad_key(c, k, "%g is out of range", v);
        } else {
            *out = v;
        }
    }
}

void zp_scene_read_robust(parse_ctx *c, zp_scene *sc) {
    sc->robust = c->sec_line[S_ROBUST] != 0;
    get_below(c, K_FORCE_ERROR, 100, &sc->force_error);
    get_range(c, K_MASS_RANGE, sc->mass_range);
    get_range(c, K_LENGTH_RANGE, sc->length_range);
    get_range(c, K_TROLLEY_MASS_RANGE, sc->trolley_mass_range);
    get_range(c, K_DAMPING_RANGE, sc->damping_range);
    get_below(c, K_START_ANGLE, 90, &sc->start_angle);
    unsigned long u;
    if (zp_scene_get_whole(c, K_SAMPLES, 1, 1000000000, &u) > 0) {
        sc->robust_samples = (int)u;
    }
    if (zp_scene_get_whole(c, K_VERIFY_SAMPLES, 1, 1000000000, &u) > 0) {
        sc->verify_samples = (int)u;
    }
    sc->scale_links = read_links(c, K_SCALE_LINKS, sc->nlink);
    double w[2];
    int nw = zp_scene_get_list(c, K_WIND_RANGE, R_ANY, w, 2);
    if (nw == 1) {
        zp_scene_bad_count(c, K_WIND_RANGE, nw, "2 (lo, hi)");
    } else if (nw == 2 && w[0] > w[1]) {
        zp_scene_bad_key(c, K_WIND_RANGE, "the range %g, %g is reversed", w[0], w[1]);
    } else if (nw == 2) {
        sc->wind_varied = 1;
        memcpy(sc->wind_range, w, sizeof w);
    }
    /* the box held is the stated one widened about the nominal (100 %): no range may then
       reach 0 % or below */
    double f;
    if (zp_scene_get_number(c, K_SAFETY_FACTOR, R_POS, &f) > 0) {
        const double *ranges[4] = {sc->mass_range, sc->length_range, sc->trolley_mass_range,
                                   sc->damping_range};
        int fits = f >= 1;
        for (int q = 0; q < 4; q++) {
            fits &= 100 + f * (ranges[q][0] - 100) > 0;
        }
        if (!fits) {
            zp_scene_bad_key(c, K_SAFETY_FACTOR, "%g is out of range", f);
        } else {
            sc->safety_factor = f;
        }
    }
}

/* drag_area's count (nlink + 1) and air_density > 0 with drag are judged in scene_rules.c */
void zp_scene_read_physics(parse_ctx *c, zp_scene *sc) {
    double tmp[ZP_MAX_LINKS + 1];
    int n = zp_scene_get_list(c, K_DRAG_AREA, R_NONNEG, tmp, ZP_MAX_LINKS + 1);
    if (n > 0) {
        sc->ndrag = n;
        memcpy(sc->drag_area, tmp, (size_t)n * sizeof *tmp);
    }
    zp_scene_get_number(c, K_AIR_DENSITY, R_NONNEG, &sc->air_density);
    zp_scene_get_number(c, K_WIND, R_ANY, &sc->wind);
    zp_scene_get_number(c, K_ROLLING, R_NONNEG, &sc->rolling);
    zp_scene_get_number(c, K_KINK_RADIUS, R_NONNEG, &sc->kink_radius);
    sc->line_kink_radius = c->key_line[K_KINK_RADIUS];
}
