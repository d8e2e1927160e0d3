/* report.html from report.md: CommonMark with GitHub's tables (Debian's cmark-gfm), every image
   node's file read from the transaction's private folder and put into the page as a data: URI,
   so the one file carries everything it shows. */
#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "out_html.h"

#define HTML_FILE_MAX (64L << 20) /* bytes of one file read: a report or a figure */

static const char style[] =
    "body{font-family:system-ui,sans-serif;max-width:60em;margin:2em auto;padding:0 1em;"
    "line-height:1.45;color:#222}"
    "table{border-collapse:collapse;margin:1em 0}"
    "th,td{border:1px solid #bbb;padding:.25em .6em;text-align:right}"
    "th{background:#eee}td:first-child,th:first-child{text-align:left}"
    "img{max-width:100%;height:auto;display:block;margin:1em 0}"
    "pre{background:#f4f4f4;padding:.6em;overflow-x:auto}"
    "h1{border-bottom:2px solid #333}h2{border-bottom:1px solid #ccc;margin-top:1.6em}";

/* name read whole from the folder dirfd (a plain file, never through a link); NULL with why */
static char *read_at(int dirfd, const char *name, size_t *len, char *err, size_t errlen) {
    int fd = openat(dirfd, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) || !S_ISREG(st.st_mode) || st.st_size > HTML_FILE_MAX) {
        snprintf(err, errlen, "report.html: cannot read %s: %s", name,
                 fd < 0 ? strerror(errno) : "not a plain file of at most 64 MiB");
        if (fd >= 0) {
            close(fd);
        }
        return NULL;
    }
    char *buf = malloc((size_t)st.st_size + 1);
    size_t got = 0;
    while (buf && got < (size_t)st.st_size) {
        ssize_t n = read(fd, buf + got, (size_t)st.st_size - got);
        if (n <= 0) {
            break;
        }
        got += (size_t)n;
    }
    close(fd);
    if (!buf || got != (size_t)st.st_size) {
        snprintf(err, errlen, "report.html: reading %s failed", name);
        free(buf);
        return NULL;
    }
    buf[got] = '\0';
    *len = got;
    return buf;
}

static const char *mime_of(const char *name) {
    const char *dot = strrchr(name, '.');
    if (dot && !strcmp(dot, ".png")) {
        return "image/png";
    }
    if (dot && !strcmp(dot, ".gif")) {
        return "image/gif";
    }
    if (dot && !strcmp(dot, ".svg")) {
        return "image/svg+xml";
    }
    return NULL;
}

/* "data:MIME;base64,..." of bytes (RFC 4648 alphabet, padded) */
static char *data_uri(const char *mime, const unsigned char *b, size_t n) {
    static const char abc[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t head = strlen("data:;base64,") + strlen(mime);
    char *out = malloc(head + 4 * ((n + 2) / 3) + 1);
    if (!out) {
        return NULL;
    }
    char *o = out + sprintf(out, "data:%s;base64,", mime);
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = (unsigned)b[i] << 16 | (i + 1 < n ? (unsigned)b[i + 1] << 8 : 0) |
                     (i + 2 < n ? b[i + 2] : 0);
        *o++ = abc[v >> 18 & 63];
        *o++ = abc[v >> 12 & 63];
        *o++ = i + 1 < n ? abc[v >> 6 & 63] : '=';
        *o++ = i + 2 < n ? abc[v & 63] : '=';
    }
    *o = '\0';
    return out;
}

/* every image of the document embedded from dirfd; 0, or -1 with why */
static int embed_images(cmark_node *doc, int dirfd, char *err, size_t errlen) {
    cmark_iter *it = cmark_iter_new(doc);
    int bad = 0;
    for (cmark_event_type ev; !bad && (ev = cmark_iter_next(it)) != CMARK_EVENT_DONE;) {
        cmark_node *node = cmark_iter_get_node(it);
        if (ev != CMARK_EVENT_ENTER || cmark_node_get_type(node) != CMARK_NODE_IMAGE) {
            continue;
        }
        const char *url = cmark_node_get_url(node);
        const char *mime = url ? mime_of(url) : NULL;
        if (!mime || strchr(url, '/') || url[0] == '.') {
            snprintf(err, errlen, "report.html: the image `%s` is not a figure of this run",
                     url ? url : "");
            bad = 1;
            continue;
        }
        size_t n;
        char *bytes = read_at(dirfd, url, &n, err, errlen);
        char *uri = bytes ? data_uri(mime, (const unsigned char *)bytes, n) : NULL;
        if (!uri) {
            if (bytes) {
                snprintf(err, errlen, "report.html: out of memory embedding %s", url);
            }
            bad = 1;
        } else {
            cmark_node_set_url(node, uri);
        }
        free(uri);
        free(bytes);
    }
    cmark_iter_free(it);
    return bad ? -1 : 0;
}

/* text with &, <, > and " escaped for an HTML title */
static void put_escaped(FILE *f, const char *s) {
    for (; *s; s++) {
        switch (*s) {
        case '&':
            fputs("&amp;", f);
            break;
        case '<':
            fputs("&lt;", f);
            break;
        case '>':
            fputs("&gt;", f);
            break;
        case '"':
            fputs("&quot;", f);
            break;
        default:
            fputc(*s, f);
        }
    }
}

int zp_out_html_report(zp_tx *t, const char *md_name, const char *html_name, const char *title,
                       char *err, size_t errlen) {
    if (zp_tx_flush(t, err, errlen)) { /* the markdown complete on disk */
        return -1;
    }
    size_t len;
    char *md = read_at(zp_tx_workdir(t), md_name, &len, err, errlen);
    if (!md) {
        return -1;
    }
    cmark_gfm_core_extensions_ensure_registered();
    cmark_parser *p = cmark_parser_new(CMARK_OPT_DEFAULT);
    cmark_syntax_extension *table = cmark_find_syntax_extension("table");
    if (!p || !table || !cmark_parser_attach_syntax_extension(p, table)) {
        snprintf(err, errlen, "report.html: cmark-gfm has no table extension");
        cmark_parser_free(p);
        free(md);
        return -1;
    }
    cmark_parser_feed(p, md, len);
    free(md);
    cmark_node *doc = cmark_parser_finish(p);
    int rc = -1;
    char *body = NULL;
    FILE *f = NULL;
    if (doc && !embed_images(doc, zp_tx_workdir(t), err, errlen) &&
        (body = cmark_render_html(doc, CMARK_OPT_DEFAULT, cmark_parser_get_syntax_extensions(p))) &&
        (f = zp_tx_open(t, html_name, err, errlen))) {
        fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
              "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>",
              f);
        put_escaped(f, title);
        fprintf(f, "</title>\n<style>%s</style>\n</head>\n<body>\n", style);
        fputs(body, f);
        fputs("</body>\n</html>\n", f);
        rc = zp_tx_flush(t, err, errlen);
    } else if (doc && !err[0]) {
        snprintf(err, errlen, "report.html: rendering failed");
    }
    free(body);
    cmark_node_free(doc);
    cmark_parser_free(p);
    return rc;
}
