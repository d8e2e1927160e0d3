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
void zp_diag_print(const zp_diag *d, FILE *f);


#endif
