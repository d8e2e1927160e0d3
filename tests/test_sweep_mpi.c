/* `mpirun -np 2 zipopt sweep`: the same sweep.csv and summary.json, bit for bit, as the
   study without MPI; Ctrl-C to mpirun keeps the finished rows, and --resume under mpirun
   again gives the same file. Skipped (77) when zipopt is built without MPI or mpirun is
   missing. */
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

/* rows of a checkpoint: its lines less the study line and the header */
static int rows_in(const char *path) {
    return tu_count_lines(path) - 2;
}

int main(void) {
    const char *mpirun = ZP_MPIEXEC;
    if (!*mpirun || access(mpirun, X_OK)) {
        printf("SKIP: zipopt is built without MPI or mpirun is missing (install openmpi-bin and "
               "libopenmpi-dev, then rebuild)\n");
        return 77;
    }
    char dir[] = "/tmp/zp_sweep_mpiXXXXXX", cmd[4096], path[600];
    static char one[1 << 15], two[1 << 15];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/s.ini", dir);
    FILE *f = fopen(path, "w");
    fputs("[scene]\nname = s\n[course]\nx_start = 0\nsection = 20 : -x/10 + 10\n"
          "section = 40 : -x/5 + 12\n[trolley]\nmass = 30\n[body]\nlengths = 1, 0.5\n"
          "masses = 5, 2\ndamping = 2\ndeath_angle = 60\n[drive]\nmin = 0\nmax = 300\n"
          "[optimize]\nmargin = 10\nmax_evals = 400\n",
          f);
    fclose(f);
    const char *vary = "--vary trolley.mass=10:60:4 --vary body.masses=0.5:2:3";
    const char *mpi = "--allow-run-as-root --oversubscribe -np 2";

    snprintf(cmd, sizeof cmd, "%s sweep %s %s --out %s/one", ZP_EXE, path, vary, dir);
    CHECK(run(cmd) == 0);
    snprintf(cmd, sizeof cmd, "%s %s %s sweep %s %s --out %s/two", mpirun, mpi, ZP_EXE, path, vary,
             dir);
    CHECK(run(cmd) == 0);
    CHECK(strstr(out, "on 2 ranks") != NULL);
    const char *files[] = {"sweep.csv", "summary.json"};
    for (int i = 0; i < 2; i++) {
        snprintf(cmd, sizeof cmd, "%s/one/%s", dir, files[i]);
        CHECK(tu_slurp(cmd, one, sizeof one) > 0);
        snprintf(cmd, sizeof cmd, "%s/two/%s", dir, files[i]);
        CHECK(tu_slurp(cmd, two, sizeof two) > 0);
        CHECK(!strcmp(one, two));
    }

    /* Ctrl-C to mpirun after some rows, then --resume under mpirun */
    snprintf(cmd, sizeof cmd, "exec %s %s %s sweep %s %s --out %s/cut >/dev/null 2>&1", mpirun, mpi,
             ZP_EXE, path, vary, dir);
    pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    snprintf(path, sizeof path, "%s/cut/checkpoint.csv", dir);
    for (int i = 0; i < 6000 && (!tu_exists(path) || rows_in(path) < 2); i++) {
        usleep(10000);
    }
    kill(pid, SIGINT);
    waitpid(pid, NULL, 0);
    int rows = rows_in(path);
    CHECK(rows >= 2 && rows < 12);
    snprintf(path, sizeof path, "%s/s.ini", dir);
    snprintf(cmd, sizeof cmd, "%s %s %s sweep %s %s --out %s/cut --resume", mpirun, mpi, ZP_EXE,
             path, vary, dir);
    CHECK(run(cmd) == 0);
    snprintf(cmd, sizeof cmd, "%s/one/sweep.csv", dir);
    tu_slurp(cmd, one, sizeof one);
    snprintf(cmd, sizeof cmd, "%s/cut/sweep.csv", dir);
    CHECK(tu_slurp(cmd, two, sizeof two) > 0 && !strcmp(one, two));
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
