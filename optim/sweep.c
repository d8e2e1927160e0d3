/* The grid of a design study (sweep.h): --vary specs checked against docs/scene-file.md's numeric
   keys, point values, and each point's scene text with the varied lines rewritten. */
#include "sweep.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_load.h"
#include "sim_opts.h"

#define TEXT -1 /* a key docs/scene-file.md knows whose value is not a number */

/* every key of docs/scene-file.md, and how a study varies it; the reader stays the judge of values
 */
static const struct {
    const char *sec, *key;
    int kind;         /* zp_vary_kind, or TEXT */
    const char *unit; /* of the value, "" for a pure number */
} vary_keys[] = {
    {"scene", "name", TEXT, ""},
    {"scene", "gravity", ZP_VARY_VALUE, "m/s^2"},
    {"course", "x_start", ZP_VARY_VALUE, "m"},
    {"course", "section", TEXT, ""},
    {"cable", "length", ZP_VARY_VALUE, "m"},
    {"cable", "tension", ZP_VARY_VALUE, "N"},
    {"cable", "weight", ZP_VARY_VALUE, "N/m"},
    {"cable", "ea", ZP_VARY_VALUE, "N"},
    {"cable", "x_start", ZP_VARY_VALUE, "m"},
    {"trolley", "mass", ZP_VARY_VALUE, "kg"},
    {"body", "lengths", ZP_VARY_SCALE, "m"},
    {"body", "masses", ZP_VARY_SCALE, "kg"},
    {"body", "damping", ZP_VARY_SCALE, "N m s/rad"},
    {"body", "death_angle", ZP_VARY_VALUE, "deg"},
    {"drive", "direction", TEXT, ""},
    {"drive", "forces", ZP_VARY_SCALE, "N"},
    {"drive", "min", ZP_VARY_VALUE, "N"},
    {"drive", "max", ZP_VARY_VALUE, "N"},
    {"solver", "method", TEXT, ""},
    {"solver", "rtol", ZP_VARY_VALUE, ""},
    {"solver", "atol", ZP_VARY_VALUE, ""},
    {"solver", "t_max", ZP_VARY_VALUE, "s"},
    {"solver", "formulation", TEXT, ""},
    {"solver", "output_dt", ZP_VARY_VALUE, "s"},
    {"optimize", "margin", ZP_VARY_VALUE, "deg"},
    {"optimize", "max_evals", ZP_VARY_WHOLE, ""},
    {"optimize", "seed", ZP_VARY_WHOLE, ""},
    {"optimize", "method", TEXT, ""},
    {"optimize", "rtol", ZP_VARY_VALUE, ""},
    {"limits", "max_g", ZP_VARY_VALUE, "g"},
    {"limits", "max_joint_force", ZP_VARY_VALUE, "N"},
    {"limits", "max_arrival_speed", ZP_VARY_VALUE, "km/h"},
    {"limits", "max_kink_dv", ZP_VARY_VALUE, "m/s"},
    {"limits", "max_cable_tension", ZP_VARY_VALUE, "N"},
    {"robust", "force_error", ZP_VARY_VALUE, "%"},
    {"robust", "mass_range", ZP_VARY_SCALE, "%"},
    {"robust", "length_range", ZP_VARY_SCALE, "%"},
    {"robust", "trolley_mass_range", ZP_VARY_SCALE, "%"},
    {"robust", "damping_range", ZP_VARY_SCALE, "%"},
    {"robust", "start_angle", ZP_VARY_VALUE, "deg"},
    {"robust", "samples", ZP_VARY_WHOLE, ""},
    {"robust", "verify_samples", ZP_VARY_WHOLE, ""},
    {"physics", "drag_area", ZP_VARY_SCALE, "m^2"},
    {"physics", "air_density", ZP_VARY_VALUE, "kg/m^3"},
    {"physics", "wind", ZP_VARY_VALUE, "m/s"},
    {"physics", "rolling", ZP_VARY_VALUE, ""},
    {"physics", "kink_radius", ZP_VARY_VALUE, "m"},
    {"brake", "start", ZP_VARY_VALUE, "m"},
    {"brake", "end", ZP_VARY_VALUE, "m"},
    {"brake", "eddy", ZP_VARY_VALUE, "N s/m"},
    {"brake", "friction", ZP_VARY_VALUE, "N"},
};
#define NKEYS ((int)(sizeof vary_keys / sizeof vary_keys[0]))

/* the numeric keys of section sec (every section's when sec is NULL), for messages */
static void list_keys(const char *sec, char *out, size_t cap) {
    out[0] = '\0';
    for (int k = 0; k < NKEYS; k++) {
        if (vary_keys[k].kind != TEXT && (!sec || !strcmp(sec, vary_keys[k].sec))) {
            size_t len = strlen(out);
            snprintf(out + len, cap - len, "%s%s.%s", len ? ", " : "", vary_keys[k].sec,
                     vary_keys[k].key);
        }
    }
}

static int find_key(const char *sec, const char *key, int *sec_known) {
    *sec_known = 0;
    for (int k = 0; k < NKEYS; k++) {
        *sec_known |= !strcmp(sec, vary_keys[k].sec);
        if (!strcmp(sec, vary_keys[k].sec) && !strcmp(key, vary_keys[k].key)) {
            return k;
        }
    }
    return -1;
}

/* a finite number taking the whole of text */
static int parse_double(const char *text, double *v) {
    char *end;
    *v = strtod(text, &end);
    return end == text || *end || !isfinite(*v) ? -1 : 0;
}

/* "A:B:N" */
static int parse_range(const char *text, zp_sweep_vary *v, char *why, size_t whylen) {
    char buf[128];
    snprintf(buf, sizeof buf, "%s", text);
    char *c1 = strchr(buf, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
    if (!c2 || strchr(c2 + 1, ':')) {
        snprintf(why, whylen, "'%s' is not A:B:N", text);
        return -1;
    }
    *c1 = *c2 = '\0';
    char *end;
    long n = strtol(c2 + 1, &end, 10);
    if (parse_double(buf, &v->a) || parse_double(c1 + 1, &v->b)) {
        snprintf(why, whylen, "'%s' is not A:B:N: A and B must be numbers", text);
        return -1;
    }
    if (end == c2 + 1 || *end) {
        snprintf(why, whylen, "'%s' is not A:B:N: N must be a whole number", text);
        return -1;
    }
    if (v->a > v->b) {
        snprintf(why, whylen, "A = %g is above B = %g; expected A <= B", v->a, v->b);
        return -1;
    }
    if (n < 1 || n > ZP_SWEEP_MAX_POINTS) {
        snprintf(why, whylen, "N = %ld; expected 1 to %d values", n, ZP_SWEEP_MAX_POINTS);
        return -1;
    }
    v->n = (int)n;
    return 0;
}

static double value_at(const zp_sweep_vary *v, int k) {
    return k == v->n - 1 ? v->b : v->a + (v->b - v->a) * k / (v->n - 1);
}

int zp_sweep_vary_parse(const char *text, zp_sweep_vary *v, char *why, size_t whylen) {
    memset(v, 0, sizeof *v);
    snprintf(v->text, sizeof v->text, "%s", text);
    const char *eq = strchr(text, '='), *dot = strchr(text, '.');
    if (!eq || !dot || dot > eq || dot == text || eq == dot + 1 ||
        (size_t)(dot - text) >= sizeof v->section || (size_t)(eq - dot - 1) >= sizeof v->key) {
        snprintf(why, whylen, "'%s' is not SECTION.KEY=A:B:N (e.g. body.masses=0.8:1.2:5)", text);
        return -1;
    }
    memcpy(v->section, text, (size_t)(dot - text));
    memcpy(v->key, dot + 1, (size_t)(eq - dot - 1));
    char keys[1024];
    int sec_known, k = find_key(v->section, v->key, &sec_known);
    if (k < 0) {
        list_keys(sec_known ? v->section : NULL, keys, sizeof keys);
        snprintf(why, whylen, "unknown key %s.%s; the keys that can vary%s%s%s: %s", v->section,
                 v->key, sec_known ? " in [" : "", sec_known ? v->section : "",
                 sec_known ? "]" : "", keys);
        return -1;
    }
    if (vary_keys[k].kind == TEXT) {
        snprintf(why, whylen, "[%s] %s is not a number; only numeric keys can vary", v->section,
                 v->key);
        return -1;
    }
    v->kind = (zp_vary_kind)vary_keys[k].kind;
    snprintf(v->unit, sizeof v->unit, "%s", vary_keys[k].unit);
    if (parse_range(eq + 1, v, why, whylen)) {
        return -1;
    }
    for (int i = 0; v->kind == ZP_VARY_WHOLE && i < v->n; i++) {
        double x = value_at(v, i);
        if (x != floor(x)) {
            snprintf(why, whylen, "[%s] %s takes whole numbers, and %s gives %g", v->section,
                     v->key, eq + 1, x);
            return -1;
        }
    }
    return 0;
}

int zp_sweep_add(zp_sweep *s, const zp_sweep_vary *v, char *why, size_t whylen) {
    for (int i = 0; i < s->nvary; i++) {
        if (!strcmp(s->vary[i].section, v->section) && !strcmp(s->vary[i].key, v->key)) {
            snprintf(why, whylen, "%s.%s is varied twice", v->section, v->key);
            return -1;
        }
    }
    if (s->nvary == ZP_SWEEP_MAX_VARY) {
        snprintf(why, whylen, "more than %d keys; expected at most %d --vary", ZP_SWEEP_MAX_VARY,
                 ZP_SWEEP_MAX_VARY);
        return -1;
    }
    long n = (s->nvary ? s->npoint : 1) * (long)v->n;
    if (n > ZP_SWEEP_MAX_POINTS) {
        snprintf(why, whylen, "%ld points; expected at most %d", n, ZP_SWEEP_MAX_POINTS);
        return -1;
    }
    s->vary[s->nvary++] = *v;
    s->npoint = (int)n;
    return 0;
}

double zp_sweep_value(const zp_sweep *s, int v, int p) {
    for (int i = 0; i < v; i++) {
        p /= s->vary[i].n;
    }
    return value_at(&s->vary[v], p % s->vary[v].n);
}

void zp_sweep_column(const zp_sweep_vary *v, char *out, size_t cap) {
    snprintf(out, cap, "%s.%s%s", v->section, v->key, v->kind == ZP_VARY_SCALE ? "_factor" : "");
}

void zp_sweep_format(double x, char *out, size_t cap) {
    /* an exponent only where plain digits would be long: 100, not 1e+02 */
    int plain = fabs(x) < 1e17 && (fabs(x) >= 1e-4 || x == 0);
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(out, cap, "%.*g", prec, x);
        if (strtod(out, NULL) == x && (!plain || !strchr(out, 'e'))) {
            return;
        }
    }
}

/* the line of key in the first [sec] that has it: [*ls, *le) and its value (comment and
   blanks stripped) in val; *hdr_end is where the first [sec] header's line ends (or SIZE_MAX) */
static int find_line(const char *t, const char *sec, const char *key, size_t *ls, size_t *le,
                     size_t *hdr_end, char *val, size_t cap) {
    char cur[64] = "", line[ZP_SWEEP_LINE_MAX];
    *hdr_end = SIZE_MAX;
    for (size_t pos = 0; t[pos];) {
        size_t len = strcspn(t + pos, "\n"), next = pos + len + (t[pos + len] == '\n');
        snprintf(line, sizeof line, "%.*s", (int)len, t + pos);
        /* comments as the reader strips them: `;` or `#` first or after a blank */
        for (size_t i = 0; line[i]; i++) {
            if ((line[i] == ';' || line[i] == '#') &&
                (i == 0 || isspace((unsigned char)line[i - 1]))) {
                line[i] = '\0';
                break;
            }
        }
        char *s = line, *close = strchr(line, ']');
        while (isspace((unsigned char)*s)) {
            s++;
        }
        char *eq = strchr(s, '=');
        if (*s == '[' && close) {
            char *a = s + 1, *b = close;
            while (a < b && isspace((unsigned char)*a)) {
                a++;
            }
            while (b > a && isspace((unsigned char)b[-1])) {
                b--;
            }
            snprintf(cur, sizeof cur, "%.*s", (int)(b - a), a);
            if (!strcmp(cur, sec) && *hdr_end == SIZE_MAX) {
                *hdr_end = next;
            }
        } else if (eq && !strcmp(cur, sec)) {
            char *e = eq;
            while (e > s && isspace((unsigned char)e[-1])) {
                e--;
            }
            if ((size_t)(e - s) == strlen(key) && !strncmp(s, key, (size_t)(e - s))) {
                snprintf(val, cap, "%s", eq + 1);
                *ls = pos;
                *le = pos + len;
                return 1;
            }
        }
        pos = next;
    }
    return 0;
}

void zp_sweep_note_base(zp_sweep *s, const char *base) {
    for (int v = 0; v < s->nvary; v++) {
        zp_sweep_vary *va = &s->vary[v];
        char val[4096];
        size_t ls, le, hdr;
        va->base[0] = '\0';
        if (find_line(base, va->section, va->key, &ls, &le, &hdr, val, sizeof val)) {
            char *t = val + strspn(val, " \t"), *end = t + strlen(t);
            while (end > t && isspace((unsigned char)end[-1])) {
                end--;
            }
            /* a value too long for an axis label is not shown, rather than cut; nor one that
               is not a plain list of numbers (it goes into a figure's script) */
            size_t n = (size_t)(end - t);
            if (n < sizeof va->base && strspn(t, "0123456789.eE+-, ") >= n) {
                snprintf(va->base, sizeof va->base, "%.*s", (int)(end - t), t);
            }
        }
    }
}

/* t with [from, to) replaced by ins; NULL without memory */
static char *splice(const char *t, size_t from, size_t to, const char *ins) {
    size_t n = strlen(t), m = strlen(ins);
    char *out = malloc(n - (to - from) + m + 1);
    if (out) {
        memcpy(out, t, from);
        memcpy(out + from, ins, m);
        memcpy(out + from + m, t + to, n - to + 1);
    }
    return out;
}

/* t with the line `key = line_value` in [sec]: replacing the key's line, else added below the
   section's header, else with the section added at the end (a new text, or NULL) */
static char *put_line(const char *t, const char *sec, const char *key, const char *line) {
    char val[4096];
    size_t ls, le, hdr;
    if (find_line(t, sec, key, &ls, &le, &hdr, val, sizeof val)) {
        return splice(t, ls, le, line);
    }
    char ins[ZP_SWEEP_LINE_MAX + 128];
    if (hdr != SIZE_MAX) {
        snprintf(ins, sizeof ins, "%s%s\n", hdr && t[hdr - 1] != '\n' ? "\n" : "", line);
        return splice(t, hdr, hdr, ins);
    }
    size_t n = strlen(t);
    snprintf(ins, sizeof ins, "%s[%s]\n%s\n", n && t[n - 1] != '\n' ? "\n" : "", sec, line);
    return splice(t, n, n, ins);
}

char *zp_sweep_set_text(const char *t, const char *sec, const char *key, const char *value) {
    char line[ZP_SWEEP_LINE_MAX];
    if (snprintf(line, sizeof line, "%s = %s", key, value) >= (int)sizeof line) {
        return NULL;
    }
    return put_line(t, sec, key, line);
}

/* one varied key set in t (a new text, or NULL with why) */
static char *set_key(const char *t, const zp_sweep_vary *v, double x, char *why, size_t whylen) {
    char val[ZP_SWEEP_LINE_MAX], line[ZP_SWEEP_LINE_MAX], num[32];
    size_t ls, le, hdr;
    int found = find_line(t, v->section, v->key, &ls, &le, &hdr, val, sizeof val);
    int len = snprintf(line, sizeof line, "%s = ", v->key);
    if (v->kind == ZP_VARY_SCALE) {
        double item[ZP_MAX_DRIVE_PARAMS]; /* the longest list a key holds: [drive] forces */
        char bad[200];
        int n = found ? zp_scene_values_parse_list(val, item, ZP_MAX_DRIVE_PARAMS, bad, sizeof bad) : -1;
        if (n < 0) {
            snprintf(why, whylen, "[%s] %s: %s; a list key is varied by scaling its values",
                     v->section, v->key, found ? bad : "not in the scene, so nothing to scale");
            return NULL;
        }
        for (int i = 0; i < n; i++) {
            zp_sweep_format(item[i] * x, num, sizeof num);
            len += snprintf(line + len, sizeof line - (size_t)len, "%s%s", i ? ", " : "", num);
        }
    } else {
        zp_sweep_format(x, num, sizeof num);
        snprintf(line + len, sizeof line - (size_t)len, "%s", num);
    }
    char *out = put_line(t, v->section, v->key, line);
    if (!out) {
        snprintf(why, whylen, "out of memory");
    }
    return out;
}

char *zp_sweep_point_text(const zp_sweep *s, const char *base, int p, char *why, size_t whylen) {
    char *t = strdup(base);
    if (!t) {
        snprintf(why, whylen, "out of memory");
    }
    for (int v = 0; t && v < s->nvary; v++) {
        char *next = set_key(t, &s->vary[v], zp_sweep_value(s, v, p), why, whylen);
        free(t);
        t = next;
    }
    return t;
}

void zp_sweep_describe(const zp_sweep *s, int p, char *out, size_t cap) {
    size_t len = 0;
    out[0] = '\0';
    for (int v = 0; v < s->nvary && len < cap; v++) {
        const zp_sweep_vary *va = &s->vary[v];
        len += (size_t)snprintf(out + len, cap - len, "%s%s.%s %s%.4g", v ? ", " : "", va->section,
                                va->key, va->kind == ZP_VARY_SCALE ? "x" : "",
                                zp_sweep_value(s, v, p));
    }
}

int zp_sweep_point_scene(const zp_sweep *s, const char *base, const char *path, int p,
                         zp_scene *sc, zp_diag *d) {
    char why[256];
    char *text = zp_sweep_point_text(s, base, p, why, sizeof why);
    if (!text) {
        zp_diag_add(d, path, 0, NULL, NULL, "%s", why);
        return -1;
    }
    zp_status rc = zp_scene_load_string(text, path, sc, d);
    free(text);
    return rc == ZP_OK ? 0 : -1;
}

int zp_sweep_check_points(const zp_sweep *s, const char *base, const char *path, zp_scene *sc,
                          zp_diag *d) {
    for (int p = 0; p < s->npoint; p++) {
        zp_diag_init(d);
        zp_model *m = NULL;
        zp_sim_opts so;
        if (zp_sweep_point_scene(s, base, path, p, sc, d) == 0 &&
            (m = zp_model_build(sc, d)) != NULL) {
            zp_sim_opts_from_scene(sc, &so, d);
        }
        zp_model_free(m);
        if (d->n || d->dropped) {
            return p;
        }
    }
    return -1;
}
