/* What `check` shows of a scene's keys: each key the file did not give, with the value zipopt
   took (the documented defaults, the file's stem for the name), and the settings of the
   optional sections ([limits], [robust], [physics]) as text or JSON; a plain key's value as its
   line of scene_keys.def says, the others by hand. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parse.h"
#include "scene_load.h"

static void list(char *out, size_t cap, const double *v, int n) {
    size_t len = 0;
    out[0] = '\0';
    for (int i = 0; i < n && len < cap; i++) {
        len += (size_t)snprintf(out + len, cap - len, "%s%g", i ? ", " : "", v[i]);
    }
}

/* a mask of links (bit i: link i + 1) as their numbers; 0 is every link */
static void links(char *out, size_t cap, unsigned mask, int nlink) {
    if (mask == 0) {
        snprintf(out, cap, "every link");
    }
    for (int i = 0, used = 0, first = 1; i < nlink && used < (int)cap; i++) {
        if (mask >> i & 1) {
            used += snprintf(out + used, cap - used, "%s%d", first ? "" : ", ", i + 1);
            first = 0;
        }
    }
}

/* the shortest text that reads back as the same double */
static void number(char *out, size_t cap, double v) {
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(out, cap, "%.*g", digits, v);
        if (strtod(out, NULL) == v) {
            return;
        }
    }
}

/* the value of a key whose member alone does not say it (lists, links, computed defaults):
   1 when written in out, 0 for a key its member says */
static int hand_text(const zp_scene *sc, int k, char *out, size_t cap) {
    const void *at = (const char *)sc + zp_scene_keys[k].field;
    switch (k) {
    case K_MAX_EVALS:
        snprintf(out, cap, "%ld (the search's default: %d per section)",
                 ZP_SCENE_EVALS_PER_SECTION * (long)sc->nsec, ZP_SCENE_EVALS_PER_SECTION);
        return 1;
    case K_DAMPING:
        list(out, cap, sc->damping, sc->ndamping);
        return 1;
    case K_ACCURACY:
        snprintf(out, cap, "off (method and rtol decide)");
        return 1;
    case K_FORCES:
        snprintf(out, cap, "0 for every section");
        return 1;
    case K_KIND:
        snprintf(out, cap, "%s", zp_drive_kind_name((zp_sched_kind)sc->drive_kind));
        return 1;
    case K_DRAG_AREA:
        if (sc->ndrag) {
            list(out, cap, sc->drag_area, sc->ndrag);
        } else {
            snprintf(out, cap, "none (no drag)");
        }
        return 1;
    case K_G_ENVELOPE:
        if (sc->nenv == 0) {
            snprintf(out, cap, "off");
        }
        for (int l = 0, used = 0; l < sc->nenv && used < (int)cap; l++) {
            used += snprintf(out + used, cap - used, "%s%g:%g", l ? ", " : "", sc->env_g[l],
                             sc->env_s[l]);
        }
        return 1;
    case K_DEATH_ANGLE:
        list(out, cap, sc->death_angles, sc->ndeath);
        return 1;
    case K_OBJECTIVE:
        snprintf(out, cap, "%s", sc->objective_slowest ? "slowest" : "nominal");
        return 1;
    case K_WIND_RANGE:
        if (sc->wind_varied) {
            list(out, cap, sc->wind_range, 2);
        } else {
            snprintf(out, cap, "off");
        }
        return 1;
    case K_MASS_RANGE:
    case K_LENGTH_RANGE:
    case K_TROLLEY_MASS_RANGE:
    case K_DAMPING_RANGE:
        list(out, cap, at, 2);
        return 1;
    case K_CABLE_START:
    case K_CABLE_END:
        list(out, cap, at, 2);
        return 1;
    case K_CABLE_SECTIONS:
        list(out, cap, sc->x_end, sc->nsec);
        return 1;
    case K_CABLE_LENGTH: /* the one not given follows from the other */
    case K_CABLE_TENSION:
        if (k == K_CABLE_LENGTH ? sc->cable_length > 0 : sc->cable_tension > 0) {
            number(out, cap, k == K_CABLE_LENGTH ? sc->cable_length : sc->cable_tension);
        } else {
            snprintf(out, cap, "from the %s", k == K_CABLE_LENGTH ? "tension" : "length");
        }
        return 1;
    case K_CABLE_EA:
        if (sc->cable_ea > 0) {
            number(out, cap, sc->cable_ea);
        } else {
            snprintf(out, cap, "inextensible");
        }
        return 1;
    case K_BRAKE_START:
    case K_BRAKE_END:
        if (!sc->brake) {
            snprintf(out, cap, "off");
            return 1;
        }
        return 0;
    case K_G_LINKS:
    case K_SCALE_LINKS:
        links(out, cap, *(const unsigned *)at, sc->nlink);
        return 1;
    default:
        return 0;
    }
}

/* a plain key's value, from its member as the table says the member holds it */
static void member_text(const zp_scene *sc, int k, char *out, size_t cap) {
    const void *at = (const char *)sc + zp_scene_keys[k].field;
    switch (zp_scene_keys[k].type) {
    case T_NUMBER:
        number(out, cap, *(const double *)at);
        break;
    case T_INT:
        snprintf(out, cap, "%d", *(const int *)at);
        break;
    case T_LONG:
        snprintf(out, cap, "%ld", *(const long *)at);
        break;
    case T_ULONG:
        snprintf(out, cap, "%lu", *(const unsigned long *)at);
        break;
    case T_TEXT:
        snprintf(out, cap, "%s", (const char *)at);
        break;
    default: /* a list no lister above knows: only the required ones, never listed given */
        snprintf(out, cap, "(required, not given)");
        break;
    }
}

/* the value key k holds in sc, as scene-file text; a key off by default and not given is off */
static void value_text(const zp_scene *sc, int k, char *out, size_t cap) {
    int given = zp_scene_given(sc, k);
    zp_scene_how how = zp_scene_keys[k].dflt.how;
    if (!given && how == D_OFF) {
        snprintf(out, cap, "off");
    } else if (sc->accuracy > 0 && (k == K_METHOD || k == K_RTOL || k == K_ATOL)) {
        snprintf(out, cap, "chosen for accuracy = %g s (work-precision table)", sc->accuracy);
    } else if (!given && how == D_REQUIRED) {
        snprintf(out, cap, "(required, not given)");
    } else if (!hand_text(sc, k, out, cap)) {
        member_text(sc, k, out, cap);
    }
}

int zp_scene_show_added(const zp_scene *sc, FILE *f, const char *indent) {
    int n = 0;
    for (int s = 0; s < S_COUNT; s++) {
        int optional = zp_scene_keys_sections[s].optional;
        int any = s == S_ROBUST && sc->robust;
        for (int k = 0; k < K_COUNT; k++) {
            any |= zp_scene_keys[k].sec == s && (zp_scene_given(sc, k));
        }
        if (optional && !any) {
            fprintf(f, "%s[%s]: none given, all off\n", indent, zp_scene_keys_sections[s].name);
            continue;
        }
        if (s == S_COURSE && sc->cable) {
            continue; /* the cable lays the course */
        }
        for (int k = 0; k < K_COUNT; k++) {
            if (zp_scene_keys[k].sec == s && !(zp_scene_given(sc, k))) {
                char v[256];
                value_text(sc, k, v, sizeof v);
                fprintf(f, "%s[%s] %s = %s\n", indent, zp_scene_keys_sections[s].name,
                        zp_scene_keys[k].name, v);
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
    return (s == S_ROBUST && sc->robust) || (zp_scene_given(sc, k));
}

/* a value as JSON: a number, a list of numbers, or (anything else) a string */
static void json_value(FILE *f, const char *text) {
    double v[2 * ZP_MAX_LINKS + 2];
    char why[64];
    int n = zp_scene_values_parse_list(text, v, (int)(sizeof v / sizeof *v), why, sizeof why);
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

void zp_scene_show_optional(const zp_scene *sc, FILE *f, int json, zp_scene_show_more more,
                            const void *user) {
    for (int s = 0, first = 1; s < S_COUNT; s++) {
        if (!zp_scene_keys_sections[s].optional) {
            continue;
        }
        int n = 0;
        if (json) {
            fprintf(f, "%s\"%s\": {", first ? "" : ", ", zp_scene_keys_sections[s].name);
            first = 0;
        } else {
            fprintf(f, "%s:", zp_scene_keys_sections[s].name);
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
        if (json && more) {
            more(f, zp_scene_keys_sections[s].name, n, user);
        }
        if (json) {
            fputc('}', f);
        } else {
            fprintf(f, "%s\n", n ? "" : s == S_ROBUST ? " none (a nominal search)" : " none");
        }
    }
}
