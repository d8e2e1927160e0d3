/* The gnuplot runner (gnuplot.h): one process per script, run in the private folder so the
   scripts name their data and images by relative paths and can be rerun by hand in the
   output folder; the wait survives signals. */
#include "gnuplot.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAX_WIDTH 8 /* scripts drawn at once */

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

/* starts `gnuplot script` in the private folder, its output kept in .log.<script> there;
   registered with the transaction before a signal can see it */
static pid_t start(zp_tx *t, const char *script) {
    char log[300];
    snprintf(log, sizeof log, ".log.%s", script);
    zp_tx_block_signals(1);
    pid_t pid = fork();
    if (pid == 0) {
        struct sigaction dfl = {.sa_handler = SIG_DFL};
        sigemptyset(&dfl.sa_mask);
        const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
        for (int i = 0; i < 4; i++) {
            sigaction(sigs[i], &dfl, NULL);
        }
        zp_tx_block_signals(0);
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
        execlp("gnuplot", "gnuplot", script, (char *)NULL);
        _exit(127);
    }
    if (pid > 0 && !zp_tx_add_child(t, pid)) {
        kill(pid, SIGKILL);
        waitpid(pid, NULL, 0);
        pid = -1;
        errno = EAGAIN;
    }
    zp_tx_block_signals(0);
    return pid;
}

/* the first lines of a script's gnuplot log, on one line, for a message */
static void log_excerpt(const zp_tx *t, const char *script, char *buf, size_t len) {
    char log[300];
    snprintf(log, sizeof log, ".log.%s", script);
    int fd = openat(zp_tx_workdir(t), log, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    ssize_t n = fd >= 0 ? read(fd, buf, len - 1) : 0;
    buf[n > 0 ? n : 0] = '\0';
    if (fd >= 0) {
        close(fd);
    }
    for (char *p = buf; *p; p++) {
        *p = *p == '\n' ? ' ' : *p;
    }
}

/* one finished child: its status, retried through interruptions; -1 when none is left */
static pid_t reap(int *st) {
    pid_t done;
    while ((done = waitpid(-1, st, 0)) < 0 && errno == EINTR) {
    }
    return done;
}

zp_status zp_gnuplot_run(zp_tx *t, const char *const *scripts, int n, int *missing, char *err,
                         size_t errlen) {
    if (zp_tx_flush(t, err, errlen)) {
        return ZP_ERR_IO;
    }
    *missing = !zp_gnuplot_have("gnuplot");
    if (*missing) {
        return ZP_OK;
    }
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    int width = ncpu < 1 ? 1 : ncpu > MAX_WIDTH ? MAX_WIDTH : (int)ncpu;
    pid_t pid[64];
    int next = 0, running = 0, failed = -1;
    while (next < n || running) {
        if (next < n && next < 64 && running < width && failed < 0) {
            pid[next] = start(t, scripts[next]);
            if (pid[next] < 0) {
                snprintf(err, errlen, "cannot start gnuplot: %s", strerror(errno));
                failed = next;
            } else {
                running++;
            }
            next++;
            continue;
        }
        int st;
        pid_t done = running ? reap(&st) : -1;
        if (done < 0) {
            break;
        }
        zp_tx_drop_child(t, done);
        running--;
        for (int i = 0; i < next; i++) {
            if (pid[i] == done && !(WIFEXITED(st) && WEXITSTATUS(st) == 0) && failed < 0) {
                char log[600];
                log_excerpt(t, scripts[i], log, sizeof log);
                snprintf(err, errlen, "gnuplot %s failed: %s", scripts[i],
                         *log ? log : "no message");
                failed = i;
            }
        }
    }
    if (failed < 0 && next < n) {
        snprintf(err, errlen, "too many gnuplot scripts (%d)", n);
        failed = next;
    }
    return failed < 0 ? ZP_OK : ZP_ERR_IO;
}
