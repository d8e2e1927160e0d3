/* The course y = f(x) of MODEL.md "Course": each section's f(x) text (CONFIG.md [course]) compiled
   by libmatheval, with f' and f'' as exact symbolic derivatives. */
#include "course.h"

#include <assert.h>
#include <ctype.h>
#include <math.h>
#include <matheval.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Design note: every zp_course owns its own evaluators rather than sharing one global set,
   because libmatheval is not thread-safe (its parser and symbol table use global state, and
   evaluators hold mutable nodes); a thread that simulates creates its own zp_course. */
typedef struct zp_course_sec {
    void *f, *fp, *fpp; /* owned libmatheval evaluators */
} zp_course_sec;

struct zp_course {
    int nsec;
    zp_course_sec sec[]; /* nsec */
};

#define ZP_EXPR_EXPECTED                                                                           \
    "expected an expression in x with + - * / ^ ( ) and sqrt exp log sin cos tan sinh cosh "       \
    "tanh"

/* CONFIG.md's functions; libmatheval knows more (abs, step, pi, ...) that the contract does
   not promise, so they are refused rather than silently accepted */
static const char *const allowed_names[] = {"x",   "sqrt", "exp",  "log",  "sin",
                                            "cos", "tan",  "sinh", "cosh", "tanh"};

static const char *skip_space(const char *p) {
    while (isspace((unsigned char)*p)) {
        p++;
    }
    return p;
}

static const char *skip_number(const char *p) {
    while (isdigit((unsigned char)*p) || *p == '.') {
        p++;
    }
    if ((*p == 'e' || *p == 'E') &&
        (isdigit((unsigned char)p[1]) ||
         ((p[1] == '+' || p[1] == '-') && isdigit((unsigned char)p[2])))) {
        p += 2;
        while (isdigit((unsigned char)*p)) {
            p++;
        }
    }
    return p;
}

static const char *skip_name(const char *p) {
    while (isalnum((unsigned char)*p) || *p == '_') {
        p++;
    }
    return p;
}

/* p at '(': returns the character after its matching ')' (or the end) */
static const char *skip_group(const char *p) {
    int depth = 0;
    do {
        depth += (*p == '(') - (*p == ')');
        p++;
    } while (*p && depth > 0);
    return p;
}

/* p just after '^': returns the character after its operand */
static const char *skip_operand(const char *p) {
    p = skip_space(p);
    while (*p == '-' || *p == '+') {
        p = skip_space(p + 1);
    }
    if (*p == '(') {
        return skip_group(p);
    }
    if (isdigit((unsigned char)*p) || *p == '.') {
        return skip_number(p);
    }
    p = skip_name(p);
    const char *q = skip_space(p);
    return *q == '(' ? skip_group(q) : p;
}

/* what libmatheval's parser does not catch: names outside CONFIG.md's list, stray
   characters, and a^b^c, which libmatheval reads as (a^b)^c against the usual a^(b^c) */
static int scan_text(const char *text, char *err, size_t errlen) {
    const char *p = skip_space(text);
    if (!*p) {
        snprintf(err, errlen, "empty expression; " ZP_EXPR_EXPECTED);
        return -1;
    }
    while (*p) {
        if (isdigit((unsigned char)*p) || *p == '.') {
            p = skip_number(p);
        } else if (isalpha((unsigned char)*p) || *p == '_') {
            const char *end = skip_name(p);
            size_t n = (size_t)(end - p), k = 0;
            while (k < sizeof allowed_names / sizeof *allowed_names &&
                   !(strlen(allowed_names[k]) == n && !strncmp(allowed_names[k], p, n))) {
                k++;
            }
            if (k == sizeof allowed_names / sizeof *allowed_names) {
                snprintf(err, errlen, "unknown name `%.*s`; " ZP_EXPR_EXPECTED, (int)n, p);
                return -1;
            }
            p = end;
        } else if (*p == '^') {
            const char *q = skip_space(skip_operand(p + 1));
            if (*q == '^') {
                snprintf(err, errlen,
                         "chained `^` is ambiguous; write a^(b^c) or (a^b)^c with parentheses");
                return -1;
            }
            p++;
        } else if (isspace((unsigned char)*p) || strchr("+-*/()", *p)) {
            p++;
        } else {
            snprintf(err, errlen, "unexpected character `%c`; " ZP_EXPR_EXPECTED, *p);
            return -1;
        }
    }
    return 0;
}

static void free_sec(zp_course_sec *s) {
    if (s->fpp) {
        evaluator_destroy(s->fpp);
    }
    if (s->fp) {
        evaluator_destroy(s->fp);
    }
    if (s->f) {
        evaluator_destroy(s->f);
    }
    memset(s, 0, sizeof *s);
}

/* compiles text into s (all three evaluators or none); 0 on success, else -1 and err */
static int compile(const char *text, zp_course_sec *s, char *err, size_t errlen) {
    memset(s, 0, sizeof *s);
    if (scan_text(text, err, errlen)) {
        return -1;
    }
    /* evaluator_create takes a writable string */
    char *buf = malloc(strlen(text) + 1);
    if (!buf) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    strcpy(buf, text);
    s->f = evaluator_create(buf);
    free(buf);
    if (!s->f) {
        snprintf(err, errlen, "syntax error; " ZP_EXPR_EXPECTED);
        return -1;
    }
    char **names;
    int count;
    evaluator_get_variables(s->f, &names, &count);
    for (int i = 0; i < count; i++) {
        if (strcmp(names[i], "x")) {
            snprintf(err, errlen, "unknown variable `%s`; " ZP_EXPR_EXPECTED, names[i]);
            free_sec(s);
            return -1;
        }
    }
    s->fp = evaluator_derivative_x(s->f);
    s->fpp = s->fp ? evaluator_derivative_x(s->fp) : NULL;
    if (!s->fpp) {
        snprintf(err, errlen, "cannot differentiate; " ZP_EXPR_EXPECTED);
        free_sec(s);
        return -1;
    }
    return 0;
}

int zp_course_check(const char *expr, char *err, size_t errlen) {
    zp_course_sec s;
    if (compile(expr, &s, err, errlen)) {
        return -1;
    }
    free_sec(&s);
    return 0;
}

zp_course *zp_course_create(int nsec, const char *const *expr, zp_course_err *e) {
    assert(nsec >= 0);
    *e = (zp_course_err){0, ""};
    zp_course *c = calloc(1, sizeof *c + (size_t)nsec * sizeof c->sec[0]);
    if (!c) {
        snprintf(e->what, sizeof e->what, "out of memory");
        return NULL;
    }
    for (int k = 0; k < nsec; k++) {
        char why[256];
        if (compile(expr[k], &c->sec[k], why, sizeof why)) {
            e->section = k + 1;
            snprintf(e->what, sizeof e->what, "section %d: f(x) = `%.200s`: %s", k + 1, expr[k],
                     why);
            zp_course_free(c);
            return NULL;
        }
        c->nsec = k + 1;
    }
    return c;
}

void zp_course_free(zp_course *c) {
    if (!c) {
        return;
    }
    for (int k = 0; k < c->nsec; k++) {
        free_sec(&c->sec[k]);
    }
    free(c);
}

/* f'' where its expression overflows though f' is finite (tanh(100 x) far from 0: sinh/cosh^3
   is inf/inf): the central difference of f', which the finite f' bounds */
static double fpp_by_difference(const zp_course_sec *s, double x) {
    double h = 1e-6 * (1 + fabs(x));
    return (evaluator_evaluate_x(s->fp, x + h) - evaluator_evaluate_x(s->fp, x - h)) / (2 * h);
}

zp_track zp_course_eval(const zp_course *c, int sec, double x) {
    assert(sec >= 0 && sec < c->nsec);
    const zp_course_sec *s = &c->sec[sec];
    zp_track t = {evaluator_evaluate_x(s->f, x), evaluator_evaluate_x(s->fp, x),
                  evaluator_evaluate_x(s->fpp, x)};
    if (!isfinite(t.fpp) && isfinite(t.fp)) {
        t.fpp = fpp_by_difference(s, x);
    }
    return t;
}

const char *zp_course_deriv_text(const zp_course *c, int sec, int order) {
    assert(sec >= 0 && sec < c->nsec && (order == 1 || order == 2));
    const zp_course_sec *s = &c->sec[sec];
    return evaluator_get_string(order == 1 ? s->fp : s->fpp);
}
