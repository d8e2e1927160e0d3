/* Writing aside, then renaming (CLI.md "Files"): a failed command leaves no partial output. */
#include "out_file.h"

#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void zp_out_set_init(zp_out_set *o) { memset(o, 0, sizeof *o); }

int zp_out_make_dirs(const char *dir) {
    char path[1024];
    snprintf(path, sizeof path, "%s", dir);
    for (char *p = path + 1; *p; p++) {
        if (*p == '/') {
            *p = '\0';
            if (mkdir(path, 0777) && errno != EEXIST) {
                return -1;
            }
            *p = '/';
        }
    }
    return mkdir(path, 0777) && errno != EEXIST ? -1 : 0;
}

FILE *zp_out_set_open(zp_out_set *o, const char *dir, const char *name, char *err,
                      size_t errlen) {
    if (o->n == ZP_OUT_MAX_FILES) {
        snprintf(err, errlen, "too many output files");
        return NULL;
    }
    if (zp_out_make_dirs(dir)) {
        snprintf(err, errlen, "cannot create the folder %s: %s", dir, strerror(errno));
        return NULL;
    }
    int i = o->n;
    snprintf(o->final[i], sizeof o->final[i], "%s/%s", dir, name);
    snprintf(o->tmp[i], sizeof o->tmp[i], "%s/.%s.%ld.tmp", dir, name, (long)getpid());
    o->f[i] = fopen(o->tmp[i], "w");
    if (!o->f[i]) {
        snprintf(err, errlen, "cannot write %s: %s", o->tmp[i], strerror(errno));
        return NULL;
    }
    o->n++;
    return o->f[i];
}

zp_status zp_out_set_commit(zp_out_set *o, char *err, size_t errlen) {
    for (int i = 0; i < o->n; i++) {
        int bad = ferror(o->f[i]);
        bad |= fclose(o->f[i]) != 0;
        o->f[i] = NULL;
        if (bad) {
            snprintf(err, errlen, "writing %s failed: %s", o->final[i], strerror(errno));
            zp_out_set_abort(o);
            return ZP_ERR_IO;
        }
    }
    for (int i = 0; i < o->n; i++) {
        if (rename(o->tmp[i], o->final[i])) {
            snprintf(err, errlen, "cannot rename %s to %s: %s", o->tmp[i], o->final[i],
                     strerror(errno));
            zp_out_set_abort(o);
            return ZP_ERR_IO;
        }
    }
    o->n = 0;
    return ZP_OK;
}

void zp_out_set_abort(zp_out_set *o) {
    for (int i = 0; i < o->n; i++) {
        if (o->f[i]) {
            fclose(o->f[i]);
        }
        remove(o->tmp[i]);
    }
    o->n = 0;
}
