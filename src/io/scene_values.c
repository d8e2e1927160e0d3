/* The scene reader's values: raw key text -> numbers, lists, whole numbers and names, each
   refusal naming the key and what it expects; the plain keys read and defaulted as their line
   of scene_keys.def says. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "text.h"
#include "scene_parse.h"
#include "scene_load.h"

int zp_scene_values_parse_list(const char *text, double *out, int max, char *why, size_t whylen) {
    return zp_text_list(text, out, max, why, whylen);
}

void zp_scene_values_bad_key(parse_ctx *c, int k, const char *fmt, ...) {
    char what[LINE_CAP + 64];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    c->key_bad[k] = 1;
    zp_scene_lines_bad(c, c->key_line[k], zp_scene_sec_of(k), zp_scene_keys[k].name, "%s; expected %s",
                 what, zp_scene_keys[k].expect);
}

void zp_scene_values_bad_count(parse_ctx *c, int k, int n, const char *fmt, ...) {
    char what[128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    c->key_bad[k] = 1;
    zp_scene_lines_bad(c, c->key_line[k], zp_scene_sec_of(k), zp_scene_keys[k].name,
                 "%d value%s, expected %s", n, n == 1 ? "" : "s", what);
}

void zp_scene_values_missing(parse_ctx *c, int k, const char *what) {
    int line = c->sec_line[zp_scene_keys[k].sec] ? c->sec_line[zp_scene_keys[k].sec] : c->line;
    zp_scene_lines_bad(c, line, zp_scene_sec_of(k), zp_scene_keys[k].name, "missing; required: %s", what);
}

static int in_range(double v, zp_range r) {
    return (r.lo_open ? v > r.lo : v >= r.lo) && (r.hi_open ? v < r.hi : v <= r.hi);
}

int zp_scene_values_number(parse_ctx *c, int k, zp_range r, double *out) {
    if (!c->key_line[k]) {
        return 0;
    }
    double v;
    int bad_number = zp_text_number(c->val[k], &v);
    if (bad_number) {
        if (c->val[k][0]) {
            zp_scene_values_bad_key(c, k, "`%s` is %s", c->val[k],
                             bad_number == -2 ? "out of range (beyond 1.8e308)" : "not a number");
        } else {
            zp_scene_values_bad_key(c, k, "no value");
        }
        return -1;
    }
    if (!in_range(v, r)) {
        zp_scene_values_bad_key(c, k, "%g is out of range", v);
        return -1;
    }
    *out = v;
    return 1;
}

int zp_scene_values_list(parse_ctx *c, int k, zp_range r, double *out, int max) {
    if (!c->key_line[k]) {
        return 0;
    }
    char what[LINE_CAP + 64];
    double v[ZP_MAX_SECTIONS];
    int n = zp_text_items(c->val[k], v, ZP_MAX_SECTIONS, what, sizeof what);
    if (n < 0) {
        zp_scene_values_bad_key(c, k, "%s", what);
        return -1;
    }
    if (n > max) {
        zp_scene_values_bad_key(c, k, "%d values, more than %d", n, max);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        if (!in_range(v[i], r)) {
            zp_scene_values_bad_key(c, k, "item %d (%g) is out of range", i + 1, v[i]);
            return -1;
        }
    }
    memcpy(out, v, (size_t)n * sizeof *v);
    return n;
}

static int zp_scene_values_whole(parse_ctx *c, int k, unsigned long lo, unsigned long hi,
                       unsigned long *out) {
    if (!c->key_line[k]) {
        return 0;
    }
    const char *t = c->val[k];
    char *end;
    errno = 0;
    unsigned long v = strtoul(t, &end, 10);
    if (!*t || strspn(t, "0123456789") != strlen(t) || errno || *end || v < lo || v > hi) {
        zp_scene_values_bad_key(c, k, "`%s` is not a whole number in [%lu, %lu]", t, lo, hi);
        return -1;
    }
    *out = v;
    return 1;
}

int zp_scene_values_text(parse_ctx *c, int k, char *out, size_t cap) {
    if (!c->key_line[k]) {
        return 0;
    }
    if (!c->val[k][0] || strlen(c->val[k]) >= cap) {
        zp_scene_values_bad_key(c, k, "%s", c->val[k][0] ? "too long" : "empty");
        return -1;
    }
    strcpy(out, c->val[k]);
    return 1;
}

/* a whole number into key k's member, of the member's type */
static void put_whole(zp_scene *sc, int k, unsigned long u) {
    void *at = zp_scene_member(sc, k);
    if (zp_scene_keys[k].type == T_INT) {
        *(int *)at = (int)u;
    } else if (zp_scene_keys[k].type == T_LONG) {
        *(long *)at = (long)u;
    } else {
        *(unsigned long *)at = u;
    }
}

void zp_scene_values_plain(parse_ctx *c, zp_scene *sc, int k) {
    const zp_scene_key *key = &zp_scene_keys[k];
    unsigned long u;
    if (key->type == T_NUMBER) {
        zp_scene_values_number(c, k, key->rule, zp_scene_member(sc, k));
    } else if (key->type == T_TEXT) {
        zp_scene_values_text(c, k, zp_scene_member(sc, k), key->size);
    } else if (zp_scene_values_whole(c, k, key->min, key->max, &u) > 0) {
        put_whole(sc, k, u);
    }
}

void zp_scene_values_defaults(zp_scene *sc) {
    for (int k = 0; k < K_COUNT; k++) {
        const zp_scene_key *key = &zp_scene_keys[k];
        if (key->dflt.how != D_VALUE) {
            continue;
        }
        if (key->type == T_NUMBER) {
            *(double *)zp_scene_member(sc, k) = key->dflt.num;
        } else if (key->type == T_TEXT) {
            snprintf(zp_scene_member(sc, k), key->size, "%s", key->dflt.text);
        } else {
            put_whole(sc, k, (unsigned long)key->dflt.num);
        }
    }
}
