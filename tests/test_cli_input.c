/* The zipopt binary on bad input (CLI.md, CONFIG.md): every command exits 2, names the file,
   the line and the key on stderr, and leaves the output folder untouched; `zipopt check`
   accepts every scene in config/ and reports the seed course's kinks where MODEL.md puts them. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"

static char tmp[512];   /* this run's scratch folder */
static char out[65536]; /* stdout of the last run */
static char err[65536]; /* stderr of the last run */

static void slurp(const char *path, char *buf, size_t cap) {
    buf[0] = '\0';
    FILE *f = fopen(path, "r");
    if (f) {
        size_t n = fread(buf, 1, cap - 1, f);
        buf[n] = '\0';
        fclose(f);
    }
}

/* runs `zipopt ARGS`, keeping stdout and stderr; returns the exit status (-1 if abnormal) */
static int run(const char *args) {
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' %s >'%s/stdout' 2>'%s/stderr'", ZP_EXE, args, tmp, tmp);
    int st = system(cmd);
    char path[1024];
    snprintf(path, sizeof path, "%s/stdout", tmp);
    slurp(path, out, sizeof out);
    snprintf(path, sizeof path, "%s/stderr", tmp);
    slurp(path, err, sizeof err);
    return st != -1 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void write_file(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* a folder that does not exist, or exists and is empty */
static int untouched(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) {
        return 1;
    }
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    }
    closedir(d);
    return n == 0;
}

static const char *valid = "[course]\n"           /* 1 */
                           "x_start = 0\n"        /* 2 */
                           "section = 10 : x/5\n" /* 3 */
                           "[trolley]\n"          /* 4 */
                           "mass = 10\n"          /* 5 */
                           "[body]\n"             /* 6 */
                           "lengths = 1\n"        /* 7 */
                           "masses = 2\n";        /* 8 */

/* each case: the valid scene with one line replaced, and where the message must point */
static const struct {
    int line;
    const char *repl, *want; /* want: "[section] key" text after FILE:LINE: */
} cases[] = {
    {5, "mass = -10", "[trolley] mass:"},
    {7, "lenghts = 1", "[body] lenghts: unknown key; did you mean `lengths`?"},
    {8, "masses = 2, 3", "[body] masses:"},
    {3, "section = 10 : x/5 + y", "[course] section:"},
    {3, "section = 10 : x/5\nsection = 20 : x + 1", "[course] section:"}, /* discontinuous */
};

static void scene_with(int line, const char *repl, char *text, size_t cap) {
    text[0] = '\0';
    const char *p = valid;
    for (int i = 1; *p; i++) {
        size_t len = strcspn(p, "\n") + 1;
        if (i == line) {
            snprintf(text + strlen(text), cap - strlen(text), "%s\n", repl);
        } else {
            snprintf(text + strlen(text), cap - strlen(text), "%.*s", (int)len, p);
        }
        p += len;
    }
}

static void test_bad_scenes(void) {
    static const char *const commands[] = {"check %s", "simulate %s --out '%s'", "%s --out '%s'"};
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char text[2048], scene[1024], want[1200];
        scene_with(cases[i].line, cases[i].repl, text, sizeof text);
        snprintf(scene, sizeof scene, "%s/bad%zu.ini", tmp, i);
        write_file(scene, text);
        snprintf(want, sizeof want, "%s:%d: %s", scene, cases[i].line + (i == 4), cases[i].want);
        for (size_t k = 0; k < sizeof commands / sizeof *commands; k++) {
            /* one output folder never made, one made empty: both must stay as they were */
            char fresh[1024], empty[1024], args[4096];
            snprintf(fresh, sizeof fresh, "%s/out_fresh", tmp);
            snprintf(empty, sizeof empty, "%s/out_empty", tmp);
            mkdir(empty, 0755);
            for (int e = 0; e < 2; e++) {
                snprintf(args, sizeof args, commands[k], scene, e ? empty : fresh);
                int st = run(args);
                int named = strstr(err, want) != NULL;
                CHECK(st == 2);
                CHECK(named);
                CHECK(untouched(fresh) && untouched(empty));
                CHECK(access(fresh, F_OK) != 0);
                if (st != 2 || !named) {
                    fprintf(stderr, "  zipopt %s: status %d, wanted `%s` in stderr:\n%s", args, st,
                            want, err);
                }
            }
        }
    }
    /* a file that cannot be read */
    char args[4096];
    snprintf(args, sizeof args, "check '%s/missing.ini'", tmp);
    CHECK(run(args) == 2);
    CHECK(strstr(err, "missing.ini") != NULL);
    /* a bad command line */
    CHECK(run("check") == 2);
    CHECK(run("check --bogus") == 2);
    snprintf(args, sizeof args, "check '%s/a.ini' '%s/b.ini'", tmp, tmp);
    CHECK(run(args) == 2);
    CHECK(run("check --help") == 0 && strstr(out, "zipopt check SCENE.ini"));
}

static void test_configs(void) {
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/config", ZP_SOURCE_DIR);
    DIR *d = opendir(dir);
    CHECK(d != NULL);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d))) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".ini")) {
            continue;
        }
        char args[2048];
        snprintf(args, sizeof args, "check '%s/%s'", dir, e->d_name);
        int st = run(args);
        CHECK(st == 0 && strstr(out, "course:") && !err[0]);
        if (st != 0 || err[0]) {
            fprintf(stderr, "  zipopt %s: status %d\n%s", args, st, err);
        }
        n++;
    }
    if (d) {
        closedir(d);
    }
    CHECK(n >= 5); /* seed, flat, straight, smooth, valley */

    /* MODEL.md: the seed course is continuous with kinks at x = 60 (y = 10) and 100 (y = 6) */
    char args[2048];
    snprintf(args, sizeof args, "check '%s/seed.ini'", dir);
    CHECK(run(args) == 0);
    const char *k1 = strstr(out, "x = 60 m, y = 10 m");
    const char *k2 = strstr(out, "x = 100 m, y = 6 m");
    CHECK(k1 && strstr(k1, "kink") && strstr(k1, "kink") < k2);
    CHECK(k2 && strstr(k2, "kink"));
    CHECK(strstr(out, "link 3: length 5 m, mass 2 kg") != NULL);
    /* a uniform rod: I = m l^2 / 12 (MODEL.md), printed to 6 significant digits */
    const char *l1 = strstr(out, "link 1: length 5 m, mass 15 kg, inertia ");
    double inertia = 0;
    CHECK(l1 &&
          sscanf(l1 + strlen("link 1: length 5 m, mass 15 kg, inertia "), "%lf", &inertia) == 1);
    CHECK_NEAR(inertia, 15.0 * 5 * 5 / 12, 1e-5 * 31.25);
}

/* `check` shows slopes as numbers (x/5: f' = 0.2, f'' = 0), every key it added with the value
   taken (CONFIG.md's defaults), and warns on stderr about a force the search could not pick */
static void test_check_shows(void) {
    char text[1024], path[1024], args[2048];
    snprintf(text, sizeof text, "%s[drive]\nforces = 600\n[solver]\natol = 1e-9\n", valid);
    snprintf(path, sizeof path, "%s/shows.ini", tmp);
    write_file(path, text);
    snprintf(args, sizeof args, "check '%s'", path);
    CHECK(run(args) == 0);
    CHECK(strstr(out, "at x = 10: f = 2 m, f' = 0.2, f'' = 0 1/m") != NULL);
    CHECK(strstr(out, "[solver] rtol = 1e-08\n") && strstr(out, "[body] death_angle = 180\n") &&
          strstr(out, "[drive] max = 500\n") && strstr(out, "[optimize] margin = 10\n") &&
          strstr(out, "[limits]: none given"));
    CHECK(!strstr(out, "[solver] atol") && !strstr(out, "[drive] forces =")); /* given */
    CHECK(strstr(err, "shows.ini:10: [drive] forces: warning: item 1 (600) is outside") != NULL);
    if (!strstr(err, "warning")) {
        fprintf(stderr, "  stdout:\n%s  stderr:\n%s", out, err);
    }
    /* the boundary height printed (sqrt(10): many digits), typed back as the next section, is
       within the continuity tolerance */
    const char *rest = strstr(valid, "[trolley]");
    snprintf(text, sizeof text,
             "[course]\nx_start = 1\nsection = 10 : sqrt(x)\nsection = 20 : sqrt(10) + 0*x\n%s", rest);
    write_file(path, text);
    run(args);
    const char *y = strstr(out, "x = 10 m, y = ");
    char typed[64] = "";
    CHECK(y && sscanf(y + strlen("x = 10 m, y = "), "%63[0-9.]", typed) == 1);
    snprintf(text, sizeof text,
             "[course]\nx_start = 1\nsection = 10 : sqrt(x)\nsection = 20 : %s\n%s", typed, rest);
    write_file(path, text);
    CHECK(run(args) == 0 && strlen(typed) > 8);
}

/* one round names every problem: the reader's, the registries' ([solver] and [optimize]
   method) and the command line's, in every command, before anything runs */
static void test_all_at_once(void) {
    char scene[1024], args[4096], fresh[1024];
    snprintf(scene, sizeof scene, "%s/many.ini", tmp);
    snprintf(fresh, sizeof fresh, "%s/out_many", tmp);
    char text[2048];
    snprintf(text, sizeof text,
             "%s[solver]\nmethod = rk45\nformulation = hamilton\n[optimize]\nmethod = euler\n",
             valid);
    write_file(scene, text);
    static const char *const commands[] = {"check '%s'", "simulate '%s' --out '%s'",
                                           "'%s' --out '%s'", "landscape '%s' --out '%s'"};
    static const char *const want[] = {":10: [solver] method: unknown method 'rk45'",
                                       ":11: [solver] formulation: unknown formulation 'hamilton'",
                                       ":13: [optimize] method: unknown method 'euler'"};
    for (size_t k = 0; k < sizeof commands / sizeof *commands; k++) {
        snprintf(args, sizeof args, commands[k], scene, fresh);
        CHECK(run(args) == 2);
        for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
            if (!strstr(err, want[i])) {
                fprintf(stderr, "  zipopt %s: `%s` missing from:\n%s", args, want[i], err);
                CHECK(0);
            }
        }
        CHECK(strstr(err, "3 errors; nothing was written") != NULL);
        CHECK(untouched(fresh));
    }
    /* a reader's problem and a registry name together */
    snprintf(text, sizeof text,
             "[course]\nx_start = 0\nsection = 10 : x/5\n[trolley]\n"
             "mass = -10\n[body]\nlengths = 1\nmasses = 2\n"
             "[solver]\nmethod = rk45\n");
    write_file(scene, text);
    snprintf(args, sizeof args, "simulate '%s' --out '%s'", scene, fresh);
    CHECK(run(args) == 2);
    CHECK(strstr(err, ":5: [trolley] mass:") && strstr(err, ":10: [solver] method:"));
    /* and a bad --force with a bad registry name */
    snprintf(text, sizeof text, "%s[solver]\nmethod = rk45\n", valid);
    write_file(scene, text);
    snprintf(args, sizeof args, "simulate '%s' --force 1,2 --out '%s'", scene, fresh);
    CHECK(run(args) == 2);
    CHECK(strstr(err, "--force: 2 values, expected 1") && strstr(err, "[solver] method:"));
    CHECK(untouched(fresh));
}

int main(void) {
    snprintf(tmp, sizeof tmp, "%s/zp_cli_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(tmp)) {
        perror("mkdtemp");
        return 1;
    }
    test_bad_scenes();
    test_configs();
    test_check_shows();
    test_all_at_once();
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
