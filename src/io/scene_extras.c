/* The readers of the optional sections' special keys (scene_keys.def: [limits], [robust],
   [physics]): lists, ranges and links, each off unless given, each refusal naming the key and
   what it expects. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parse.h"

/* key k as link numbers 1..nlink into its mask (bit i: link i + 1), 0 when absent or bad */
void zp_scene_extras_links(parse_ctx *c, zp_scene *sc, int k) {
    double links[ZP_MAX_LINKS];
    int n = zp_scene_values_list(c, k, R_POS, links, ZP_MAX_LINKS);
    unsigned mask = 0;
    for (int i = 0; i < n; i++) {
        if (links[i] != floor(links[i]) || links[i] > sc->nlink) {
            zp_scene_values_bad_key(c, k, "item %d (%g) is not a link number from 1 to %d", i + 1,
                             links[i], sc->nlink);
            mask = 0;
            break;
        }
        mask |= 1u << ((int)links[i] - 1);
    }
    *(unsigned *)zp_scene_member(sc, k) = mask;
}

/* g_envelope: comma-separated pairs g:s, each number finite and > 0 */
void zp_scene_extras_envelope(parse_ctx *c, zp_scene *sc, int k) {
    if (!c->key_line[k]) {
        return;
    }
    char text[LINE_CAP];
    snprintf(text, sizeof text, "%s", c->val[k]);
    int n = 0;
    for (char *save = NULL, *item = strtok_r(text, ",", &save); item;
         item = strtok_r(NULL, ",", &save)) {
        char *colon = strchr(item, ':'), *end1, *end2;
        if (!colon) {
            zp_scene_values_bad_key(c, k, "item %d ('%s') is not g:s", n + 1, item);
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
        if (end1 == item || *end1 || end2 == colon + 1 || *end2 || !isfinite(g) || !isfinite(s) ||
            !(g > 0) || !(s > 0)) {
            zp_scene_values_bad_key(c, k, "item %d is not two numbers > 0", n + 1);
            return;
        }
        if (n == 8) {
            zp_scene_values_bad_key(c, k, "more than 8 levels");
            return;
        }
        sc->env_g[n] = g;
        sc->env_s[n++] = s;
    }
    if (n == 0) {
        zp_scene_values_bad_key(c, k, "no levels");
        return;
    }
    sc->nenv = n;
}

/* key k as `lo, hi` in range r with lo <= hi: 1 when set in v, else 0 */
static int get_pair(parse_ctx *c, int k, zp_range r, double v[2]) {
    int n = zp_scene_values_list(c, k, r, v, 2);
    if (n == 1) {
        zp_scene_values_bad_count(c, k, n, "2 (lo, hi)");
    } else if (n == 2 && v[0] > v[1]) {
        zp_scene_values_bad_key(c, k, "the range %g, %g is reversed", v[0], v[1]);
    }
    return n == 2 && v[0] <= v[1];
}

/* key k as `lo, hi` percentages with 0 < lo <= hi, into its member */
void zp_scene_extras_range(parse_ctx *c, zp_scene *sc, int k) {
    double v[2];
    if (get_pair(c, k, R_POS, v)) {
        memcpy(zp_scene_member(sc, k), v, sizeof v);
    }
}

/* wind acts through drag: that it is given without drag_area is judged in scene_rules.c */
void zp_scene_extras_wind_range(parse_ctx *c, zp_scene *sc, int k) {
    double w[2];
    if (get_pair(c, k, R_ANY, w)) {
        sc->wind_varied = 1;
        memcpy(sc->wind_range, w, sizeof w);
    }
}

/* the box held is the stated one widened about the nominal (100 %): no range (read before)
   may then reach 0 % or below */
void zp_scene_extras_safety_factor(parse_ctx *c, zp_scene *sc, int k) {
    double f;
    if (zp_scene_values_number(c, k, zp_scene_keys[k].rule, &f) > 0) {
        const double *ranges[4] = {sc->mass_range, sc->length_range, sc->trolley_mass_range,
                                   sc->damping_range};
        int fits = 1;
        for (int q = 0; q < 4; q++) {
            fits &= 100 + f * (ranges[q][0] - 100) > 0;
        }
        if (!fits) {
            zp_scene_values_bad_key(c, k, "%g is out of range", f);
        } else {
            sc->safety_factor = f;
        }
    }
}

/* drag_area's count (nlink + 1) and air_density > 0 with drag are judged in scene_rules.c */
void zp_scene_extras_drag_area(parse_ctx *c, zp_scene *sc, int k) {
    double tmp[ZP_MAX_LINKS + 1];
    int n = zp_scene_values_list(c, k, R_NONNEG, tmp, ZP_MAX_LINKS + 1);
    if (n > 0) {
        sc->ndrag = n;
        memcpy(sc->drag_area, tmp, (size_t)n * sizeof *tmp);
    }
}
