/* `mpirun -np 2 zipopt sweep`: the same sweep.csv and summary.json, bit for bit, as the
   study without MPI (killing and resuming is tested without MPI, in test_cli_sweep: the
   checkpoint is rank 0's alone, written the same way). Skipped (77) when zipopt is built without MPI or mpirun is
   missing. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "testutil.h"

static char out[1 << 16];

static int run(const char *cmd) {
    return tu_sh(cmd, out, sizeof out);
}

int main(void) {
    const char *mpirun = tu_mpirun();
    if (!mpirun) {
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
          "[optimize]\nmargin = 10\nmax_evals = 3000\n",
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

    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
