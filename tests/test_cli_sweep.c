/* `zipopt sweep` as a user runs it (docs/commands.md): bad --vary exits 2 writing nothing; each
   point is the same run as `zipopt simulate` (or the search `zipopt SCENE`) of a scene file written
   here by hand with that value (a brake's eddy varied slowing the arrival point by point); a
   study killed mid-way and resumed gives the same sweep.csv as one never stopped; a
   checkpoint of another study is refused; the schedule that survives across the grid survives
   each point's scene written by hand, run by `zipopt simulate`, also where the corners do not
   bound survival (the points an answer breaks searched again). */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "testutil.h"

static char out[1 << 16];
static char dir[] = "/tmp/zp_cli_sweepXXXXXX";

static int run(const char *cmd) {
    return tu_sh(cmd, out, sizeof out);
}

/* the scene, with the trolley mass and the first link's mass given */
static const char *scene(const char *name, const char *trolley, const char *masses, int evals) {
    static char path[4][512];
    static int k;
    char *p = path[k++ % 4];
    snprintf(p, 512, "%s/%s.ini", dir, name);
    FILE *f = fopen(p, "w");
    fprintf(f,
            "[scene]\nname = small\n[course]\nx_start = 0\nsection = 20 : -x/10 + 10\n"
            "section = 40 : -x/5 + 12\n[trolley]\nmass = %s\n[body]\nlengths = 1, 0.5\n"
            "masses = %s\ndamping = 2\ndeath_angle = 60\n[drive]\nforces = 90, 120\nmin = 0\n"
            "max = 300\n[optimize]\nmargin = 10\nmax_evals = %d\n",
            trolley, masses, evals);
    fclose(f);
    return p;
}

/* field i (0-based) of CSV line `line` of text (line 0: the header) */
static double field(const char *text, int line, int i) {
    const char *p = text;
    for (int l = 0; l < line && p; l++) {
        p = strchr(p, '\n');
        p = p ? p + 1 : NULL;
    }
    for (int k = 0; k < i && p; k++) {
        p = strchr(p, ',');
        p = p ? p + 1 : NULL;
    }
    return p ? strtod(p, NULL) : NAN;
}

static double json_num(const char *text, const char *key) {
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = strstr(text, pat);
    return p ? strtod(p + strlen(pat), NULL) : NAN;
}

static void bad_input(void) {
    const char *base = scene("base", "30", "5, 2", 100);
    const char *cases[][2] = {
        {"--vary body.mass=1:2:3", "unknown key"},
        {"--vary body.masses=2:1:3", "A <= B"},
        {"--vary body.masses=1:2:0", "N = 0"},
        {"--vary drive.direction=1:2:2", "not a number"},
        {"--vary body.death_angle=30:400:3", "death_angle"}, /* a point the reader refuses */
        {"--vary trolley.mass=1:2:2 --run fly", "--run"},
        {"", "--vary"},
    };
    char cmd[2048], path[600];
    for (int i = 0; i < (int)(sizeof cases / sizeof cases[0]); i++) {
        snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/bad 2>&1", ZP_EXE, base, cases[i][0],
                 dir);
        CHECK(run(cmd) == 2);
        if (!strstr(out, cases[i][1])) {
            fprintf(stderr, "%s: no '%s' in: %s\n", cases[i][0], cases[i][1], out);
            CHECK(0);
        }
    }
    snprintf(path, sizeof path, "%s/bad", dir);
    CHECK(!tu_exists(path));
}

/* the scene is read as every command reads it: a NUL byte is refused with its line (not a
   scene cut short there), a file over 1 MiB is refused (not read until memory runs out) */
static void bad_files(void) {
    char path[600], cmd[2048];
    snprintf(path, sizeof path, "%s/nul.ini", dir);
    FILE *f = fopen(path, "wb");
    static const char nul_scene[] =
        "[scene]\nname = nul\n[course]\nx_start = 0\nsection = 6 : 6 - x/2\n[trolley]\n"
        "mass = 20\n[body]\nlengths = 0.5\nmasses = 2\n[drive]\nforces = 10\0, 20\n";
    CHECK(f && fwrite(nul_scene, 1, sizeof nul_scene - 1, f) == sizeof nul_scene - 1);
    fclose(f);
    snprintf(cmd, sizeof cmd,
             "%s sweep %s --vary trolley.mass=10:20:2 --run simulate --out %s/nul 2>&1", ZP_EXE,
             path, dir);
    CHECK(run(cmd) == 2 && strstr(out, "nul.ini:12:") && strstr(out, "NUL byte"));
    snprintf(path, sizeof path, "%s/nul", dir);
    CHECK(!tu_exists(path));
    /* a valid scene after 2 MiB of comment lines */
    snprintf(path, sizeof path, "%s/huge.ini", dir);
    f = fopen(path, "w");
    for (int i = 0; f && i < 2 * 1024 * 1024 / 16; i++) {
        fputs("; padding line\n", f);
    }
    fclose(f);
    snprintf(cmd, sizeof cmd, "cat %s >> %s", scene("huge-tail", "30", "5, 2", 100), path);
    CHECK(run(cmd) == 0);
    snprintf(cmd, sizeof cmd,
             "%s sweep %s --vary trolley.mass=10:20:2 --run simulate --out %s/huge 2>&1", ZP_EXE,
             path, dir);
    CHECK(run(cmd) == 2 && strstr(out, "larger than 1 MiB"));
    snprintf(path, sizeof path, "%s/huge", dir);
    CHECK(!tu_exists(path));
}

/* --resume on a checkpoint.csv that is a FIFO: refused at once (a regular file only), not a
   wait forever for a writer */
static void fifo_checkpoint(void) {
    char cmd[2048], path[600];
    snprintf(path, sizeof path, "%s/fifo", dir);
    CHECK(mkdir(path, 0777) == 0);
    snprintf(path, sizeof path, "%s/fifo/checkpoint.csv", dir);
    CHECK(mkfifo(path, 0666) == 0);
    snprintf(cmd, sizeof cmd,
             "timeout 20 %s sweep %s --vary trolley.mass=20:40:2 --run simulate --out %s/fifo "
             "--resume 2>&1",
             ZP_EXE, scene("fifo", "30", "5, 2", 100), dir);
    CHECK(run(cmd) == 2 && strstr(out, "checkpoint.csv is not a regular file"));
}

/* every point of a simulate study is `zipopt simulate` of the scene written with its values */
static void same_as_simulate(void) {
    char cmd[2048], csv[8192], path[600];
    const char *base = scene("base", "30", "5, 2", 100);
    snprintf(cmd, sizeof cmd,
             "%s sweep %s --vary trolley.mass=20:40:3 --vary body.masses=0.5:1.5:2 --run "
             "simulate --out %s/sim",
             ZP_EXE, base, dir);
    CHECK(run(cmd) == 0);
    snprintf(path, sizeof path, "%s/sim/sweep.csv", dir);
    CHECK(tu_slurp(path, csv, sizeof csv) > 0);
    const char *trolley[] = {"20", "30", "40"}, *masses[] = {"2.5, 1", "7.5, 3"};
    for (int p = 0; p < 6; p++) {
        const char *one = scene("one", trolley[p % 3], masses[p / 3], 100);
        snprintf(cmd, sizeof cmd, "%s simulate %s --json --out %s/one", ZP_EXE, one, dir);
        CHECK(run(cmd) == 0);
        CHECK(field(csv, p + 1, 0) == p);
        CHECK(field(csv, p + 1, 6) == json_num(out, "time")); /* the same bits */
    }
    snprintf(path, sizeof path, "%s/sim/sweep.png", dir);
    CHECK(tu_exists(path));
    snprintf(path, sizeof path, "%s/sim/checkpoint.csv", dir);
    CHECK(!tu_exists(path)); /* sweep.csv holds every row */
}

/* the small scene with a brake zone over its second section of eddy coefficient eddy */
static const char *braked_scene(const char *name, const char *eddy) {
    static char path[2][512];
    static int k;
    char *p = path[k++ % 2];
    snprintf(p, 512, "%s/%s.ini", dir, name);
    FILE *f = fopen(p, "w");
    fprintf(f,
            "[scene]\nname = braked\n[course]\nx_start = 0\nsection = 20 : -x/10 + 10\n"
            "section = 40 : -x/5 + 12\n[trolley]\nmass = 30\n[body]\nlengths = 1, 0.5\n"
            "masses = 5, 2\ndamping = 2\n[drive]\nforces = 90, 120\n[brake]\nstart = 20\n"
            "eddy = %s\n",
            eddy);
    fclose(f);
    return p;
}

/* --vary brake.eddy: each point `zipopt simulate` of the scene written with that eddy, the
   arrival slower the stronger the brake */
static void brake_eddy(void) {
    char cmd[2048], csv[8192], path[600];
    snprintf(cmd, sizeof cmd, "%s sweep %s --vary brake.eddy=20:120:6 --run simulate --out %s/brk",
             ZP_EXE, braked_scene("brk", "40"), dir);
    CHECK(run(cmd) == 0);
    snprintf(path, sizeof path, "%s/brk/sweep.csv", dir);
    CHECK(tu_slurp(path, csv, sizeof csv) > 0 && strstr(csv, "point,brake.eddy,"));
    const char *eddy[] = {"20", "40", "60", "80", "100", "120"};
    for (int p = 0; p < 6; p++) {
        snprintf(cmd, sizeof cmd, "%s simulate %s --json --out %s/one", ZP_EXE,
                 braked_scene("one", eddy[p]), dir);
        CHECK(run(cmd) == 0 && strstr(out, "\"brake_work\": "));
        CHECK(field(csv, p + 1, 1) == atof(eddy[p]));
        CHECK(field(csv, p + 1, 5) == json_num(out, "time"));       /* the same bits */
        CHECK(p == 0 || field(csv, p + 1, 12) < field(csv, p, 12)); /* arrival km/h */
    }
}

/* a search point is `zipopt SCENE` of the scene written with its value */
static void same_as_search(void) {
    char cmd[2048], csv[8192], json[65536], path[600];
    const char *base = scene("base", "30", "5, 2", 120);
    snprintf(cmd, sizeof cmd, "%s sweep %s --vary trolley.mass=25:25:1 --out %s/srch", ZP_EXE, base,
             dir);
    CHECK(run(cmd) == 0);
    snprintf(path, sizeof path, "%s/srch/sweep.csv", dir);
    tu_slurp(path, csv, sizeof csv);
    const char *one = scene("one", "25", "5, 2", 120);
    snprintf(cmd, sizeof cmd, "%s %s --no-plot --out %s/one >/dev/null", ZP_EXE, one, dir);
    CHECK(run(cmd) == 0);
    snprintf(path, sizeof path, "%s/one/summary.json", dir);
    tu_slurp(path, json, sizeof json);
    CHECK(field(csv, 1, 5) == json_num(json, "time"));
    CHECK(field(csv, 1, 3) == 1 && strstr(json, "\"found\": true"));
}

/* the n numbers of the JSON array after "key": [ in text (from where from is found) */
static int json_array(const char *text, const char *from, const char *key, double *x, int n) {
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": [", key);
    const char *p = strstr(text, from);
    p = p ? strstr(p, pat) : NULL;
    for (int i = 0; p && i < n; i++) {
        char *end;
        x[i] = strtod(p + (i ? 1 : strlen(pat)), &end);
        if (end == p) {
            return -1;
        }
        p = end;
    }
    return p ? 0 : -1;
}

/* `zipopt simulate --force f` of the small scene with that trolley and link masses: 1 when it
   finishes with the margin kept (60 deg death angle, 10 deg margin); its finish time in *t */
static int survives(const char *trolley, const char *masses, const double *f, double *t) {
    char cmd[2048];
    const char *one = scene("one", trolley, masses, 100);
    snprintf(cmd, sizeof cmd, "%s simulate %s --force %.17g,%.17g --json --out %s/one", ZP_EXE, one,
             f[0], f[1], dir);
    CHECK(run(cmd) == 0);
    double angle[2];
    CHECK(json_array(out, "{", "max_rel_angle", angle, 2) == 0);
    *t = json_num(out, "time");
    return strstr(out, "\"outcome\": \"finished\"") && angle[0] <= 50 && angle[1] <= 50;
}

/* a lighter trolley swings more under the same push: the grid's corners (10 and 60 kg) bound
   survival; the grid schedule survives every point, each run by hand, and is no faster at the
   middle than that point's own optimum; the heaviest point's optimum breaks somewhere */
static void grid_schedule(void) {
    char cmd[2048], csv[8192], json[65536], path[600], base[512];
    snprintf(base, sizeof base, "%s", scene("base", "30", "5, 2", 1000)); /* scene() reuses */
    const char *vary = "--vary trolley.mass=10:60:4";
    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/grid", ZP_EXE, base, vary, dir);
    CHECK(run(cmd) == 0);
    CHECK(strstr(out, "Fastest schedule that the grid's 2 corners and its middle all") != NULL);
    snprintf(path, sizeof path, "%s/grid/sweep.csv", dir);
    CHECK(tu_slurp(path, csv, sizeof csv) > 0);
    snprintf(path, sizeof path, "%s/grid/summary.json", dir);
    CHECK(tu_slurp(path, json, sizeof json) > 0);
    CHECK(strstr(json, "\"grid_schedule\": {\"found\": true") != NULL);
    CHECK(json_num(json, "points_survived") == 4);
    double f[2], heavy[2] = {field(csv, 4, 10), field(csv, 4, 11)}, t;
    CHECK(json_array(json, "grid_schedule", "forces", f, 2) == 0);
    const char *trolley[] = {"10", "26.666666666666668", "43.333333333333336", "60"};
    int heavy_ok = 1;
    for (int p = 0; p < 4; p++) {
        CHECK(survives(trolley[p], "5, 2", f, &t));
        if (p == 1) { /* the middle: the same run, the same bits */
            CHECK(t == json_num(strstr(json, "\"nominal\""), "time"));
            CHECK(t >= field(csv, 2, 5));
        }
        heavy_ok &= survives(trolley[p], "5, 2", heavy, &t);
    }
    CHECK(!heavy_ok);

    /* killed after one row (the grid schedule's line before it): resumed, the grid schedule
       is not searched again and the outputs are those of the study never stopped */
    snprintf(cmd, sizeof cmd,
             "ZIPOPT_SWEEP_FAULT_AFTER=1 %s sweep %s %s --out %s/gridcut >/dev/null 2>&1", ZP_EXE,
             base, vary, dir);
    CHECK(run(cmd) != 0);
    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/gridcut --resume", ZP_EXE, base, vary, dir);
    CHECK(run(cmd) == 0);
    CHECK(strstr(out, "(1 from the checkpoint) and the grid schedule (from the checkpoint)"));
    static char again[65536];
    snprintf(path, sizeof path, "%s/gridcut/summary.json", dir);
    CHECK(tu_slurp(path, again, sizeof again) > 0 && !strcmp(json, again));
    snprintf(path, sizeof path, "%s/gridcut/sweep.csv", dir);
    CHECK(tu_slurp(path, again, sizeof again) > 0 && !strcmp(csv, again));
}

/* the JSON array of point indices after "key": [ in text, as a bit per point (up to 64) */
static unsigned long long json_points(const char *text, const char *key) {
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": [", key);
    const char *p = strstr(text, pat);
    unsigned long long bits = 0;
    for (p = p ? p + strlen(pat) : NULL; p && *p != ']';) {
        char *end;
        long i = strtol(p, &end, 10);
        CHECK(end != p && i >= 0 && i < 64);
        bits |= 1ull << i;
        p = *end == ',' ? end + 1 : end;
    }
    return bits;
}

/* the link masses scaled x0.5 to x3: the corners do not bound survival, the answer held to
   them and the middle breaks points between. Those points
   are added and searched again; the answer then survives every point, each run by hand, and
   the points added are exactly those the first answer breaks (that answer is the grid
   schedule of the 3-point grid of the same corners and middle) */
static void grid_rounds(void) {
    char cmd[2048], csv[8192], json[65536], path[600], base[512];
    snprintf(base, sizeof base, "%s", scene("base", "30", "5, 2", 1000)); /* scene() reuses */
    double first[2], f[2], t;
    snprintf(cmd, sizeof cmd,
             "%s sweep %s --vary body.masses=0.5:3:3 --run simulate --grid-schedule --out "
             "%s/rounds3 --json",
             ZP_EXE, base, dir);
    CHECK(run(cmd) == 0);
    CHECK(json_array(out, "grid_schedule", "forces", first, 2) == 0);
    CHECK(json_num(out, "rounds") == 1);
    const char *vary = "--vary body.masses=0.5:3:7 --run simulate --grid-schedule";
    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/rounds", ZP_EXE, base, vary, dir);
    CHECK(run(cmd) == 0);
    CHECK(strstr(out, "its middle and ") && strstr(out, "all survive"));
    CHECK(strstr(out, "it keeps the limits at 7 of 7 points, after 2 searches (added as an "
                      "answer broke them: body.masses x"));
    snprintf(path, sizeof path, "%s/rounds/sweep.csv", dir);
    CHECK(tu_slurp(path, csv, sizeof csv) > 0);
    snprintf(path, sizeof path, "%s/rounds/summary.json", dir);
    CHECK(tu_slurp(path, json, sizeof json) > 0);
    CHECK(strstr(json, "\"grid_schedule\": {\"found\": true") != NULL);
    CHECK(json_num(json, "rounds") == 2 && json_num(json, "points_survived") == 7);
    CHECK(json_array(json, "grid_schedule", "forces", f, 2) == 0);
    unsigned long long added = json_points(json, "added"), broke = 0;
    CHECK(added != 0);
    for (int p = 0; p < 7; p++) {
        double x = field(csv, p + 1, 1);
        char masses[64];
        snprintf(masses, sizeof masses, "%.17g, %.17g", 5 * x, 2 * x);
        CHECK(survives("30", masses, f, &t));
        broke |= (unsigned long long)!survives("30", masses, first, &t) << p;
    }
    CHECK(broke == added);
    /* on one thread: the same rounds, the same bits */
    static char again[65536];
    snprintf(cmd, sizeof cmd, "OMP_NUM_THREADS=1 %s sweep %s %s --out %s/rounds1 >/dev/null",
             ZP_EXE, base, vary, dir);
    CHECK(run(cmd) == 0);
    snprintf(path, sizeof path, "%s/rounds1/summary.json", dir);
    CHECK(tu_slurp(path, again, sizeof again) > 0 && !strcmp(json, again));

    /* a checkpoint whose grid line an older zipopt wrote (no rounds, no points added): its rows
       are kept, the grid schedule is searched again, the outputs are the study's never stopped */
    snprintf(cmd, sizeof cmd,
             "ZIPOPT_SWEEP_FAULT_AFTER=2 %s sweep %s %s --out %s/roundscut >/dev/null 2>&1", ZP_EXE,
             base, vary, dir);
    CHECK(run(cmd) != 0);
    char cp[8192], *grid = NULL, *eol = NULL;
    snprintf(path, sizeof path, "%s/roundscut/checkpoint.csv", dir);
    CHECK(tu_slurp(path, cp, sizeof cp) > 0 && (grid = strstr(cp, "\ngrid,")) != NULL &&
          (eol = strchr(grid + 1, '\n')) != NULL);
    FILE *fp = fopen(path, "w");
    fprintf(fp, "%.*s\ngrid,0,1,3,2,2,872,4.2,12.9,0,10.0,3,151.2,161.7,07,%s", (int)(grid - cp),
            cp, eol);
    fclose(fp);
    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/roundscut --resume", ZP_EXE, base, vary,
             dir);
    CHECK(run(cmd) == 0);
    CHECK(strstr(out, "(2 from the checkpoint) and the grid schedule in"));
    snprintf(path, sizeof path, "%s/roundscut/summary.json", dir);
    CHECK(tu_slurp(path, again, sizeof again) > 0 && !strcmp(json, again));
}

/* killed after some rows, resumed: the same sweep.csv as a study never stopped */
static void kill_and_resume(void) {
    char cmd[2048], path[600], whole[16384], resumed[16384];
    const char *base = scene("base", "30", "5, 2", 300);
    const char *vary =
        "--vary trolley.mass=20:40:3 --vary body.masses=0.5:1.5:2 --no-grid-schedule";
    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/whole >/dev/null", ZP_EXE, base, vary, dir);
    CHECK(run(cmd) == 0);
    snprintf(path, sizeof path, "%s/whole/sweep.csv", dir);
    CHECK(tu_slurp(path, whole, sizeof whole) > 0);

    snprintf(cmd, sizeof cmd, "exec %s sweep %s %s --out %s/cut >/dev/null 2>&1", ZP_EXE, base,
             vary, dir);
    pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    snprintf(path, sizeof path, "%s/cut/checkpoint.csv", dir);
    for (int i = 0; i < 3000 && (!tu_exists(path) || tu_count_lines(path) < 2 + 2); i++) {
        usleep(10000); /* until two rows are in */
    }
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
    int rows = tu_count_lines(path) - 2;
    CHECK(rows >= 2 && rows < 6);
    /* its head names the program that wrote it, as zipopt --version does */
    char head[16384], version[256];
    CHECK(tu_slurp(path, head, sizeof head) > 0);
    snprintf(cmd, sizeof cmd, "%s --version", ZP_EXE);
    CHECK(run(cmd) == 0 && !strncmp(out, "zipopt ", 7));
    snprintf(version, sizeof version, " version=%.*s ", (int)strcspn(out + 7, "\n"), out + 7);
    CHECK(strstr(head, version) != NULL && strstr(head, version) < strchr(head, '\n'));
    /* a row torn by the kill: cut on resume */
    FILE *f = fopen(path, "a");
    fputs("5,40,1.5,ok,1,fini", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/cut/sweep.csv", dir);
    CHECK(!tu_exists(path)); /* not written by a study cut short */

    /* another study's checkpoint is refused */
    snprintf(cmd, sizeof cmd, "%s sweep %s --vary trolley.mass=20:40:4 --out %s/cut --resume 2>&1",
             ZP_EXE, base, dir);
    CHECK(run(cmd) == 2 && strstr(out, "another study"));

    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/cut --resume", ZP_EXE, base, vary, dir);
    CHECK(run(cmd) == 0);
    char says[64];
    snprintf(says, sizeof says, "(%d from the checkpoint)", rows);
    CHECK(strstr(out, says) != NULL);
    CHECK(tu_slurp(path, resumed, sizeof resumed) > 0);
    CHECK(!strcmp(whole, resumed));
}

int main(void) {
    CHECK(mkdtemp(dir) != NULL);
    bad_input();
    bad_files();
    fifo_checkpoint();
    same_as_simulate();
    brake_eddy();
    same_as_search();
    grid_schedule();
    grid_rounds();
    kill_and_resume();
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
