/* course.c: f, f', f'' of compiled sections equal the closed forms of MODEL.md "Course" (seed)
   and hand-derived derivatives of every allowed function; bad expressions are refused. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "course.h"

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
    /* MODEL.md: continuous at 60 (y = 10) and 100 (y = 6); slopes 0.6 -> -0.1 -> 0.4 */
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

static void test_functions(void) {
    const char *expr[] = {
        "2*cosh(x/4) - 3*sin(2*x)",     "sqrt(1 + x^2) + exp(-x/3)", "log(2 + x) + tan(x/5)",
        "tanh(x) + sinh(x/2) * cos(x)", "1.5e-3*x^3 + 2E+1",
    };
    zp_course_err e;
    zp_course *c = zp_course_create(5, expr, &e);
    CHECK(c != NULL);
    if (!c) {
        fprintf(stderr, "%s\n", e.what);
        return;
    }
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
    zp_course_free(c);
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
    test_seed_course();
    test_functions();
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
    return CHECK_DONE();
}
