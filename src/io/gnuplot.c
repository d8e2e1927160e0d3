/* Figures made aside then renamed (gnuplot.h): one gnuplot process per script, run in the
   hidden folder so the scripts name their data and images by relative paths and can be rerun
   by hand in the output folder. */
#include "gnuplot.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "out_file.h"

/* removes path and, for a folder, everything below it */
static void remove_tree(const char *path) {
    DIR *d = opendir(path);
    if (d) {
        struct dirent *e;
        while ((e = readdir(d))) {
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
                char sub[2048];
                snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
                remove_tree(sub);
            }
        }
        closedir(d);
    }
    remove(path);
}

zp_status zp_gnuplot_begin(zp_gnuplot *g, const char *dir, char *err, size_t errlen) {
    memset(g, 0, sizeof *g);
    snprintf(g->dir, sizeof g->dir, "%s", dir);
    snprintf(g->tmp, sizeof g->tmp, "%s/.plots.%ld.tmp", dir, (long)getpid());
    if (zp_out_make_dirs(dir)) {
        snprintf(err, errlen, "cannot create the folder %s: %s", dir, strerror(errno));
        return ZP_ERR_IO;
    }
    remove_tree(g->tmp); /* left by a crashed process with this id */
    if (mkdir(g->tmp, 0777)) {
        snprintf(err, errlen, "cannot create the folder %s: %s", g->tmp, strerror(errno));
        return ZP_ERR_IO;
    }
    return ZP_OK;
}

FILE *zp_gnuplot_open(zp_gnuplot *g, const char *name, int script, char *err, size_t errlen) {
    if (g->nfile == ZP_GNUPLOT_MAX_FILES) {
        snprintf(err, errlen, "too many plot files");
        return NULL;
    }
    char path[1300];
    snprintf(path, sizeof path, "%s/%s", g->tmp, name);
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        return NULL;
    }
    g->f[g->nfile++] = f;
    if (script) {
        snprintf(g->script[g->nscript++], sizeof g->script[0], "%s", name);
    }
    return f;
}

int zp_gnuplot_have(const char *prog) {
    const char *path = getenv("PATH");
    while (path && *path) {
        size_t n = strcspn(path, ":");
        char full[4096];
        snprintf(full, sizeof full, "%.*s/%s", (int)n, n ? path : ".", prog);
        if (access(full, X_OK) == 0) {
            return 1;
        }
        path += n + (path[n] == ':');
    }
    return 0;
}

/* starts `gnuplot script` in the hidden folder, its output kept in .log.<script> there */
static pid_t start(const zp_gnuplot *g, const char *script) {
    pid_t pid = fork();
    if (pid == 0) {
        char log[256];
        snprintf(log, sizeof log, ".log.%s", script);
        int fd = chdir(g->tmp) ? -1 : open(log, O_WRONLY | O_CREAT | O_TRUNC, 0666);
        if (fd < 0) {
            _exit(126);
        }
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        execlp("gnuplot", "gnuplot", script, (char *)NULL);
        _exit(127);
    }
    return pid;
}

/* the first lines of a script's gnuplot log, on one line, for a message */
static void log_excerpt(const zp_gnuplot *g, const char *script, char *buf, size_t len) {
    char path[1400];
    snprintf(path, sizeof path, "%s/.log.%s", g->tmp, script);
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(buf, 1, len - 1, f) : 0;
    buf[n] = '\0';
    if (f) {
        fclose(f);
    }
    for (char *p = buf; *p; p++) {
        *p = *p == '\n' ? ' ' : *p;
    }
}

/* runs every script, a few at a time; 0, or -1 with the first failure in err */
static int run_all(const zp_gnuplot *g, char *err, size_t errlen) {
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    int width = ncpu < 1 ? 1 : ncpu > 8 ? 8 : (int)ncpu;
    pid_t pid[ZP_GNUPLOT_MAX_FILES];
    int next = 0, running = 0, failed = -1;
    while (next < g->nscript || running) {
        if (next < g->nscript && running < width && failed < 0) {
            pid[next] = start(g, g->script[next]);
            if (pid[next] < 0) {
                snprintf(err, errlen, "cannot start gnuplot: %s", strerror(errno));
                failed = next;
            } else {
                running++;
            }
            next++;
            continue;
        }
        if (!running) {
            break;
        }
        int st;
        pid_t done = wait(&st);
        if (done < 0) {
            break;
        }
        running--;
        for (int i = 0; i < next; i++) {
            if (pid[i] == done && !(WIFEXITED(st) && WEXITSTATUS(st) == 0) && failed < 0) {
                char log[600];
                log_excerpt(g, g->script[i], log, sizeof log);
                snprintf(err, errlen, "gnuplot %s failed: %s", g->script[i],
                         *log ? log : "no message");
                failed = i;
            }
        }
    }
    return failed < 0 ? 0 : -1;
}

/* renames every visible file of the hidden folder into the output folder */
static int move_all(const zp_gnuplot *g, char *err, size_t errlen) {
    DIR *d = opendir(g->tmp);
    if (!d) {
        snprintf(err, errlen, "cannot read %s: %s", g->tmp, strerror(errno));
        return -1;
    }
    int bad = 0;
    struct dirent *e;
    while (!bad && (e = readdir(d))) {
        char from[1400], to[1400];
        struct stat st;
        snprintf(from, sizeof from, "%s/%s", g->tmp, e->d_name);
        snprintf(to, sizeof to, "%s/%s", g->dir, e->d_name);
        if (e->d_name[0] != '.' && !stat(from, &st) && S_ISREG(st.st_mode) && rename(from, to)) {
            snprintf(err, errlen, "cannot rename %s to %s: %s", from, to, strerror(errno));
            bad = 1;
        }
    }
    closedir(d);
    return bad ? -1 : 0;
}

zp_status zp_gnuplot_finish(zp_gnuplot *g, int *missing, char *err, size_t errlen) {
    int bad = 0;
    for (int i = 0; i < g->nfile; i++) {
        int fail = ferror(g->f[i]);
        fail |= fclose(g->f[i]) != 0;
        if (fail && !bad) {
            snprintf(err, errlen, "writing the plot files in %s failed: %s", g->tmp,
                     strerror(errno));
            bad = 1;
        }
    }
    g->nfile = 0;
    *missing = !zp_gnuplot_have("gnuplot");
    if (!bad && !*missing) {
        bad = run_all(g, err, errlen);
    }
    if (!bad) {
        bad = move_all(g, err, errlen);
    }
    zp_gnuplot_abort(g);
    return bad ? ZP_ERR_IO : ZP_OK;
}

void zp_gnuplot_abort(zp_gnuplot *g) {
    for (int i = 0; i < g->nfile; i++) {
        fclose(g->f[i]);
    }
    g->nfile = 0;
    remove_tree(g->tmp);
}
