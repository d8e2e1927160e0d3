/* The g-duration envelope (src/core/envelope.c) on constructed felt-g histories whose
   excursions are known in closed form: g(t) = 5 + 2 sin t read interval by interval stays above
   6 for 2 pi / 3 at a time, above 4 for 4 pi / 3 (the first excursion, from t = 0, is 7 pi / 6),
   never above 8; a jump (an impulse) across a level ends or starts an excursion at its time.
   And on a run: the seed with g_links naming only the first link judges max_g on that link's
   peak alone, and the envelope's longest excursion agrees with one read off a fine trajectory. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "envelope.h"
#include "testutil.h"

#define CROSS_TOL 1e-12 /* s: crossings are bisected to the last bits of t */
#define ROW_DT 1e-4     /* s between the trajectory rows of the run check */

static int sine(double t, double *g, void *user) {
    (void)user;
    *g = 5 + 2 * sin(t);
    return 0;
}

static void check_sine(double h) {
    double level[3] = {6, 4, 8};
    zp_envelope e;
    double g0;
    sine(0, &g0, NULL);
    zp_envelope_start(&e, 3, level, 0, g0);
    double t_end = 10;
    for (double a = 0; a < t_end;) {
        double b = fmin(a + h, t_end), gb;
        sine(b, &gb, NULL);
        zp_envelope_interval(&e, b, gb, sine, NULL);
        a = b;
    }
    zp_envelope_end(&e, t_end);
    CHECK_NEAR(e.longest[0], 2 * M_PI / 3, CROSS_TOL);
    CHECK_NEAR(e.longest[1], 4 * M_PI / 3, CROSS_TOL);
    CHECK(e.longest[2] == 0);

    /* a jump below 4 at t = 1 ends the first excursion above 4 there */
    zp_envelope_start(&e, 3, level, 0, g0);
    double gb;
    sine(1, &gb, NULL);
    zp_envelope_interval(&e, 1, gb, sine, NULL);
    zp_envelope_jump(&e, 1, 3);
    zp_envelope_jump(&e, 1.5, 7); /* and one above 6 starts an excursion at 1.5 */
    zp_envelope_end(&e, 2);
    CHECK_NEAR(e.longest[1], 1, CROSS_TOL);
    CHECK_NEAR(e.longest[0], 0.5, CROSS_TOL);
}

static const char *seed_ini(const char *limits) {
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "[course]\nx_start = 0\nsection = 60  : (x/10 - 3)^2 + 1\n"
             "section = 100 : -x/10 + 16\nsection = 140 : -(x/10 - 12)^2 + 10\n"
             "[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 1\n"
             "[limits]\n%s\n",
             limits);
    return buf;
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

static void check_run(void) {
    zp_scene sc;
    zp_model *m = tu_model(seed_ini("max_g = 12\ng_links = 1\ng_envelope = 1.2:1, 1.05:5"), &sc);
    CHECK(m->g_links == 1u && m->nenv == 2);
    zp_limits lim;
    zp_limits_from_scene(&sc, &lim);
    zp_sim_opts o = tu_opts(&sc, 1e-9);
    o.peaks = zp_limits_need_peaks(&lim);
    CHECK(o.peaks);
    o.output_dt = ROW_DT;
    double f[3] = {20, 20, 20};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(s && zp_sim_run(m, s, &in, &r) == ZP_OK);
    double v[ZP_LIMIT_COUNT];
    zp_limits_reached(m, &r, v);
    CHECK(v[ZP_LIMIT_G] == r.peaks.acc_g[0]);
    CHECK(r.peaks.acc_g[2] > r.peaks.acc_g[0]); /* the toe feels more, and is not judged */

    /* the longest excursion of link 1's felt g above each level, from the rows */
    int n;
    zp_row *rows = rows_copy(s, &n);
    for (int l = 0; l < m->nenv; l++) {
        double longest = 0, since = NAN;
        for (int j = 0; j < n; j++) {
            zp_row_view rv;
            zp_row_derive(m, &rows[j], &rv);
            int above = rv.acc_g[0] > m->env_g[l];
            if (above && isnan(since)) {
                since = rows[j].t;
            } else if (!above && !isnan(since)) {
                longest = fmax(longest, rows[j].t - since);
                since = NAN;
            }
        }
        printf("level %g g: longest %.6f s (rows: %.6f s)\n", m->env_g[l], r.env_longest[l],
               longest);
        CHECK(longest > 0);
        /* rows every ROW_DT see each end of an excursion within a row's spacing */
        CHECK_NEAR(r.env_longest[l], longest, 2 * ROW_DT);
    }
    free(rows);
    zp_sim_free(s);
    zp_model_free(m);
}

int main(void) {
    check_sine(0.3);
    check_sine(1.7);
    check_run();
    return CHECK_DONE();
}
