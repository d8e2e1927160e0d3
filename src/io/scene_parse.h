/* Inside the scene reader (not for other floors): the key table's types (scene_keys.def), the
   parse context and the helpers its files share: the line reader, the value getters, the
   special keys' readers. */
#ifndef ZP_SCENE_PARSE_H
#define ZP_SCENE_PARSE_H

#include <ini.h>
#include <math.h>

#include "drive.h"
#include "scene.h"

/* the sections and keys of scene_keys.def: S_SCENE.., K_NAME.. in its order */
#define ZP_KEY(id, ...)
#define ZP_SECTION(id, ...) S_##id,
enum {
#include "scene_keys.def"
    S_COUNT
};
#undef ZP_SECTION
#define ZP_SECTION(id, ...)
#undef ZP_KEY
#define ZP_KEY(id, ...) K_##id,
enum {
#include "scene_keys.def"
    K_COUNT
};
#undef ZP_KEY
#undef ZP_SECTION

/* the numbers a key accepts: from lo to hi, each end included unless open */
typedef struct zp_range {
    double lo, hi;
    int lo_open, hi_open;
} zp_range;
#define R_ANY ((zp_range){-INFINITY, INFINITY, 0, 0})
#define R_POS ((zp_range){0, INFINITY, 1, 0})
#define R_NONNEG ((zp_range){0, INFINITY, 0, 0})

/* what a key's member of zp_scene holds: how the plain reader stores it, how the defaults set
   it and how `check` lists it (T_OTHER: only its own reader and lister know) */
typedef enum { T_NUMBER, T_INT, T_LONG, T_ULONG, T_TEXT, T_OTHER } zp_scene_type;

/* a key's default (scene_keys.def): D_VALUE num, or text for a text; D_OFF zero, listed as
   off; D_REQUIRED none, text says what the missing message asks for; D_HAND set and listed
   by hand-written code */
typedef enum { D_VALUE, D_OFF, D_REQUIRED, D_HAND } zp_scene_how;
typedef struct zp_scene_default {
    zp_scene_how how;
    double num;
    const char *text;
    const char *docs; /* the docs' default column */
} zp_scene_default;

typedef struct parse_ctx parse_ctx;
/* a special key's reader: key k's raw value (absent too, unless required) -> sc, its refusals
   reported */
typedef void zp_scene_reader(parse_ctx *c, zp_scene *sc, int k);

/* one line of scene_keys.def */
typedef struct zp_scene_key {
    int sec;
    const char *name;
    size_t field;           /* offsetof(zp_scene, member) of the member it fills */
    size_t size;            /* sizeof that member: a text's capacity */
    zp_scene_type type;     /* what the member holds */
    zp_range rule;          /* a number's values */
    unsigned long min, max; /* a whole number's values */
    zp_scene_reader *read;  /* a special key's own reader; NULL: read as its type says */
    zp_scene_default dflt;
    const char *expect; /* after "expected" in its messages, and in the docs */
    const char *doc;    /* what it means, for the docs */
} zp_scene_key;
extern const zp_scene_key zp_scene_keys[K_COUNT];

typedef struct zp_scene_section {
    const char *name;
    int optional; /* off unless given: check lists what it sets */
} zp_scene_section;
extern const zp_scene_section zp_scene_keys_sections[S_COUNT];

/* key k's section name */
static inline const char *zp_scene_sec_of(int k) {
    return zp_scene_keys_sections[zp_scene_keys[k].sec].name;
}
/* where key k's value lives in sc: its member */
static inline void *zp_scene_member(zp_scene *sc, int k) {
    return (char *)sc + zp_scene_keys[k].field;
}

#define LINE_CAP INI_MAX_LINE /* inih's line buffer; a longer line is an error, not split */
/* a [drive] forces line: every parameter of the largest schedule in 17 digits */
#define ZP_FORCES_TEXT_MAX (ZP_SCHED_MAX_PARAMS * 26 + 64)
#define MSG_MAX (2 * ZP_DIAG_MAX) /* enough to pick the first ZP_DIAG_MAX by line */

/* Design note: inih is built here without INI_HANDLER_LINENO, so it cannot say where a key
   was. Our own reader hands it the text line by line and counts; inih calls the handler for a
   line before it asks for the next, so ctx->line is that key's line. The reader also checks
   each line's shape, which lets every syntax error be reported (inih keeps only the first). */
struct parse_ctx {
    const char *file; /* borrowed: the name in messages */
    zp_diag *d;
    int schedule;     /* a schedule file: only [drive] forces */
    int need_name;    /* the scene must name a plain folder (a command writes under it) */
    const char *text; /* borrowed: the whole file */
    size_t len;       /* its length: a NUL before it is an error, not the end */
    size_t pos;
    int line;              /* line being parsed (1-based); after parsing, the last line */
    int sec_line[S_COUNT]; /* line of each section's first header, 0 if absent */
    int key_line[K_COUNT]; /* line of each key (section: its first), 0 if absent */
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
};

/* ---- scene_lines.c: the line reader, messages and "did you mean" hints ---- */

/* runs inih over text (len bytes, which may hold a NUL: reported); problems are held in c */
void zp_scene_lines_parse(parse_ctx *c, const char *text, size_t len);
/* holds one message about line, [sec] key (either may be NULL) */
void zp_scene_lines_bad(parse_ctx *c, int line, const char *sec, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
/* hands the held messages to c->d, ordered by line (stable); returns how many */
int zp_scene_lines_flush(parse_ctx *c);

/* ---- scene_values.c: raw text -> numbers, each with the key's "expected ..." ---- */

/* a message about key k on its own line: what; expected ... */
void zp_scene_values_bad_key(parse_ctx *c, int k, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* a list of key k with n values where the scene needs another count (said by fmt) */
void zp_scene_values_bad_count(parse_ctx *c, int k, int n, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* a required key that is absent: pointed at its section's header, else at the file's end */
void zp_scene_values_missing(parse_ctx *c, int k, const char *what);
/* key k as a number in range r: 1 if set in *out, 0 if absent, -1 if bad (reported) */
int zp_scene_values_number(parse_ctx *c, int k, zp_range r, double *out);
/* key k as a list in range r: its length if set in out (at most max), 0 absent, -1 bad */
int zp_scene_values_list(parse_ctx *c, int k, zp_range r, double *out, int max);
/* key k as text that fits cap bytes: 1 if set, 0 absent, -1 bad */
int zp_scene_values_text(parse_ctx *c, int k, char *out, size_t cap);
/* a plain key k (number, whole number or text, as its table line says) into its member of sc
   when given and accepted */
void zp_scene_values_plain(parse_ctx *c, zp_scene *sc, int k);
/* every key's table default (NUM, TXT) into its member of sc; the others are left alone */
void zp_scene_values_defaults(zp_scene *sc);

/* ---- scene_sections.c, scene_extras.c: the special keys' readers (scene_keys.def) ---- */

/* [drive] forces through the drive module, as many as shape (kind, sections, knots) takes: 1
   read into *s, 0 absent, -1 bad (reported) */
int zp_scene_sections_parse_forces(parse_ctx *c, const zp_schedule *shape, zp_schedule *s);
/* the schedule's parameters into the scene (its kind is the scene's already) */
void zp_scene_sections_set_forces(zp_scene *sc, const zp_schedule *s);

zp_scene_reader zp_scene_sections_name, zp_scene_sections_section, zp_scene_sections_lengths,
    zp_scene_sections_masses, zp_scene_sections_damping, zp_scene_sections_death_angle, zp_scene_sections_direction,
    zp_scene_sections_kind, zp_scene_sections_knots,
    zp_scene_sections_forces, zp_scene_sections_accuracy, zp_scene_sections_objective;
zp_scene_reader zp_scene_extras_envelope, zp_scene_extras_links, zp_scene_extras_range,
    zp_scene_extras_safety_factor, zp_scene_extras_wind_range, zp_scene_extras_drag_area;

/* ---- scene_cable.c: [cable] (docs/model.md "A cable that sags") ---- */

zp_scene_reader zp_scene_cable_anchor, zp_scene_cable_sections;
/* the drive sections [cable] sections gives (its values counted, as the forces need before
   it is read) */
int zp_scene_cable_nsec(const parse_ctx *c);
/* [cable]'s rules: the anchors' order, length or tension, the cable hangs, the ride inside the
   span, no [course] or kink_radius beside it; x_start's default */
void zp_scene_cable_rules(parse_ctx *c, zp_scene *sc);

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
