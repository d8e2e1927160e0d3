/* Numbers and number lists as docs/scene-file.md writes them (finite decimals, comma-separated),
   read alike by the scene reader, the drive schedule and the command line. */
#ifndef ZP_NUMTEXT_H
#define ZP_NUMTEXT_H

#include <stddef.h>

/* Strips leading and trailing white space in place. */
void zp_text_trim(char *s);
/* A finite decimal number taking the whole text (no hex, inf, nan or trailing junk): 0; -1 if
   it is not one, -2 if it is beyond the largest double (1e400). */
int zp_text_number(const char *text, double *out);
/* "a, b, c": returns how many items the list has (storing at most max in out), or -1 with why
   on an empty or bad item. */
int zp_text_items(const char *text, double *out, int max, char *why, size_t whylen);
/* The same, refusing more than max items ("N values, at most max"). */
int zp_text_list(const char *text, double *out, int max, char *why, size_t whylen);

#endif
