/* Shared by the tests: a model from inline scene text, and one run with given options. */
#ifndef ZP_TESTUTIL_H
#define ZP_TESTUTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "objective.h"
#include "scene_load.h"
#include "sim.h"
#include "sim_opts.h"

/* Builds a model from scene text; aborts the test on bad input (a broken test, not a check). */
static inline zp_model *tu_model(const char *ini, zp_scene *sc) {
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = NULL;
    if (zp_scene_load_string(ini, "test.ini", sc, &d) == ZP_OK) {
        m = zp_model_build(sc, &d);
    }
    if (!m) {
        zp_diag_print(&d, stderr);
        abort();
    }
    return m;
}

/* The built-in seed scene and its model; aborts if it does not build (a broken test). */
static inline zp_model *tu_seed_model(zp_scene *sc) {
    zp_diag d;
    zp_diag_init(&d);
    zp_scene_load_seed(sc);
    zp_model *m = zp_model_build(sc, &d);
    if (!m) {
        zp_diag_print(&d, stderr);
        abort();
    }
    return m;
}

/* A scene file and its model; NULL (its diagnostics printed) where it does not load or build,
   for the test to check. */
static inline zp_model *tu_model_file(const char *path, zp_scene *sc) {
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = zp_scene_load(path, sc, &d) == ZP_OK ? zp_model_build(sc, &d) : NULL;
    if (!m) {
        zp_diag_print(&d, stderr);
    }
    return m;
}

/* Options of the scene with the given tolerance (atol = rtol / 100) and no trajectory. */
static inline zp_sim_opts tu_opts(const zp_scene *sc, double rtol) {
    zp_sim_opts o;
    zp_diag d;
    zp_diag_init(&d);
    if (zp_sim_opts_from_scene(sc, &o, &d)) {
        zp_diag_print(&d, stderr);
        abort();
    }
    o.rtol = rtol;
    o.atol = rtol / 100;
    o.output_dt = 0;
    return o;
}

/* The workspace of the last tu_run (kept for its kink crossings until the next call). */
static inline zp_sim **tu_last_sim(void) {
    static zp_sim *s;
    return &s;
}

/* One run; the result lives in static storage until the next call. */
static inline const zp_result *tu_run(const zp_model *m, const zp_sim_opts *o, const zp_input *in) {
    static zp_result r;
    zp_sim_free(*tu_last_sim());
    zp_sim *s = *tu_last_sim() = zp_sim_create(m, o);
    if (!s || zp_sim_run(m, s, in, &r) != ZP_OK) {
        fprintf(stderr, "run failed: %s\n", r.message);
        abort();
    }
    return &r;
}

/* A spy on a straight slope whose swing grows with the push: survival is monotone in the one
   force, so the optimum is the largest push that keeps the margin. */
static const char *const tu_swing =
    "[course]\nx_start = 0\nsection = 40 : -x/10 + 10\n"
    "[trolley]\nmass = 30\n"
    "[body]\nlengths = 1\nmasses = 5\ndamping = 2\ndeath_angle = 30\n"
    "[drive]\nmin = 0\nmax = 400\n"
    "[optimize]\nmargin = 5\nmax_evals = 400\n";

/* m/m: a 1 g link on a 30 kg trolley changes its acceleration by ~3e-5 of itself, so a bare
   trolley's time agrees with tu_slope_time to this */
#define TU_BARE_TOL 2e-4

/* s: a point trolley of `mass` kg from rest down a straight slope of drop `slope` per metre over
   `length` m of x, pushed with `force` N horizontally (along the slope: force cos(alpha)) */
static inline double tu_slope_time(double length, double slope, double force, double mass) {
    double alpha = atan(slope);
    double a = 9.81 * sin(alpha) + force / mass * cos(alpha);
    return sqrt(2 * (length / cos(alpha)) / a);
}

/* The search's objective for m: the scene's margin, the options' t_max, no limits or set. */
static inline zp_objective tu_objective(const zp_model *m, const zp_scene *sc,
                                        const zp_sim_opts *o) {
    return (zp_objective){.m = m, .limit = m->phi_max - sc->margin * M_PI / 180,
                          .t_max = o->t_max};
}

/* The scene's box of pushes, the same bounds for every section: lo, hi (sc->nsec each). */
static inline void tu_scene_box(const zp_scene *sc, double *lo, double *hi) {
    for (int k = 0; k < sc->nsec; k++) {
        lo[k] = sc->force_min;
        hi[k] = sc->force_max;
    }
}

/* The kink crossings of the last tu_run. */
static inline const zp_crossing *tu_crossings(void) {
    int n;
    return zp_sim_crossings(*tu_last_sim(), &n);
}

/* Per-section constant forces f (N, one per section of m) as a schedule. */
static inline zp_schedule tu_sched(const zp_model *m, const double *f) {
    return zp_drive_sections(m->nsec, f, 0, 0);
}

/* Runs a shell command; its stdout (up to cap - 1 bytes) in out; returns its exit status. */
static inline int tu_sh(const char *cmd, char *out, size_t cap) {
    FILE *p = popen(cmd, "r");
    size_t n = p ? fread(out, 1, cap - 1, p) : 0;
    out[n] = '\0';
    int st = p ? pclose(p) : -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static inline int tu_exists(const char *path) {
    struct stat sb;
    return stat(path, &sb) == 0;
}

/* The file at path into buf (at most n - 1 bytes, NUL added); its length, or -1 if absent. */
static inline long tu_slurp(const char *path, char *buf, size_t n) {
    FILE *f = fopen(path, "r");
    size_t k = f ? fread(buf, 1, n - 1, f) : 0;
    buf[k] = '\0';
    if (f) {
        fclose(f);
    }
    return f ? (long)k : -1;
}

/* Whole lines (newlines) in the file at path: 0 if absent. */
static inline int tu_count_lines(const char *path) {
    FILE *f = fopen(path, "r");
    int n = 0;
    for (int c; f && (c = getc(f)) != EOF;) {
        n += c == '\n';
    }
    if (f) {
        fclose(f);
    }
    return n;
}

#ifdef ZP_MPIEXEC
/* mpirun, or NULL after saying why the test skips (exit 77): zipopt built without MPI, or no
   mpirun */
static inline const char *tu_mpirun(void) {
    const char *mpirun = ZP_MPIEXEC;
    if (!*mpirun || access(mpirun, X_OK)) {
        printf("SKIP: zipopt is built without MPI or mpirun is missing (install openmpi-bin and "
               "libopenmpi-dev, then rebuild)\n");
        return NULL;
    }
    return mpirun;
}
#endif

#endif
