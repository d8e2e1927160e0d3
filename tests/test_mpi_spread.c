/* `mpirun -np 2 zipopt landscape` and the robust search under mpirun: the same files, bit for
   bit, as without MPI, written once by rank 0: each rank is told its own --out folder
   (OMPI_COMM_WORLD_RANK) and only rank 0's may appear; the other rank prints nothing. Ranks
   that do not read the same scene (missing on rank 1, or other contents under its name) stop
   together within seconds, exit 2, rank 0 saying which rank and why, nothing written (they
   used to hang or abort with MPI's "Data unpack had inadequate space").
   Skipped (77) when zipopt is built without MPI or mpirun is missing. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "check.h"
#include "testutil.h"

static char out[1 << 16], one[1 << 17], two[1 << 17];
static const char *mpi = "--allow-run-as-root --oversubscribe -np 2";

static int run(const char *cmd) {
    return tu_sh(cmd, out, sizeof out);
}

/* occurrences of needle in text */
static int count(const char *text, const char *needle) {
    int n = 0;
    for (const char *p = text; (p = strstr(p, needle)); p += strlen(needle)) {
        n++;
    }
    return n;
}

/* the file name in folders a and b has the same bytes in both, except lines holding skip
   (may be NULL) */
static int same_file(const char *a, const char *b, const char *name, const char *skip) {
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "grep -v '%s' %s/%s", skip ? skip : "^$-none", a, name);
    int n1 = tu_sh(cmd, one, sizeof one);
    snprintf(cmd, sizeof cmd, "grep -v '%s' %s/%s", skip ? skip : "^$-none", b, name);
    int n2 = tu_sh(cmd, two, sizeof two);
    return n1 == 0 && n2 == 0 && strlen(one) > 100 && !strcmp(one, two);
}

/* the folder listings of a and b are the same, and b's parent holds b alone: the other rank
   made no folder of its own */
static int same_listing(const char *a, const char *b, const char *parent) {
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "ls -A %s", a);
    tu_sh(cmd, one, sizeof one);
    snprintf(cmd, sizeof cmd, "ls -A %s", b);
    tu_sh(cmd, two, sizeof two);
    int same = !strcmp(one, two);
    snprintf(cmd, sizeof cmd, "ls -A %s | wc -l", parent);
    tu_sh(cmd, one, sizeof one);
    return same && atoi(one) == 1;
}

/* the command (after the binary, before --out) once alone into dir/tag_one (a), then under
   mpirun -np 2 with each rank's --out dir/tag_mpi/rank<its rank> (b: rank 0's); stdout of the
   second in out */
static void run_both(const char *mpirun, const char *dir, const char *tag, const char *args,
                     char *a, char *b, char *parent) {
    char cmd[4096];
    snprintf(a, 600, "%s/%s_one", dir, tag);
    snprintf(parent, 600, "%s/%s_mpi", dir, tag);
    snprintf(b, 700, "%s/rank0", parent);
    snprintf(cmd, sizeof cmd, "%s %s --out %s", ZP_EXE, args, a);
    CHECK(run(cmd) == 0);
    snprintf(cmd, sizeof cmd,
             "mkdir %s && %s %s sh -c 'exec %s %s --out %s/rank$OMPI_COMM_WORLD_RANK'", parent,
             mpirun, mpi, ZP_EXE, args, parent);
    CHECK(run(cmd) == 0);
}

static void landscape(const char *mpirun, const char *dir) {
    char args[1024], a[600], b[700], parent[600];
    snprintf(args, sizeof args,
             "landscape %s/config/seed.ini --force-range 0:500:41 --slice 1,3 --range 0:500:7",
             ZP_SOURCE_DIR);
    run_both(mpirun, dir, "land", args, a, b, parent);
    CHECK(strstr(out, "90 runs in") != NULL && strstr(out, "on 2 ranks") != NULL);
    CHECK(count(out, "wrote in") == 1 && count(out, "fastest:") == 1); /* rank 1 is quiet */
    CHECK(same_file(a, b, "landscape.csv", NULL));
    CHECK(same_file(a, b, "landscape_slice.csv", NULL));
    CHECK(same_listing(a, b, parent));
}

static void robust_search(const char *mpirun, const char *dir) {
    char args[1024], a[600], b[700], parent[600];
    snprintf(args, sizeof args, "%s/config/seed_robust.ini --no-plot --max-evals 300",
             ZP_SOURCE_DIR);
    run_both(mpirun, dir, "search", args, a, b, parent);
    CHECK(count(out, "wrote in") == 1 && count(out, "on 2000 fresh ones") == 1);
    /* summary.json: the forces, the robust numbers (verify: 2000 scenarios), all but the wall
       time */
    CHECK(same_file(a, b, "summary.json", "\"wall_s\""));
    CHECK(strstr(one, "\"verify\": {\"samples\": 2000") != NULL);
    CHECK(same_listing(a, b, parent));
}

/* every MPI command with rank r reading dir/rank<r>.ini: rank 1's missing, then different */
static void disagreeing_ranks(const char *mpirun, const char *dir) {
    char cmd[4096], path[700];
    const char *commands[3] = {"sweep %s --vary drive.max=400:500:3 --run simulate",
                               "%s --no-plot --max-evals 300", "landscape %s"};
    snprintf(path, sizeof path, "%s/rank0.ini", dir);
    snprintf(cmd, sizeof cmd, "cp %s/config/seed.ini %s", ZP_SOURCE_DIR, path);
    CHECK(system(cmd) == 0);
    for (int differ = 0; differ < 2; differ++) {
        if (differ) { /* the same name on rank 1's machine, another body */
            snprintf(cmd, sizeof cmd,
                     "sed 's/^masses = 15, 5, 2/masses = 15, 5, 3/' %s > %s/rank1.ini", path, dir);
            CHECK(system(cmd) == 0);
        }
        for (int c = 0; c < 3; c++) {
            char args[1024];
            snprintf(args, sizeof args, commands[c], "'\"$D\"'/rank$OMPI_COMM_WORLD_RANK.ini");
            snprintf(cmd, sizeof cmd,
                     "D=%s; export D; timeout 120 %s %s sh -c 'exec %s %s --out %s/out' 2>&1", dir,
                     mpirun, mpi, ZP_EXE, args, dir);
            time_t t0 = time(NULL);
            int rc = run(cmd);
            CHECK(rc == 2);
            CHECK(time(NULL) - t0 < 60); /* not a hang: seconds, on a loaded machine */
            CHECK(strstr(out, "the MPI ranks must read the same input") != NULL);
            CHECK(strstr(out, differ ? "differs from rank 0's" : "rank 1: ") != NULL);
            CHECK(differ || strstr(out, "No such file or directory") != NULL);
            snprintf(cmd, sizeof cmd, "%s/out", dir);
            CHECK(!tu_exists(cmd));
        }
    }
}

int main(void) {
    const char *mpirun = tu_mpirun();
    if (!mpirun) {
        return 77;
    }
    char dir[] = "/tmp/zp_mpi_spreadXXXXXX", cmd[600];
    CHECK(mkdtemp(dir) != NULL);
    landscape(mpirun, dir);
    robust_search(mpirun, dir);
    disagreeing_ranks(mpirun, dir);
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    return CHECK_DONE();
}
