/* The bang-bang search (optim/pinned.c): which parameters it sets to the top of the box and
   which it searches, and, on a course where the largest push wins (a bare trolley down one straight
   slope cut into three sections), that from a schedule with one push near the top it reaches
   the top everywhere, at the closed-form time, within the simulations it says it may spend.
   Independent expectations: the box arithmetic by hand, and the closed-form time of a trolley
   pushed down a straight slope. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "pinned.h"
#include "testutil.h"

static const char *bare3 = "[course]\nx_start = 0\nsection = 10 : -x/10 + 10\n"
                           "section = 25 : y0 - (x - 10)/10\nsection = 40 : y0 - (x - 25)/10\n"
                           "[trolley]\nmass = 30\n"
                           "[body]\nlengths = 0.2\nmasses = 0.001\ndamping = 0\n"
                           "[drive]\nmin = 0\nmax = 50\n"
                           "[optimize]\nmargin = 10\n";

/* which parameters a schedule pins, on a box of five of [0, 100] and one of [7, 7] */
static void pins(void) {
    double lo[6] = {0, 0, 0, 0, 0, 7}, hi[6] = {100, 100, 100, 100, 100, 7};
    zp_objective ob = {.t_max = 60};
    zp_search_state S = {.ob = &ob, .n = 6, .lo = lo, .hi = hi};
    zp_subsearch p;
    CHECK(zp_pinned_make(&p, &S, (double[6]){97, 50, 3, 100, 40, 7}, 5) == 1);
    const double want[6] = {100, 50, 3, 100, 40, 7}; /* the top only: 3 N stays free */
    CHECK(!memcmp(p.base, want, sizeof want));
    CHECK(p.nfree == 3 && p.free[0] == 1 && p.free[1] == 2 && p.free[2] == 4);
    CHECK(p.popsize >= 8 && zp_pinned_cap(&p) == 1 + p.gens * p.popsize && p.seed == 5);
    /* nothing near the top, or nothing away from it: nothing to search */
    CHECK(zp_pinned_make(&p, &S, (double[6]){50, 0, 50, 5, 50, 7}, 5) == 0);
    CHECK(zp_pinned_make(&p, &S, (double[6]){100, 96, 97, 99, 98, 7}, 5) == 0);
    /* either side of "near" (5 % of the box from the top) */
    CHECK(zp_pinned_make(&p, &S, (double[6]){94, 96, 0.1, 50, 50, 7}, 5) == 1);
    CHECK(p.nfree == 4 && p.base[0] == 94 && p.base[1] == 100 && p.base[2] == 0.1);
}

/* the search on a fresh state of the bare course from (48, 20, 30) N */
static void reaches_the_top(void) {
    zp_scene sc;
    zp_model *m = tu_model(bare3, &sc);
    CHECK(sc.nsec == 3);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_objective ob = tu_objective(m, &sc, &o);
    double lo[3] = {0, 0, 0}, hi[3] = {50, 50, 50}, x0[3] = {48, 20, 30};
    static zp_search_result r;
    zp_search_opts so = {.max_evals = 100000, .seed = 1, .nthreads = 1};
    zp_search_state S;
    char err[256];
    zp_search_state_begin(&S, &ob, lo, hi, &so, &r);
    CHECK(zp_search_state_start(&S, &o, err, sizeof err) == ZP_OK);
    zp_subsearch p;
    CHECK(zp_pinned_make(&p, &S, x0, 3) == 1 && p.nfree == 2 && p.base[0] == 50);
    zp_leg_rec rec;
    zp_leg_job job = {.x0 = x0, .cap = zp_pinned_cap(&p), .out = &rec};
    CHECK(zp_leg_batch(&S, zp_pinned_run, &p, &job, 1, err, sizeof err) == ZP_OK);
    CHECK(rec.n > 100 && rec.n <= job.cap && S.spent == rec.n);
    double t = tu_slope_time(40, 0.1, 50, 30 + 0.001);
    CHECK(zp_objective_feasible(&rec.e));
    CHECK_REL(rec.e.time, t, TU_BARE_TOL);
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(rec.end[k], 50, 1e-6);
    }
    zp_search_state_end(&S);
    zp_model_free(m);
}

int main(void) {
    pins();
    reaches_the_top();
    return CHECK_DONE();
}
