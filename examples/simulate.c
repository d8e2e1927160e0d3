/* Embedding zipopt: load a scene, set the drive forces, simulate, print the result and the
   trajectory's last row. Build against the installed library:
     cc simulate.c $(pkg-config --cflags --libs zipopt) -o simulate
   Run: ./simulate SCENE.ini [F1,F2,..] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <zipopt.h>

#define MAX_FORCES 64

/* "10,10,10" -> forces; returns how many, -1 on a bad item */
static int parse_forces(char *text, double *f) {
    int n = 0;
    for (char *tok = strtok(text, ","); tok; tok = strtok(NULL, ",")) {
        char *end;
        if (n == MAX_FORCES) {
            return -1;
        }
        f[n++] = strtod(tok, &end);
        if (end == tok || *end) {
            return -1;
        }
    }
    return n;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s SCENE.ini [F1,F2,..]\n", argv[0]);
        return 2;
    }
    char err[4096];
    zipopt_scene *sc = zipopt_scene_load(argv[1], err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err); /* FILE:LINE: [section] key: ... */
        return 2;
    }
    double f[MAX_FORCES];
    int n = argc > 2 ? parse_forces(argv[2], f) : 0;
    if (n < 0 || (argc > 2 && zipopt_scene_set_forces(sc, f, n, err, sizeof err))) {
        fprintf(stderr, "%s\n", n < 0 ? "forces: expected numbers separated by commas" : err);
        zipopt_scene_free(sc);
        return 2;
    }
    zipopt_run *run = zipopt_simulate(sc, err, sizeof err);
    if (!run) {
        fprintf(stderr, "simulation failed: %s\n", err);
        zipopt_scene_free(sc);
        return 1;
    }
    printf("zipopt %s, scene %s\n", zipopt_version(), zipopt_scene_name(sc));
    printf("outcome: %s\n", zipopt_outcome_name(zipopt_run_outcome(run)));
    printf("time: %.17g s\n", zipopt_run_get(run, "time"));
    printf("energy residual: %.3g J\n", zipopt_run_get(run, "energy_residual"));
    /* the trajectory: rows x columns, row-major */
    int rows = zipopt_run_rows(run), cols = zipopt_run_columns(run);
    const double *t = zipopt_run_trajectory(run);
    printf("trajectory: %d rows; last:", rows);
    for (int j = 0; rows > 0 && j < cols; j++) {
        printf(" %s=%.6g", zipopt_run_column(run, j), t[(size_t)(rows - 1) * cols + j]);
    }
    printf("\n");
    zipopt_run_free(run);
    zipopt_scene_free(sc);
    return 0;
}
