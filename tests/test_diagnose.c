/* The diagnosis of an answer's failures: on made-up verdicts whose rule is known (heavy riders
   die, a weak drive breaks the margin, every seventh scenario breaks max_g by a known excess)
   each count, each range's halves and each needed limit equal the rule's own tally; on the
   seed's robust verification the broken scenarios are exactly those the verification does not
   count as kept. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "diagnose.h"
#include "testutil.h"

#define N 400

static void made_up(void) {
    zp_model m;
    memset(&m, 0, sizeof m);
    m.phi_max = M_PI;
    zp_objective ob = {.m = &m, .limit = M_PI - 10 * M_PI / 180};
    ob.lim.max[ZP_LIMIT_G] = 12;
    /* two force coordinates, the rider's mass third, no other range */
    zp_box b = {.d = 3,
                .nforce = 2,
                .force_error = 0.05,
                .dim = {2, -1, -1, -1},
                .theta0 = -1,
                .nlink = 3,
                .range = {{0.8, 1.2}}};
    static zp_robust_worst each[N];
    int died = 0, margin = 0, g = 0, heavy = 0, heavy_bad = 0, weak = 0, weak_bad = 0;
    double need = 0;
    unsigned long x = 12345;
    for (int i = 0; i < N; i++) {
        zp_robust_worst *w = &each[i];
        for (int c = 0; c < 3; c++) {
            x = x * 6364136223846793005UL + 1442695040888963407UL;
            w->u[c] = (double)(x >> 11) / (double)(1UL << 53) * 2 - 1;
        }
        w->outcome = ZP_OUTCOME_FINISHED;
        w->margin_deg = 40;
        w->limit = ZP_LIMIT_G;
        w->excess = -0.2;
        int bad = 1;
        if (w->u[2] > 0.5) {
            w->outcome = ZP_OUTCOME_DIED;
            died++;
        } else if ((w->u[0] + w->u[1]) / 2 < -0.6) {
            w->margin_deg = 5 + (i % 4); /* 5..8 deg left of 10 */
            margin++;
        } else if (i % 7 == 0) {
            w->excess = 0.1 * (i % 3 + 1);
            need = fmax(need, 12 * (1 + w->excess));
            g++;
        } else {
            bad = 0;
        }
        heavy += w->u[2] >= 0;
        heavy_bad += w->u[2] >= 0 && bad;
        weak += (w->u[0] + w->u[1]) / 2 < 0;
        weak_bad += (w->u[0] + w->u[1]) / 2 < 0 && bad;
    }
    zp_diagnosis d;
    zp_diagnose(&b, &ob, each, N, &d);
    CHECK(d.samples == N && d.broken == died + margin + g);
    CHECK(d.by[ZP_FAIL_DIED] == died && d.by[ZP_FAIL_MARGIN] == margin);
    CHECK(d.by[ZP_FAIL_LIMIT + ZP_LIMIT_G] == g && d.by[ZP_FAIL_STALLED] == 0);
    CHECK(died > 0 && margin > 0 && g > 0);
    CHECK(fabs(d.needed[ZP_LIMIT_G] - need) < 1e-12 && d.needed[ZP_LIMIT_JOINT] == 0);
    CHECK(d.margin_deg == 5);
    CHECK(d.range[1].varied && d.range[0].varied && !d.range[2].varied && !d.range[5].varied);
    CHECK(d.range[1].n[1] == heavy && d.range[1].bad[1] == heavy_bad);
    CHECK(d.range[1].n[0] + d.range[1].n[1] == N);
    CHECK(d.range[0].n[0] == weak && d.range[0].bad[0] == weak_bad);
    CHECK(!strcmp(zp_diagnose_kind_name(ZP_FAIL_LIMIT + ZP_LIMIT_G), "max_g"));
    CHECK(fabs(d.range[1].edge[0] - 80) < 1e-12 && fabs(d.range[1].edge[1] - 100) < 1e-12 &&
          fabs(d.range[1].edge[2] - 120) < 1e-12);
    CHECK(fabs(d.range[0].edge[0] + 5) < 1e-12 && d.range[0].edge[1] == 0);
}

/* the seed at the nominal optimum, held to +/-5 % forces: most scenarios break it */
static void seed_verify(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    sc.force_error = 5;
    sc.robust = 1;
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    zp_objective ob = {.m = m, .limit = m->phi_max - 10 * M_PI / 180, .t_max = sc.t_max};
    zp_sim_opts o = tu_opts(&sc, 1e-7);
    double p[3] = {59.58914569124449, 500, 500};
    enum { NV = 64 };
    static zp_robust_worst each[NV];
    zp_robust_check c;
    CHECK(zp_robust_verify_each(&ob, &b, &o, p, NV, 1, 0, NULL, &c, each) == ZP_OK);
    zp_diagnosis d;
    zp_diagnose(&b, &ob, each, NV, &d);
    CHECK(d.broken == NV - c.all_kept);
    CHECK(d.by[ZP_FAIL_DIED] + d.by[ZP_FAIL_STALLED] == NV - c.survived);
    CHECK(d.broken > 0 && d.range[0].varied && !d.range[1].varied);
    zp_model_free(m);
}

int main(void) {
    made_up();
    seed_verify();
    return CHECK_DONE();
}
