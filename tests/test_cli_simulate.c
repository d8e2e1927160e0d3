/* `zipopt simulate` as a user runs it (docs/commands.md): every contract key in valid JSON, the
   files written whole, samples at the requested times, a schedule file laid over the scene, and
   exit 1 with nothing written when the numerics fail. The JSON is checked by Python's parser,
   the numbers against the library run in this process. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "check.h"
#include "testutil.h"

static char out[8192];

/* runs a shell command, keeps its stdout in out, returns the exit status */
static int run(const char *cmd) { return tu_sh(cmd, out, sizeof out); }

int main(void) {
    char cmd[2048], dir[] = "/tmp/zp_cli_simXXXXXX";
    CHECK(mkdtemp(dir) != NULL);

    /* every key of docs/commands.md in one valid JSON object */
    snprintf(cmd, sizeof cmd,
             "%s simulate %s/config/seed.ini --json --sample-times 1,2.5 --out %s/a | "
             "python3 -c 'import json,sys; d=json.load(sys.stdin); "
             "keys=[\"outcome\",\"time\",\"x\",\"died_link\",\"kinks\",\"max_rel_angle\","
             "\"energy\",\"constraint_residual\",\"samples\",\"stall_reason\",\"stats\"]; "
             "miss=[k for k in keys if k not in d]; "
             "miss+=[k for k in [\"initial\",\"final\",\"drive_work\",\"damper_work\","
             "\"impulse_loss\",\"residual\"] if k not in d[\"energy\"]]; "
             "miss+=[k for k in [\"steps\",\"rhs_evals\",\"wall_s\"] if k not in d[\"stats\"]]; "
             "s=d[\"samples\"]; "
             "miss+=[k for k in [\"t\",\"x\",\"y\",\"theta\",\"omega\",\"normal_force\"] "
             "if k not in s[0]]; "
             "print(\" \".join(miss) or \"ok\", d[\"outcome\"], repr(d[\"time\"]), len(s), "
             "s[1][\"t\"], len(s[0][\"theta\"]))'",
             ZP_EXE, ZP_SOURCE_DIR, dir);
    CHECK(run(cmd) == 0);
    char keys[64] = "", outcome[32] = "";
    double t = 0, t2 = 0;
    int nsamp = 0, ntheta = 0;
    CHECK(sscanf(out, "%63s %31s %lf %d %lf %d", keys, outcome, &t, &nsamp, &t2, &ntheta) == 6);
    CHECK(!strcmp(keys, "ok"));
    CHECK(nsamp == 2 && t2 == 2.5 && ntheta == 3);

    /* the same run in this process: the CLI adds nothing and loses nothing */
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    zp_sim_opts o = tu_opts(&sc, sc.rtol);
    o.atol = sc.atol;
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(!strcmp(outcome, zp_sim_outcome_name(r->outcome)));
    CHECK(t == r->time);
    char path[1200];
    snprintf(path, sizeof path, "%s/a/trajectory.csv", dir);
    CHECK(tu_exists(path));
    snprintf(path, sizeof path, "%s/a/summary.json", dir);
    CHECK(tu_exists(path));

    /* samples in text mode, and a time after the end said to be not reached (text, JSON) */
    snprintf(cmd, sizeof cmd, "%s simulate %s/config/seed.ini --sample-times 100,2.5 --out %s/a",
             ZP_EXE, ZP_SOURCE_DIR, dir);
    CHECK(run(cmd) == 0);
    CHECK(strstr(out, "sample t = 2.5 s: x = ") != NULL);
    CHECK(strstr(out, "sample t = 100 s: not reached") != NULL);
    snprintf(cmd, sizeof cmd,
             "%s simulate %s/config/seed.ini --sample-times 100,2.5 --json --out %s/a | "
             "python3 -c 'import json,sys; d=json.load(sys.stdin); "
             "print(len(d[\"samples\"]), d[\"samples_not_reached\"])'",
             ZP_EXE, ZP_SOURCE_DIR, dir);
    CHECK(run(cmd) == 0);
    CHECK(!strcmp(out, "1 [100]\n"));

    /* a schedule file overrides [drive] forces: 10 N finishes where the seed's 100 N dies */
    snprintf(path, sizeof path, "%s/sched.ini", dir);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    fputs("[drive]\nforces = 10, 10, 10\n", f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "%s simulate %s/config/seed.ini --schedule %s --out %s/b --json",
             ZP_EXE, ZP_SOURCE_DIR, path, dir);
    CHECK(run(cmd) == 0);
    double f10[3] = {10, 10, 10};
    in_sched = tu_sched(m, f10);
    r = tu_run(m, &o, &in);
    char expect[64];
    snprintf(expect, sizeof expect, "\"time\": %.17g,", r->time);
    CHECK(r->outcome == ZP_OUTCOME_FINISHED && strstr(out, expect) != NULL);

    /* numerical failure: exit 1, a message, nothing written */
    snprintf(cmd, sizeof cmd,
             "%s simulate %s/config/seed.ini --force 1e300,1e300,1e300 --out %s/c 2>&1",
             ZP_EXE, ZP_SOURCE_DIR, dir);
    CHECK(run(cmd) == 1);
    CHECK(strstr(out, "numerical failure") && strstr(out, "nothing was written"));
    snprintf(path, sizeof path, "%s/c", dir);
    CHECK(!tu_exists(path));

    zp_model_free(m);
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(run(cmd) == 0);
    return CHECK_DONE();
}
