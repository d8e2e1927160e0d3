/* Output files written whole or not at all: each goes to a hidden temporary name beside its
   target and is renamed only when every file of the command has been written. */
#ifndef ZP_OUT_FILE_H
#define ZP_OUT_FILE_H

#include <stdio.h>

#include "diag.h"

#define ZP_OUT_MAX_FILES 16

typedef struct zp_out_set {
    int n;
    char final[ZP_OUT_MAX_FILES][1024];
    char tmp[ZP_OUT_MAX_FILES][1100];
    FILE *f[ZP_OUT_MAX_FILES];
} zp_out_set;

void zp_out_set_init(zp_out_set *o);
/* Creates dir and its parents (like mkdir -p); 0, or -1 with errno set. */
int zp_out_make_dirs(const char *dir);
/* Creates dir (and its parents) and opens dir/name aside; NULL with a message on failure. */
FILE *zp_out_set_open(zp_out_set *o, const char *dir, const char *name, char *err, size_t errlen);
/* Closes and renames every file; on any failure removes them all and reports the first. */
zp_status zp_out_set_commit(zp_out_set *o, char *err, size_t errlen);
/* Closes and removes every temporary file: nothing is written. */
void zp_out_set_abort(zp_out_set *o);

#endif
