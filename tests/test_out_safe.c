/* The output folder as a hostile or unlucky user meets it (docs/commands.md "Files"): links planted
   where zipopt writes are neither followed nor removed through, a scene file's name never
   climbs out of out/, a full disk or a failed rename leaves nothing of the run, two runs into
   one folder each commit whole, a signal leaves no temporary folder, each command keeps its
   own default folder and a rerun never deletes a file it did not write. The expectations are
   the files on disk, compared with what was there before. */
#include <dirent.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "check.h"
#include "testutil.h"

static char tmp[512];
static char out[65536];

#define SEED ZP_SOURCE_DIR "/config/seed.ini"

/* a shell command built like printf, run in tmp; its stdout and stderr in out; exit status */
static int sh(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int sh(const char *fmt, ...) {
    char cmd[4096];
    int n = snprintf(cmd, sizeof cmd, "cd '%s' && ( ", tmp);
    va_list ap;
    va_start(ap, fmt);
    n += vsnprintf(cmd + n, sizeof cmd - (size_t)n, fmt, ap);
    va_end(ap);
    snprintf(cmd + n, sizeof cmd - (size_t)n, " ) 2>&1");
    return tu_sh(cmd, out, sizeof out);
}

/* tmp/rel as a path */
static const char *at(const char *rel) {
    static char path[4][1024];
    static int k;
    k = (k + 1) % 4;
    snprintf(path[k], sizeof path[k], "%s/%s", tmp, rel);
    return path[k];
}

/* the whole file, or "" (static buffer per slot) */
static const char *slurp(const char *path, int slot) {
    static char buf[2][262144];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(buf[slot], 1, sizeof buf[slot] - 1, f) : 0;
    buf[slot][n] = '\0';
    if (f) {
        fclose(f);
    }
    return buf[slot];
}

static void put(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static int is_regular(const char *path) {
    struct stat st;
    return lstat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* entries of a folder: all of them, and those whose name starts with a dot; -1 if absent */
static int count(const char *dir, int *hidden) {
    DIR *d = opendir(dir);
    if (!d) {
        return -1;
    }
    int n = 0, h = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            n++;
            h += e->d_name[0] == '.';
        }
    }
    closedir(d);
    if (hidden) {
        *hidden = h;
    }
    return n;
}

/* zipopt with these arguments in a child whose id is known before it starts: plant() runs
   first with that id; returns the child */
static pid_t spawn(char *const argv[], void (*plant)(pid_t, void *), void *user) {
    int p[2];
    if (pipe(p)) {
        return -1;
    }
    pid_t pid = fork();
    if (pid == 0) {
        char c;
        close(p[1]);
        if (read(p[0], &c, 1) != 1) {
            _exit(126);
        }
        if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) {
            _exit(126);
        }
        execv(ZP_EXE, argv);
        _exit(127);
    }
    close(p[0]);
    if (plant) {
        plant(pid, user);
    }
    if (write(p[1], "g", 1) != 1) {
        perror("write");
    }
    close(p[1]);
    return pid;
}

static int wait_exit(pid_t pid) {
    int st;
    waitpid(pid, &st, 0);
    return WIFEXITED(st) ? WEXITSTATUS(st) : WIFSIGNALED(st) ? 128 + WTERMSIG(st) : -1;
}

/* the names an older zipopt made from its process id, as links to the precious things */
static void plant_pid_links(pid_t pid, void *user) {
    const char *dir = user;
    char link[1200];
    snprintf(link, sizeof link, "%s/.plots.%ld.tmp", dir, (long)pid);
    CHECK(symlink(at("precious"), link) == 0);
    const char *names[] = {"summary.json", "trajectory.csv"};
    for (int i = 0; i < 2; i++) {
        snprintf(link, sizeof link, "%s/.%s.%ld.tmp", dir, names[i], (long)pid);
        CHECK(symlink(at("precious.txt"), link) == 0);
    }
}

static void test_links(void) {
    CHECK(sh("mkdir -p precious d1 d2 w/out/seed && echo PRECIOUS > precious/keep.txt && "
             "echo PRECIOUS > precious.txt && ln -s '%s/precious' w/out/seed/simulate && "
             "ln -s '%s/precious.txt' d2/summary.json",
             tmp, tmp) == 0);
    /* links at every name the run could predict */
    char *argv[] = {ZP_EXE,  "simulate",       SEED, "--force", "20,20,20", "--plot",
                    "--out", (char *)at("d1"), NULL};
    CHECK(wait_exit(spawn(argv, plant_pid_links, (void *)at("d1"))) == 0);
    CHECK(!strcmp(slurp(at("precious/keep.txt"), 0), "PRECIOUS\n")); /* the tree not emptied */
    CHECK(!strcmp(slurp(at("precious.txt"), 0), "PRECIOUS\n"));      /* the target not written */
    CHECK(is_regular(at("d1/summary.json")) && is_regular(at("d1/trajectory.csv")));
    CHECK(is_regular(at("d1/course.png")));
    /* a link in place of the command's own folder: refused, nothing written through it */
    CHECK(sh("cd w && '%s' simulate '%s'", ZP_EXE, SEED) == 1);
    CHECK(strstr(out, "nothing was written") != NULL);
    CHECK(count(at("precious"), NULL) == 1);
    /* a link at a final name is replaced, its target untouched */
    CHECK(sh("'%s' simulate '%s' --out d2", ZP_EXE, SEED) == 0);
    CHECK(is_regular(at("d2/summary.json")));
    CHECK(!strcmp(slurp(at("precious.txt"), 0), "PRECIOUS\n"));
    /* a scene file's name that is no plain folder name: exit 2, nothing written anywhere */
    CHECK(sh("mkdir -p s && grep -v '^name' tiny.ini > s/...ini && cp s/...ini s/..ini && "
             "cd s && '%s' simulate ...ini",
             ZP_EXE) == 2);
    CHECK(strstr(out, "no plain folder name") != NULL);
    CHECK(sh("cd s && '%s' simulate ..ini", ZP_EXE) == 2);
    CHECK(count(at("s"), NULL) == 2);
}

/* nothing of a failed run: the folder as it was (absent: before == -1) */
static void check_untouched(const char *dir, int before) {
    int hidden = 0;
    CHECK(count(dir, &hidden) == before);
    CHECK(hidden == 0);
}

static void test_full_disk(void) {
    /* the first, second, ... file written fails as on a full disk */
    for (int n = 1; n <= 4; n++) {
        CHECK(sh("ZIPOPT_TEST_FULL=%d '%s' simulate tiny.ini --plot --out full", n, ZP_EXE) == 1);
        CHECK(strstr(out, "No space left") && strstr(out, "nothing was written"));
        check_untouched(at("full"), -1);
    }
    /* over an earlier run: that run's files stay as they were, a user's file too */
    CHECK(sh("'%s' simulate tiny.ini --out full2 && echo mine > full2/notes.txt", ZP_EXE) == 0);
    char before[8192];
    snprintf(before, sizeof before, "%s", slurp(at("full2/summary.json"), 0));
    CHECK(sh("ZIPOPT_TEST_FULL=3 '%s' simulate tiny.ini --force 20 --plot --out full2", ZP_EXE) ==
          1);
    CHECK(!strcmp(slurp(at("full2/summary.json"), 0), before));
    check_untouched(at("full2"), 3);
    /* the search: neither figures nor the checkpoint remain */
    CHECK(sh("ZIPOPT_TEST_FULL=1 '%s' tiny.ini --max-evals 40 --out full3", ZP_EXE) == 1);
    check_untouched(at("full3"), -1);
    /* a real full disk, where a small tmpfs can be mounted (root) */
    if (geteuid() == 0 && mkdir(at("mnt"), 0777) == 0 &&
        mount("tmpfs", at("mnt"), "tmpfs", 0, "size=160k") == 0) {
        CHECK(sh("'%s' simulate '%s' --plot --out mnt/x", ZP_EXE, SEED) == 1);
        CHECK(strstr(out, "nothing was written") != NULL);
        check_untouched(at("mnt"), 0);
        umount(at("mnt"));
    } else {
        fprintf(stderr, "note: no tmpfs could be mounted; the injected failures stand alone\n");
    }
}

/* 1 when path is a whole image, judged here from the formats' own ends: a PNG's IEND
   chunk, a GIF's trailer byte, an SVG's closing tag */
static int image_whole(const char *path) {
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    FILE *f = fopen(path, "rb");
    unsigned char tail[12] = {0};
    long size = f && fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    int ok = size >= 12 && fseek(f, -12, SEEK_END) == 0 && fread(tail, 1, 12, f) == 12;
    if (f) {
        fclose(f);
    }
    const char *ext = strrchr(path, '.');
    if (!ok || !ext) {
        return 0;
    }
    if (!strcmp(ext, ".png")) {
        return !memcmp(tail, iend, 12);
    }
    if (!strcmp(ext, ".gif")) {
        return tail[11] == 0x3b;
    }
    int n = 12;
    while (n > 0 && strchr(" \t\r\n", tail[n - 1])) {
        n--;
    }
    return n >= 6 && !memcmp(tail + n - 6, "</svg>", 6);
}

/* one run of cmd into dir (empty before) on a disk that may fill: either it fails, saying
   nothing was written, and leaves dir empty, or it succeeds with every image whole; 1 when
   it failed while drawing */
static int whole_or_nothing(const char *dir, const char *cmd) {
    int rc = sh("%s", cmd);
    if (rc != 0) {
        CHECK(rc == 1 && strstr(out, "nothing was written") != NULL);
        check_untouched(dir, 0);
        return strstr(out, "not written whole") != NULL;
    }
    DIR *d = opendir(dir);
    int images = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        const char *ext = strrchr(e->d_name, '.');
        if (ext && (!strcmp(ext, ".png") || !strcmp(ext, ".gif") || !strcmp(ext, ".svg"))) {
            char path[2048];
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            images++;
            if (!image_whole(path)) {
                fprintf(stderr, "%s: exit 0 with %s cut short\n", cmd, path);
                CHECK(0);
            }
        }
    }
    if (d) {
        closedir(d);
    }
    CHECK(images > 0);
    return 0;
}

/* the disk fills while gnuplot draws (it then ends with 0 and a cut image): a tmpfs of sizes
   from what the data files need to what the whole set needs (root only), and file size
   limits below an image's size (anyone; gnuplot's writes then fail as on a full disk,
   SIGXFSZ ignored) */
static void test_full_while_drawing(void) {
    int drawn_fail = 0;
    char cmd[2048];
    if (geteuid() == 0 && mkdir(at("mnt2"), 0777) == 0) {
        for (int kib = 56; kib <= 216; kib += 80) {
            char opts[32];
            snprintf(opts, sizeof opts, "size=%dk", kib);
            if (mount("tmpfs", at("mnt2"), "tmpfs", 0, opts)) {
                fprintf(stderr, "note: no tmpfs could be mounted; the size limits stand alone\n");
                break;
            }
            snprintf(cmd, sizeof cmd, "'%s' simulate tiny.ini --plot --out mnt2/x", ZP_EXE);
            CHECK(mkdir(at("mnt2/x"), 0777) == 0);
            drawn_fail += whole_or_nothing(at("mnt2/x"), cmd);
            umount(at("mnt2"));
        }
    }
    /* 40 KiB: every data file fits, course.png (about 45 KiB) does not */
    CHECK(mkdir(at("fsize1"), 0777) == 0 && mkdir(at("fsize2"), 0777) == 0 &&
          mkdir(at("fsize3"), 0777) == 0);
    snprintf(cmd, sizeof cmd,
             "trap '' XFSZ; ulimit -f 40; '%s' simulate tiny.ini --plot --out fsize1", ZP_EXE);
    drawn_fail += whole_or_nothing(at("fsize1"), cmd);
    /* 200 KiB: the figures fit, run.gif (about 270 KiB) does not */
    snprintf(cmd, sizeof cmd,
             "trap '' XFSZ; ulimit -f 200; '%s' simulate tiny.ini --animate --out fsize2", ZP_EXE);
    drawn_fail += whole_or_nothing(at("fsize2"), cmd);
    /* a command drawing through zp_cli_out_draw_commit: landscape.png is about 35 KiB */
    snprintf(
        cmd, sizeof cmd,
        "trap '' XFSZ; ulimit -f 16; '%s' landscape tiny.ini --force-range 0:40:5 --out fsize3",
        ZP_EXE);
    drawn_fail += whole_or_nothing(at("fsize3"), cmd);
    CHECK(drawn_fail >= 3);
}

static void test_failed_rename(void) {
    CHECK(sh("mkdir -p r1/summary.json/x && '%s' simulate '%s' --out r1", ZP_EXE, SEED) == 1);
    CHECK(strstr(out, "nothing was written") != NULL);
    check_untouched(at("r1"), 1);
    /* a later file fails: the earlier ones are put back as they were */
    CHECK(sh("'%s' simulate '%s' --force 10,10,10 --out r2", ZP_EXE, SEED) == 0);
    char before[8192];
    snprintf(before, sizeof before, "%s", slurp(at("r2/summary.json"), 0));
    CHECK(sh("rm r2/trajectory.csv && mkdir -p r2/trajectory.csv/x && "
             "'%s' simulate '%s' --force 20,20,20 --out r2",
             ZP_EXE, SEED) == 1);
    CHECK(!strcmp(slurp(at("r2/summary.json"), 0), before));
    check_untouched(at("r2"), 2);
}

/* "time": of a summary.json */
static double json_time(const char *text) {
    const char *p = strstr(text, "\"time\": ");
    return p ? atof(p + 8) : -1;
}

static void test_concurrent(void) {
    const char *force[2] = {"5", "60"};
    static char traj[2][65536];
    double t[2];
    for (int k = 0; k < 2; k++) {
        CHECK(sh("'%s' simulate tiny.ini --force %s --out ref%d", ZP_EXE, force[k], k) == 0);
        snprintf(traj[k], sizeof traj[k], "%s",
                 slurp(at(k ? "ref1/trajectory.csv" : "ref0/trajectory.csv"), 0));
        t[k] = json_time(slurp(at(k ? "ref1/summary.json" : "ref0/summary.json"), 0));
    }
    CHECK(t[0] != t[1] && strcmp(traj[0], traj[1]));
    int mixed = 0, whole = 0;
    for (int i = 0; i < 200; i++) {
        pid_t pid[2];
        for (int k = 0; k < 2; k++) {
            char *argv[] = {ZP_EXE,           "simulate", (char *)at("tiny.ini"), "--force",
                            (char *)force[k], "--out",    (char *)at("conc"),     NULL};
            pid[k] = spawn(argv, NULL, NULL);
        }
        int ok = wait_exit(pid[0]) == 0;
        ok &= wait_exit(pid[1]) == 0;
        const char *csv = slurp(at("conc/trajectory.csv"), 1);
        double tj = json_time(slurp(at("conc/summary.json"), 0));
        int k = !strcmp(csv, traj[0]) ? 0 : !strcmp(csv, traj[1]) ? 1 : -1;
        whole += ok && k >= 0 && tj == t[k];
        mixed += k >= 0 && tj != t[k];
    }
    CHECK(whole == 200);
    CHECK(mixed == 0);
    check_untouched(at("conc"), 2);
}

/* waits (up to 10 s) until path exists */
static int await(const char *path) {
    for (int i = 0; i < 1000; i++) {
        if (tu_exists(path)) {
            return 1;
        }
        usleep(10000);
    }
    return 0;
}

/* waits (up to 10 s) until gnuplot draws in dir's private folder */
static int await_gnuplot(const char *dir) {
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "ls -A '%s'/.zipopt-*/ 2>/dev/null | grep -q '^\\.log\\.'", dir);
    for (int i = 0; i < 1000; i++) {
        if (system(cmd) == 0) {
            return 1;
        }
        usleep(10000);
    }
    return 0;
}

static void test_signals(void) {
    /* SIGTERM during the search: its checkpoint and folder go too */
    char *search[] = {ZP_EXE, SEED, "--max-evals", "1000000", "--out", (char *)at("sig1"), NULL};
    pid_t pid = spawn(search, NULL, NULL);
    CHECK(await(at("sig1/checkpoint.ini")));
    kill(pid, SIGTERM);
    CHECK(wait_exit(pid) == 128 + SIGTERM);
    check_untouched(at("sig1"), -1);
    /* two Ctrl-C: the first stops the search, the second the run */
    search[5] = (char *)at("sig2");
    pid = spawn(search, NULL, NULL);
    CHECK(await(at("sig2/checkpoint.ini")));
    kill(pid, SIGINT);
    usleep(50000); /* apart, as two key presses are: one signal pending is one signal */
    kill(pid, SIGINT);
    CHECK(wait_exit(pid) == 128 + SIGINT);
    check_untouched(at("sig2"), -1);
    /* SIGTERM while gnuplot draws */
    char *anim[] = {ZP_EXE, "simulate", SEED, "--animate", "--out", (char *)at("sig3"), NULL};
    pid = spawn(anim, NULL, NULL);
    CHECK(await_gnuplot(at("sig3")));
    kill(pid, SIGTERM);
    CHECK(wait_exit(pid) == 128 + SIGTERM);
    check_untouched(at("sig3"), -1);
}

/* each command its own default folder; a rerun removes nothing it did not write */
static void test_folders(void) {
    CHECK(
        sh("mkdir -p f && cd f && '%s' ../tiny.ini --max-evals 40 >/dev/null && "
           "'%s' simulate ../tiny.ini --plot >/dev/null && echo mine > out/tiny/simulate/notes.txt",
           ZP_EXE, ZP_EXE) == 0);
    CHECK(is_regular(at("f/out/tiny/search/report.md")));
    CHECK(is_regular(at("f/out/tiny/search/course.png"))); /* the figures the report links */
    CHECK(is_regular(at("f/out/tiny/simulate/course.png")));
    char search_json[8192];
    snprintf(search_json, sizeof search_json, "%s", slurp(at("f/out/tiny/search/summary.json"), 0));
    CHECK(strstr(search_json, "\"found\"") != NULL); /* the search's, not the simulation's */
    CHECK(sh("cd f && '%s' simulate ../tiny.ini --force 20", ZP_EXE) == 0);
    CHECK(!strcmp(slurp(at("f/out/tiny/search/summary.json"), 0), search_json));
    CHECK(is_regular(at("f/out/tiny/simulate/notes.txt")));
    CHECK(is_regular(at("f/out/tiny/simulate/course.png"))); /* an earlier run's, kept */
    CHECK(strstr(out, "wrote in out/tiny/simulate: summary.json, trajectory.csv") != NULL);
}

int main(void) {
    snprintf(tmp, sizeof tmp, "%s/zp_out_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(tmp)) {
        perror("mkdtemp");
        return 1;
    }
    /* a small scene: quick runs and searches */
    put(at("tiny.ini"), "[scene]\nname = tiny\n[course]\nx_start = 0\nsection = 6 : 6 - x/2\n"
                        "[trolley]\nmass = 20\n[body]\nlengths = 0.5\nmasses = 2\n"
                        "[drive]\nforces = 10\n[solver]\noutput_dt = 0.05\n");
    void (*tests[])(void) = {test_links,         test_full_disk,  test_full_while_drawing,
                             test_failed_rename, test_concurrent, test_signals,
                             test_folders};
    for (size_t i = 0; i < sizeof tests / sizeof tests[0]; i++) {
        time_t t0 = time(NULL);
        tests[i]();
        fprintf(stderr, "part %zu: %.0f s\n", i + 1, difftime(time(NULL), t0));
    }
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    if (system(cmd)) {
        fprintf(stderr, "could not remove %s\n", tmp);
    }
    return CHECK_DONE();
}
