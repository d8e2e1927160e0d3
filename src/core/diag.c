/* Program status names and the input-diagnostic list (diag.h): messages in the form
   FILE:LINE: [section] key: what is wrong; what is expected. */
#include "diag.h"

#include <stdarg.h>
#include <string.h>

void zp_diag_init(zp_diag *d) {
    memset(d, 0, sizeof *d);
}

void zp_diag_add(zp_diag *d, const char *file, int line, const char *section, const char *key,
                 const char *fmt, ...) {
    /* past the cap, count only: the first messages are the ones worth reading */
    if (d->n >= ZP_DIAG_MAX) {
        d->dropped++;
        return;
    }
    char *s = d->text[d->n++];
    size_t cap = ZP_DIAG_TEXT, len = 0;
    if (file) {
        len += (size_t)snprintf(s + len, cap - len, "%s:", file);
    }
    if (line > 0 && len < cap) {
        len += (size_t)snprintf(s + len, cap - len, "%d:", line);
    }
    if (len > 0 && len < cap) {
        len += (size_t)snprintf(s + len, cap - len, " ");
    }
    if (section && len < cap) {
        len += (size_t)snprintf(s + len, cap - len, "[%s] ", section);
    }
    if (key && len < cap) {
        len += (size_t)snprintf(s + len, cap - len, "%s: ", key);
    }
    if (len < cap) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(s + len, cap - len, fmt, ap);
        va_end(ap);
    }
}

void zp_diag_print(const zp_diag *d, FILE *f) {
    for (int i = 0; i < d->n; i++) {
        fprintf(f, "%s\n", d->text[i]);
    }
    if (d->dropped > 0) {
        fprintf(f, "... and %d more message%s\n", d->dropped, d->dropped == 1 ? "" : "s");
    }
}
