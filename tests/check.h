/* Test assertions: a failure prints file:line, the expression, both values and the tolerance.
   Tolerances are scaled by ZIPOPT_TOL_SCALE (set it to 0 to see the real residuals). */
#ifndef ZP_CHECK_H
#define ZP_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int zp_check_failures;
static int zp_check_count;

static inline double zp_tol_scale(void) {
    const char *s = getenv("ZIPOPT_TOL_SCALE");
    return s ? atof(s) : 1.0;
}

#define CHECK(cond)                                                                          \
    do {                                                                                     \
        zp_check_count++;                                                                    \
        if (!(cond)) {                                                                       \
            zp_check_failures++;                                                             \
            fprintf(stderr, "%s:%d: CHECK(%s) failed\n", __FILE__, __LINE__, #cond);         \
        }                                                                                    \
    } while (0)

/* |a - b| <= tol */
#define CHECK_NEAR(a, b, tol)                                                                \
    do {                                                                                     \
        double zp_a_ = (a), zp_b_ = (b), zp_t_ = (tol) * zp_tol_scale();                      \
        zp_check_count++;                                                                    \
        if (!(fabs(zp_a_ - zp_b_) <= zp_t_)) {                                               \
            zp_check_failures++;                                                             \
            fprintf(stderr, "%s:%d: CHECK_NEAR(%s, %s): %.17g vs %.17g, |diff| %.3g > tol %.3g\n", \
                    __FILE__, __LINE__, #a, #b, zp_a_, zp_b_, fabs(zp_a_ - zp_b_), zp_t_);   \
        }                                                                                    \
    } while (0)

/* |a - b| <= rel * max(|a|, |b|) */
#define CHECK_REL(a, b, rel)                                                                 \
    do {                                                                                     \
        double zp_a_ = (a), zp_b_ = (b);                                                     \
        double zp_t_ = (rel) * zp_tol_scale() * fmax(fabs(zp_a_), fabs(zp_b_));              \
        zp_check_count++;                                                                    \
        if (!(fabs(zp_a_ - zp_b_) <= zp_t_)) {                                               \
            zp_check_failures++;                                                             \
            fprintf(stderr, "%s:%d: CHECK_REL(%s, %s): %.17g vs %.17g, rel diff %.3g > %.3g\n", \
                    __FILE__, __LINE__, #a, #b, zp_a_, zp_b_,                                \
                    fabs(zp_a_ - zp_b_) / fmax(fmax(fabs(zp_a_), fabs(zp_b_)), 1e-300), (rel)); \
        }                                                                                    \
    } while (0)

/* ends main(): prints the plain count line and returns the exit status */
#define CHECK_DONE()                                                                         \
    (printf("%d passed, %d failed\n", zp_check_count - zp_check_failures, zp_check_failures), \
     zp_check_failures ? 1 : 0)

#endif
