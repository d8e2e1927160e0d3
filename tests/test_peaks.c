/* Exact load peaks (src/core/peaks.c): at the scene's tolerance, every reported peak of felt
   acceleration (per link) and joint force (per joint) is within 1e-7 relative of the peak
   located on a fine resampling of the same run's dense output, over random schedules on the
   seed and human.ini. Independent expectation: the resampling sees the run only through
   trajectory rows and samples (outputs never change a run) - rows every millisecond, then
   around each coarse maximum near the top 401 samples and a parabola through the best three,
   plus the states just before and after every kink. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "peaks.h"
#include "testutil.h"

#define SCHEDULES 8    /* random schedules per scene */
#define PEAK_REL 1e-7  /* the bound on a reported peak against the resampled one */
#define COARSE_DT 1e-3 /* s between rows */
#define FINE_N 401     /* samples across two coarse intervals around a coarse maximum */
#define NEAR_TOP 0.98  /* coarse maxima below this share of the coarse top are not refined */
#define MAXC 64        /* candidate maxima refined per history */

static zp_model *scene_model(const char *path, zp_scene *sc) {
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = NULL;
    if (zp_scene_load(path, sc, &d) == ZP_OK) {
        m = zp_model_build(sc, &d);
    }
    if (!m) {
        zp_diag_print(&d, stderr);
        abort();
    }
    return m;
}

/* history q (felt g per link, then force per joint) of a row */
static double history(const zp_model *m, const zp_row *r, int q) {
    double joint[ZP_MAX_LINKS], acc[ZP_MAX_LINKS];
    zp_row_loads(m, &r->loads, joint, acc);
    return q < m->nlink ? acc[q] : joint[q - m->nlink];
}

/* the trajectory rows of s's last run, copied out of its packed store (the caller frees) */
static zp_row *rows_copy(const zp_sim *s, int *n) {
    const zp_row_store *st = zp_sim_rows(s);
    zp_row *v = malloc(sizeof *v * (size_t)(st->n > 0 ? st->n : 1));
    for (int k = 0; v && k < st->n; k++) {
        zp_row_store_get(st, k, &v[k]);
    }
    *n = v ? st->n : 0;
    return v;
}

static const zp_row *run_rows(const zp_model *m, zp_sim *s, zp_input *in, zp_result *r, int *n,
                              int samples) {
    if (zp_sim_run(m, s, in, r) != ZP_OK) {
        fprintf(stderr, "run failed: %s\n", r->message);
        abort();
    }
    static zp_row *copy; /* the last rows copied out, kept until the next call */
    if (samples) {
        return zp_sim_samples(s, n);
    }
    free(copy);
    return copy = rows_copy(s, n);
}

static void check_schedule(const zp_model *m, const zp_scene *sc, const double *f) {
    zp_sim_opts o = tu_opts(sc, sc->rtol);
    o.atol = sc->atol;
    o.peaks = 1;
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    static zp_result r, rr;
    zp_sim *s = zp_sim_create(m, &o);
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK);
    int nq = 2 * m->nlink;
    double reported[ZP_PEAKS_MAX];
    for (int i = 0; i < m->nlink; i++) {
        reported[i] = r.peaks.acc_g[i];
        reported[m->nlink + i] = r.peaks.joint[i];
    }
    /* the kinks' times: the states just before and after each count as they are */
    int nk;
    const zp_crossing *cr = zp_sim_crossings(s, &nk);
    double kt[2 * ZP_MAX_SECTIONS];
    int nkt = 0;
    for (int k = 0; k < nk && nkt + 2 <= 2 * ZP_MAX_SECTIONS; k++) {
        kt[nkt++] = cr[k].t - 2e-9;
        kt[nkt++] = cr[k].t;
    }
    zp_sim_free(s);

    /* coarse rows, then each coarse maximum near the top resampled finely */
    zp_sim_opts fo = o;
    fo.peaks = 0;
    fo.output_dt = COARSE_DT;
    zp_sim *fs = zp_sim_create(m, &fo);
    int n;
    const zp_row *rows = run_rows(m, fs, &in, &rr, &n, 0);
    CHECK(rr.outcome == r.outcome && rr.time == r.time);
    double top[ZP_PEAKS_MAX], cand[ZP_PEAKS_MAX][MAXC];
    int ncand[ZP_PEAKS_MAX] = {0};
    for (int q = 0; q < nq; q++) {
        top[q] = 0;
        for (int j = 0; j < n; j++) {
            top[q] = fmax(top[q], history(m, &rows[j], q));
        }
        for (int j = 1; j + 1 < n && ncand[q] < MAXC; j++) {
            double v = history(m, &rows[j], q);
            if (v >= NEAR_TOP * top[q] && v >= history(m, &rows[j - 1], q) &&
                v >= history(m, &rows[j + 1], q)) {
                cand[q][ncand[q]++] = rows[j].t;
            }
        }
    }
    zp_sim_opts so = fo;
    so.output_dt = 0;
    zp_sim *ss = zp_sim_create(m, &so);
    double fine[ZP_PEAKS_MAX];
    for (int q = 0; q < nq; q++) {
        fine[q] = top[q];
        for (int c = 0; c < ncand[q]; c++) {
            static double ts[FINE_N];
            for (int j = 0; j < FINE_N; j++) {
                ts[j] = cand[q][c] + COARSE_DT * (2.0 * j / (FINE_N - 1) - 1);
            }
            in.sample_t = ts;
            in.nsample = FINE_N;
            const zp_row *smp = run_rows(m, ss, &in, &rr, &n, 1);
            int best = 0;
            for (int j = 1; j < n; j++) {
                best = history(m, &smp[j], q) > history(m, &smp[best], q) ? j : best;
            }
            double v0 = history(m, &smp[best], q), peak = v0;
            /* a parabola through the best three, when they lie on one smooth piece */
            if (best > 0 && best + 1 < n && smp[best - 1].sec == smp[best + 1].sec) {
                double vl = history(m, &smp[best - 1], q), vr = history(m, &smp[best + 1], q);
                double den = vl - 2 * v0 + vr;
                if (den < 0) {
                    peak = v0 - 0.125 * (vr - vl) * (vr - vl) / den;
                }
            }
            fine[q] = fmax(fine[q], peak);
        }
        in.sample_t = kt;
        in.nsample = nkt;
        const zp_row *smp = run_rows(m, ss, &in, &rr, &n, 1);
        for (int j = 0; j < n; j++) {
            fine[q] = fmax(fine[q], history(m, &smp[j], q));
        }
        in.sample_t = NULL;
        in.nsample = 0;
        CHECK_REL(reported[q], fine[q], PEAK_REL);
    }
    zp_sim_free(ss);
    zp_sim_free(fs);
}

static void check_scene(const char *name, unsigned seed) {
    char path[512];
    snprintf(path, sizeof path, "%s/config/%s", ZP_SOURCE_DIR, name);
    zp_scene sc;
    zp_model *m = scene_model(path, &sc);
    srand(seed);
    for (int k = 0; k < SCHEDULES; k++) {
        double f[ZP_MAX_SECTIONS];
        for (int i = 0; i < m->nsec; i++) {
            f[i] = sc.force_min + (sc.force_max - sc.force_min) * rand() / (double)RAND_MAX;
        }
        check_schedule(m, &sc, f);
    }
    zp_model_free(m);
}

int main(void) {
    check_scene("seed.ini", 1);
    check_scene("human.ini", 2);
    return CHECK_DONE();
}
