/* Scene files (CONFIG.md) -> zp_scene: inih splits the lines; this file applies every rule of
   CONFIG.md and reports each violation as FILE:LINE: [section] key: what; expected. */
#include "scene_read.h"

#include <ctype.h>
#include <errno.h>
#include <ini.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "course.h"
#include "drive.h"
#include "numtext.h"

enum { S_SCENE, S_COURSE, S_TROLLEY, S_BODY, S_DRIVE, S_SOLVER, S_OPTIMIZE, S_COUNT };
static const char *const sec_names[S_COUNT] = {"scene", "course", "trolley", "body",
                                               "drive", "solver", "optimize"};

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
    K_MARGIN,
    K_MAX_EVALS,
    K_SEED,
    K_SEARCH_METHOD,
    K_SEARCH_RTOL,
    K_COUNT
};

/* the CONFIG.md contract: section, key and what a value must be (for "expected ...") */
static const struct {
    int sec;
    const char *name;
    const char *expect;
} keys[K_COUNT] = {
    [K_NAME] = {S_SCENE, "name", "a folder name of letters, digits, `.`, `_` or `-`"},
    [K_GRAVITY] = {S_SCENE, "gravity", "a number >= 0 (m/s^2)"},
    [K_X_START] = {S_COURSE, "x_start", "a number (m)"},
    [K_SECTION] = {S_COURSE, "section", "`x_end : f(x)`, x_end in m"},
    [K_MASS] = {S_TROLLEY, "mass", "a number > 0 (kg)"},
    [K_LENGTHS] = {S_BODY, "lengths", "1 to 8 numbers > 0 (m), one per link"},
    [K_MASSES] = {S_BODY, "masses", "numbers > 0 (kg), one per link"},
    [K_DAMPING] = {S_BODY, "damping", "numbers >= 0 (N m s/rad), one, or one per joint"},
    [K_DEATH_ANGLE] = {S_BODY, "death_angle", "a number in (0, 360] (deg)"},
    [K_DIRECTION] = {S_DRIVE, "direction", "horizontal or tangent"},
    [K_FORCES] = {S_DRIVE, "forces", "numbers (N), one per section"},
    [K_MIN] = {S_DRIVE, "min", "a number (N)"},
    [K_MAX] = {S_DRIVE, "max", "a number (N)"},
    [K_METHOD] = {S_SOLVER, "method", "a method name (see zipopt --help)"},
    [K_RTOL] = {S_SOLVER, "rtol", "a number > 0"},
    [K_ATOL] = {S_SOLVER, "atol", "a number > 0"},
    [K_T_MAX] = {S_SOLVER, "t_max", "a number > 0 (s)"},
    [K_FORMULATION] = {S_SOLVER, "formulation", "a formulation name (see zipopt --help)"},
    [K_OUTPUT_DT] = {S_SOLVER, "output_dt", "a number > 0 (s)"},
    [K_MARGIN] = {S_OPTIMIZE, "margin", "a number >= 0 (deg) below death_angle"},
    [K_MAX_EVALS] = {S_OPTIMIZE, "max_evals", "a whole number >= 1"},
    [K_SEED] = {S_OPTIMIZE, "seed", "a whole number >= 0"},
    [K_SEARCH_METHOD] = {S_OPTIMIZE, "method", "a method name (see zipopt --help)"},
    [K_SEARCH_RTOL] = {S_OPTIMIZE, "rtol", "a number > 0"},
};

#define LINE_CAP INI_MAX_LINE     /* inih's line buffer; a longer line is an error, not split */
#define MSG_MAX (2 * ZP_DIAG_MAX) /* enough to pick the first ZP_DIAG_MAX by line */

/* Design note: inih is built here without INI_HANDLER_LINENO, so it cannot say where a key
   was. Our own reader hands it the text line by line and counts; inih calls the handler for a
   line before it asks for the next, so ctx->line is that key's line. The reader also checks
   each line's shape, which lets every syntax error be reported (inih keeps only the first). */
typedef struct parse_ctx {
    const char *file; /* borrowed: the name in messages */
    zp_diag *d;
    int schedule;     /* a schedule file: only [drive] forces */
    const char *text; /* borrowed: the whole file */
    size_t pos;
    int line;              /* line being parsed (1-based); after parsing, the last line */
    int sec_line[S_COUNT]; /* line of each section's first header, 0 if absent */
    int key_line[K_COUNT]; /* line of each key, 0 if absent */
    char val[K_COUNT][LINE_CAP];
    int nsect; /* `section` lines seen (may exceed ZP_MAX_SECTIONS) */
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

/* ---- helpers: messages, names, numbers ---- */

static const char *sec_of(int k) {
    return sec_names[keys[k].sec];
}

static int find_section(const char *name) {
    for (int s = 0; s < S_COUNT; s++) {
        if (!strcmp(name, sec_names[s])) {
            return s;
        }
    }
    return -1;
}

/* edit distance with adjacent transpositions counting 1, so `lenghts` is 1 from `lengths` */
static int edit_distance(const char *a, const char *b) {
    enum { N = 40 };
    size_t na = strlen(a), nb = strlen(b);
    if (na >= N || nb >= N) {
        return N;
    }
    int dp[N + 1][N + 1];
    for (size_t i = 0; i <= na; i++) {
        for (size_t j = 0; j <= nb; j++) {
            if (i == 0 || j == 0) {
                dp[i][j] = (int)(i + j);
                continue;
            }
            int best = dp[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            best = dp[i - 1][j] + 1 < best ? dp[i - 1][j] + 1 : best;
            best = dp[i][j - 1] + 1 < best ? dp[i][j - 1] + 1 : best;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                dp[i - 2][j - 2] + 1 < best) {
                best = dp[i - 2][j - 2] + 1;
            }
            dp[i][j] = best;
        }
    }
    return dp[na][nb];
}

/* close enough to be a typo: about one slip per four letters */
static int is_near(const char *typed, const char *valid) {
    return edit_distance(typed, valid) <= 1 + (int)strlen(valid) / 4;
}

int zp_scene_parse_list(const char *text, double *out, int max, char *why, size_t whylen) {
    return zp_text_list(text, out, max, why, whylen);
}

static void bad(parse_ctx *c, int line, const char *sec, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
static void bad(parse_ctx *c, int line, const char *sec, const char *key, const char *fmt, ...) {
    if (c->nmsg == MSG_MAX) {
        c->nmore++;
        return;
    }
    int i = c->nmsg++;
    c->msg[i].line = line;
    snprintf(c->msg[i].sec, sizeof c->msg[i].sec, "%s", sec ? sec : "");
    snprintf(c->msg[i].key, sizeof c->msg[i].key, "%s", key ? key : "");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->msg[i].what, sizeof c->msg[i].what, fmt, ap);
    va_end(ap);
}

/* hands the held messages to the zp_diag, ordered by line (stable); returns how many */
static int flush_messages(parse_ctx *c) {
    int done[MSG_MAX] = {0};
    for (int n = 0; n < c->nmsg; n++) {
        int best = -1;
        for (int i = 0; i < c->nmsg; i++) {
            if (!done[i] && (best < 0 || c->msg[i].line < c->msg[best].line)) {
                best = i;
            }
        }
        done[best] = 1;
        zp_diag_add(c->d, c->file, c->msg[best].line, c->msg[best].sec[0] ? c->msg[best].sec : NULL,
                    c->msg[best].key[0] ? c->msg[best].key : NULL, "%s", c->msg[best].what);
    }
    c->d->dropped += c->nmore;
    return c->nmsg;
}

/* a message about key k on its own line */
static void bad_key(parse_ctx *c, int k, const char *what) {
    bad(c, c->key_line[k], sec_of(k), keys[k].name, "%s; expected %s", what, keys[k].expect);
}

/* a list of key k with n values where the scene needs another count (said by fmt) */
static void bad_count(parse_ctx *c, int k, int n, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static void bad_count(parse_ctx *c, int k, int n, const char *fmt, ...) {
    char what[128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    bad(c, c->key_line[k], sec_of(k), keys[k].name, "%d value%s, expected %s", n, n == 1 ? "" : "s",
        what);
}

/* ---- reading: inih's reader and handler ---- */

static void unknown_section(parse_ctx *c, const char *name) {
    if (c->schedule) {
        bad(c, c->line, NULL, NULL,
            "unknown section [%s]; a schedule file holds only [drive] forces", name);
        return;
    }
    for (int s = 0; s < S_COUNT; s++) {
        if (is_near(name, sec_names[s])) {
            bad(c, c->line, NULL, NULL, "unknown section [%s]; did you mean [%s]?", name,
                sec_names[s]);
            return;
        }
    }
    bad(c, c->line, NULL, NULL,
        "unknown section [%s]; expected one of [scene] [course] [trolley] [body] [drive] "
        "[solver] [optimize]",
        name);
}

static void unknown_key(parse_ctx *c, int s, const char *name) {
    if (c->schedule) {
        bad(c, c->line, sec_names[s], name,
            "unknown key; a schedule file holds only [drive] forces");
        return;
    }
    /* a right key in the wrong section says where it belongs, before any near miss */
    for (int k = 0; k < K_COUNT; k++) {
        if (!strcmp(name, keys[k].name)) {
            bad(c, c->line, sec_names[s], name, "unknown key here; `%s` belongs in [%s]", name,
                sec_of(k));
            return;
        }
    }
    int best = -1, best_d = 0;
    for (int k = 0; k < K_COUNT; k++) {
        if (keys[k].sec == s && is_near(name, keys[k].name)) {
            int dk = edit_distance(name, keys[k].name);
            if (best < 0 || dk < best_d) {
                best = k;
                best_d = dk;
            }
        }
    }
    if (best >= 0) {
        bad(c, c->line, sec_names[s], name, "unknown key; did you mean `%s`?", keys[best].name);
        return;
    }
    char list[256] = "";
    for (int k = 0; k < K_COUNT; k++) {
        if (keys[k].sec == s) {
            size_t len = strlen(list);
            snprintf(list + len, sizeof list - len, "%s%s", len ? ", " : "", keys[k].name);
        }
    }
    bad(c, c->line, sec_names[s], name, "unknown key; expected one of: %s", list);
}

/* hands inih one line at a time, left-trimmed (so no line reads as a continuation of the
   previous value), without ` ;...` or ` #...` comments, and blank if malformed (reported) */
static char *read_line(char *str, int num, void *stream) {
    parse_ctx *c = stream;
    if (!c->text[c->pos]) {
        return NULL;
    }
    const char *s = c->text + c->pos;
    size_t len = strcspn(s, "\n");
    c->pos += len + (s[len] == '\n');
    c->line++;
    if (len > 0 && s[len - 1] == '\r') {
        len--;
    }
    if (c->line == 1 && len >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) {
        s += 3;
        len -= 3;
    }
    str[0] = '\0';
    if (len + 2 > (size_t)num) {
        bad(c, c->line, NULL, NULL, "line is %zu characters long; expected at most %d", len,
            num - 2);
        return str;
    }
    memcpy(str, s, len);
    str[len] = '\0';
    for (size_t i = 0; str[i]; i++) {
        if ((str[i] == ';' || str[i] == '#') && (i == 0 || isspace((unsigned char)str[i - 1]))) {
            str[i] = '\0';
            break;
        }
    }
    zp_text_trim(str);
    if (!*str) {
        return str;
    }

    /* a section header: checked here, since inih does not report headers */
    if (str[0] == '[') {
        char *close = strchr(str, ']');
        if (!close) {
            bad(c, c->line, NULL, NULL, "section header without `]`; expected [name]");
            str[0] = '\0';
            return str;
        }
        if (close[1]) {
            bad(c, c->line, NULL, NULL, "text after the section header; expected [name] alone");
        }
        *close = '\0';
        char name[LINE_CAP];
        strcpy(name, str + 1);
        zp_text_trim(name);
        int sec = find_section(name);
        if (sec < 0 || (c->schedule && sec != S_DRIVE)) {
            unknown_section(c, name);
            /* its keys are skipped: the handler ignores sections it does not know */
            strcpy(str, "[?]");
            return str;
        }
        if (!c->sec_line[sec]) {
            c->sec_line[sec] = c->line;
        }
        snprintf(str, (size_t)num, "[%s]", name);
        return str;
    }

    /* key = value; inih also splits at `:`, which CONFIG.md does not use for keys */
    size_t eq = strcspn(str, "=:");
    if (str[eq] != '=' || eq == 0) {
        bad(c, c->line, NULL, NULL, "`%s` is not a `key = value` line; expected key = value", str);
        str[0] = '\0';
    }
    return str;
}

static int on_key(void *user, const char *section, const char *name, const char *value) {
    parse_ctx *c = user;
    if (!*section) {
        bad(c, c->line, NULL, name, "key outside any section; expected it under its [section]");
        return 1;
    }
    int s = find_section(section);
    if (s < 0) {
        return 1; /* an unknown section, reported at its header */
    }
    int k = 0;
    while (k < K_COUNT && !(keys[k].sec == s && !strcmp(keys[k].name, name))) {
        k++;
    }
    if (k == K_COUNT || (c->schedule && k != K_FORCES)) {
        unknown_key(c, s, name);
        return 1;
    }
    /* `section` repeats, once per course section */
    if (k == K_SECTION) {
        if (c->nsect < ZP_MAX_SECTIONS) {
            c->sect_line[c->nsect] = c->line;
            snprintf(c->sect_val[c->nsect], LINE_CAP, "%s", value);
        } else if (c->nsect == ZP_MAX_SECTIONS) {
            bad(c, c->line, "course", "section", "more than %d sections; expected at most %d",
                ZP_MAX_SECTIONS, ZP_MAX_SECTIONS);
        }
        c->nsect++;
        return 1;
    }
    if (c->key_line[k]) {
        bad(c, c->line, sec_names[s], name,
            "duplicate key (first set on line %d); expected it once", c->key_line[k]);
        return 1;
    }
    c->key_line[k] = c->line;
    snprintf(c->val[k], LINE_CAP, "%s", value);
    return 1;
}

/* runs inih over text; every problem found goes to c->d */
static void parse_text(parse_ctx *c, const char *text) {
    c->text = text;
    ini_parse_stream(read_line, c, on_key, c);
}

/* ---- converting: raw values -> zp_scene, with every CONFIG.md rule ---- */

/* a required key that is absent: pointed at its section's header, else at the file's end */
static void missing(parse_ctx *c, int k, const char *what) {
    int line = c->sec_line[keys[k].sec] ? c->sec_line[keys[k].sec] : c->line;
    bad(c, line, sec_of(k), keys[k].name, "missing; required: %s", what);
}

typedef enum { R_ANY, R_POS, R_NONNEG } range;

static int in_range(double v, range r) {
    return r == R_ANY || (r == R_POS && v > 0) || (r == R_NONNEG && v >= 0);
}

/* key k as a number in range r: 1 if set in *out, 0 if absent, -1 if bad (reported) */
static int get_number(parse_ctx *c, int k, range r, double *out) {
    if (!c->key_line[k]) {
        return 0;
    }
    double v;
    char what[LINE_CAP + 64];
    if (zp_text_number(c->val[k], &v)) {
        snprintf(what, sizeof what, c->val[k][0] ? "`%s` is not a number" : "no value%s",
                 c->val[k]);
        bad_key(c, k, what);
        return -1;
    }
    if (!in_range(v, r)) {
        snprintf(what, sizeof what, "%g is out of range", v);
        bad_key(c, k, what);
        return -1;
    }
    *out = v;
    return 1;
}

/* key k as a list in range r: its length if set in out (at most max), 0 absent, -1 bad */
static int get_list(parse_ctx *c, int k, range r, double *out, int max) {
    if (!c->key_line[k]) {
        return 0;
    }
    char what[LINE_CAP + 64];
    double v[ZP_MAX_SECTIONS];
    int n = zp_text_items(c->val[k], v, ZP_MAX_SECTIONS, what, sizeof what);
    if (n < 0) {
        bad_key(c, k, what);
        return -1;
    }
    if (n > max) {
        snprintf(what, sizeof what, "%d values, more than %d", n, max);
        bad_key(c, k, what);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        if (!in_range(v[i], r)) {
            snprintf(what, sizeof what, "item %d (%g) is out of range", i + 1, v[i]);
            bad_key(c, k, what);
            return -1;
        }
    }
    memcpy(out, v, (size_t)n * sizeof *v);
    return n;
}

/* key k as a whole number in [lo, hi]: 1 if set, 0 absent, -1 bad */
static int get_whole(parse_ctx *c, int k, unsigned long lo, unsigned long hi, unsigned long *out) {
    if (!c->key_line[k]) {
        return 0;
    }
    const char *t = c->val[k];
    char *end;
    errno = 0;
    unsigned long v = strtoul(t, &end, 10);
    if (!*t || strspn(t, "0123456789") != strlen(t) || errno || *end || v < lo || v > hi) {
        char what[LINE_CAP + 64];
        snprintf(what, sizeof what, "`%s` is not a whole number in [%lu, %lu]", t, lo, hi);
        bad_key(c, k, what);
        return -1;
    }
    *out = v;
    return 1;
}

/* key k as text that fits cap bytes: 1 if set, 0 absent, -1 bad */
static int get_text(parse_ctx *c, int k, char *out, size_t cap) {
    if (!c->key_line[k]) {
        return 0;
    }
    if (!c->val[k][0] || strlen(c->val[k]) >= cap) {
        char what[64];
        snprintf(what, sizeof what, "%s", c->val[k][0] ? "too long" : "empty");
        bad_key(c, k, what);
        return -1;
    }
    strcpy(out, c->val[k]);
    return 1;
}

/* [drive] forces through the drive module, for a course of nsec sections: 1 read into *s,
   0 absent, -1 bad */
static int read_forces(parse_ctx *c, int nsec, zp_schedule *s) {
    if (!c->key_line[K_FORCES]) {
        return 0;
    }
    char why[LINE_CAP + 64];
    int rc = zp_schedule_parse(c->val[K_FORCES], nsec, s, why, sizeof why);
    if (rc == -2) {
        bad(c, c->key_line[K_FORCES], "drive", keys[K_FORCES].name, "%s", why);
    } else if (rc) {
        bad_key(c, K_FORCES, why);
    }
    return rc ? -1 : 1;
}

/* the schedule's kind and parameters into the scene */
static void set_forces(zp_scene *sc, const zp_schedule *s) {
    sc->drive_kind = (int)s->kind;
    sc->nforce = s->np;
    memcpy(sc->forces, s->p, sizeof *s->p * (size_t)s->np);
}

static void convert_scene(parse_ctx *c, zp_scene *sc) {
    double v;
    unsigned long u;
    char what[LINE_CAP + 64];

    /* [scene]: the name becomes a folder under out/, so it may not climb or nest */
    char name[ZP_NAME_MAX];
    if (get_text(c, K_NAME, name, sizeof name) > 0) {
        if (name[0] == '.' ||
            strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") !=
                strlen(name)) {
            snprintf(what, sizeof what, "`%s` is not a plain folder name", name);
            bad_key(c, K_NAME, what);
        } else {
            strcpy(sc->name, name);
        }
    }
    get_number(c, K_GRAVITY, R_NONNEG, &sc->gravity);

    /* [course] */
    int have_start = get_number(c, K_X_START, R_ANY, &sc->x_start);
    if (!have_start) {
        missing(c, K_X_START, "where the trolley starts (m)");
    }
    if (c->nsect == 0) {
        missing(c, K_SECTION, "at least one `section = x_end : f(x)` line");
    }
    sc->nsec = c->nsect < ZP_MAX_SECTIONS ? c->nsect : ZP_MAX_SECTIONS;
    int prev_ok = have_start > 0;
    double prev = sc->x_start;
    for (int i = 0; i < sc->nsec; i++) {
        int line = c->sect_line[i];
        char *text = c->sect_val[i];
        sc->sec_line[i] = line;
        char *colon = strchr(text, ':');
        if (!colon) {
            bad(c, line, "course", "section", "`%s` has no `:`; expected `x_end : f(x)`", text);
            prev_ok = 0;
            continue;
        }
        *colon = '\0';
        char *expr = colon + 1;
        zp_text_trim(text);
        zp_text_trim(expr);
        int ok = 1;
        if (zp_text_number(text, &sc->x_end[i])) {
            bad(c, line, "course", "section", "x_end `%s` is not a number; expected `x_end : f(x)`",
                text);
            ok = 0;
        } else if (prev_ok && !(sc->x_end[i] > prev)) {
            bad(c, line, "course", "section",
                "x_end %g is not past %g; expected x_end to increase past x_start and the previous "
                "section's x_end",
                sc->x_end[i], prev);
        }
        prev_ok = ok;
        prev = sc->x_end[i];
        char why[ZP_DIAG_TEXT / 2];
        if (zp_course_check(expr, why, sizeof why)) {
            bad(c, line, "course", "section", "f(x) = `%s`: %s", expr, why);
        }
        snprintf(sc->expr[i], ZP_EXPR_MAX, "%s", expr);
    }

    /* [trolley] */
    if (!get_number(c, K_MASS, R_POS, &sc->trolley_mass)) {
        missing(c, K_MASS, "the trolley's mass (kg)");
    }

    /* [body]: lengths say how many links; masses and damping follow them */
    int nlen = get_list(c, K_LENGTHS, R_POS, sc->lengths, ZP_MAX_LINKS);
    if (nlen == 0) {
        missing(c, K_LENGTHS, "the links' lengths (m), 1 to 8 of them");
    } else if (nlen > 0) {
        sc->nlink = nlen;
    }
    double tmp[ZP_MAX_SECTIONS];
    int nmass = get_list(c, K_MASSES, R_POS, tmp, ZP_MAX_LINKS);
    if (nmass == 0) {
        missing(c, K_MASSES, "the links' masses (kg), one per link");
    } else if (nmass > 0 && nlen > 0 && nmass != nlen) {
        bad_count(c, K_MASSES, nmass, "%d (one per link)", nlen);
    } else if (nmass > 0) {
        memcpy(sc->masses, tmp, (size_t)nmass * sizeof *tmp);
    }
    int ndamp = get_list(c, K_DAMPING, R_NONNEG, tmp, ZP_MAX_LINKS);
    if (ndamp > 1 && nlen > 0 && ndamp != nlen) {
        bad_count(c, K_DAMPING, ndamp, "1 or %d (one per joint)", nlen);
    } else if (ndamp > 0) {
        /* one value serves every joint; stored for each so readers need not branch */
        sc->ndamping = ndamp;
        for (int i = 0; i < ZP_MAX_LINKS; i++) {
            sc->damping[i] = ndamp == 1 ? tmp[0] : i < ndamp ? tmp[i] : 0;
        }
    }
    int have_death = get_number(c, K_DEATH_ANGLE, R_POS, &v);
    if (have_death > 0 && v > 360) {
        snprintf(what, sizeof what, "%g is out of range", v);
        bad_key(c, K_DEATH_ANGLE, what);
        have_death = -1;
    } else if (have_death > 0) {
        sc->death_angle = v;
    }

    /* [drive]: the schedule's text is the drive module's to read */
    if (get_text(c, K_DIRECTION, sc->direction, sizeof sc->direction) >= 0 &&
        zp_drive_dir_find(sc->direction) < 0) {
        snprintf(what, sizeof what, "unknown direction `%s`", sc->direction);
        bad_key(c, K_DIRECTION, what);
    }
    zp_schedule sched;
    if (read_forces(c, c->nsect, &sched) > 0) {
        set_forces(sc, &sched);
    }
    sc->line_forces = c->key_line[K_FORCES];
    int have_min = get_number(c, K_MIN, R_ANY, &sc->force_min);
    int have_max = get_number(c, K_MAX, R_ANY, &sc->force_max);
    if (have_min >= 0 && have_max >= 0 && sc->force_min > sc->force_max) {
        int k = have_max ? K_MAX : K_MIN;
        bad(c, c->key_line[k], "drive", keys[k].name, "min %g > max %g; expected min <= max",
            sc->force_min, sc->force_max);
    }

    /* [solver]: method and formulation names are checked against their registries later */
    get_text(c, K_METHOD, sc->method, sizeof sc->method);
    get_text(c, K_FORMULATION, sc->formulation, sizeof sc->formulation);
    sc->line_method = c->key_line[K_METHOD];
    sc->line_formulation = c->key_line[K_FORMULATION];
    get_number(c, K_RTOL, R_POS, &sc->rtol);
    get_number(c, K_ATOL, R_POS, &sc->atol);
    get_number(c, K_T_MAX, R_POS, &sc->t_max);
    get_number(c, K_OUTPUT_DT, R_POS, &sc->output_dt);

    /* [optimize] */
    if (get_number(c, K_MARGIN, R_NONNEG, &v) > 0) {
        if (have_death >= 0 && v >= sc->death_angle) {
            snprintf(what, sizeof what, "%g is not below death_angle %g", v, sc->death_angle);
            bad_key(c, K_MARGIN, what);
        } else {
            sc->margin = v;
        }
    }
    if (get_whole(c, K_MAX_EVALS, 1, LONG_MAX, &u) > 0) {
        sc->max_evals = (long)u;
        sc->line_max_evals = c->key_line[K_MAX_EVALS];
    }
    if (get_whole(c, K_SEED, 0, ULONG_MAX, &u) > 0) {
        sc->seed = u;
    }
    get_text(c, K_SEARCH_METHOD, sc->search_method, sizeof sc->search_method);
    sc->line_search_method = c->key_line[K_SEARCH_METHOD];
    get_number(c, K_SEARCH_RTOL, R_POS, &sc->search_rtol);
}

/* ---- entry points ---- */

static void set_defaults(zp_scene *sc, const char *path) {
    memset(sc, 0, sizeof *sc);
    snprintf(sc->path, sizeof sc->path, "%s", path);
    /* the name is the file's stem: no folders, no extension */
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    snprintf(sc->name, sizeof sc->name, "%s", base);
    char *dot = strrchr(sc->name, '.');
    if (dot && dot != sc->name) {
        *dot = '\0';
    }
    sc->gravity = 9.81;
    sc->ndamping = 1;
    sc->death_angle = 180;
    strcpy(sc->direction, "horizontal");
    sc->force_min = 0;
    sc->force_max = 500;
    strcpy(sc->method, "cvode-adams");
    strcpy(sc->formulation, "lagrange");
    sc->rtol = 1e-8;
    sc->atol = 1e-10;
    sc->t_max = 120;
    sc->output_dt = 0.02;
    sc->margin = 10;
    sc->max_evals = 5000;
    sc->seed = 1;
    /* the fastest setting that keeps search runs within 1e-6 s (docs/trade.md) */
    strcpy(sc->search_method, "gsl-rk8pd");
    sc->search_rtol = 1e-5;
    /* [robust] ranges at 100 % of nominal mean "not varied" */
    for (int i = 0; i < 2; i++) {
        sc->mass_range[i] = sc->length_range[i] = 100;
        sc->trolley_mass_range[i] = sc->damping_range[i] = 100;
    }
    sc->robust_samples = 64;
    sc->verify_samples = 2000;
    sc->air_density = 1.225;
}

/* the whole file as a string (caller frees), or NULL with a message */
static char *slurp(const char *path, zp_diag *d) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        zp_diag_add(d, path, 0, NULL, NULL, "cannot open: %s; expected a readable scene file",
                    strerror(errno));
        return NULL;
    }
    size_t cap = 4096, n = 0;
    char *text = malloc(cap);
    while (text) {
        n += fread(text + n, 1, cap - 1 - n, f);
        if (n < cap - 1) {
            break;
        }
        char *grown = realloc(text, cap *= 2);
        if (!grown) {
            free(text);
        }
        text = grown;
    }
    int failed = ferror(f);
    fclose(f);
    if (!text || failed) {
        free(text);
        zp_diag_add(d, path, 0, NULL, NULL, "cannot read: %s",
                    text ? "read error" : "out of memory");
        return NULL;
    }
    text[n] = '\0';
    return text;
}

zp_status zp_scene_load_string(const char *text, const char *path, zp_scene *sc, zp_diag *d) {
    if (!path) {
        path = "<string>";
    }
    set_defaults(sc, path);
    parse_ctx *c = calloc(1, sizeof *c);
    if (!c) {
        zp_diag_add(d, path, 0, NULL, NULL, "out of memory reading the scene");
        return ZP_ERR_NOMEM;
    }
    c->file = path;
    c->d = d;
    parse_text(c, text);
    convert_scene(c, sc);
    int nbad = flush_messages(c);
    free(c);
    return nbad ? ZP_ERR_INPUT : ZP_OK;
}

zp_status zp_scene_load(const char *path, zp_scene *sc, zp_diag *d) {
    char *text = slurp(path, d);
    if (!text) {
        set_defaults(sc, path);
        return ZP_ERR_INPUT;
    }
    zp_status st = zp_scene_load_string(text, path, sc, d);
    free(text);
    return st;
}

void zp_scene_seed(zp_scene *sc) {
    set_defaults(sc, "<built-in seed scene>");
    strcpy(sc->name, "seed");
    static const double x_end[] = {60, 100, 140};
    static const char *const expr[] = {"(x/10 - 3)^2 + 1", "-x/10 + 16", "-(x/10 - 12)^2 + 10"};
    sc->x_start = 0;
    sc->nsec = 3;
    for (int i = 0; i < 3; i++) {
        sc->x_end[i] = x_end[i];
        strcpy(sc->expr[i], expr[i]);
        sc->forces[i] = 100;
    }
    sc->nforce = 3;
    sc->trolley_mass = 30;
    sc->nlink = 3;
    static const double masses[] = {15, 5, 2};
    for (int i = 0; i < 3; i++) {
        sc->lengths[i] = 5;
        sc->masses[i] = masses[i];
    }
    for (int i = 0; i < ZP_MAX_LINKS; i++) {
        sc->damping[i] = 1;
    }
}

zp_status zp_scene_overlay_schedule(const char *path, zp_scene *sc, zp_diag *d) {
    char *text = slurp(path, d);
    if (!text) {
        return ZP_ERR_INPUT;
    }
    parse_ctx *c = calloc(1, sizeof *c);
    if (!c) {
        free(text);
        zp_diag_add(d, path, 0, NULL, NULL, "out of memory reading the schedule");
        return ZP_ERR_NOMEM;
    }
    c->file = path;
    c->d = d;
    c->schedule = 1;
    parse_text(c, text);
    free(text);
    /* the forces must fit the scene they are laid over */
    zp_schedule sched;
    if (read_forces(c, sc->nsec, &sched) == 0) {
        missing(c, K_FORCES, "the forces (N), one per section");
    }
    int nbad = flush_messages(c);
    free(c);
    if (nbad) {
        return ZP_ERR_INPUT;
    }
    set_forces(sc, &sched);
    /* sc->path names the scene, not this file: no line there to point at */
    sc->line_forces = 0;
    return ZP_OK;
}
