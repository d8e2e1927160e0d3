/* The names a section's f(x) may use beyond x (docs/scene-file.md): `pi`, `e` and `y0`, the
   previous section's end height, written into the text as numbers (17 significant digits) before
   any course evaluator compiles it, so every evaluator sees plain numbers. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "course.h"
#include "scene_parse.h"

/* appends n bytes of s to out (at *len, cap bytes); -1 when it does not fit */
static int put(char *out, size_t cap, size_t *len, const char *s, size_t n) {
    if (*len + n + 1 > cap) {
        return -1;
    }
    memcpy(out + *len, s, n);
    *len += n;
    out[*len] = '\0';
    return 0;
}

/* the number a name stands for, as text in parentheses (a negative y0 stays one operand);
   0 when the name is not one of ours, -1 with why when it cannot be given */
static int value_of(const char *name, size_t n, int has_prev, const double *y0, char *num,
                    size_t cap, char *why, size_t whylen) {
    double v;
    if (n == 2 && !strncmp(name, "pi", 2)) {
        v = M_PI;
    } else if (n == 1 && name[0] == 'e') {
        v = M_E;
    } else if (n == 2 && !strncmp(name, "y0", 2)) {
        if (!has_prev) {
            snprintf(why, whylen,
                     "`y0` is the previous section's end height and the first section has none; "
                     "expected a number there");
            return -1;
        }
        if (!y0) {
            snprintf(why, whylen, "`y0` is unknown: the previous section has no finite end height");
            return -2;
        }
        v = *y0;
    } else {
        return 0;
    }
    snprintf(num, cap, "(%.17g)", v);
    return 1;
}

int zp_scene_expr_subst(const char *in, int has_prev, const double *y0, char *out, size_t cap,
                        char *why, size_t whylen) {
    size_t len = 0;
    out[0] = '\0';
    for (const char *p = in; *p;) {
        const char *q = p + 1;
        char num[40];
        int r = 0;
        if (isdigit((unsigned char)*p) || *p == '.') {
            /* a number whole, so the `e` of `1e5` stays its exponent */
            char *end;
            strtod(p, &end);
            q = end > p ? end : p + 1;
        } else if (isalpha((unsigned char)*p) || *p == '_') {
            for (q = p; isalnum((unsigned char)*q) || *q == '_'; q++) {
            }
            r = value_of(p, (size_t)(q - p), has_prev, y0, num, sizeof num, why, whylen);
        }
        if (r < 0) {
            return r;
        }
        if (r ? put(out, cap, &len, num, strlen(num)) : put(out, cap, &len, p, (size_t)(q - p))) {
            snprintf(why, whylen,
                     "too long with `pi`, `e` and `y0` written as numbers; expected at most %zu "
                     "characters then",
                     cap - 1);
            return -1;
        }
        p = q;
    }
    return 0;
}

int zp_scene_expr_end(const char *expr, double x, double *y) {
    zp_course_err err;
    zp_course *c = zp_course_create(1, &expr, &err);
    if (!c) {
        return -1;
    }
    *y = zp_course_eval(c, 0, x).f;
    zp_course_free(c);
    return isfinite(*y) ? 0 : -1;
}
