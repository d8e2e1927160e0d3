/* The course y = f(x) of docs/model.md "Course": each section's f(x) text (docs/scene-file.md
   [course]) checked and interpreted by libmatheval, and compiled to native code (expr.c, jit.c) for
   the simulations, with f' and f'' as exact symbolic derivatives in both. */
#include "course.h"

#include <assert.h>
#include <ctype.h>
#include <math.h>
#include <matheval.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr.h"
#include "jit.h"

/* Design note: libmatheval is not thread-safe (its parser and symbol table use global state,
   and evaluators hold mutable nodes), so a course built here keeps its evaluators to itself:
   they check the text, give the derivative texts and evaluate for single-threaded callers
   (model checks, plots). Simulations, one per thread, take handles from zp_course_for_thread:
   all sections compiled once, in one libgccjit compile on the first request, read-only and
   shared. The code does the interpreter's arithmetic on simplified trees, so the two agree
   to round-off (tests/test_course.c holds them to 1e-14). */
typedef struct zp_course_sec {
    void *f, *fp, *fpp; /* owned libmatheval evaluators */
} zp_course_sec;

/* the compiled sections, shared by every handle; freed with the last one */
typedef struct course_code {
    atomic_int refs;
    zp_jit *jit; /* owned */
} course_code;

/* what zp_course_for_thread builds on first use, behind a const course */
typedef struct course_lazy {
    pthread_mutex_t lock;
    int tried;         /* the compile has been attempted */
    course_code *code; /* one reference, or NULL when the compile failed */
} course_lazy;

struct zp_course {
    int nsec;
    course_code *code;   /* a handle's compiled sections (one reference); NULL: interpreter */
    course_lazy *lazy;   /* owned by a built course, NULL in a handle */
    char **text;         /* owned by a built course: the nsec f(x) texts */
    zp_course_sec sec[]; /* nsec; a handle of compiled code has no evaluators */
};

#define ZP_EXPR_EXPECTED                                                                           \
    "expected an expression in x with + - * / ^ ( ) and sqrt exp log sin cos tan sinh cosh "       \
    "tanh"

/* docs/scene-file.md's functions; libmatheval knows more (abs, step, pi, ...) that the contract
   does not promise, so they are refused rather than silently accepted */
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

/* what libmatheval's parser does not catch: names outside docs/scene-file.md's list, stray
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

static void code_release(course_code *code) {
    if (code && atomic_fetch_sub(&code->refs, 1) == 1) {
        zp_jit_free(code->jit);
        free(code);
    }
}

zp_course *zp_course_create(int nsec, const char *const *expr, zp_course_err *e) {
    assert(nsec >= 0);
    *e = (zp_course_err){0, ""};
    zp_course *c = calloc(1, sizeof *c + (size_t)nsec * sizeof c->sec[0]);
    if (!c || !(c->lazy = calloc(1, sizeof *c->lazy)) ||
        !(c->text = calloc((size_t)nsec + 1, sizeof *c->text))) {
        snprintf(e->what, sizeof e->what, "out of memory");
        zp_course_free(c);
        return NULL;
    }
    pthread_mutex_init(&c->lazy->lock, NULL);
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
        if (!(c->text[k] = strdup(expr[k]))) {
            snprintf(e->what, sizeof e->what, "out of memory");
            zp_course_free(c);
            return NULL;
        }
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
    code_release(c->code);
    if (c->lazy) {
        code_release(c->lazy->code);
        pthread_mutex_destroy(&c->lazy->lock);
        free(c->lazy);
    }
    for (int k = 0; c->text && k < c->nsec; k++) {
        free(c->text[k]);
    }
    free(c->text);
    free(c);
}

/* all sections' f, f', f'' in one compile; NULL with why in err */
static course_code *compile_code(const zp_course *c, char *err, size_t errlen) {
    zp_expr e = {0};
    int *roots = malloc(sizeof *roots * 3 * (size_t)(c->nsec ? c->nsec : 1));
    course_code *code = calloc(1, sizeof *code);
    int ok = roots && code;
    for (int k = 0; ok && k < c->nsec; k++) {
        int *r = roots + 3 * k;
        ok = (r[0] = zp_expr_parse(&e, c->text[k], err, errlen)) >= 0 &&
             (r[1] = zp_expr_deriv(&e, r[0])) >= 0 && (r[2] = zp_expr_deriv(&e, r[1])) >= 0;
        if (!ok && r[0] >= 0) {
            snprintf(err, errlen, "out of memory");
        }
    }
    if (ok && !(code->jit = zp_jit_compile(&e, c->nsec, 3, roots, err, errlen))) {
        ok = 0;
    }
    zp_expr_free(&e);
    free(roots);
    if (!ok) {
        free(code);
        return NULL;
    }
    atomic_init(&code->refs, 1);
    return code;
}

/* where the notice of an interpreted course goes: nowhere until the program names a stream
   (the library prints nothing) */
static _Atomic(FILE *) notice_to;

void zp_course_notices_to(FILE *f) {
    atomic_store(&notice_to, f);
}

zp_course *zp_course_for_thread(const zp_course *c, zp_course_err *e) {
    assert(c->lazy);
    course_lazy *lz = c->lazy;
    pthread_mutex_lock(&lz->lock);
    if (!lz->tried) {
        lz->tried = 1;
        const char *off = getenv("ZIPOPT_NO_JIT");
        char why[256] = "ZIPOPT_NO_JIT is set";
        lz->code = off && *off && strcmp(off, "0") ? NULL : compile_code(c, why, sizeof why);
        static atomic_flag said = ATOMIC_FLAG_INIT;
        FILE *to = atomic_load(&notice_to);
        if (!lz->code && to && !atomic_flag_test_and_set(&said)) {
            fprintf(to, "zipopt: notice: the course is interpreted, not compiled (%s)\n", why);
        }
    }
    course_code *code = lz->code;
    if (code) {
        atomic_fetch_add(&code->refs, 1);
    }
    pthread_mutex_unlock(&lz->lock);
    if (!code) {
        return zp_course_create(c->nsec, (const char *const *)c->text, e);
    }
    zp_course *h = calloc(1, sizeof *h + (size_t)c->nsec * sizeof h->sec[0]);
    if (!h) {
        code_release(code);
        *e = (zp_course_err){0, "out of memory"};
        return NULL;
    }
    h->nsec = c->nsec;
    h->code = code;
    return h;
}

int zp_course_compiled(const zp_course *c) {
    return c->code != NULL;
}

/* f' of section sec at x, by whichever evaluator c has */
static double fp_at(const zp_course *c, int sec, double x) {
    if (c->code) {
        double out[3];
        zp_jit_get(c->code->jit, sec)(x, out);
        return out[1];
    }
    return evaluator_evaluate_x(c->sec[sec].fp, x);
}

/* f'' where its expression overflows though f' is finite (tanh(100 x) far from 0: sinh/cosh^3
   is inf/inf): the central difference of f', which the finite f' bounds */
static double fpp_by_difference(const zp_course *c, int sec, double x) {
    double h = 1e-6 * (1 + fabs(x));
    return (fp_at(c, sec, x + h) - fp_at(c, sec, x - h)) / (2 * h);
}

zp_track zp_course_eval(const zp_course *c, int sec, double x) {
    assert(sec >= 0 && sec < c->nsec);
    zp_track t;
    if (c->code) {
        double out[3];
        zp_jit_get(c->code->jit, sec)(x, out);
        t = (zp_track){out[0], out[1], out[2]};
    } else {
        const zp_course_sec *s = &c->sec[sec];
        t = (zp_track){evaluator_evaluate_x(s->f, x), evaluator_evaluate_x(s->fp, x),
                       evaluator_evaluate_x(s->fpp, x)};
    }
    if (!isfinite(t.fpp) && isfinite(t.fp)) {
        t.fpp = fpp_by_difference(c, sec, x);
    }
    return t;
}

const char *zp_course_deriv_text(const zp_course *c, int sec, int order) {
    assert(sec >= 0 && sec < c->nsec && (order == 1 || order == 2) && c->sec[sec].f);
    const zp_course_sec *s = &c->sec[sec];
    return evaluator_get_string(order == 1 ? s->fp : s->fpp);
}
