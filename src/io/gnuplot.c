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
    return failed ? ZP_ERR_IO : ZP_OK;
}

zp_status zp_gnuplot_run(zp_tx *t, const char *const *scripts, int n, int *missing, char *err,
                         size_t errlen) {
    zp_gnuplot_job j;
    zp_status st = zp_gnuplot_start(t, scripts, n, 0, &j, err, errlen);
    *missing = j.missing;
    return st ? st : zp_gnuplot_wait(t, &j, err, errlen);
}
