/* The inner simulator alone (no trajectory, no load tracking, no output): the seed scene at a
   constant push, repeated in one process. One JSON line per tolerance with the median,
   smallest and first wall time of zp_sim_run (the first tolerance's first run is a fresh
   process's: cold caches, fresh memory), steps, rejected steps, rhs evaluations and the
   finish time. --as-simulate: with what `zipopt simulate` asks of the run besides (the scene's
   trajectory rows, loads tracked at every step), to see what those cost.
   Usage: bench_sim [--repeat N] [--method NAME] [--formulation NAME] [--force F]
                    [--as-simulate] RTOL [RTOL..]   (atol = rtol/100) */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_load.h"
#include "sim.h"

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv) {
    int repeat = 21, method = ZP_METHOD_CVODE_ADAMS, form = ZP_FORM_LAGRANGE;
    double force = 10;
    int first_rtol = argc, as_simulate = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--repeat") && i + 1 < argc) {
            repeat = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--method") && i + 1 < argc) {
            method = zp_method_find(argv[++i]);
        } else if (!strcmp(argv[i], "--formulation") && i + 1 < argc) {
            form = zp_formulation_find(argv[++i]);
        } else if (!strcmp(argv[i], "--force") && i + 1 < argc) {
            force = atof(argv[++i]);
        } else if (!strcmp(argv[i], "--as-simulate")) {
            as_simulate = 1;
        } else {
            first_rtol = i;
            break;
        }
    }
    if (repeat < 1 || method < 0 || form < 0 || first_rtol >= argc) {
        fputs("usage: bench_sim [--repeat N] [--method NAME] [--formulation NAME] [--force F] "
              "[--as-simulate] RTOL [RTOL..]\n",
              stderr);
        return 2;
    }
    gsl_set_error_handler_off();
    zp_scene sc;
    zp_scene_load_seed(&sc);
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = zp_model_build(&sc, &d);
    double *wall = malloc(sizeof *wall * repeat);
    if (!m || !wall) {
        return 1;
    }
    zp_schedule shape = zp_drive_of_scene(&sc);
    zp_schedule sched = zp_drive_constant(&shape, force);
    zp_input in = {.sched = &sched};
    zp_result r;
    for (int a = first_rtol; a < argc; a++) {
        double rtol = atof(argv[a]);
        zp_sim_opts o = {.method = method,
                         .formulation = form,
                         .rtol = rtol,
                         .atol = rtol / 100,
                         .t_max = sc.t_max,
                         .max_steps = 2000000,
                         .output_dt = as_simulate ? sc.output_dt : 0,
                         .track_loads = as_simulate};
        zp_sim *s = zp_sim_create(m, &o);
        for (int k = 0; k < repeat; k++) {
            if (!s || zp_sim_run(m, s, &in, &r) != ZP_OK) {
                fprintf(stderr, "bench_sim: run failed: %s\n", s ? r.message : "no workspace");
                return 1;
            }
            wall[k] = r.wall_s;
        }
        double first = wall[0]; /* the process's first run for the first RTOL: cold caches */
        qsort(wall, repeat, sizeof *wall, cmp_double);
        printf("{\"method\": \"%s\", \"formulation\": \"%s\", \"rtol\": %g, \"atol\": %g, "
               "\"outcome\": \"%s\", \"time\": %.17g, \"steps\": %ld, \"rejected\": %ld, "
               "\"rhs_evals\": %ld, "
               "\"wall_median_s\": %.6g, \"wall_min_s\": %.6g, \"wall_first_s\": %.6g, "
               "\"constraint_residual\": %.3g}\n",
               zp_method_get(method)->name, zp_formulation_get(form)->name, rtol, rtol / 100,
               zp_sim_outcome_name(r.outcome), r.time, r.steps, r.rejected, r.rhs_evals,
               wall[repeat / 2], wall[0], first, r.constraint_residual);
        zp_sim_free(s);
    }
    free(wall);
    zp_model_free(m);
    return 0;
}
