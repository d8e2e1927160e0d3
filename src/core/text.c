/* docs/scene-file.md numbers and lists: strict decimals, so that a typo is an error, not a zero. */
#include "text.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void zp_text_trim(char *s) {
    size_t a = 0, n = strlen(s);
    while (isspace((unsigned char)s[a])) {
        a++;
    }
    while (n > a && isspace((unsigned char)s[n - 1])) {
        n--;
    }
    memmove(s, s + a, n - a);
    s[n - a] = '\0';
}

int zp_text_number(const char *text, double *out) {
    if (!*text || strspn(text, "0123456789+-.eE") != strlen(text)) {
        return -1;
    }
    char *end;
    double v = strtod(text, &end);
    if (*end) {
        return -1;
    }
    if (!isfinite(v)) {
        return -2;
    }
    *out = v;
    return 0;
}

int zp_text_items(const char *text, double *out, int max, char *why, size_t whylen) {
    int n = 0;
    for (const char *item = text;; n++) {
        size_t len = strcspn(item, ",");
        char buf[64];
        if (len >= sizeof buf) {
            snprintf(why, whylen, "item %d is too long", n + 1);
            return -1;
        }
        memcpy(buf, item, len);
        buf[len] = '\0';
        zp_text_trim(buf);
        double v;
        if (!*buf) {
            if (n == 0 && !item[len]) {
                snprintf(why, whylen, "the list is empty");
            } else {
                snprintf(why, whylen, "item %d is empty", n + 1);
            }
            return -1;
        }
        int bad_number = zp_text_number(buf, &v);
        if (bad_number) {
            snprintf(why, whylen, "item %d `%s` is %s", n + 1, buf,
                     bad_number == -2 ? "out of range (beyond 1.8e308)" : "not a number");
            return -1;
        }
        if (n < max) {
            out[n] = v;
        }
        if (!item[len]) {
            return n + 1;
        }
        item += len + 1;
    }
}

int zp_text_list(const char *text, double *out, int max, char *why, size_t whylen) {
    int n = zp_text_items(text, out, max, why, whylen);
    if (n > max) {
        snprintf(why, whylen, "%d values, at most %d", n, max);
        return -1;
    }
    return n;
}
