/* The loaded-cable path's table (cable_path.h) against the direct solve (cable_solve.h) at
   random x: every value to 1e-13 of its size beyond the direct solve's own round-off; nothing
   evaluated outside the built interval; bad intervals refused; threads sharing one path read
   the same bits; the anchor tensions fitted on the same pieces agree with the exact chain of
   equilibria (cable_ride.h) to 1e-13. Build and evaluation times are printed, not asserted. */
#include <math.h>
#include <pthread.h>
#include <string.h>
#include <time.h>

#include "cable.h"
#include "cable_path.h"
#include "cable_ride.h"
#include "cable_solve.h"
#include "check.h"

#define G 9.81
#define SAMPLES 300
/* the table against the direct solve, relative to each value's size, */
#define TOL_PATH 1e-13
/* beyond this many times the direct solve's own round-off, measured as the largest difference
   of two solves at one x (from scratch, and from a neighbour): the series carry the round-off
   of their points up to 3.2 times (the Lebesgue constant of 32 Chebyshev points), the sample
   adds its own, and one pair per sample may see half the largest. It matters for f'', the
   tensions and Pi_c, which the geometry sets through about EA / L0 (a few hundred), or through
   a near-vertical side: their round-off reaches 1e-13 .. 1e-12 of their size. */
#define ROUNDOFF_FACTOR 8
#define THREADS 4

static double wall_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double cpu_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* a reproducible uniform number in [0, 1) */
static double uniform(unsigned long long *state) {
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) * 0x1p-53;
}

typedef struct line {
    const char *name;
    zp_cable_def def;
    double load, lo, hi; /* N, m, m */
} line;

static void check_line(const line *ln) {
    zp_cable c;
    char why[256];
    CHECK(zp_cable_build(&ln->def, &c, why, sizeof why) == ZP_OK);
    double w0 = wall_s(), c0 = cpu_s();
    zp_cable_path *p = zp_cable_path_create(&c, ln->load, ln->lo, ln->hi, why, sizeof why);
    double build_wall = wall_s() - w0, build_cpu = cpu_s() - c0;
    CHECK(p != NULL);
    if (!p) {
        fprintf(stderr, "%s: %s\n", ln->name, why);
        return;
    }
    /* the largest error of each value, its size and the direct solve's round-off, over x */
    enum { F, FP, FPP, ENERGY, HA, HB, NVAL };
    double err[NVAL] = {0}, size[NVAL] = {0}, noise[NVAL] = {0};
    unsigned long long rng = 12345;
    for (int i = 0; i < SAMPLES; i++) {
        double x = ln->lo + (ln->hi - ln->lo) * uniform(&rng);
        double from =
            x > 0.5 * (ln->lo + ln->hi) ? x - 0.01 * (c.xb - c.xa) : x + 0.01 * (c.xb - c.xa);
        zp_cable_state s, neighbour, again;
        zp_cable_path_value v;
        CHECK(zp_cable_solve(&c, ln->load, x, &s, why, sizeof why) == ZP_OK);
        CHECK(zp_cable_solve(&c, ln->load, from, &neighbour, why, sizeof why) == ZP_OK);
        CHECK(zp_cable_solve_near(&c, &neighbour, x, &again, why, sizeof why) == ZP_OK);
        CHECK(zp_cable_path_eval(p, x, &v) == 0);
        double track[3];
        CHECK(zp_cable_path_track(p, x, track) == 0);
        CHECK(track[0] == v.f && track[1] == v.fp && track[2] == v.fpp);
        CHECK(v.denergy == (v.ha - v.hb) - ln->load * v.fp);
        const double direct[NVAL] = {s.f, s.fp, s.fpp, s.energy, s.ha, s.hb};
        const double table[NVAL] = {v.f, v.fp, v.fpp, v.energy, v.ha, v.hb};
        const double other[NVAL] = {again.f, again.fp, again.fpp, again.energy, again.ha, again.hb};
        for (int k = 0; k < NVAL; k++) {
            err[k] = fmax(err[k], fabs(direct[k] - table[k]));
            size[k] = fmax(size[k], fabs(direct[k]));
            noise[k] = fmax(noise[k], fabs(direct[k] - other[k]));
        }
    }
    for (int k = 0; k < NVAL; k++) {
        /* Pi_c of a weightless inextensible cable is 0 throughout */
        double tol = TOL_PATH * (size[k] > 0 ? size[k] : 1) + ROUNDOFF_FACTOR * noise[k];
        CHECK_NEAR(err[k], 0, tol);
    }
    /* the anchor tensions fitted on the same pieces: over a stretch, as the exact chain of
       equilibria at the same x (what max_cable_tension is judged by away from the limit) */
    double exact, lo = ln->lo + 0.1 * (ln->hi - ln->lo), hi = ln->hi - 0.2 * (ln->hi - ln->lo);
    CHECK(zp_cable_ride_anchor_max(&c, ln->load, lo, hi, &exact, why, sizeof why) == ZP_OK);
    CHECK_NEAR(zp_cable_path_anchor_max(p, lo, hi), exact, TOL_PATH * exact);
    CHECK(isnan(zp_cable_path_anchor_max(p, ln->lo - 1e-3, hi)));
    /* the fast evaluation of f, f', f'' together */
    enum { EVALS = 1000000 };
    double sum = 0, f[3], e0 = cpu_s();
    for (int i = 0; i < EVALS; i++) {
        double u = fmod(0.6180339887498949 * i, 1.0);
        zp_cable_path_track(p, ln->lo + (ln->hi - ln->lo) * u, f);
        sum += f[0] + f[1] + f[2];
    }
    double eval_ns = (cpu_s() - e0) / EVALS * 1e9;
    CHECK(isfinite(sum));
    printf("%s: %d pieces, tail %.1e; built in %.2f ms (%.2f ms CPU); f, f', f'' in %.0f ns CPU\n",
           ln->name, zp_cable_path_pieces(p), zp_cable_path_tail(p), build_wall * 1e3,
           build_cpu * 1e3, eval_ns);
    const char *names[NVAL] = {"f", "f'", "f''", "Pi_c", "H_A", "H_B"};
    printf("  table - direct, relative to size (direct's own round-off):");
    for (int k = 0; k < NVAL; k++) {
        double sz = size[k] > 0 ? size[k] : 1;
        printf(" %s %.1e (%.1e)", names[k], err[k] / sz, noise[k] / sz);
    }
    printf("\n");
    zp_cable_path_free(p);
}

static const line lines[] = {
    {"realistic, 85 kg", {0, 40, 350, 5, 0, 20000, 5.4, 8e6}, 85 * G, 3.5, 346.5},
    {"realistic, empty", {0, 40, 350, 5, 0, 20000, 5.4, 8e6}, 0, 3.5, 346.5},
    {"realistic, 300 kg near the anchors",
     {0, 40, 350, 5, 0, 20000, 5.4, 8e6},
     300 * G,
     0.05,
     349.95},
    {"heavy slack rope", {0, 0, 100, 30, 160, 0, 10, INFINITY}, 400, 1, 99},
    {"weightless inextensible (ellipse)", {0, 30, 120, 10, 130, 0, 0, INFINITY}, 800, 1.2, 118.8},
    {"weightless elastic", {0, 0, 100, -10, 104, 0, 0, 2e5}, 1500, 1, 99},
};

/* nothing past the built interval: a status and NaN */
static void test_outside(void) {
    zp_cable c;
    char why[256];
    CHECK(zp_cable_build(&lines[0].def, &c, why, sizeof why) == ZP_OK);
    zp_cable_path *p = zp_cable_path_create(&c, 85 * G, 3.5, 346.5, why, sizeof why);
    CHECK(p != NULL);
    if (!p) {
        return;
    }
    double lo, hi, f[3];
    zp_cable_path_interval(p, &lo, &hi);
    CHECK(lo == 3.5 && hi == 346.5);
    CHECK(zp_cable_path_track(p, lo, f) == 0 && zp_cable_path_track(p, hi, f) == 0);
    const double outside[] = {nextafter(lo, 0), nextafter(hi, 400), 350, 351, -1, NAN, INFINITY};
    for (int i = 0; i < 7; i++) {
        zp_cable_path_value v;
        CHECK(zp_cable_path_track(p, outside[i], f) == -1);
        CHECK(isnan(f[0]) && isnan(f[1]) && isnan(f[2]));
        CHECK(zp_cable_path_eval(p, outside[i], &v) == -1);
        CHECK(isnan(v.f) && isnan(v.energy) && isnan(v.ha) && isnan(v.denergy));
    }
    zp_cable_path_free(p);
    /* intervals that reach an anchor, or are empty; a negative load */
    const double bad[][2] = {{0, 100}, {-1, 100}, {3.5, 350}, {3.5, 360}, {200, 100}, {50, 50}};
    for (int i = 0; i < 6; i++) {
        CHECK(zp_cable_path_create(&c, 85 * G, bad[i][0], bad[i][1], why, sizeof why) == NULL);
        CHECK(strstr(why, "expected") != NULL);
    }
    CHECK(zp_cable_path_create(&c, -1, 3.5, 346.5, why, sizeof why) == NULL);
    CHECK(strstr(why, "load") != NULL);
    zp_cable_path_free(NULL);
}

typedef struct reader {
    const zp_cable_path *p;
    double f[SAMPLES][3];
} reader;

static void *read_path(void *arg) {
    reader *r = arg;
    for (int i = 0; i < SAMPLES; i++) {
        zp_cable_path_track(r->p, 3.5 + 343.0 * i / (SAMPLES - 1), r->f[i]);
    }
    return NULL;
}

/* one path, read by several threads at once: the same bits as one thread */
static void test_threads(void) {
    zp_cable c;
    char why[256];
    CHECK(zp_cable_build(&lines[0].def, &c, why, sizeof why) == ZP_OK);
    zp_cable_path *p = zp_cable_path_create(&c, 85 * G, 3.5, 346.5, why, sizeof why);
    CHECK(p != NULL);
    if (!p) {
        return;
    }
    static reader serial, each[THREADS];
    serial.p = p;
    read_path(&serial);
    pthread_t th[THREADS];
    for (int t = 0; t < THREADS; t++) {
        each[t].p = p;
        CHECK(pthread_create(&th[t], NULL, read_path, &each[t]) == 0);
    }
    for (int t = 0; t < THREADS; t++) {
        CHECK(pthread_join(th[t], NULL) == 0);
        CHECK(memcmp(each[t].f, serial.f, sizeof serial.f) == 0);
    }
    zp_cable_path_free(p);
}

int main(void) {
    for (size_t i = 0; i < sizeof lines / sizeof *lines; i++) {
        check_line(&lines[i]);
    }
    test_outside();
    test_threads();
    return CHECK_DONE();
}
