/* The write-aside transaction (out_file.h): folders opened one name at a time, files made
   exclusively in a private folder, moved as a set under flock, and a cleanup that never
   follows a link, run on a signal by the one thread that takes the signals. */
#include "tx.h"

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <dirent.h>

static const int handled[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
#define NHANDLED ((int)(sizeof handled / sizeof handled[0]))
static zp_tx *active; /* the transaction a signal cleans up; under lock */
/* held by every step that moves or creates files of a transaction, and by the signal thread
   while it cleans up: the cleanup never runs in the middle of a commit or a checkpoint */
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

/* one entry as getdents64 returns it: readdir allocates, and the cleanup must not */
struct dirent64_raw {
    uint64_t ino;
    int64_t off;
    unsigned short reclen;
    unsigned char type;
    char name[];
};

static int dots(const char *n) {
    return n[0] == '.' && (!n[1] || (n[1] == '.' && !n[2]));
}

/* unlinks every entry of the folder fd (allocates nothing; never follows a link) */
static void empty_dir(int fd) {
    _Alignas(8) char buf[4096];
    for (int pass = 0; pass < 64; pass++) {
        int removed = 0;
        long n;
        lseek(fd, 0, SEEK_SET);
        while ((n = syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0) {
            for (long off = 0; off < n;) {
                struct dirent64_raw *e = (struct dirent64_raw *)(void *)(buf + off);
                removed += !dots(e->name) && unlinkat(fd, e->name, 0) == 0;
                off += e->reclen;
            }
        }
        if (!removed) {
            break;
        }
    }
}

/* removes the checkpoint when it is still the file this run put there */
static void drop_checkpoint(zp_tx *t) {
    struct stat st;
    if (t->ck_ino && t->dirfd >= 0 &&
        fstatat(t->dirfd, t->ck_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && st.st_ino == t->ck_ino &&
        st.st_dev == t->ck_dev) {
        unlinkat(t->dirfd, t->ck_name, 0);
    }
    t->ck_ino = 0;
}

/* everything but the open FILEs: helpers killed, private folder removed, descriptors closed;
   with undo, also the checkpoint and the empty folders this run created. Allocates nothing
   (readdir would), so it may run while another thread is stopped anywhere. */
static void cleanup(zp_tx *t, int undo) {
    for (int i = 0; i < ZP_TX_MAX_CHILD; i++) {
        pid_t pid = t->child[i];
        if (pid > 0) {
            kill(pid, SIGKILL);
            while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {
            }
            t->child[i] = 0;
        }
    }
    if (t->tmpfd >= 0) {
        empty_dir(t->tmpfd);
        unlinkat(t->dirfd, t->tmp_name, AT_REMOVEDIR);
        close(t->tmpfd);
        t->tmpfd = -1;
    }
    if (undo) {
        drop_checkpoint(t);
    }
    if (t->dirfd >= 0) {
        close(t->dirfd);
        t->dirfd = -1;
    }
    for (int i = t->ndir - 1; i >= 0; i--) {
        if (undo) {
            unlinkat(t->dir_parent[i], t->dir_name[i], AT_REMOVEDIR); /* only when empty */
        }
        close(t->dir_parent[i]);
    }
    t->ndir = 0;
}

/* Design note: the handled signals are blocked in every thread and taken by one thread in
   sigwait. A handler runs on whichever thread does not block the signal, and OpenMP's and
   OpenMPI's threads do not: it then cleaned up beside a commit that blocked the signal only
   in its own thread, leaving a mix of two runs. A thread that waits for the signals can take
   the lock the commit holds, so the cleanup comes before or after the moves, never amid
   them; blocking in the handler thread alone was rejected for that reason. */
static void *signal_loop(void *arg) {
    const sigset_t *set = arg;
    for (;;) {
        int sig;
        if (sigwait(set, &sig)) {
            continue;
        }
        pthread_mutex_lock(&lock);
        zp_tx *t = active;
        if (t && sig == SIGINT && t->soft_stop && !*t->soft_stop) {
            *t->soft_stop = 1;
            pthread_mutex_unlock(&lock);
            continue;
        }
        if (t) {
            active = NULL;
            cleanup(t, 1);
            static const char msg[] =
                "zipopt: stopped by a signal; nothing of this run was written\n";
            ssize_t ignored = write(STDERR_FILENO, msg, sizeof msg - 1);
            (void)ignored;
        }
        /* the lock stays held: no thread moves a file before the process ends of the signal */
        struct sigaction dfl = {.sa_handler = SIG_DFL};
        sigemptyset(&dfl.sa_mask);
        sigaction(sig, &dfl, NULL);
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, sig);
        pthread_sigmask(SIG_UNBLOCK, &one, NULL);
        raise(sig);
    }
    return NULL;
}

static void start_signal_thread(void) {
    static sigset_t set;
    sigemptyset(&set);
    for (int i = 0; i < NHANDLED; i++) {
        sigaddset(&set, handled[i]);
    }
    pthread_sigmask(SIG_BLOCK, &set, NULL);
    pthread_attr_t attr;
    pthread_t th;
    if (pthread_attr_init(&attr) == 0) {
        pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
        if (pthread_create(&th, &attr, signal_loop, &set)) {
            /* no thread: the signals keep their default action (the run ends, uncleaned) */
            pthread_sigmask(SIG_UNBLOCK, &set, NULL);
        }
        pthread_attr_destroy(&attr);
    }
}

void zp_tx_signals_start(void) {
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, start_signal_thread);
}

void zp_tx_lock(void) {
    pthread_mutex_lock(&lock);
}

void zp_tx_unlock(void) {
    pthread_mutex_unlock(&lock);
}

void zp_tx_child_signals(void) {
    sigset_t set;
    sigemptyset(&set);
    struct sigaction dfl = {.sa_handler = SIG_DFL};
    sigemptyset(&dfl.sa_mask);
    for (int i = 0; i < NHANDLED; i++) {
        sigaddset(&set, handled[i]);
        sigaction(handled[i], &dfl, NULL);
    }
    sigprocmask(SIG_UNBLOCK, &set, NULL);
}

/* opens path one folder at a time from cur (owned), creating what is missing (a failed run
   removes at most ZP_TX_MAX_DIRS of them again); follow = 0 refuses links. The folder's
   descriptor, or -1 with why. */
static int walk(zp_tx *t, int cur, const char *path, int follow, char *err, size_t errlen) {
    char buf[1024], *save = NULL;
    snprintf(buf, sizeof buf, "%s", path);
    int flags = O_RDONLY | O_DIRECTORY | O_CLOEXEC | (follow ? 0 : O_NOFOLLOW);
    for (char *c = strtok_r(buf, "/", &save); c && cur >= 0; c = strtok_r(NULL, "/", &save)) {
        int made = mkdirat(cur, c, 0777) == 0;
        if (!made && errno != EEXIST) {
            snprintf(err, errlen, "cannot create the folder %s in %s: %s", c, t->dir,
                     strerror(errno));
            close(cur);
            return -1;
        }
        int next = openat(cur, c, flags);
        if (next < 0) {
            snprintf(err, errlen, "cannot open the folder %s in %s: %s%s", c, t->dir,
                     strerror(errno),
                     errno == ELOOP || errno == ENOTDIR ? " (zipopt follows no link it adds)" : "");
        }
        if (made && t->ndir < ZP_TX_MAX_DIRS) { /* its parent stays open to remove it again */
            t->dir_parent[t->ndir] = cur;
            snprintf(t->dir_name[t->ndir], sizeof t->dir_name[0], "%s", c);
            t->ndir++;
        } else {
            close(cur);
        }
        cur = next;
    }
    return cur;
}

void zp_tx_soft_interrupt(zp_tx *t, volatile sig_atomic_t *stop) {
    t->soft_stop = stop;
}

/* the private folder: a fresh unpredictable name, made by this process alone */
static int make_private(zp_tx *t, char *err, size_t errlen) {
    for (int tries = 0; tries < 16; tries++) {
        unsigned char r[8];
        if (getentropy(r, sizeof r)) {
            break;
        }
        snprintf(t->tmp_name, sizeof t->tmp_name, ".zipopt-%02x%02x%02x%02x%02x%02x%02x%02x", r[0],
                 r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
        if (mkdirat(t->dirfd, t->tmp_name, 0700) == 0) {
            t->tmpfd =
                openat(t->dirfd, t->tmp_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (t->tmpfd < 0) {
                unlinkat(t->dirfd, t->tmp_name, AT_REMOVEDIR);
                break;
            }
            return 0;
        }
        if (errno != EEXIST) {
            break;
        }
    }
    snprintf(err, errlen, "cannot create a private folder in %s: %s", t->dir, strerror(errno));
    return -1;
}

zp_status zp_tx_begin(zp_tx *t, const char *base, const char *sub, char *err, size_t errlen) {
    memset(t, 0, sizeof *t);
    t->dirfd = t->tmpfd = -1;
    int len = snprintf(t->dir, sizeof t->dir, "%s%s%s", base, sub ? "/" : "", sub ? sub : "");
    if (len >= (int)sizeof t->dir) {
        snprintf(err, errlen, "the output folder's name is longer than %zu bytes",
                 sizeof t->dir - 1);
        return ZP_ERR_IO;
    }
    zp_tx_signals_start();
    zp_tx_lock();
    active = t;
    int fd = open(base[0] == '/' ? "/" : ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        snprintf(err, errlen, "cannot open the current folder: %s", strerror(errno));
    }
    fd = fd < 0 ? -1 : walk(t, fd, base, 1, err, errlen);
    if (fd >= 0 && sub) {
        fd = walk(t, fd, sub, 0, err, errlen);
    }
    t->dirfd = fd;
    int bad = fd < 0 || make_private(t, err, errlen);
    if (bad) {
        cleanup(t, 1);
        active = NULL;
    }
    zp_tx_unlock();
    return bad ? ZP_ERR_IO : ZP_OK;
}

/* the Nth file opened in this process goes to /dev/full (ZIPOPT_TEST_FULL=N; tests only) */
static int test_full(void) {
    static long n = -1, k;
    if (n < 0) {
        const char *e = getenv("ZIPOPT_TEST_FULL");
        n = e ? atol(e) : 0;
    }
    return n > 0 && ++k == n;
}

FILE *zp_tx_open(zp_tx *t, const char *name, char *err, size_t errlen) {
    if (t->nopen == ZP_TX_MAX_OPEN || strchr(name, '/') || name[0] == '.' ||
        strlen(name) >= sizeof t->fname[0]) {
        snprintf(err, errlen, "cannot write %s in %s: too many files or a bad name", name, t->dir);
        return NULL;
    }
    zp_tx_lock();
    int fd = openat(t->tmpfd, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    zp_tx_unlock();
    FILE *f = NULL;
    if (fd >= 0 && test_full()) {
        close(fd);
        f = fopen("/dev/full", "w");
    } else if (fd >= 0 && !(f = fdopen(fd, "w"))) {
        close(fd);
    }
    if (!f) {
        snprintf(err, errlen, "cannot write %s in %s: %s", name, t->dir, strerror(errno));
        return NULL;
    }
    t->f[t->nopen] = f;
    snprintf(t->fname[t->nopen++], sizeof t->fname[0], "%s", name);
    return f;
}

int zp_tx_open_set(zp_tx *t, const char *const *names, FILE **f, int n, char *err,
                   size_t errlen) {
    for (int i = 0; i < n; i++) {
        if (!(f[i] = zp_tx_open(t, names[i], err, errlen))) {
            return -1;
        }
    }
    return 0;
}

int zp_tx_flush(zp_tx *t, char *err, size_t errlen) {
    int bad = 0;
    for (int i = 0; i < t->nopen; i++) {
        int fail = ferror(t->f[i]);
        fail |= fclose(t->f[i]) != 0;
        if (fail && !bad) {
            snprintf(err, errlen, "writing %s in %s failed: %s", t->fname[i], t->dir,
                     strerror(errno));
            bad = 1;
        }
    }
    t->nopen = 0;
    return bad ? -1 : 0;
}

int zp_tx_workdir(const zp_tx *t) {
    return t->tmpfd;
}

int zp_tx_add_child(zp_tx *t, pid_t pid) {
    for (int i = 0; i < ZP_TX_MAX_CHILD; i++) {
        if (!t->child[i]) {
            t->child[i] = pid;
            return 1;
        }
    }
    return 0;
}

void zp_tx_drop_child(zp_tx *t, pid_t pid) {
    for (int i = 0; i < ZP_TX_MAX_CHILD; i++) {
        if (t->child[i] == pid) {
            t->child[i] = 0;
        }
    }
}

int zp_tx_checkpoint(zp_tx *t, const char *name, void (*write)(FILE *f, void *user), void *user,
                     char *err, size_t errlen) {
    char aside[80];
    snprintf(aside, sizeof aside, ".ck.%s", name);
    zp_tx_lock();
    int fd = openat(t->tmpfd, aside, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    struct stat st;
    int bad = !f;
    if (f) {
        write(f, user);
        bad = ferror(f) | fstat(fd, &st);
        bad |= fclose(f) != 0;
    } else if (fd >= 0) {
        close(fd);
    }
    flock(t->dirfd, LOCK_EX);
    bad = bad || renameat(t->tmpfd, aside, t->dirfd, name);
    if (!bad) {
        snprintf(t->ck_name, sizeof t->ck_name, "%s", name);
        t->ck_dev = st.st_dev;
        t->ck_ino = st.st_ino;
    }
    flock(t->dirfd, LOCK_UN);
    if (bad) {
        snprintf(err, errlen, "cannot write %s in %s: %s", name, t->dir, strerror(errno));
        unlinkat(t->tmpfd, aside, 0);
    }
    zp_tx_unlock();
    return bad ? -1 : 0;
}

static int by_name(const void *a, const void *b) {
    return strcmp(a, b);
}

/* the visible regular files of the private folder, sorted (caller frees); -1 on failure */
static int list_files(const zp_tx *t, char (**names)[256]) {
    int fd = openat(t->tmpfd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    if (!d) {
        if (fd >= 0) {
            close(fd);
        }
        return -1;
    }
    int n = 0, cap = 0;
    *names = NULL;
    struct dirent *e;
    struct stat st;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' || strlen(e->d_name) >= 256 ||
            fstatat(t->tmpfd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) || !S_ISREG(st.st_mode)) {
            continue;
        }
        if (n == cap) {
            cap = cap ? 2 * cap : 32;
            void *grown = realloc(*names, sizeof **names * (size_t)cap);
            if (!grown) {
                n = -1;
                break;
            }
            *names = grown;
        }
        strcpy((*names)[n++], e->d_name);
    }
    closedir(d);
    if (n > 0) {
        qsort(*names, (size_t)n, sizeof **names, by_name);
    }
    return n;
}

/* puts back what moves 0..upto did: the earlier files or nothing; the names not restored are
   added to err */
static void undo_moves(zp_tx *t, char (*names)[256], const char *backed, int upto, int moved_upto,
                       char *err, size_t errlen) {
    for (int j = upto; j >= 0; j--) {
        char old[300];
        snprintf(old, sizeof old, ".old.%s", names[j]);
        int ok = backed[j]        ? renameat(t->tmpfd, old, t->dirfd, names[j]) == 0
                 : j < moved_upto ? unlinkat(t->dirfd, names[j], 0) == 0
                                  : 1;
        if (!ok) {
            size_t len = strlen(err);
            snprintf(err + len, errlen - len, "; could not put back %s", names[j]);
        }
    }
}

/* moves every file into place, each old file set aside first; all or none */
static int move_all(zp_tx *t, char (*names)[256], int n, char *err, size_t errlen) {
    char *backed = calloc((size_t)n + 1, 1);
    if (!backed) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int i = 0;
    for (; i < n; i++) {
        char old[300];
        struct stat st;
        snprintf(old, sizeof old, ".old.%s", names[i]);
        int exists = fstatat(t->dirfd, names[i], &st, AT_SYMLINK_NOFOLLOW) == 0;
        if (exists && S_ISDIR(st.st_mode)) {
            snprintf(err, errlen, "cannot replace %s/%s: it is a folder", t->dir, names[i]);
            break;
        }
        if (exists && linkat(t->dirfd, names[i], t->tmpfd, old, 0) &&
            renameat(t->dirfd, names[i], t->tmpfd, old)) {
            snprintf(err, errlen, "cannot set %s/%s aside: %s", t->dir, names[i], strerror(errno));
            break;
        }
        backed[i] = (char)exists;
        if (renameat(t->tmpfd, names[i], t->dirfd, names[i])) {
            snprintf(err, errlen, "cannot move %s into %s: %s", names[i], t->dir, strerror(errno));
            break;
        }
    }
    if (i < n) {
        undo_moves(t, names, backed, i < n ? i : n - 1, i, err, errlen);
    }
    free(backed);
    return i < n ? -1 : 0;
}

zp_status zp_tx_commit(zp_tx *t, char *err, size_t errlen) {
    if (zp_tx_flush(t, err, errlen)) {
        zp_tx_abort(t);
        return ZP_ERR_IO;
    }
    char(*names)[256] = NULL;
    zp_tx_lock();
    int n = list_files(t, &names);
    if (n < 0) {
        snprintf(err, errlen, "cannot read the private folder in %s", t->dir);
        free(names);
        zp_tx_unlock();
        zp_tx_abort(t);
        return ZP_ERR_IO;
    }
    flock(t->dirfd, LOCK_EX);
    int bad = move_all(t, names, n, err, errlen);
    if (!bad) {
        drop_checkpoint(t); /* superseded by the committed files */
    }
    size_t len = 0;
    t->written[0] = '\0';
    for (int i = 0; !bad && i < n && len < sizeof t->written; i++) {
        len += (size_t)snprintf(t->written + len, sizeof t->written - len, "%s%s", i ? ", " : "",
                                names[i]);
    }
    free(names);
    flock(t->dirfd, LOCK_UN);
    cleanup(t, bad);
    active = NULL;
    zp_tx_unlock();
    return bad ? ZP_ERR_IO : ZP_OK;
}

void zp_tx_abort(zp_tx *t) {
    for (int i = 0; i < t->nopen; i++) {
        fclose(t->f[i]);
    }
    t->nopen = 0;
    zp_tx_lock();
    if (t->dirfd >= 0) {
        flock(t->dirfd, LOCK_EX); /* the checkpoint is compared and removed as one step */
    }
    cleanup(t, 1);
    if (active == t) {
        active = NULL;
    }
    zp_tx_unlock();
}
