/* course.c: f, f', f'' of interpreted and compiled sections equal the closed forms of docs/model.md
   "Course" (seed) and hand-derived derivatives of every allowed function; the compiled code
   agrees with libmatheval on every scene in config/ and on random expressions; bad
   expressions are refused. */
#include <dirent.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <matheval.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "course.h"
#include "model.h"
#include "scene_load.h"
#include "testutil.h"

/* the derivatives are symbolic, so only round-off separates them from the closed forms */
static double round_off(double v) {
    return 1e-12 * (1 + fabs(v));
}

static void check_track(zp_track t, double f, double fp, double fpp) {
    CHECK_NEAR(t.f, f, round_off(f));
    CHECK_NEAR(t.fp, fp, round_off(fp));
    CHECK_NEAR(t.fpp, fpp, round_off(fpp));
}

static void test_seed_course(void) {
    const char *expr[] = {"(x/10 - 3)^2 + 1", "-x/10 + 16", "-(x/10 - 12)^2 + 10"};
    zp_course_err e;
    zp_course *c = zp_course_create(3, expr, &e);
    CHECK(c != NULL);
    if (!c) {
        return;
    }
    const double xs[] = {0, 13.7, 30, 60, 77.25, 100, 118, 140};
    for (size_t i = 0; i < sizeof xs / sizeof *xs; i++) {
        double x = xs[i];
        check_track(zp_course_eval(c, 0, x), pow(x / 10 - 3, 2) + 1, (x / 10 - 3) / 5, 1.0 / 50);
        check_track(zp_course_eval(c, 1, x), -x / 10 + 16, -0.1, 0);
        check_track(zp_course_eval(c, 2, x), -pow(x / 10 - 12, 2) + 10, -(x / 10 - 12) / 5,
                    -1.0 / 50);
    }
    /* docs/model.md: continuous at 60 (y = 10) and 100 (y = 6); slopes 0.6 -> -0.1 -> 0.4 */
    CHECK_NEAR(zp_course_eval(c, 0, 60).f, 10, round_off(10));
    CHECK_NEAR(zp_course_eval(c, 1, 60).f, 10, round_off(10));
    CHECK_NEAR(zp_course_eval(c, 1, 100).f, 6, round_off(6));
    CHECK_NEAR(zp_course_eval(c, 2, 100).f, 6, round_off(6));
    CHECK_NEAR(zp_course_eval(c, 0, 60).fp, 0.6, round_off(0.6));
    CHECK_NEAR(zp_course_eval(c, 2, 100).fp, 0.4, round_off(0.4));
    /* the derivative texts exist for `check`; f' of section 1 depends on x, f'' does not */
    CHECK(strchr(zp_course_deriv_text(c, 0, 1), 'x') != NULL);
    CHECK(zp_course_deriv_text(c, 0, 2) != NULL);
    zp_course_free(c);
}

static void check_functions(const zp_course *c);

static void test_functions(void) {
    const char *expr[] = {
        "2*cosh(x/4) - 3*sin(2*x)",     "sqrt(1 + x^2) + exp(-x/3)", "log(2 + x) + tan(x/5)",
        "tanh(x) + sinh(x/2) * cos(x)", "1.5e-3*x^3 + 2E+1",
    };
    zp_course_err err;
    zp_course *built = zp_course_create(5, expr, &err);
    CHECK(built != NULL);
    if (!built) {
        fprintf(stderr, "%s\n", err.what);
        return;
    }
    zp_course *compiled = zp_course_for_thread(built, &err);
    CHECK(compiled && zp_course_compiled(compiled) && !zp_course_compiled(built));
    for (zp_course *c = built; c; c = c == built ? compiled : NULL) {
        check_functions(c);
    }
    zp_course_free(compiled);
    zp_course_free(built);
}

static void check_functions(const zp_course *c) {
    const double xs[] = {0.3, 1, 2.5, 4};
    for (size_t i = 0; i < sizeof xs / sizeof *xs; i++) {
        double x = xs[i];
        check_track(zp_course_eval(c, 0, x), 2 * cosh(x / 4) - 3 * sin(2 * x),
                    0.5 * sinh(x / 4) - 6 * cos(2 * x), 0.125 * cosh(x / 4) + 12 * sin(2 * x));
        double r = sqrt(1 + x * x), e = exp(-x / 3);
        check_track(zp_course_eval(c, 1, x), r + e, x / r - e / 3, 1 / (r * r * r) + e / 9);
        double t = tan(x / 5), sec2 = 1 + t * t;
        check_track(zp_course_eval(c, 2, x), log(2 + x) + t, 1 / (2 + x) + sec2 / 5,
                    -1 / ((2 + x) * (2 + x)) + 2 * sec2 * t / 25);
        double th = tanh(x), sh = sinh(x / 2), ch = cosh(x / 2);
        double sech2 = 1 - th * th;
        check_track(zp_course_eval(c, 3, x), th + sh * cos(x),
                    sech2 + 0.5 * ch * cos(x) - sh * sin(x),
                    -2 * th * sech2 + 0.25 * sh * cos(x) - ch * sin(x) - sh * cos(x));
        check_track(zp_course_eval(c, 4, x), 1.5e-3 * x * x * x + 20, 4.5e-3 * x * x, 9e-3 * x);
    }
}

/* The compiled f, f', f'' of section sec against libmatheval's own evaluators of text at npt
   points over [lo, hi]: finite where libmatheval is, and then within 1e-14 of the largest |value|
   of that derivative over the points (its scale: a zero crossing is no excuse and no trap). Returns
   the points compared. */
static int agree_with_matheval(const zp_course *c, int sec, const char *text, double lo, double hi,
                               int npt) {
    char *buf = strdup(text); /* evaluator_create takes a writable string */
    void *ev[3] = {evaluator_create(buf)};
    free(buf);
    CHECK(ev[0] != NULL);
    if (!ev[0]) {
        return 0;
    }
    ev[1] = evaluator_derivative_x(ev[0]);
    ev[2] = evaluator_derivative_x(ev[1]);
    double *ref = malloc(sizeof *ref * 3 * npt), *got = malloc(sizeof *got * 3 * npt);
    double scale[3] = {0, 0, 0};
    for (int i = 0; i < npt; i++) {
        double x = lo + (hi - lo) * i / (npt - 1);
        zp_track t = zp_course_eval(c, sec, x);
        double g[3] = {t.f, t.fp, t.fpp};
        for (int k = 0; k < 3; k++) {
            ref[3 * i + k] = evaluator_evaluate_x(ev[k], x);
            got[3 * i + k] = g[k];
            if (isfinite(ref[3 * i + k])) {
                scale[k] = fmax(scale[k], fabs(ref[3 * i + k]));
            }
        }
    }
    /* a derivative that is zero up to round-off (x^0.5^2) is measured against the one below
       it over the interval, the size its round-off has */
    for (int k = 1; k < 3; k++) {
        scale[k] = fmax(scale[k], scale[k - 1] / (hi - lo));
    }
    int compared = 0;
    for (int i = 0; i < 3 * npt; i++) {
        /* where libmatheval's value is finite the compiled one is too; the converse may fail,
           as the simplified tree skips 0/0 and 0*inf of an unsimplified one (sqrt(x - x)) */
        if (!isfinite(ref[i]) || !isfinite(got[i])) {
            if (isfinite(ref[i])) {
                fprintf(stderr, "`%s` d%d/dx%d at x = %.17g: compiled %.17g, libmatheval %.17g\n",
                        text, i % 3, i % 3, lo + (hi - lo) * (i / 3) / (npt - 1), got[i], ref[i]);
                CHECK(0);
            }
            continue;
        }
        compared++;
        if (!(fabs(got[i] - ref[i]) <= 1e-14 * scale[i % 3] * zp_tol_scale())) {
            fprintf(stderr, "`%s` d%d/dx%d at x = %.17g: compiled %.17g, libmatheval %.17g\n", text,
                    i % 3, i % 3, lo + (hi - lo) * (i / 3) / (npt - 1), got[i], ref[i]);
            CHECK(0);
        }
    }
    free(ref);
    free(got);
    for (int k = 2; k >= 0; k--) {
        evaluator_destroy(ev[k]);
    }
    return compared;
}

/* every section of every scene in config/, compiled as the simulations get it */
static void test_scenes_compiled(void) {
    static const char *const scenes[] = {"seed", "flat", "human", "smooth", "straight", "valley"};
    for (size_t i = 0; i < sizeof scenes / sizeof *scenes; i++) {
        char path[1024];
        zp_course_err err;
        snprintf(path, sizeof path, "%s/config/%s.ini", ZP_SOURCE_DIR, scenes[i]);
        zp_scene sc;
        zp_model *m = tu_model_file(path, &sc);
        zp_course *c = m ? zp_model_course(m, &err) : NULL;
        CHECK(c && zp_course_compiled(c));
        for (int k = 0; c && k < m->nsec; k++) {
            CHECK(agree_with_matheval(c, k, m->expr[k], m->xb[k], m->xb[k + 1], 1001) == 3 * 1001);
        }
        zp_course_free(c);
        zp_model_free(m);
    }
}

/* a random expression in x of the docs/scene-file.md grammar, depth levels deep, appended to buf */
static void random_expr(gsl_rng *r, int depth, char *buf, size_t len) {
    static const char *const funcs[] = {"sqrt", "exp",  "log",  "sin", "cos",
                                        "tan",  "sinh", "cosh", "tanh"};
    size_t used = strlen(buf);
    unsigned kind = depth <= 0 ? gsl_rng_uniform_int(r, 2) : 2 + gsl_rng_uniform_int(r, 5);
    if (kind == 0) {
        snprintf(buf + used, len - used, "x");
    } else if (kind == 1) {
        snprintf(buf + used, len - used, "%.4g", 0.1 + 4.9 * gsl_rng_uniform(r));
    } else if (kind == 2) { /* a binary operator */
        snprintf(buf + used, len - used, "(");
        random_expr(r, depth - 1, buf, len);
        used = strlen(buf);
        snprintf(buf + used, len - used, " %c ", "+-*/"[gsl_rng_uniform_int(r, 4)]);
        random_expr(r, depth - 1, buf, len);
        used = strlen(buf);
        snprintf(buf + used, len - used, ")");
    } else if (kind == 3) { /* a power with a constant exponent (powers in x: test_powers) */
        static const char *const exps[] = {"2", "3", "-1", "0.5"};
        snprintf(buf + used, len - used, "(");
        random_expr(r, depth - 1, buf, len);
        used = strlen(buf);
        snprintf(buf + used, len - used, ")^%s", exps[gsl_rng_uniform_int(r, 4)]);
    } else if (kind == 4) {
        snprintf(buf + used, len - used, "-");
        random_expr(r, depth - 1, buf, len);
    } else {
        snprintf(buf + used, len - used, "%s(", funcs[gsl_rng_uniform_int(r, 9)]);
        random_expr(r, depth - 1, buf, len);
        used = strlen(buf);
        snprintf(buf + used, len - used, ")");
    }
}

/* powers with x in the exponent (the random expressions have constant exponents, as a
   general power's second derivative cancels too much for random nesting) */
static void test_powers(void) {
    const char *expr[] = {"x^x", "2^x", "(1 + x)^(x/2)", "exp(x)^sin(x)"};
    zp_course_err err;
    zp_course *built = zp_course_create(4, expr, &err);
    zp_course *c = built ? zp_course_for_thread(built, &err) : NULL;
    CHECK(c && zp_course_compiled(c));
    for (int k = 0; c && k < 4; k++) {
        CHECK(agree_with_matheval(c, k, expr[k], 0.25, 2, 64) == 3 * 64);
    }
    zp_course_free(c);
    zp_course_free(built);
}

/* random expressions, eight sections to a course (one compile), against libmatheval */
static void test_random_compiled(void) {
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 1);
    int compared = 0;
    for (int batch = 0; batch < 25; batch++) {
        char text[8][512];
        zp_course_err err;
        const char *expr[8];
        for (int k = 0; k < 8; k++) {
            text[k][0] = '\0';
            random_expr(r, 1 + (int)gsl_rng_uniform_int(r, 4), text[k], sizeof text[k]);
            expr[k] = text[k];
        }
        zp_course *built = zp_course_create(8, expr, &err);
        CHECK(built != NULL);
        zp_course *c = built ? zp_course_for_thread(built, &err) : NULL;
        CHECK(c && zp_course_compiled(c));
        for (int k = 0; c && k < 8; k++) {
            compared += agree_with_matheval(c, k, text[k], 0.25, 2, 64);
        }
        zp_course_free(c);
        zp_course_free(built);
    }
    /* most points are in every expression's domain */
    CHECK(compared > 25 * 8 * 3 * 64 / 2);
    gsl_rng_free(r);
}

/* the number of files in dir; *ino the inode of the last (a file rewritten gets a new one) */
static int count_files(const char *dir, unsigned long *ino) {
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *de; d && (de = readdir(d));) {
        if (de->d_name[0] != '.') {
            n++;
            *ino = (unsigned long)de->d_ino;
        }
    }
    if (d) {
        closedir(d);
    }
    return n;
}

/* the compiled code is cached on disk: a second course of the same text loads the file (no
   new one) and evaluates the same; a damaged file is not loaded but replaced */
static void test_cache(const char *cache) {
    const char *expr[] = {"sinh(x/7) + x^3/1000"};
    char dir[1100];
    zp_course_err err;
    snprintf(dir, sizeof dir, "%s/zipopt", cache);
    double v[3][3];
    unsigned long ino[3] = {0, 0, 0};
    for (int round = 0; round < 3; round++) {
        if (round == 2) { /* damage the file: same name, no key */
            char path[1400];
            DIR *d = opendir(dir);
            for (struct dirent *de; d && (de = readdir(d));) {
                if (de->d_name[0] != '.') {
                    snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
                }
            }
            closedir(d);
            FILE *f = fopen(path, "w");
            CHECK(f && fputs("not a library\n", f) >= 0);
            fclose(f);
        }
        zp_course *built = zp_course_create(1, expr, &err);
        zp_course *c = built ? zp_course_for_thread(built, &err) : NULL;
        CHECK(c && zp_course_compiled(c));
        zp_track t = c ? zp_course_eval(c, 0, 2.5) : (zp_track){0, 0, 0};
        v[round][0] = t.f;
        v[round][1] = t.fp;
        v[round][2] = t.fpp;
        CHECK(count_files(dir, &ino[round]) == 1);
        zp_course_free(c);
        zp_course_free(built);
    }
    CHECK(ino[1] == ino[0] && ino[2] != ino[0]); /* loaded, then replaced */
    for (int k = 0; k < 3; k++) {
        CHECK(v[1][k] == v[0][k] && v[2][k] == v[0][k]);
    }
    CHECK(v[0][0] == sinh(2.5 / 7) + pow(2.5, 3) / 1000);
}

/* loading cached code runs it: a cache folder others may write to is not used (the course is
   still compiled, in memory, and nothing is written there) */
static void test_cache_not_shared(const char *cache) {
    char dir[1100];
    snprintf(dir, sizeof dir, "%s/shared", cache);
    CHECK(mkdir(dir, 0700) == 0 && chmod(dir, 0777) == 0);
    char sub[1200];
    snprintf(sub, sizeof sub, "%s/zipopt", dir);
    CHECK(mkdir(sub, 0777) == 0 && chmod(sub, 0777) == 0);
    setenv("XDG_CACHE_HOME", dir, 1);
    const char *expr[] = {"cosh(x/9) - x^2/500"};
    zp_course_err err;
    zp_course *built = zp_course_create(1, expr, &err);
    zp_course *c = built ? zp_course_for_thread(built, &err) : NULL;
    CHECK(c && zp_course_compiled(c));
    unsigned long ino = 0;
    CHECK(count_files(sub, &ino) == 0);
    zp_course_free(c);
    zp_course_free(built);
    setenv("XDG_CACHE_HOME", cache, 1);
    rmdir(sub);
    rmdir(dir);
}

/* each bad text is refused by zp_course_check and by zp_course_create, which names the
   (1-based) section and says why */
static void test_bad(const char *bad, const char *why_part) {
    char err[512] = "";
    CHECK(zp_course_check(bad, err, sizeof err) == -1);
    if (!strstr(err, why_part)) {
        fprintf(stderr, "`%s`: message `%s` lacks `%s`\n", bad, err, why_part);
        CHECK(0);
    }
    const char *expr[] = {"x", bad};
    zp_course_err e;
    CHECK(zp_course_create(2, expr, &e) == NULL);
    CHECK(e.section == 2 && strstr(e.what, "section 2") != NULL);
}

int main(void) {
    /* the compiled code's cache in a directory of this run's own */
    char cache[] = "/tmp/zp_test_course_XXXXXX";
    CHECK(mkdtemp(cache) != NULL);
    setenv("XDG_CACHE_HOME", cache, 1);
    test_cache(cache);
    test_cache_not_shared(cache);
    test_seed_course();
    test_functions();
    test_scenes_compiled();
    test_powers();
    test_random_compiled();
    test_bad("x +", "syntax error");
    test_bad("(x/10 - 3^2", "syntax error");
    test_bad("2x", "syntax error");
    test_bad("y * x", "`y`");
    test_bad("abs(x)", "`abs`");
    test_bad("pi * x", "`pi`");
    test_bad("x^2^3", "chained");
    test_bad("sin(x, 2)", "`,`");
    test_bad("x $ 2", "`$`");
    test_bad("   ", "empty");
    char err[256];
    CHECK(zp_course_check("-(x/10 - 12)^2 + 10", err, sizeof err) == 0);
    CHECK(zp_course_check("(x^2)^3 + x^(2^3)", err, sizeof err) == 0);
    zp_course_free(NULL);
    /* the cache directory and its files, two levels */
    char dir[1100], path[1400];
    snprintf(dir, sizeof dir, "%s/zipopt", cache);
    DIR *d = opendir(dir);
    for (struct dirent *de; d && (de = readdir(d));) {
        snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
        if (de->d_name[0] != '.') {
            remove(path);
        }
    }
    if (d) {
        closedir(d);
    }
    rmdir(dir);
    rmdir(cache);
    return CHECK_DONE();
}
