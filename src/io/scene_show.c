/* What `check` shows of a scene's keys: each key the file did not give, with the value zipopt
   took (the documented defaults, the file's stem for the name), and the settings of the
   optional sections ([limits], [robust], [physics]) as text or JSON. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parse.h"
#include "scene_read.h"

_Static_assert(K_COUNT <= 64, "zp_scene.given holds one bit per key");

static void list(char *out, size_t cap, const double *v, int n) {
    size_t len = 0;
    out[0] = '\0';
    for (int i = 0; i < n && len < cap; i++) {
        len += (size_t)snprintf(out + len, cap - len, "%s%g", i ? ", " : "", v[i]);
    }
}

/* keys whose value is one double, and keys whose value is a `lo, hi` pair, in zp_scene */
static const struct {
    int k;
    size_t off;
} numbers[] =
    {
        {K_GRAVITY, offsetof(zp_scene, gravity)},
        {K_MIN, offsetof(zp_scene, force_min)},
        {K_MAX, offsetof(zp_scene, force_max)},
        {K_RTOL, offsetof(zp_scene, rtol)},
        {K_ATOL, offsetof(zp_scene, atol)},
        {K_T_MAX, offsetof(zp_scene, t_max)},
        {K_OUTPUT_DT, offsetof(zp_scene, output_dt)},
        {K_MARGIN, offsetof(zp_scene, margin)},
        {K_SEARCH_RTOL, offsetof(zp_scene, search_rtol)},
        {K_FORCE_ERROR, offsetof(zp_scene, force_error)},
        {K_START_ANGLE, offsetof(zp_scene, start_angle)},
        {K_SAFETY_FACTOR, offsetof(zp_scene, safety_factor)},
        {K_AIR_DENSITY, offsetof(zp_scene, air_density)},
        {K_WIND, offsetof(zp_scene, wind)},
        {K_ROLLING, offsetof(zp_scene, rolling)},
        {K_KINK_RADIUS, offsetof(zp_scene, kink_radius)},
        {K_MAX_G, offsetof(zp_scene, max_g)},
        {K_MAX_JOINT_FORCE, offsetof(zp_scene, max_joint_force)},
        {K_MAX_ARRIVAL_SPEED, offsetof(zp_scene, max_arrival_speed)},
        {K_MAX_KINK_DV, offsetof(zp_scene, max_kink_dv)},
        {K_MIN_ARRIVAL_SPEED, offsetof(zp_scene, min_arrival_speed)},
},
  pairs[] = {
      {K_MASS_RANGE, offsetof(zp_scene, mass_range)},
      {K_LENGTH_RANGE, offsetof(zp_scene, length_range)},
      {K_TROLLEY_MASS_RANGE, offsetof(zp_scene, trolley_mass_range)},
      {K_DAMPING_RANGE, offsetof(zp_scene, damping_range)},
};

/* the shortest text that reads back as the same double */
static void number(char *out, size_t cap, double v) {
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(out, cap, "%.*g", digits, v);
        if (strtod(out, NULL) == v) {
            return;
        }
    }
}

/* the value of a key that is neither one double nor a pair */
static void other_text(const zp_scene *sc, int k, char *out, size_t cap) {
    switch (k) {
    case K_NAME:
        snprintf(out, cap, "%s", sc->name);
        break;
    case K_DIRECTION:
        snprintf(out, cap, "%s", sc->direction);
        break;
    case K_METHOD:
        snprintf(out, cap, "%s", sc->method);
        break;
    case K_FORMULATION:
        snprintf(out, cap, "%s", sc->formulation);
        break;
    case K_SEARCH_METHOD:
        snprintf(out, cap, "%s", sc->search_method);
        break;
    case K_MAX_EVALS:
        snprintf(out, cap, "%ld (the search's default: %d per section)",
                 ZP_SCENE_EVALS_PER_SECTION * (long)sc->nsec, ZP_SCENE_EVALS_PER_SECTION);
        break;
    case K_SEED:
        snprintf(out, cap, "%lu", sc->seed);
        break;
    case K_SAMPLES:
        snprintf(out, cap, "%d", sc->robust_samples);
        break;
    case K_VERIFY_SAMPLES:
        snprintf(out, cap, "%d", sc->verify_samples);
        break;
    case K_DAMPING:
        list(out, cap, sc->damping, sc->ndamping);
        break;
    case K_ACCURACY:
        snprintf(out, cap, "off (method and rtol decide)");
        break;
    case K_FORCES:
        snprintf(out, cap, "0 for every section");
        break;
    case K_DRAG_AREA:
        if (sc->ndrag) {
            list(out, cap, sc->drag_area, sc->ndrag);
        } else {
            snprintf(out, cap, "none (no drag)");
        }
        break;
    case K_G_ENVELOPE:
        if (sc->nenv == 0) {
            snprintf(out, cap, "off");
        }
        for (int l = 0, used = 0; l < sc->nenv && used < (int)cap; l++) {
            used += snprintf(out + used, cap - used, "%s%g:%g", l ? ", " : "", sc->env_g[l],
                             sc->env_s[l]);
        }
        break;
    case K_DEATH_ANGLE:
        list(out, cap, sc->death_angles, sc->ndeath);
        break;
    case K_OBJECTIVE:
        snprintf(out, cap, "%s", sc->objective_slowest ? "slowest" : "nominal");
        break;
    case K_WIND_RANGE:
        if (sc->wind_varied) {
            list(out, cap, sc->wind_range, 2);
        } else {
            snprintf(out, cap, "off");
        }
        break;
    case K_G_LINKS:
    case K_SCALE_LINKS: {
        unsigned mask = k == K_G_LINKS ? sc->g_links : sc->scale_links;
        if (mask == 0) {
            snprintf(out, cap, "every link");
        }
        for (int i = 0, used = 0, first = 1; i < sc->nlink && used < (int)cap; i++) {
            if (mask >> i & 1) {
                used += snprintf(out + used, cap - used, "%s%d", first ? "" : ", ", i + 1);
                first = 0;
            }
        }
        break;
    }
    default:
        snprintf(out, cap, "(required, not given)");
        break;
    }
}

/* the value key k holds in sc, as scene-file text; a limit not given is off */
static void value_text(const zp_scene *sc, int k, char *out, size_t cap) {
    const char *base = (const char *)sc;
    if (zp_scene_keys[k].sec == S_LIMITS && !(sc->given >> k & 1)) {
        snprintf(out, cap, "off");
        return;
    }
    if (sc->accuracy > 0 && (k == K_METHOD || k == K_RTOL || k == K_ATOL)) {
        snprintf(out, cap, "chosen for accuracy = %g s (work-precision table)", sc->accuracy);
        return;
    }
    for (size_t i = 0; i < sizeof numbers / sizeof *numbers; i++) {
        if (numbers[i].k == k) {
            number(out, cap, *(const double *)(base + numbers[i].off));
            return;
        }
    }
    for (size_t i = 0; i < sizeof pairs / sizeof *pairs; i++) {
        if (pairs[i].k == k) {
            list(out, cap, (const double *)(base + pairs[i].off), 2);
            return;
        }
    }
    other_text(sc, k, out, cap);
}

int zp_scene_print_added(const zp_scene *sc, FILE *f, const char *indent) {
    int n = 0;
    for (int s = 0; s < S_COUNT; s++) {
        int optional = s == S_LIMITS || s == S_ROBUST || s == S_PHYSICS;
        int any = s == S_ROBUST && sc->robust;
        for (int k = 0; k < K_COUNT; k++) {
            any |= zp_scene_keys[k].sec == s && (sc->given >> k & 1);
        }
        if (optional && !any) {
            fprintf(f, "%s[%s]: none given, all off\n", indent, zp_scene_sec_names[s]);
            continue;
        }
        for (int k = 0; k < K_COUNT; k++) {
            if (zp_scene_keys[k].sec == s && !(sc->given >> k & 1)) {
                char v[256];
                value_text(sc, k, v, sizeof v);
                fprintf(f, "%s[%s] %s = %s\n", indent, zp_scene_sec_names[s], zp_scene_keys[k].name,
                        v);
                n++;
            }
        }
    }
    return n;
}

/* the keys `check` shows of an optional section: the limits and effects given, and every
   [robust] key of a robust scene (its defaults decide the search as much as what is given) */
static int shown(const zp_scene *sc, int s, int k) {
    if (zp_scene_keys[k].sec != s) {
        return 0;
    }
    return (s == S_ROBUST && sc->robust) || (sc->given >> k & 1);
}

/* a value as JSON: a number, a list of numbers, or (anything else) a string */
static void json_value(FILE *f, const char *text) {
    double v[2 * ZP_MAX_LINKS + 2];
    char why[64];
    int n = zp_scene_parse_list(text, v, (int)(sizeof v / sizeof *v), why, sizeof why);
    if (n == 1 && !strchr(text, ',')) {
        fprintf(f, "%.17g", v[0]);
        return;
    }
    if (n >= 1) {
        fputc('[', f);
        for (int i = 0; i < n; i++) {
            fprintf(f, "%s%.17g", i ? ", " : "", v[i]);
        }
        fputc(']', f);
        return;
    }
    fputc('"', f);
    for (const char *c = text; *c; c++) {
        if (*c == '"' || *c == '\\') {
            fputc('\\', f);
        }
        fputc(*c, f);
    }
    fputc('"', f);
}

void zp_scene_print_optional(const zp_scene *sc, FILE *f, int json) {
    static const int optional[] = {S_LIMITS, S_ROBUST, S_PHYSICS};
    for (size_t i = 0; i < sizeof optional / sizeof *optional; i++) {
        int s = optional[i], n = 0;
        if (json) {
            fprintf(f, "%s\"%s\": {", i ? ", " : "", zp_scene_sec_names[s]);
        } else {
            fprintf(f, "%s:", zp_scene_sec_names[s]);
        }
        for (int k = 0; k < K_COUNT; k++) {
            if (!shown(sc, s, k)) {
                continue;
            }
            char v[256];
            value_text(sc, k, v, sizeof v);
            if (json) {
                fprintf(f, "%s\"%s\": ", n ? ", " : "", zp_scene_keys[k].name);
                json_value(f, v);
            } else {
                fprintf(f, "%s %s = %s", n ? ";" : "", zp_scene_keys[k].name, v);
            }
            n++;
        }
        if (json) {
            fputc('}', f);
        } else {
            fprintf(f, "%s\n", n ? "" : s == S_ROBUST ? " none (a nominal search)" : " none");
        }
    }
}
