/* A report people share: one self-contained HTML file made from a markdown report of the same
   transaction, its figures embedded, so it opens offline, mailed or copied anywhere. */
#ifndef ZP_OUT_HTML_H
#define ZP_OUT_HTML_H

#include <stddef.h>

#include "tx.h"

/* Renders md_name (a markdown file already written in t's private folder, GitHub tables
   included) as html_name in the same folder, with title, a print-friendly style and every
   image it shows embedded as a data: URI read from the private folder. An image that is not
   there, or anything but a plain file name, fails: the page never refers to anything outside
   itself. 0, or -1 with why in err. */
int zp_out_html_report(zp_tx *t, const char *md_name, const char *html_name, const char *title,
                       char *err, size_t errlen);

#endif
