/* Benchmark of the two formulations (lagrange, newton-euler) on the seed scene: median wall
   time of a full run over repeats, steps and rhs evaluations, for each integration method.
   Usage: bench_formulations [repeats (default 21)] [rtol (default 1e-8; atol = rtol/100)] */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene.h"
#include "sim.h"

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv) {
    int repeats = argc > 1 ? atoi(argv[1]) : 21;
    double rtol = argc > 2 ? atof(argv[2]) : 1e-8;
    if (repeats < 1 || repeats > 1000 || !(rtol > 0)) {
        fputs("usage: bench_formulations [repeats 1..1000] [rtol > 0]\n", stderr);
        return 2;
    }
    gsl_set_error_handler_off();
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    zp_scene_seed(&sc);
    zp_model *m = zp_model_build(&sc, &d);
    if (!m) {
        zp_diag_print(&d, stderr);
        return 1;
    }
    /* the benchmark schedule of bench/run_bench.py (finishes after two kinks) and the
       seed's own (dies early) */
    static const double schedules[][3] = {{10, 10, 10}, {100, 100, 100}};
    printf("seed scene, rtol %g, atol %g, median of %d runs\n", rtol, rtol / 100, repeats);
    printf("%-9s %-13s %-12s %-9s %-15s %10s %8s %10s %14s\n", "schedule", "method",
           "formulation", "outcome", "time_s", "wall_ms", "steps", "rhs_evals", "drift_m");
    double *wall = malloc(sizeof *wall * repeats);
    static zp_result r;
    for (int k = 0; k < 2; k++) {
        zp_input in = {.force = schedules[k]};
        for (int meth = 0; meth < ZP_METHOD_COUNT; meth++) {
            for (int form = 0; form < ZP_FORM_COUNT; form++) {
                zp_sim_opts o = {.method = meth,
                                 .formulation = form,
                                 .rtol = rtol,
                                 .atol = rtol / 100,
                                 .t_max = sc.t_max,
                                 .max_steps = 2000000};
                zp_sim *s = zp_sim_create(m, &o);
                if (!s || !wall) {
                    fputs("out of memory\n", stderr);
                    return 1;
                }
                for (int rep = 0; rep < repeats; rep++) {
                    if (zp_sim_run(m, s, &in, &r) != ZP_OK) {
                        fprintf(stderr, "%s\n", r.message);
                        return 1;
                    }
                    wall[rep] = r.wall_s;
                }
                qsort(wall, repeats, sizeof *wall, cmp_double);
                printf("%-9g %-13s %-12s %-9s %-15.10f %10.3f %8ld %10ld %14.3g\n",
                       schedules[k][0], zp_method_get(meth)->name,
                       zp_formulation_get(form)->name, zp_sim_outcome_name(r.outcome), r.time,
                       1e3 * wall[repeats / 2], r.steps, r.rhs_evals, r.constraint_residual);
                zp_sim_free(s);
            }
        }
    }
    free(wall);
    zp_model_free(m);
    return 0;
}
