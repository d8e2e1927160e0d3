/* Inside the scene reader (not for other floors): the key table, the parse context and the
   helpers its files share: the line reader, the value getters, one reader per INI section. */
#ifndef ZP_SCENE_PARSE_H
#define ZP_SCENE_PARSE_H

#include <ini.h>

#include "drive.h"
#include "scene.h"

enum {
    S_SCENE,
    S_COURSE,
    S_TROLLEY,
    S_BODY,
    S_DRIVE,
    S_SOLVER,
    S_OPTIMIZE,
    S_LIMITS,
    S_ROBUST,
    S_PHYSICS,
    S_COUNT
};

enum {
    K_NAME,
    K_GRAVITY,
    K_X_START,
    K_SECTION,
    K_MASS,
    K_LENGTHS,
    K_MASSES,
    K_DAMPING,
    K_DEATH_ANGLE,
    K_DIRECTION,
    K_FORCES,
    K_MIN,
    K_MAX,
    K_METHOD,
    K_RTOL,
    K_ATOL,
    K_T_MAX,
    K_FORMULATION,
    K_OUTPUT_DT,
    K_ACCURACY,
    K_MARGIN,
    K_MAX_EVALS,
    K_SEED,
    K_SEARCH_METHOD,
    K_SEARCH_RTOL,
    K_OBJECTIVE,
    K_MAX_G,
    K_MAX_JOINT_FORCE,
    K_MAX_ARRIVAL_SPEED,
    K_MAX_KINK_DV,
    K_MIN_ARRIVAL_SPEED,
    K_G_ENVELOPE,
    K_G_LINKS,
    K_FORCE_ERROR,
    K_MASS_RANGE,
    K_LENGTH_RANGE,
    K_TROLLEY_MASS_RANGE,
    K_DAMPING_RANGE,
    K_START_ANGLE,
    K_SAMPLES,
    K_VERIFY_SAMPLES,
    K_SAFETY_FACTOR,
    K_SCALE_LINKS,
    K_WIND_RANGE,
    K_DRAG_AREA,
    K_AIR_DENSITY,
    K_WIND,
    K_ROLLING,
    K_KINK_RADIUS,
    K_COUNT
};

/* the docs/scene-file.md contract: section, key and what a value must be (for "expected ...") */
typedef struct zp_scene_key {
    int sec;
    const char *name;
    const char *expect;
} zp_scene_key;
extern const zp_scene_key zp_scene_keys[K_COUNT];
extern const char *const zp_scene_sec_names[S_COUNT];

#define LINE_CAP INI_MAX_LINE /* inih's line buffer; a longer line is an error, not split */
/* a [drive] forces line: every parameter of the largest schedule in 17 digits */
#define ZP_FORCES_TEXT_MAX (ZP_SCHED_MAX_PARAMS * 26 + 64)
#define MSG_MAX (2 * ZP_DIAG_MAX) /* enough to pick the first ZP_DIAG_MAX by line */

/* Design note: inih is built here without INI_HANDLER_LINENO, so it cannot say where a key
   was. Our own reader hands it the text line by line and counts; inih calls the handler for a
   line before it asks for the next, so ctx->line is that key's line. The reader also checks
   each line's shape, which lets every syntax error be reported (inih keeps only the first). */
typedef struct parse_ctx {
    const char *file; /* borrowed: the name in messages */
    zp_diag *d;
    int schedule;     /* a schedule file: only [drive] forces */
    int need_name;    /* the scene must name a plain folder (a command writes under it) */
    const char *text; /* borrowed: the whole file */
    size_t len;       /* its length: a NUL before it is an error, not the end */
    size_t pos;
    int line;              /* line being parsed (1-based); after parsing, the last line */
    int sec_line[S_COUNT]; /* line of each section's first header, 0 if absent */
    int key_line[K_COUNT]; /* line of each key, 0 if absent */
    int key_bad[K_COUNT];  /* 1 once a value of the key was refused: rules joining keys skip it */
    char val[K_COUNT][LINE_CAP];
    char forces_val[ZP_FORCES_TEXT_MAX];  /* [drive] forces: its line may exceed LINE_CAP */
    char forces_long[ZP_FORCES_TEXT_MAX]; /* a long forces line's value, before inih sees it */
    int forces_long_line;                 /* its line, 0 if none */
    int nsect;                            /* `section` lines seen (may exceed ZP_MAX_SECTIONS) */
    int sect_line[ZP_MAX_SECTIONS];
    char sect_val[ZP_MAX_SECTIONS][LINE_CAP];
    /* messages are held here and handed to the zp_diag in line order at the end, since the
       line checks (while reading) and the value checks (after) find them out of order */
    int nmsg, nmore; /* held, and beyond MSG_MAX (counted as dropped) */
    struct {
        int line;
        char sec[16], key[LINE_CAP], what[ZP_DIAG_TEXT];
    } msg[MSG_MAX];
} parse_ctx;

/* ---- scene_lines.c: the line reader, messages and "did you mean" hints ---- */

/* runs inih over text (len bytes, which may hold a NUL: reported); problems are held in c */
void zp_scene_parse_text(parse_ctx *c, const char *text, size_t len);
/* holds one message about line, [sec] key (either may be NULL) */
void zp_scene_bad(parse_ctx *c, int line, const char *sec, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
/* hands the held messages to c->d, ordered by line (stable); returns how many */
int zp_scene_flush(parse_ctx *c);

/* ---- scene_values.c: raw text -> numbers, each with the key's "expected ..." ---- */

typedef enum { R_ANY, R_POS, R_NONNEG } zp_range;

/* a message about key k on its own line: what; expected ... */
void zp_scene_bad_key(parse_ctx *c, int k, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* a list of key k with n values where the scene needs another count (said by fmt) */
void zp_scene_bad_count(parse_ctx *c, int k, int n, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* a required key that is absent: pointed at its section's header, else at the file's end */
void zp_scene_missing(parse_ctx *c, int k, const char *what);
/* key k as a number in range r: 1 if set in *out, 0 if absent, -1 if bad (reported) */
int zp_scene_get_number(parse_ctx *c, int k, zp_range r, double *out);
/* key k as a list in range r: its length if set in out (at most max), 0 absent, -1 bad */
int zp_scene_get_list(parse_ctx *c, int k, zp_range r, double *out, int max);
/* key k as a whole number in [lo, hi]: 1 if set, 0 absent, -1 bad */
int zp_scene_get_whole(parse_ctx *c, int k, unsigned long lo, unsigned long hi, unsigned long *out);
/* key k as text that fits cap bytes: 1 if set, 0 absent, -1 bad */
int zp_scene_get_text(parse_ctx *c, int k, char *out, size_t cap);

/* ---- scene_sections.c, scene_extras.c: one reader per INI section ---- */

/* [drive] forces through the drive module, for a course of nsec sections: 1 read into *s,
   0 absent, -1 bad (reported) */
int zp_scene_read_forces(parse_ctx *c, int nsec, zp_schedule *s);
/* the schedule's kind and parameters into the scene */
void zp_scene_set_forces(zp_scene *sc, const zp_schedule *s);

void zp_scene_read_scene(parse_ctx *c, zp_scene *sc);
void zp_scene_read_course(parse_ctx *c, zp_scene *sc);
void zp_scene_read_trolley(parse_ctx *c, zp_scene *sc);
void zp_scene_read_body(parse_ctx *c, zp_scene *sc);
void zp_scene_read_drive(parse_ctx *c, zp_scene *sc);
void zp_scene_read_solver(parse_ctx *c, zp_scene *sc);
void zp_scene_read_optimize(parse_ctx *c, zp_scene *sc);
void zp_scene_read_limits(parse_ctx *c, zp_scene *sc);
void zp_scene_read_robust(parse_ctx *c, zp_scene *sc);
void zp_scene_read_physics(parse_ctx *c, zp_scene *sc);

/* ---- scene_expr.c: `y0`, `pi` and `e` replaced by numbers in each section's f(x) ---- */

/* in with `pi`, `e` and `y0` (*y0; y0 NULL: unknown, as after a bad previous section) written
   as numbers into out (cap bytes); 0, or -1 with why: y0 where no section precedes (has_prev 0),
   or the result too long; -2 with why: y0 where it is unknown */
int zp_scene_expr_subst(const char *in, int has_prev, const double *y0, char *out, size_t cap,
                        char *why, size_t whylen);
/* f(x) of a (substituted) expression at x: 0, or -1 when it does not compile or is not finite */
int zp_scene_expr_end(const char *expr, double x, double *y);

/* ---- scene_rules.c: rules that join keys of several sections ---- */

void zp_scene_rules(parse_ctx *c, zp_scene *sc);

#endif
