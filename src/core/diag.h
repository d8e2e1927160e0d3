/* Program status and input diagnostics: FILE:LINE: [section] key: message, collected, printed once. */
#ifndef ZP_DIAG_H
#define ZP_DIAG_H

#include <stdio.h>

/* What happened to the program (not to the spy: that is zp_outcome in sim.h). */
typedef enum {
    ZP_OK = 0,
    ZP_ERR_INPUT,   /* bad command line or scene file: exit 2 */
    ZP_ERR_NUMERIC, /* the integration broke down (non-finite numbers, no progress) */
    ZP_ERR_IO,      /* a file could not be read or written */
    ZP_ERR_NOMEM,
    ZP_STATUS_COUNT
} zp_status;

#define ZP_DIAG_MAX 20    /* messages kept; more are counted, not stored */
#define ZP_DIAG_TEXT 512

typedef struct zp_diag {
    int n;       /* messages stored */
    int dropped; /* messages beyond ZP_DIAG_MAX */
    char text[ZP_DIAG_MAX][ZP_DIAG_TEXT];
} zp_diag;

void zp_diag_init(zp_diag *d);
/* Adds "file:line: [section] key: <fmt>"; file/section/key may be NULL, line <= 0 omits it. */
void zp_diag_add(zp_diag *d, const char *file, int line, const char *section, const char *key,
                 const char *fmt, ...) __attribute__((format(printf, 6, 7)));
/* Prints every message, control bytes escaped (zp_diag_put_escaped). */
void zp_diag_print(const zp_diag *d, FILE *f);
/* Writes s with control bytes shown as \n, \t or \xNN, so user text (a file name, a value)
   cannot break or forge a line of a message. */
void zp_diag_put_escaped(FILE *f, const char *s);

/* Edit distance with adjacent transpositions counting 1 (`lenghts` is 1 from `lengths`). */
int zp_diag_edit_distance(const char *a, const char *b);
/* Close enough to be a typo: about one slip per four letters of valid. */
int zp_diag_is_near(const char *typed, const char *valid);
/* The index of the name in names[0..n) nearest to typed if it is near (a typo), else -1:
   for "did you mean" hints. */
int zp_diag_nearest(const char *typed, const char *const *names, int n);

#endif
