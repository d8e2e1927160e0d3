/* `zipopt simulate`: one schedule through the simulator; results to stdout, files to the
   output folder (CLI.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "out_csv.h"
#include "out_file.h"
#include "out_json.h"
#include "sim.h"

#define MAX_SAMPLES 10000

static void usage(FILE *f) {
    fputs("usage: zipopt simulate SCENE.ini [--force F1,F2,..] [--schedule FILE] [--json]\n"
          "                       [--sample-times T1,T2,..] [--out DIR]\n"
          "Runs one schedule of drive forces (one per course section, N) through the\n"
          "simulator and reports the outcome: finished (finish time), died (time, x, link)\n"
          "or stalled (why).\n"
          "  --force F1,..       the schedule, overriding [drive] forces\n"
          "  --schedule FILE     a schedule file ([drive] forces) laid over the scene\n"
          "  --json              print the result as one JSON object (keys: README, CLI.md)\n"
          "  --sample-times T,.. also report the state at these times (s)\n"
          "  --out DIR           write trajectory.csv and summary.json to DIR\n"
          "                      (default out/<scene name>/)\n",
          f);
}

typedef struct sim_args {
    const char *scene, *schedule, *out;
    const char *force_text, *sample_text;
    int json;
} sim_args;

static int parse_args(int argc, char **argv, sim_args *a) {
    memset(a, 0, sizeof *a);
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        int has_value = i + 1 < argc;
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            usage(stdout);
            exit(ZP_EXIT_OK);
        } else if (!strcmp(o, "--json")) {
            a->json = 1;
        } else if (!strcmp(o, "--force") && has_value) {
            a->force_text = argv[++i];
        } else if (!strcmp(o, "--schedule") && has_value) {
            a->schedule = argv[++i];
        } else if (!strcmp(o, "--sample-times") && has_value) {
            a->sample_text = argv[++i];
        } else if (!strcmp(o, "--out") && has_value) {
            a->out = argv[++i];
        } else if (o[0] == '-' || a->scene) {
            fprintf(stderr, "zipopt simulate: %s '%s'%s; see zipopt simulate --help\n",
                    o[0] == '-' ? "unknown option or missing value" : "unexpected argument", o,
                    o[0] == '-' ? "" : " (one scene file only)");
            return -1;
        } else {
            a->scene = o;
        }
    }
    if (!a->scene) {
        fputs("zipopt simulate: a scene file is required; see zipopt simulate --help\n", stderr);
        return -1;
    }
    return 0;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void print_text(const zp_model *m, const zp_result *r) {
    printf("outcome: %s", zp_sim_outcome_name(r->outcome));
    if (r->outcome == ZP_OUTCOME_DIED) {
        printf(" (joint of link %d looped)", r->died_link);
    } else if (r->outcome == ZP_OUTCOME_STALLED) {
        printf(" (%s)", zp_sim_stall_name(r->stall));
    }
    printf("\ntime: %.9f s\nx: %.6f m\nspeed: %.4f m/s\n", r->time, r->x, r->v);
    printf("largest |relative joint angle| (deg):");
    for (int i = 0; i < m->nlink; i++) {
        printf(" %.3f", r->max_rel_angle[i] * 180.0 / M_PI);
    }
    printf("\nkink crossings: %d\n", r->ncross);
    printf("energy audit residual: %.3g J\n",
           r->e_final - r->e_initial - r->w_drive + r->w_damp + r->e_impulse);
    printf("steps: %ld, rhs evaluations: %ld, wall: %.4f s\n", r->steps, r->rhs_evals, r->wall_s);
}

/* trajectory.csv and summary.json, both or neither */
static int write_files(const char *dir, const zp_model *m, zp_sim *s, const zp_result *r,
                       const zp_row *smp, int nsmp, const zp_run_meta *meta) {
    zp_out_set set;
    zp_out_set_init(&set);
    char err[1200] = "";
    FILE *csv = zp_out_set_open(&set, dir, "trajectory.csv", err, sizeof err);
    FILE *js = csv ? zp_out_set_open(&set, dir, "summary.json", err, sizeof err) : NULL;
    if (!js) {
        zp_out_set_abort(&set);
        fprintf(stderr, "zipopt simulate: %s; nothing was written\n", err);
        return ZP_EXIT_FAIL;
    }
    int nrows;
    const zp_row *rows = zp_sim_rows(s, &nrows);
    zp_out_csv_trajectory(csv, m, rows, nrows);
    zp_out_json_result(js, m, r, smp, nsmp, meta);
    if (zp_out_set_commit(&set, err, sizeof err)) {
        fprintf(stderr, "zipopt simulate: %s; nothing was written\n", err);
        return ZP_EXIT_FAIL;
    }
    return ZP_EXIT_OK;
}

int zp_cmd_simulate(int argc, char **argv) {
    sim_args a;
    if (parse_args(argc, argv, &a)) {
        return ZP_EXIT_USAGE;
    }
    zp_scene sc;
    zp_model *m = zp_cli_load(a.scene, &sc);
    if (!m) {
        return ZP_EXIT_USAGE;
    }
    int status = ZP_EXIT_USAGE;
    zp_sim *s = NULL;
    double *samples = NULL;
    zp_diag d;
    zp_diag_init(&d);
    if (a.schedule && zp_scene_overlay_schedule(a.schedule, &sc, &d)) {
        zp_diag_print(&d, stderr);
        goto done;
    }
    char why[256];
    if (a.force_text) {
        int n = zp_cli_parse_list(a.force_text, sc.forces, ZP_MAX_SECTIONS, why, sizeof why);
        if (n != sc.nsec) {
            fprintf(stderr, "zipopt simulate: --force: %s; expected %d values (one per section)\n",
                    n < 0 ? why : "wrong number of values", sc.nsec);
            goto done;
        }
        sc.nforce = n;
    }
    int nsample = 0;
    if (a.sample_text) {
        samples = malloc(sizeof *samples * MAX_SAMPLES);
        nsample = samples ? zp_cli_parse_list(a.sample_text, samples, MAX_SAMPLES, why, sizeof why)
                          : -1;
        for (int i = 0; i < nsample; i++) {
            if (samples[i] < 0) {
                snprintf(why, sizeof why, "%g is negative", samples[i]);
                nsample = -1;
            }
        }
        if (nsample < 0) {
            fprintf(stderr, "zipopt simulate: --sample-times: %s; expected times >= 0 in s\n",
                    why);
            goto done;
        }
        qsort(samples, nsample, sizeof *samples, cmp_double);
    }
    zp_sim_opts o;
    if (zp_sim_opts_from_scene(&sc, &o, &d)) {
        zp_diag_print(&d, stderr);
        goto done;
    }
    status = ZP_EXIT_FAIL;
    s = zp_sim_create(m, &o);
    if (!s) {
        fputs("zipopt simulate: cannot create the simulator (out of memory)\n", stderr);
        goto done;
    }
    static zp_result r; /* large: kept off the stack */
    zp_input in = {.force = sc.forces, .sample_t = samples, .nsample = nsample};
    if (zp_sim_run(m, s, &in, &r)) {
        fprintf(stderr, "zipopt simulate: %s; nothing was written\n", r.message);
        goto done;
    }
    int nsmp;
    const zp_row *smp = zp_sim_samples(s, &nsmp);
    zp_run_meta meta = {sc.name, zp_method_get(o.method)->name,
                        zp_formulation_get(o.formulation)->name, o.rtol, o.atol, sc.forces};
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", a.out ? a.out : "out/");
    if (!a.out) {
        snprintf(dir, sizeof dir, "out/%s", sc.name);
    }
    status = write_files(dir, m, s, &r, smp, nsmp, &meta);
    if (status == ZP_EXIT_OK) {
        if (a.json) {
            zp_out_json_result(stdout, m, &r, smp, nsmp, &meta);
        } else {
            print_text(m, &r);
            printf("wrote %s/trajectory.csv and %s/summary.json\n", dir, dir);
        }
    }
done:
    free(samples);
    zp_sim_free(s);
    zp_model_free(m);
    return status;
}
