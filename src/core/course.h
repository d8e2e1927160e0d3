/* The course y = f(x): per-section expressions with exact f' and f'' (libmatheval). */
#ifndef ZP_COURSE_H
#define ZP_COURSE_H

#include <stddef.h>

typedef struct zp_course zp_course;

/* The course at one x, on one section. */
typedef struct zp_track {
    double f;   /* m */
    double fp;  /* slope, 1 */
    double fpp; /* 1/m */
} zp_track;

/* Why a course did not compile. */
typedef struct zp_course_err {
    int section;    /* 1-based section whose f(x) failed; 0: none in particular (out of memory) */
    char what[512]; /* "section 2: f(x) = `x +`: syntax error; expected .." */
} zp_course_err;

/* Compiles nsec expressions in x. Returns NULL and fills e when one does not parse or uses a
   variable other than x. Each zp_course owns its evaluators: libmatheval is not thread-safe,
   so each thread's workspace creates its own. */
zp_course *zp_course_create(int nsec, const char *const *expr, zp_course_err *e);
void zp_course_free(zp_course *c);
/* Checks one f(x) text exactly as zp_course_create does, for messages that name the scene
   line: 0 when it compiles, else -1 with what is wrong and what is expected in err. */
int zp_course_check(const char *expr, char *err, size_t errlen);
/* f, f', f'' of section sec (0-based) at x. */
zp_track zp_course_eval(const zp_course *c, int sec, double x);
/* The derivative expressions as text (sec 0-based, order 1 or 2), for `check`. */
const char *zp_course_deriv_text(const zp_course *c, int sec, int order);

#endif
