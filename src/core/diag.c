/* Program status names and the input-diagnostic list (diag.h): messages in the form
   FILE:LINE: [section] key: what is wrong; what is expected. */
#include "diag.h"

#include <stdarg.h>
#include <string.h>

void zp_diag_put_escaped(FILE *f, const char *s) {
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '\n') {
            fputs("\\n", f);
        } else if (*p == '\t') {
            fputs("\\t", f);
        } else if (*p < 0x20 || *p == 0x7f) {
            fprintf(f, "\\x%02x", *p);
        } else {
            fputc(*p, f);
        }
    }
}

int zp_diag_edit_distance(const char *a, const char *b) {
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

int zp_diag_is_near(const char *typed, const char *valid) {
    return zp_diag_edit_distance(typed, valid) <= 1 + (int)strlen(valid) / 4;
}

int zp_diag_nearest(const char *typed, const char *const *names, int n) {
    int best = -1, best_d = 0;
    for (int i = 0; i < n; i++) {
        int d = zp_diag_edit_distance(typed, names[i]);
        if (zp_diag_is_near(typed, names[i]) && (best < 0 || d < best_d)) {
            best = i;
            best_d = d;
        }
    }
    return best;
}

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
    /* file names and values come from the user: control bytes are shown, not sent */
    for (int i = 0; i < d->n; i++) {
        zp_diag_put_escaped(f, d->text[i]);
        fputc('\n', f);
    }
    if (d->dropped > 0) {
        fprintf(f, "... and %d more message%s\n", d->dropped, d->dropped == 1 ? "" : "s");
    }
}
