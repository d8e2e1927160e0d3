/* The course y = f(x): per-section expressions with exact f' and f'' (libmatheval, and compiled
   for the simulations). */
#ifndef ZP_COURSE_H
#define ZP_COURSE_H

#include <stddef.h>
#include <stdio.h>

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

/* Builds nsec expressions in x. Returns NULL and fills e when one does not parse or uses a
   variable other than x. The course's own evaluators (libmatheval) are not thread-safe: it
   serves one thread, and hands out handles for the others through zp_course_for_thread. */
zp_course *zp_course_create(int nsec, const char *const *expr, zp_course_err *e);
/* A course for one simulating thread, owned by the caller (zp_course_free): the sections
   compiled to native code (compiled once per c on the first call, shared read-only, any thread
   may evaluate), or, when the compiler fails or ZIPOPT_NO_JIT is set (a one-line notice, once
   per process, on the stream of zp_course_notices_to), a new interpreted course, which must
   then be made serially. NULL with why in e. */
zp_course *zp_course_for_thread(const zp_course *c, zp_course_err *e);
/* Where the notice of an interpreted course is printed (the program: stderr); none before
   this is called or after it is called with NULL (a library prints nothing). */
void zp_course_notices_to(FILE *f);
/* 1 when c evaluates compiled code, 0 when it interprets. */
int zp_course_compiled(const zp_course *c);
void zp_course_free(zp_course *c);
/* Checks one f(x) text exactly as zp_course_create does, for messages that name the scene
   line: 0 when it compiles, else -1 with what is wrong and what is expected in err. */
int zp_course_check(const char *expr, char *err, size_t errlen);
/* f, f', f'' of section sec (0-based) at x. */
zp_track zp_course_eval(const zp_course *c, int sec, double x);
/* The derivative expressions as text (sec 0-based, order 1 or 2), for `check`; a course from
   zp_course_create only. */
const char *zp_course_deriv_text(const zp_course *c, int sec, int order);

#endif
