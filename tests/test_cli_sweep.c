/* `zipopt sweep` as a user runs it (CLI.md): bad --vary exits 2 writing nothing; each point
   is the same run as `zipopt simulate` (or the search `zipopt SCENE`) of a scene file written
   here by hand with that value; a study killed mid-way and resumed gives the same sweep.csv
   as one never stopped; a checkpoint of another study is refused. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

/* killed after some rows, resumed: the same sweep.csv as a study never stopped */
static void kill_and_resume(void) {
    char cmd[2048], path[600], whole[16384], resumed[16384];
    const char *base = scene("base", "30", "5, 2", 300);
    const char *vary = "--vary trolley.mass=20:40:3 --vary body.masses=0.5:1.5:2";
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
    same_as_simulate();
    same_as_search();
    kill_and_resume();
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
