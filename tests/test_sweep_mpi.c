/* `mpirun -np 2 zipopt sweep`: the same sweep.csv and summary.json (the grid schedule in it,
   also one searched again in rounds), bit for bit, as the study without MPI; and so after the job
   lost rank 0 (a node) mid-way, or was stopped by SIGTERM to mpirun while a rank hung, and was
   resumed with --resume. The faults come where the test says (ZIPOPT_SWEEP_FAULT_AFTER), not after
   a guessed sleep. Skipped (77) when zipopt is built without MPI or mpirun is missing. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "testutil.h"

static char out[1 << 16];

static int run(const char *cmd) {
    return tu_sh(cmd, out, sizeof out);
}

static char dir[] = "/tmp/zp_sweep_mpiXXXXXX";
static const char *mpi = "--allow-run-as-root --oversubscribe -np 2";
static const char *vary = "--vary trolley.mass=10:60:4 --vary body.masses=0.5:2:3";

/* the rows (lines that start with a point) of a checkpoint; -1 when its last line is torn */
static int rows_in(const char *path) {
    static char text[1 << 16];
    long n = tu_slurp(path, text, sizeof text);
    int rows = 0;
    for (char *l = text; n > 0 && *l; l = strchr(l, '\n') + 1) {
        if (!strchr(l, '\n')) {
            return -1;
        }
        rows += *l >= '0' && *l <= '9';
    }
    return rows;
}

/* resumed under mpirun from the checkpoint in sub (with k rows): the outputs of one/ */
static void resume_same(const char *scene, const char *sub, int k) {
    char cmd[4096], says[64], a[1 << 15], b[1 << 15];
    snprintf(cmd, sizeof cmd, "%s/%s/sweep.csv", dir, sub);
    CHECK(!tu_exists(cmd)); /* not written by a study cut short */
    snprintf(cmd, sizeof cmd, "%s/%s/checkpoint.csv", dir, sub);
    FILE *f = fopen(cmd, "a"); /* as a kill inside a write would leave it: cut on resume */
    fputs("5,26.6666,1.25,ok,1,fini", f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "%s %s %s sweep %s %s --out %s/%s --resume", ZP_MPIEXEC, mpi, ZP_EXE,
             scene, vary, dir, sub);
    CHECK(run(cmd) == 0);
    snprintf(says, sizeof says, "(%d from the checkpoint)", k);
    CHECK(strstr(out, says) != NULL);
    const char *files[] = {"sweep.csv", "summary.json"};
    for (int i = 0; i < 2; i++) {
        snprintf(cmd, sizeof cmd, "%s/one/%s", dir, files[i]);
        CHECK(tu_slurp(cmd, a, sizeof a) > 0);
        snprintf(cmd, sizeof cmd, "%s/%s/%s", dir, sub, files[i]);
        CHECK(tu_slurp(cmd, b, sizeof b) > 0);
        CHECK(!strcmp(a, b));
    }
}

/* rank 0 killed hard (SIGKILL, as a lost node) after 3 rows: mpirun ends the job */
static void lost_node(const char *scene) {
    char cmd[4096];
    snprintf(cmd, sizeof cmd,
             "ZIPOPT_SWEEP_FAULT_AFTER=3 %s %s -x ZIPOPT_SWEEP_FAULT_AFTER %s sweep %s %s "
             "--out %s/lost >/dev/null 2>&1",
             ZP_MPIEXEC, mpi, ZP_EXE, scene, vary, dir);
    CHECK(run(cmd) != 0);
    snprintf(cmd, sizeof cmd, "%s/lost/checkpoint.csv", dir);
    CHECK(rows_in(cmd) == 3);
    resume_same(scene, "lost", 3);
}

/* rank 0 hangs after 2 rows; SIGTERM to mpirun (as Ctrl-C or a scheduler's stop, which
   OpenMPI forwards to the ranks as SIGTERM) ends the job with the checkpoint whole */
static void stopped(const char *scene) {
    char cmd[4096], path[600];
    snprintf(cmd, sizeof cmd,
             "ZIPOPT_SWEEP_FAULT_AFTER=2 ZIPOPT_SWEEP_FAULT=hang exec %s %s -x "
             "ZIPOPT_SWEEP_FAULT_AFTER -x ZIPOPT_SWEEP_FAULT %s sweep %s %s --out %s/stop "
             ">/dev/null 2>&1",
             ZP_MPIEXEC, mpi, ZP_EXE, scene, vary, dir);
    pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    snprintf(path, sizeof path, "%s/stop/checkpoint.csv", dir);
    for (int i = 0; i < 12000 && rows_in(path) < 2; i++) {
        usleep(10000); /* rank 0 hangs once two rows are in: no race with the end */
    }
    CHECK(rows_in(path) == 2);
    kill(pid, SIGTERM);
    int ws;
    waitpid(pid, &ws, 0);
    CHECK(!(WIFEXITED(ws) && WEXITSTATUS(ws) == 0));
    CHECK(rows_in(path) == 2); /* whole lines only */
    resume_same(scene, "stop", 2);
}

/* the study of args without MPI into a/, under mpirun -np 2 into b/ (its output left in out):
   the same sweep.csv and summary.json */
static void same_on_two_ranks(const char *mpirun, const char *scene, const char *args,
                              const char *a, const char *b) {
    char cmd[4096];
    static char one[1 << 15], two[1 << 15];
    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/%s", ZP_EXE, scene, args, dir, a);
    CHECK(run(cmd) == 0);
    snprintf(cmd, sizeof cmd, "%s %s %s sweep %s %s --out %s/%s", mpirun, mpi, ZP_EXE, scene, args,
             dir, b);
    CHECK(run(cmd) == 0);
    CHECK(strstr(out, "on 2 ranks") != NULL);
    const char *files[] = {"sweep.csv", "summary.json"};
    for (int i = 0; i < 2; i++) {
        snprintf(cmd, sizeof cmd, "%s/%s/%s", dir, a, files[i]);
        CHECK(tu_slurp(cmd, one, sizeof one) > 0);
        snprintf(cmd, sizeof cmd, "%s/%s/%s", dir, b, files[i]);
        CHECK(tu_slurp(cmd, two, sizeof two) > 0);
        CHECK(!strcmp(one, two));
    }
}

int main(void) {
    const char *mpirun = tu_mpirun();
    if (!mpirun) {
        return 77;
    }
    char cmd[4096], path[600];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/s.ini", dir);
    FILE *f = fopen(path, "w");
    fputs("[scene]\nname = s\n[course]\nx_start = 0\nsection = 20 : -x/10 + 10\n"
          "section = 40 : -x/5 + 12\n[trolley]\nmass = 30\n[body]\nlengths = 1, 0.5\n"
          "masses = 5, 2\ndamping = 2\ndeath_angle = 60\n[drive]\nmin = 0\nmax = 300\n"
          "[optimize]\nmargin = 10\nmax_evals = 3000\n",
          f);
    fclose(f);

    same_on_two_ranks(mpirun, path, vary, "one", "two");
    /* a grid whose corners do not bound survival: the same rounds, the same bits */
    same_on_two_ranks(mpirun, path, "--vary body.masses=0.5:3:7 --run simulate --grid-schedule",
                      "r1", "r2");
    CHECK(strstr(out, "after 2 searches") != NULL);
    lost_node(path);
    stopped(path);

    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
