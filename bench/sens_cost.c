/* What a run with gradients (sens.h) costs against a plain run of the same schedule: the best
   of N wall times of each at the scene's [solver] settings (no trajectory), their ratio, and
   the integrator's steps and rate evaluations of each (the sensitivity run's steps counted once
   per step; each of its evaluations costs the plain rates 1 + 2 np times, np the parameters
   the run has felt so far).
   Usage: sens_cost [N] SCENE.ini...   (prints a markdown table) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "scene_load.h"
#include "sens.h"
#include "sim.h"
#include "sim_opts.h"

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void scene_row(const char *path, int reps) {
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = zp_scene_load(path, &sc, &d) == ZP_OK ? zp_model_build(&sc, &d) : NULL;
    zp_sim_opts o;
    if (!m || zp_sim_opts_from_scene(&sc, &o, &d)) {
        zp_diag_print(&d, stderr);
        zp_model_free(m);
        return;
    }
    o.output_dt = 0;
    zp_schedule sh = zp_drive_of_scene(&sc);
    zp_sim *s = zp_sim_create(m, &o);
    zp_input in = {.sched = &sh};
    zp_result r;
    zp_sens_result g;
    double plain = 1e30, sens = 1e30;
    for (int i = 0; s && i < reps; i++) {
        double t0 = now();
        zp_sim_run(m, s, &in, &r);
        double t1 = now();
        zp_sens_run(m, &o, &sh, NULL, &g);
        double t2 = now();
        plain = t1 - t0 < plain ? t1 - t0 : plain;
        sens = t2 - t1 < sens ? t2 - t1 : sens;
    }
    const char *name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    printf("| %s | %d | %.3f ms | %.3f ms | %.2fx | %ld / %ld | %ld / %ld |\n", name, sh.np,
           1e3 * plain, 1e3 * sens, sens / plain, r.steps, g.steps, r.rhs_evals, g.rhs_evals);
    zp_sim_free(s);
    zp_model_free(m);
}

int main(int argc, char **argv) {
    int first = 1, reps = 20;
    if (argc > 1 && atoi(argv[1]) > 0) {
        reps = atoi(argv[1]);
        first = 2;
    }
    printf("| scene | params | plain | with gradients | ratio | steps plain / sens | rate "
           "evaluations plain / sens |\n|---|---|---|---|---|---|---|\n");
    for (int i = first; i < argc; i++) {
        scene_row(argv[i], reps);
    }
    return 0;
}
