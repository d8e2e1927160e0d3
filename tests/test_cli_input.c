/* The zipopt binary on bad input (docs/commands.md, docs/scene-file.md): every command exits 2,
   names the file, the line and the key on stderr, and leaves the output folder untouched; `zipopt
   check` accepts every scene in config/ and reports the seed course's kinks where docs/model.md
   puts them. */
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

/* each case: the valid scene with one line replaced, and where the message must point: line
   `at` (0: the line replaced) */
static const struct {
    int line, at;
    const char *repl, *want; /* want: "[section] key" text after FILE:LINE: */
} cases[] = {
    {5, 0, "mass = -10", "[trolley] mass:"},
    {7, 0, "lenghts = 1", "[body] lenghts: unknown key; did you mean `lengths`?"},
    {8, 0, "masses = 2, 3", "[body] masses:"},
    {3, 0, "section = 10 : x/5 + y", "[course] section:"},
    {3, 4, "section = 10 : x/5\nsection = 20 : x + 1", "[course] section:"}, /* discontinuous */
    {8, 11, "masses = 2\n[brake]\nstart = 5\nend = 5\neddy = 10", "[brake] end:"}, /* empty zone */
    {8, 11, "masses = 2\n[brake]\nstart = 5\neddy = -10", "[brake] eddy:"},
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
        snprintf(want, sizeof want, "%s:%d: %s", scene, cases[i].at ? cases[i].at : cases[i].line,
                 cases[i].want);
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

    /* docs/model.md: the seed course is continuous with kinks at x = 60 (y = 10) and 100 (y = 6) */
    char args[2048];
    snprintf(args, sizeof args, "check '%s/seed.ini'", dir);
    CHECK(run(args) == 0);
    const char *k1 = strstr(out, "x = 60 m, y = 10 m");
    const char *k2 = strstr(out, "x = 100 m, y = 6 m");
    CHECK(k1 && strstr(k1, "kink") && strstr(k1, "kink") < k2);
    CHECK(k2 && strstr(k2, "kink"));
    CHECK(strstr(out, "link 3: length 5 m, mass 2 kg") != NULL);
    /* a uniform rod: I = m l^2 / 12 (docs/model.md), printed to 6 significant digits */
    const char *l1 = strstr(out, "link 1: length 5 m, mass 15 kg, inertia ");
    double inertia = 0;
    CHECK(l1 &&
          sscanf(l1 + strlen("link 1: length 5 m, mass 15 kg, inertia "), "%lf", &inertia) == 1);
    CHECK_NEAR(inertia, 15.0 * 5 * 5 / 12, 1e-5 * 31.25);
}

/* the lines of the last stderr */
static int err_lines(void) {
    int n = 0;
    for (const char *p = err; *p; p++) {
        n += *p == '\n';
    }
    return n;
}

/* a message for the run of args: its status, stderr, and what it was expected to say */
static void expect(const char *args, int status, const char *want) {
    int st = run(args);
    int said = !want || strstr(err, want) != NULL;
    CHECK(st == status);
    CHECK(said);
    if (st != status || !said) {
        fprintf(stderr, "  zipopt %s: status %d (wanted %d), wanted `%s` in stderr:\n%s", args, st,
                status, want ? want : "", err);
    }
}

/* getopt_long's forms (docs/commands.md): --name=value, `--`, and one message per mistake */
static void test_options(const char *scene) {
    char args[4096], dir[1024], path[1100];
    snprintf(dir, sizeof dir, "%s/eq", tmp);
    snprintf(args, sizeof args, "simulate '%s' --out='%s' --force=5", scene, dir);
    expect(args, 0, NULL);
    snprintf(path, sizeof path, "%s/summary.json", dir);
    CHECK(access(path, F_OK) == 0);

    /* `--` ends the options: a scene file whose name starts with a dash */
    char cwd[1024];
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    CHECK(chdir(tmp) == 0);
    write_file("-dash.ini", valid);
    expect("check -- -dash.ini", 0, NULL);
    CHECK(chdir(cwd) == 0);

    snprintf(args, sizeof args, "simulate '%s' --out", scene);
    expect(args, 2, "option '--out' requires an argument");
    CHECK(err_lines() == 1);
    snprintf(args, sizeof args, "--max-evals -5 '%s'", scene);
    expect(args, 2, "--max-evals");
    CHECK(err_lines() == 1);
    snprintf(args, sizeof args, "simulate '%s' --forse 5", scene);
    expect(args, 2, "unknown option '--forse'; did you mean '--force'?");
    CHECK(err_lines() == 1);
    snprintf(args, sizeof args, "check '%s' --json=yes", scene);
    expect(args, 2, "option '--json' takes no value");
    snprintf(args, sizeof args, "--algorithm scan-cobila '%s'", scene);
    expect(args, 2, "did you mean 'scan-cobyla'?");
    snprintf(args, sizeof args, "simulat '%s'", scene);
    expect(args, 2, "unknown command 'simulat'; did you mean 'simulate'?");
    CHECK(err_lines() == 1);
}

/* numbers beyond their type, control bytes, long paths and huge animations: refused with a
   message that says so, nothing written */
static void test_limits(const char *scene) {
    char args[8192], dir[4096];
    snprintf(dir, sizeof dir, "%s/lim", tmp);
    snprintf(args, sizeof args,
             "--seed 99999999999999999999999 --max-evals 1 --no-plot --out "
             "'%s' '%s'",
             dir, scene);
    expect(args, 2, "--seed: '99999999999999999999999' is out of range");
    CHECK(untouched(dir));
    snprintf(args, sizeof args, "simulate '%s' --force 1e400 --out '%s'", scene, dir);
    expect(args, 2, "`1e400` is out of range");
    CHECK(strstr(err, "not a number") == NULL);

    /* a control byte in user text is shown escaped, never sent raw */
    snprintf(args, sizeof args, "check '%s/bad\001name.ini'", tmp);
    expect(args, 2, "bad\\x01name.ini");
    CHECK(strchr(err, '\001') == NULL);
    snprintf(args, sizeof args, "simulate '%s' --force '5\002'", scene);
    expect(args, 2, "5\\x02");
    CHECK(strchr(err, '\002') == NULL);

    /* a 1010-character output folder: refused, not truncated into another folder */
    size_t len = strlen(dir);
    while (len < 1010) {
        len +=
            (size_t)snprintf(dir + len, sizeof dir - len, "/%s", "dddddddddddddddddddddddddddddd");
    }
    snprintf(args, sizeof args, "simulate '%s' --out '%s'", scene, dir);
    expect(args, 2, "at most 900");
    char lim[1100];
    snprintf(lim, sizeof lim, "%s/lim", tmp);
    CHECK(untouched(lim));

    /* frames of run.gif: capped before anything is written */
    snprintf(args, sizeof args, "simulate '%s' --force 50 --animate --speedup 1e-9 --out '%s'",
             scene, lim);
    expect(args, 2, "at most 20000");
    snprintf(args, sizeof args,
             "simulate '%s' --force 50 --animate --speedup 0.001 --fps 100 --out '%s'", scene, lim);
    expect(args, 2, "at most 20000");
    CHECK(untouched(lim));
}

/* --json on check and landscape: one JSON object on stdout (parsed by Python's json) */
static void test_json(void) {
    char args[2048], json[1100], cmd[4096];
    snprintf(json, sizeof json, "%s/out.json", tmp);
    snprintf(args, sizeof args, "check '%s/config/seed.ini' --json", ZP_SOURCE_DIR);
    expect(args, 0, NULL);
    write_file(json, out);
    /* docs/model.md: the seed course's kinks at x = 60 (y = 10) and 100 (y = 6) */
    snprintf(cmd, sizeof cmd,
             "python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); "
             "b=d[\"boundaries\"]; assert [(x[\"x\"], x[\"y\"], x[\"kink\"]) for x in b] == "
             "[(60, 10, True), (100, 6, True)], b; assert len(d[\"sections\"]) == 3' '%s'",
             json);
    CHECK(system(cmd) == 0);
    snprintf(args, sizeof args,
             "landscape '%s/config/seed.ini' --force-range 0:100:11 --json --out '%s/land'",
             ZP_SOURCE_DIR, tmp);
    expect(args, 0, NULL);
    write_file(json, out);
    /* the windows are runs of consecutive finished rows of landscape.csv */
    snprintf(cmd, sizeof cmd,
             "python3 -c 'import json,sys,csv; d=json.load(open(sys.argv[1])); "
             "rows=list(csv.DictReader(open(sys.argv[2]))); w=[]; prev=False\n"
             "for r in rows:\n"
             "  fin = r[\"outcome\"] == \"finished\"; f = float(r[\"force\"])\n"
             "  if fin and not prev: w.append([f, f])\n"
             "  if fin: w[-1][1] = f\n"
             "  prev = fin\n"
             "assert d[\"windows\"] == w, (d[\"windows\"], w); assert d[\"points\"] == 11' "
             "'%s' '%s/land/landscape.csv'",
             json, tmp);
    CHECK(system(cmd) == 0);
}

/* `check` shows slopes as numbers (x/5: f' = 0.2, f'' = 0), every key it added with the value
   taken (docs/scene-file.md's defaults), and warns on stderr about a force the search could not
   pick */
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
             "[course]\nx_start = 1\nsection = 10 : sqrt(x)\nsection = 20 : sqrt(10) + 0*x\n%s",
             rest);
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

/* sweep's and tradeoff's arguments and folders shown with control bytes escaped (\x1b, as
   zp_diag_put_escaped does), never raw; an empty --out or scene path refused (not the
   current folder); forces beyond what gnuplot can draw refused before any run (exit 2, not
   a gnuplot failure after the work) */
static void test_hostile_arguments(const char *scene) {
    char args[4096];
    snprintf(args, sizeof args, "sweep '%s' --vary 'trolley.mass=1:2:2\033[31m' --out '%s/h'",
             scene, tmp);
    expect(args, 2, "\\x1b[31m");
    CHECK(!strchr(err, '\033'));
    snprintf(args, sizeof args, "sweep '%s' --vary trolley.mass=1:2:2 --run 'x\033y' --out '%s/h'",
             scene, tmp);
    expect(args, 2, "'x\\x1by'");
    CHECK(!strchr(err, '\033'));
    snprintf(args, sizeof args, "tradeoff '%s' --levels '1,\0332' --out '%s/h'", scene, tmp);
    expect(args, 2, "\\x1b2");
    CHECK(!strchr(err, '\033'));
    /* a folder named with a control byte: written, and named escaped */
    snprintf(args, sizeof args,
             "sweep '%s' --vary trolley.mass=20:30:2 --run simulate --out '%s/h\033'", scene, tmp);
    expect(args, 0, NULL);
    CHECK(strstr(out, "h\\x1b/sweep.csv") && !strchr(out, '\033'));

    /* --out '' and an empty scene path */
    char dir[1100];
    snprintf(dir, sizeof dir, "%s/empty", tmp);
    CHECK(mkdir(dir, 0777) == 0);
    snprintf(args, sizeof args, "simulate '%s' --out ''", scene);
    char cmd[8400];
    snprintf(cmd, sizeof cmd, "cd '%s' && '%s' %s >/dev/null 2>&1", dir, ZP_EXE, args);
    int st = system(cmd);
    CHECK(WIFEXITED(st) && WEXITSTATUS(st) == 2);
    snprintf(cmd, sizeof cmd, "%s/summary.json", dir);
    CHECK(access(cmd, F_OK) != 0);
    expect("simulate ''", 2, "empty path");

    /* forces gnuplot cannot draw */
    snprintf(args, sizeof args, "landscape '%s' --force-range 0:1e308:3 --out '%s/h2'", scene, tmp);
    expect(args, 2, "--force-range");
    snprintf(args, sizeof args, "landscape '%s' --force-range -1e308:1e308:3 --out '%s/h2'", scene,
             tmp);
    expect(args, 2, "--force-range");
    snprintf(dir, sizeof dir, "%s/h2", tmp);
    CHECK(access(dir, F_OK) != 0);
}

int main(void) {
    snprintf(tmp, sizeof tmp, "%s/zp_cli_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(tmp)) {
        perror("mkdtemp");
        return 1;
    }
    test_bad_scenes();
    test_configs();
    char scene[1024];
    snprintf(scene, sizeof scene, "%s/valid.ini", tmp);
    write_file(scene, valid);
    test_options(scene);
    test_limits(scene);
    test_hostile_arguments(scene);
    test_json();
    test_check_shows();
    test_all_at_once();
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
