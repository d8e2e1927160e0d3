/* The gnuplot runner (gnuplot.h): a process per core, each drawing its share of the scripts,
   run in the private folder so the scripts name their data and images by relative paths and
   can be rerun by hand in the output folder; the wait survives signals. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "gnuplot.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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

int zp_gnuplot_cores(void) {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) {
        return CPU_COUNT(&set);
    }
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > INT_MAX ? INT_MAX : (int)n;
}

/* starts one gnuplot drawing the scripts of group g (every nproc-th from g) in the private
   folder, each after a fresh session and a marker line, the output kept in .log.<first script>;
   registered with the transaction before a signal can see it */
static pid_t start(zp_tx *t, const zp_gnuplot_job *j, int g) {
    char log[300], mark[ZP_GNUPLOT_MAX_SCRIPTS][300];
    const char *argv[3 * ZP_GNUPLOT_MAX_SCRIPTS + 2] = {"gnuplot"};
    int argc = 1;
    for (int i = g; i < j->n; i += j->nproc) {
        snprintf(mark[i], sizeof mark[i], "print '%s%s'; reset session", ZP_GNUPLOT_MARK,
                 j->script[i]);
        argv[argc++] = "-e";
        argv[argc++] = mark[i];
        argv[argc++] = j->script[i];
    }
    argv[argc] = NULL;
    snprintf(log, sizeof log, ".log.%s", j->script[g]);
    zp_tx_lock();
    pid_t pid = fork();
    if (pid == 0) {
        zp_tx_child_signals();
        setpgid(0, 0);
        int fd = fchdir(zp_tx_workdir(t)) ? -1
                                          : openat(zp_tx_workdir(t), log,
                                                   O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0666);
        int in = open("/dev/null", O_RDONLY);
        if (fd < 0 || in < 0) {
            _exit(126);
        }
        dup2(in, STDIN_FILENO);
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        execvp("gnuplot", (char *const *)argv);
        _exit(127);
    }
    if (pid > 0 && !zp_tx_add_child(t, pid)) {
        kill(pid, SIGKILL);
        waitpid(pid, NULL, 0);
        pid = -1;
        errno = EAGAIN;
    }
    zp_tx_unlock();
    return pid;
}

/* of group g's log: the script it was drawing when it stopped (after the last marker; the
   group's first when there is none) and that script's lines, on one line, for a message */
static const char *failed_script(const zp_tx *t, const zp_gnuplot_job *j, int g, char *buf,
                                 size_t len) {
    char log[300], text[4096];
    snprintf(log, sizeof log, ".log.%s", j->script[g]);
    int fd = openat(zp_tx_workdir(t), log, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    ssize_t n = fd >= 0 ? read(fd, text, sizeof text - 1) : 0;
    text[n > 0 ? n : 0] = '\0';
    if (fd >= 0) {
        close(fd);
    }
    const char *name = j->script[g], *from = text;
    for (int i = g; i < j->n; i += j->nproc) {
        char mark[300];
        snprintf(mark, sizeof mark, "%s%s\n", ZP_GNUPLOT_MARK, j->script[i]);
        const char *at = strstr(text, mark);
        if (at) {
            name = j->script[i];
            from = at + strlen(mark);
        }
    }
    snprintf(buf, len, "%s", from);
    for (char *p = buf; *p; p++) {
        *p = *p == '\n' ? ' ' : *p;
    }
    return name;
}

/* the n bytes of fd at off (from the end when off < 0) into buf; 0 when all were read */
static int read_at(int fd, off_t size, off_t off, void *buf, size_t n) {
    off_t at = off < 0 ? size + off : off;
    return at < 0 || at + (off_t)n > size || pread(fd, buf, n, at) != (ssize_t)n ? -1 : 0;
}

/* 1 when the boxes of an MP4 file (size, type; size 1: a 64-bit size follows; 0: to the end)
   add up to the file's length exactly, the first being ftyp */
static int mp4_whole(int fd, off_t size) {
    off_t off = 0;
    while (off < size) {
        unsigned char h[16];
        if (read_at(fd, size, off, h, 8) || (off == 0 && memcmp(h + 4, "ftyp", 4))) {
            return 0;
        }
        unsigned long long box = (unsigned long long)h[0] << 24 | (unsigned long long)h[1] << 16 |
                                 (unsigned long long)h[2] << 8 | h[3];
        if (box == 1) {
            if (read_at(fd, size, off + 8, h + 8, 8)) {
                return 0;
            }
            box = 0;
            for (int i = 8; i < 16; i++) {
                box = box << 8 | h[i];
            }
        } else if (box == 0) {
            box = (unsigned long long)(size - off);
        }
        if (box < 8 || box > (unsigned long long)(size - off)) {
            return 0;
        }
        off += (off_t)box;
    }
    return off == size && size > 0;
}

int zp_gnuplot_whole(int dirfd, const char *name) {
    int fd = openat(dirfd, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    if (fd < 0) {
        return 0;
    }
    int ok = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0;
    const char *ext = strrchr(name, '.');
    ext = ext ? ext + 1 : "";
    unsigned char head[8], tail[64];
    size_t ntail = st.st_size < (off_t)sizeof tail ? (size_t)st.st_size : sizeof tail;
    if (ok && !strcmp(ext, "png")) {
        static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
        static const unsigned char iend[12] = {0,   0,   0,    0,    'I',  'E',
                                               'N', 'D', 0xae, 0x42, 0x60, 0x82};
        ok = !read_at(fd, st.st_size, 0, head, 8) && !memcmp(head, sig, 8) &&
             !read_at(fd, st.st_size, -12, tail, 12) && !memcmp(tail, iend, 12);
    } else if (ok && !strcmp(ext, "gif")) {
        ok = !read_at(fd, st.st_size, 0, head, 6) &&
             (!memcmp(head, "GIF87a", 6) || !memcmp(head, "GIF89a", 6)) &&
             !read_at(fd, st.st_size, -1, tail, 1) && tail[0] == 0x3b;
    } else if (ok && !strcmp(ext, "svg")) {
        ok = !read_at(fd, st.st_size, -(off_t)ntail, tail, ntail);
        while (ok && ntail > 0 && strchr(" \t\r\n", tail[ntail - 1])) {
            ntail--;
        }
        ok = ok && ntail >= 6 && !memcmp(tail + ntail - 6, "</svg>", 6);
    } else if (ok && !strcmp(ext, "mp4")) {
        ok = mp4_whole(fd, st.st_size);
    }
    close(fd);
    return ok;
}

/* the first image that script (in the private folder) names in `set output '...'` and that
   is missing or not whole, into bad; 0 when every one is whole */
static int check_images(const zp_tx *t, const char *script, char *bad, size_t badlen) {
    int fd = openat(zp_tx_workdir(t), script, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    FILE *f = fd >= 0 ? fdopen(fd, "r") : NULL;
    if (!f) {
        if (fd >= 0) {
            close(fd);
        }
        snprintf(bad, badlen, "%s (its script cannot be read back)", script);
        return -1;
    }
    static const char key[] = "set output '";
    char line[1024];
    int failed = 0;
    while (!failed && fgets(line, sizeof line, f)) {
        const char *at = strstr(line, key);
        const char *end = at ? strchr(at + sizeof key - 1, '\'') : NULL;
        if (!end) {
            continue;
        }
        snprintf(bad, badlen, "%.*s", (int)(end - at - (sizeof key - 1)), at + sizeof key - 1);
        failed = !zp_gnuplot_whole(zp_tx_workdir(t), bad);
    }
    fclose(f);
    return failed ? -1 : 0;
}

/* one finished child: its status, retried through interruptions; -1 when none is left */
static pid_t reap(int *st) {
    pid_t done;
    while ((done = waitpid(-1, st, 0)) < 0 && errno == EINTR) {
    }
    return done;
}

zp_status zp_gnuplot_start(zp_tx *t, const char *const *scripts, int n, int nproc,
                           zp_gnuplot_job *j, char *err, size_t errlen) {
    memset(j, 0, sizeof *j);
    if (zp_tx_flush(t, err, errlen)) {
        return ZP_ERR_IO;
    }
    if (n > ZP_GNUPLOT_MAX_SCRIPTS) {
        snprintf(err, errlen, "too many gnuplot scripts (%d)", n);
        return ZP_ERR_IO;
    }
    j->missing = !zp_gnuplot_have("gnuplot");
    if (j->missing) {
        return ZP_OK;
    }
    /* a process per core: each start-up (fonts, terminal) costs about what drawing one does */
    int ncpu = nproc > 0 ? nproc : zp_gnuplot_cores();
    j->n = n;
    j->nproc = ncpu > ZP_GNUPLOT_MAX_PROC ? ZP_GNUPLOT_MAX_PROC : ncpu;
    j->nproc = j->nproc < n ? j->nproc : n;
    for (int i = 0; i < n; i++) {
        j->script[i] = scripts[i];
    }
    for (int g = 0; g < j->nproc; g++) {
        j->pid[g] = start(t, j, g);
        if (j->pid[g] < 0) {
            snprintf(err, errlen, "cannot start gnuplot: %s", strerror(errno));
            return ZP_ERR_IO; /* the caller's abort ends those started */
        }
        j->running++;
    }
    return ZP_OK;
}

zp_status zp_gnuplot_wait(zp_tx *t, zp_gnuplot_job *j, char *err, size_t errlen) {
    int failed = 0;
    while (j->running > 0) {
        int st;
        pid_t done = reap(&st);
        if (done < 0) {
            break;
        }
        zp_tx_drop_child(t, done);
        for (int g = 0; g < j->nproc; g++) {
            if (j->pid[g] != done) {
                continue;
            }
            j->running--;
            if (!(WIFEXITED(st) && WEXITSTATUS(st) == 0) && !failed) {
                char log[600];
                const char *name = failed_script(t, j, g, log, sizeof log);
                snprintf(err, errlen, "gnuplot %s failed: %s", name, *log ? log : "no message");
                failed = 1;
            }
        }
    }
    /* gnuplot ends with 0 when the disk fills under an image: each is checked whole */
    for (int i = 0; !failed && i < j->n; i++) {
        char image[300];
        if (check_images(t, j->script[i], image, sizeof image)) {
            snprintf(err, errlen, "gnuplot %s: %s was not written whole (is the disk full?)",
                     j->script[i], image);
            failed = 1;
        }
    }
    return failed ? ZP_ERR_IO : ZP_OK;
}

zp_status zp_gnuplot_run(zp_tx *t, const char *const *scripts, int n, int *missing, char *err,
                         size_t errlen) {
    zp_gnuplot_job j;
    zp_status st = zp_gnuplot_start(t, scripts, n, 0, &j, err, errlen);
    *missing = j.missing;
    return st ? st : zp_gnuplot_wait(t, &j, err, errlen);
}
