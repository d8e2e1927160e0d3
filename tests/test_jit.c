/* jit.c's on-disk cache is used through descriptors: while another thread keeps swapping the
   cache folder with a link to someone else's folder, nothing is ever written there and every
   compiled course evaluates to its closed form; a relative XDG_CACHE_HOME is ignored (XDG
   spec); no folder is created in a tree another user owns; several courses loaded at once
   each load their own file. The expectations are the folders' contents and inodes, read
   after the fact, and the closed forms of the expressions. */
#define _GNU_SOURCE /* renameat2's RENAME_EXCHANGE */
#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "check.h"
#include "course.h"

/* courses compiled while the swapper runs: each compile (tens of ms) spans many swaps, so
   a path-based cache writes into the swapped-in folder within the first few */
#define RACE_COURSES 24

/* the visible entries of the folder at dirfd (read through the descriptor) */
static int count_entries(int dirfd) {
    int fd = openat(dirfd, ".", O_RDONLY | O_DIRECTORY);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    int n = 0;
    for (struct dirent *de; d && (de = readdir(d));) {
        n += strcmp(de->d_name, ".") && strcmp(de->d_name, "..");
    }
    if (d) {
        closedir(d);
    }
    return n;
}

static int count_in(const char *path) {
    int fd = open(path, O_RDONLY | O_DIRECTORY);
    int n = fd >= 0 ? count_entries(fd) : -1;
    if (fd >= 0) {
        close(fd);
    }
    return n;
}

/* removes path and everything in it (files and folders, one level of nesting per call) */
static void remove_tree(const char *path) {
    DIR *d = opendir(path);
    for (struct dirent *de; d && (de = readdir(d));) {
        if (!strcmp(de->d_name, ".") || !strcmp(de->d_name, "..")) {
            continue;
        }
        char sub[2048];
        snprintf(sub, sizeof sub, "%s/%s", path, de->d_name);
        struct stat st;
        if (lstat(sub, &st) == 0 && S_ISDIR(st.st_mode)) {
            remove_tree(sub);
        } else {
            unlink(sub);
        }
    }
    if (d) {
        closedir(d);
    }
    rmdir(path);
}

/* one course "sinh(x/7) + k": compiled, and its value at 2.5 checked against the closed form */
static void compile_and_check(int k) {
    char text[64];
    snprintf(text, sizeof text, "sinh(x/7) + %d", k);
    const char *expr[] = {text};
    zp_course_err err;
    zp_course *built = zp_course_create(1, expr, &err);
    zp_course *c = built ? zp_course_for_thread(built, &err) : NULL;
    CHECK(c && zp_course_compiled(c));
    if (c) {
        CHECK(zp_course_eval(c, 0, 2.5).f == sinh(2.5 / 7) + k);
    }
    zp_course_free(c);
    zp_course_free(built);
}

typedef struct swapper {
    int basefd;
    volatile int stop;
    long swaps;
} swapper;

/* exchanges the names "zipopt" (the real cache folder) and "link" (a link to the victim's
   folder) in the cache base, over and over, as one who can rename entries there could */
static void *swap_loop(void *arg) {
    swapper *s = arg;
    while (!s->stop) {
        if (syscall(SYS_renameat2, s->basefd, "zipopt", s->basefd, "link", RENAME_EXCHANGE) == 0) {
            s->swaps++;
        }
    }
    return NULL;
}

static void test_swapped_folder(const char *root) {
    char base[1100], victim[1100], real[1200], link[1200];
    snprintf(base, sizeof base, "%s/base", root);
    snprintf(victim, sizeof victim, "%s/victim", root);
    snprintf(real, sizeof real, "%s/zipopt", base);
    snprintf(link, sizeof link, "%s/link", base);
    CHECK(mkdir(base, 0700) == 0 && mkdir(victim, 0700) == 0 && mkdir(real, 0700) == 0);
    CHECK(symlink(victim, link) == 0);
    setenv("XDG_CACHE_HOME", base, 1);
    swapper s = {.basefd = open(base, O_RDONLY | O_DIRECTORY)};
    pthread_t th;
    CHECK(s.basefd >= 0 && pthread_create(&th, NULL, swap_loop, &s) == 0);
    for (int k = 0; k < RACE_COURSES; k++) {
        compile_and_check(k);
    }
    s.stop = 1;
    pthread_join(th, NULL);
    int vfd = open(victim, O_RDONLY | O_DIRECTORY);
    int written = vfd >= 0 ? count_entries(vfd) : -1;
    if (written != 0) {
        fprintf(stderr, "%d files written through the swapped-in link (%ld swaps)\n", written,
                s.swaps);
    }
    CHECK(s.swaps > 0 && written == 0);
    if (vfd >= 0) {
        close(vfd);
    }
    close(s.basefd);
    remove_tree(base);
    remove_tree(victim);
}

/* the inode of each visible file of the folder path, in name order, into ino (at most max);
   their count */
static int inodes(const char *path, ino_t *ino, int max) {
    struct dirent **list = NULL;
    int n = scandir(path, &list, NULL, alphasort), k = 0;
    for (int i = 0; i < n; i++) {
        if (list[i]->d_name[0] != '.' && k < max) {
            ino[k++] = list[i]->d_ino;
        }
        free(list[i]);
    }
    free(list);
    return k;
}

/* several courses loaded at once each load their own cache file: a second round of the same
   courses, the first round's still loaded, compiles nothing (every file keeps its inode) and
   evaluates the closed forms */
static void test_several_loaded(const char *root) {
    enum { N = 4 };
    char base[1100], dir[1200];
    snprintf(base, sizeof base, "%s/several", root);
    snprintf(dir, sizeof dir, "%s/zipopt", base);
    CHECK(mkdir(base, 0700) == 0);
    setenv("XDG_CACHE_HOME", base, 1);
    zp_course *built[2][N] = {{NULL}}, *c[2][N] = {{NULL}};
    ino_t ino[2][N];
    for (int round = 0; round < 2; round++) {
        for (int k = 0; k < N; k++) {
            char text[64];
            snprintf(text, sizeof text, "cosh(x/11) + %d", 3000 + k);
            const char *expr[] = {text};
            zp_course_err err;
            built[round][k] = zp_course_create(1, expr, &err);
            c[round][k] = built[round][k] ? zp_course_for_thread(built[round][k], &err) : NULL;
            CHECK(c[round][k] && zp_course_compiled(c[round][k]));
            CHECK(c[round][k] &&
                  zp_course_eval(c[round][k], 0, 2.5).f == cosh(2.5 / 11) + 3000 + k);
        }
        CHECK(inodes(dir, ino[round], N) == N);
    }
    CHECK(!memcmp(ino[0], ino[1], sizeof ino[0]));
    for (int round = 0; round < 2; round++) {
        for (int k = 0; k < N; k++) {
            zp_course_free(c[round][k]);
            zp_course_free(built[round][k]);
        }
    }
    remove_tree(base);
}

/* XDG_CACHE_HOME=relative is ignored: $HOME/.cache is used, nothing under the working folder */
static void test_relative_xdg(const char *root) {
    char home[1100], cwd[1100], saved[4096];
    snprintf(home, sizeof home, "%s/home", root);
    snprintf(cwd, sizeof cwd, "%s/cwd", root);
    CHECK(mkdir(home, 0700) == 0 && mkdir(cwd, 0700) == 0);
    CHECK(getcwd(saved, sizeof saved) != NULL && chdir(cwd) == 0);
    setenv("XDG_CACHE_HOME", "rel", 1);
    setenv("HOME", home, 1);
    compile_and_check(1000);
    CHECK(count_in(cwd) == 0);
    char cache[1200];
    snprintf(cache, sizeof cache, "%s/.cache/zipopt", home);
    CHECK(count_in(cache) == 1);
    CHECK(chdir(saved) == 0);
    remove_tree(cwd);
    remove_tree(home);
}

/* a HOME owned by another user (root runs zipopt with someone's HOME): no .cache is made
   there, and a cache folder of theirs is not used; the course still compiles (in memory) */
static void test_other_users_tree(const char *root) {
    if (geteuid() != 0) {
        printf("test_other_users_tree: not root, cannot give a folder away; skipped\n");
        return;
    }
    char home[1100], cache[1200], theirs[1300];
    snprintf(home, sizeof home, "%s/alice", root);
    snprintf(cache, sizeof cache, "%s/.cache", home);
    snprintf(theirs, sizeof theirs, "%s/zipopt", cache);
    CHECK(mkdir(home, 0755) == 0 && chown(home, 65534, 65534) == 0);
    setenv("HOME", home, 1);
    unsetenv("XDG_CACHE_HOME");
    compile_and_check(2000);
    CHECK(count_in(home) == 0);
    /* their own cache folder, private to them: not ours to load from or write to */
    CHECK(mkdir(cache, 0700) == 0 && mkdir(theirs, 0700) == 0);
    CHECK(chown(cache, 65534, 65534) == 0 && chown(theirs, 65534, 65534) == 0);
    compile_and_check(2001);
    CHECK(count_in(theirs) == 0);
    remove_tree(cache);
    remove_tree(home);
}

int main(void) {
    char root[] = "/tmp/zp_test_jit_XXXXXX";
    CHECK(mkdtemp(root) != NULL);
    test_swapped_folder(root);
    test_several_loaded(root);
    test_relative_xdg(root);
    test_other_users_tree(root);
    remove_tree(root);
    return CHECK_DONE();
}
