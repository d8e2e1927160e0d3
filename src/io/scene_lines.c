/* The scene reader's first pass: hands inih the text line by line (counting lines, checking each
   line's shape, refusing NUL bytes), files each key's value and line, holds the messages and
   suggests the nearest valid name for a typo. */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "text.h"
#include "scene_parse.h"

static int find_section(const char *name) {
    for (int s = 0; s < S_COUNT; s++) {
        if (!strcmp(name, zp_scene_keys_sections[s].name)) {
            return s;
        }
    }
    return -1;
}

void zp_scene_lines_bad(parse_ctx *c, int line, const char *sec, const char *key, const char *fmt, ...) {
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

int zp_scene_lines_flush(parse_ctx *c) {
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
/* ---- reading: inih's reader and handler ---- */

static void unknown_section(parse_ctx *c, const char *name) {
    if (c->schedule) {
        zp_scene_lines_bad(c, c->line, NULL, NULL,
                     "unknown section [%s]; a schedule file holds only [drive] forces", name);
        return;
    }
    for (int s = 0; s < S_COUNT; s++) {
        if (zp_diag_is_near(name, zp_scene_keys_sections[s].name)) {
            zp_scene_lines_bad(c, c->line, NULL, NULL, "unknown section [%s]; did you mean [%s]?", name,
                         zp_scene_keys_sections[s].name);
            return;
        }
    }
    char list[256] = "";
    for (int s = 0; s < S_COUNT; s++) {
        size_t len = strlen(list);
        snprintf(list + len, sizeof list - len, " [%s]", zp_scene_keys_sections[s].name);
    }
    zp_scene_lines_bad(c, c->line, NULL, NULL, "unknown section [%s]; expected one of%s", name, list);
}

static void unknown_key(parse_ctx *c, int s, const char *name) {
    if (c->schedule) {
        zp_scene_lines_bad(c, c->line, zp_scene_keys_sections[s].name, name,
                     "unknown key; a schedule file holds only [drive] forces");
        return;
    }
    /* a right key in the wrong section says where it belongs, before any near miss */
    for (int k = 0; k < K_COUNT; k++) {
        if (!strcmp(name, zp_scene_keys[k].name)) {
            zp_scene_lines_bad(c, c->line, zp_scene_keys_sections[s].name, name,
                         "unknown key here; `%s` belongs in [%s]", name, zp_scene_sec_of(k));
            return;
        }
    }
    int best = -1, best_d = 0;
    for (int k = 0; k < K_COUNT; k++) {
        if (zp_scene_keys[k].sec == s && zp_diag_is_near(name, zp_scene_keys[k].name)) {
            int dk = zp_diag_edit_distance(name, zp_scene_keys[k].name);
            if (best < 0 || dk < best_d) {
                best = k;
                best_d = dk;
            }
        }
    }
    if (best >= 0) {
        zp_scene_lines_bad(c, c->line, zp_scene_keys_sections[s].name, name,
                     "unknown key; did you mean `%s`?", zp_scene_keys[best].name);
        return;
    }
    char list[256] = "";
    for (int k = 0; k < K_COUNT; k++) {
        if (zp_scene_keys[k].sec == s) {
            size_t len = strlen(list);
            snprintf(list + len, sizeof list - len, "%s%s", len ? ", " : "", zp_scene_keys[k].name);
        }
    }
    zp_scene_lines_bad(c, c->line, zp_scene_keys_sections[s].name, name,
                 "unknown key; expected one of: %s", list);
}

/* the next raw line of the text (without its newline, CR, or the file's UTF-8 mark) in
 *s, *len; 0 at the end. A NUL byte inside the file is reported and its line blanked. */
static int take_line(parse_ctx *c, const char **s, size_t *len) {
    if (c->pos >= c->len) {
        return 0;
    }
    const char *p = c->text + c->pos, *nl = memchr(p, '\n', c->len - c->pos);
    size_t n = nl ? (size_t)(nl - p) : c->len - c->pos;
    c->pos += n + (nl != NULL);
    c->line++;
    /* reported; the line is read up to it, so the NUL is the only message */
    const char *nul = memchr(p, '\0', n);
    if (nul) {
        zp_scene_lines_bad(c, c->line, NULL, NULL,
                     "a NUL byte at column %zu; expected a text file without NUL bytes",
                     (size_t)(nul - p) + 1);
        n = (size_t)(nul - p);
    }
    if (n > 0 && p[n - 1] == '\r') {
        n--;
    }
    if (c->line == 1 && n >= 3 && !memcmp(p, "\xEF\xBB\xBF", 3)) {
        p += 3;
        n -= 3;
    }
    *s = p;
    *len = n;
    return 1;
}

/* a section header in str: checked here, since inih does not report headers; str becomes
   what inih should see (`[?]` for a section whose keys are to be skipped, "" if malformed) */
static void header(parse_ctx *c, char *str, int num) {
    char *close = strchr(str, ']');
    if (!close) {
        zp_scene_lines_bad(c, c->line, NULL, NULL, "section header without `]`; expected [name]");
        str[0] = '\0';
        return;
    }
    if (close[1]) {
        zp_scene_lines_bad(c, c->line, NULL, NULL,
                     "text after the section header; expected [name] alone");
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
        return;
    }
    if (!c->sec_line[sec]) {
        c->sec_line[sec] = c->line;
    }
    snprintf(str, (size_t)num, "[%s]", name);
}

/* Design note: inih's line buffer (200 bytes, fixed in the system's library) is too short for
   the forces of many sections, which the search writes on one line (16 sections and more).
   Continuation lines were rejected: inih hands each to the handler as a repeat of the key,
   indistinguishable from a duplicate. A long `forces =` line is kept here whole and inih is
   given a stand-in, which the handler swaps back. */
#define LONG_FORCES_MARK "<long line>"

/* 1 when the raw line s (len bytes) is a `forces = ..` line short enough to keep whole: its
   value (comments and blanks cut) is put aside for on_key */
static int long_forces(parse_ctx *c, const char *s, size_t len) {
    if (len >= sizeof c->forces_long) {
        return 0;
    }
    char *line = c->forces_long;
    memcpy(line, s, len);
    line[len] = '\0';
    for (size_t i = 0; line[i]; i++) {
        if ((line[i] == ';' || line[i] == '#') && (i == 0 || isspace((unsigned char)line[i - 1]))) {
            line[i] = '\0';
            break;
        }
    }
    zp_text_trim(line);
    size_t eq = strcspn(line, "=");
    char name[16];
    snprintf(name, sizeof name, "%.*s", (int)(eq < 15 ? eq : 15), line);
    zp_text_trim(name);
    if (!line[eq] || eq >= 15 || strcmp(name, "forces")) {
        line[0] = '\0';
        return 0;
    }
    memmove(line, line + eq + 1, strlen(line + eq + 1) + 1);
    zp_text_trim(line);
    c->forces_long_line = c->line;
    return 1;
}

/* hands inih one line at a time, left-trimmed (so no line reads as a continuation of the
   previous value), without ` ;...` or ` #...` comments, and blank if malformed (reported) */
static char *read_line(char *str, int num, void *stream) {
    parse_ctx *c = stream;
    const char *s;
    size_t len;
    if (!take_line(c, &s, &len)) {
        return NULL;
    }
    str[0] = '\0';
    if (len + 2 > (size_t)num && long_forces(c, s, len)) {
        snprintf(str, (size_t)num, "forces = %s", LONG_FORCES_MARK);
        return str;
    }
    if (len + 2 > (size_t)num) {
        zp_scene_lines_bad(c, c->line, NULL, NULL,
                     "line is %zu characters long; expected at most %d (a [drive] forces line: "
                     "at most %d)",
                     len, num - 2, ZP_FORCES_TEXT_MAX - 1);
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
    if (str[0] == '[') {
        header(c, str, num);
        return str;
    }
    /* key = value; inih also splits at `:`, which docs/scene-file.md does not use for keys */
    size_t eq = strcspn(str, "=:");
    if (*str && (str[eq] != '=' || eq == 0)) {
        zp_scene_lines_bad(c, c->line, NULL, NULL,
                     "`%s` is not a `key = value` line; expected key = value", str);
        str[0] = '\0';
    }
    return str;
}

static int on_key(void *user, const char *section, const char *name, const char *value) {
    parse_ctx *c = user;
    if (!*section) {
        zp_scene_lines_bad(c, c->line, NULL, name,
                     "key outside any section; expected it under its [section]");
        return 1;
    }
    int s = find_section(section);
    if (s < 0) {
        return 1; /* an unknown section, reported at its header */
    }
    int k = 0;
    while (k < K_COUNT && !(zp_scene_keys[k].sec == s && !strcmp(zp_scene_keys[k].name, name))) {
        k++;
    }
    if (k == K_COUNT || (c->schedule && k != K_FORCES)) {
        unknown_key(c, s, name);
        return 1;
    }
    /* `section` repeats, once per course section */
    if (k == K_SECTION) {
        if (c->nsect == 0) {
            c->key_line[k] = c->line;
        }
        if (c->nsect < ZP_MAX_SECTIONS) {
            c->sect_line[c->nsect] = c->line;
            snprintf(c->sect_val[c->nsect], LINE_CAP, "%s", value);
        } else if (c->nsect == ZP_MAX_SECTIONS) {
            zp_scene_lines_bad(c, c->line, "course", "section",
                         "more than %d sections; expected at most %d", ZP_MAX_SECTIONS,
                         ZP_MAX_SECTIONS);
        }
        c->nsect++;
        return 1;
    }
    if (c->key_line[k]) {
        zp_scene_lines_bad(c, c->line, zp_scene_keys_sections[s].name, name,
                     "duplicate key (first set on line %d); expected it once", c->key_line[k]);
        return 1;
    }
    c->key_line[k] = c->line;
    if (k == K_FORCES) {
        int kept = c->forces_long_line == c->line && !strcmp(value, LONG_FORCES_MARK);
        snprintf(c->forces_val, sizeof c->forces_val, "%s", kept ? c->forces_long : value);
    } else {
        snprintf(c->val[k], LINE_CAP, "%s", value);
    }
    return 1;
}
void zp_scene_lines_parse(parse_ctx *c, const char *text, size_t len) {
    c->text = text;
    c->len = len;
    ini_parse_stream(read_line, c, on_key, c);
}
