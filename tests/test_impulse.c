/* The kink impulse (docs/model.md "Section boundaries"): the result is fixed uniquely by two
   properties checked here independently of the formula: the entered constraint holds after
   (A v+ = 0) and the change is along the constraint normal (M (v+ - v-) = Lambda A^T).
   Also: kinetic energy never rises and its drop is what is reported; positions stay; slopes
   that agree give no impulse; both directions of crossing. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "impulse.h"
#include "testutil.h"

/* round-off on momenta of order m v ~ 1e3 kg m/s */
#define TOL_MOMENTUM 1e-9

static void check_one(const zp_model *m, gsl_rng *rng, double s_out, double s_in, double dir) {
    int n = m->nlink + 2;
    zp_chain c;
    memset(&c, 0, sizeof c);
    c.q[0] = 60;
    c.q[1] = 10;
    c.v[0] = dir * (1 + 10 * gsl_rng_uniform(rng));
    c.v[1] = s_out * c.v[0]; /* obeys the section it leaves */
    for (int i = 0; i < m->nlink; i++) {
        c.q[2 + i] = 2 * gsl_rng_uniform(rng) - 1;
        c.v[2 + i] = 4 * gsl_rng_uniform(rng) - 2;
    }
    zp_chain before = c;
    zp_impulse imp;
    CHECK(zp_impulse_apply(m, s_in, &c, &imp) == 0);
    /* the entered constraint holds after */
    CHECK_NEAR(c.v[1], s_in * c.v[0], TOL_MOMENTUM);
    /* M dv is along A = (-s_in, 1, 0..) with magnitude Lambda */
    double M[ZP_NQ * ZP_NQ];
    zp_state_mass_full(m, c.q, M);
    for (int i = 0; i < n; i++) {
        double p = 0;
        for (int j = 0; j < n; j++) {
            p += M[i * n + j] * (c.v[j] - before.v[j]);
        }
        double expect = i == 0 ? -s_in * imp.lambda : i == 1 ? imp.lambda : 0;
        CHECK_NEAR(p, expect, TOL_MOMENTUM);
    }
    for (int i = 0; i < n; i++) {
        CHECK(c.q[i] == before.q[i]);
    }
    /* energy: never rises; the reported loss is the drop of the body-by-body kinetic energy */
    double k0 = zp_state_energy(m, &before).kinetic, k1 = zp_state_energy(m, &c).kinetic;
    CHECK(k1 <= k0 + 1e-12 * k0);
    CHECK(imp.energy_lost >= 0);
    CHECK_NEAR(imp.energy_lost, k0 - k1, 1e-9 * k0);
    if (s_in == s_out) {
        CHECK_NEAR(imp.lambda, 0, 1e-12);
        CHECK_NEAR(imp.energy_lost, 0, 1e-9);
    }
}

int main(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    CHECK(m != NULL);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    for (int trial = 0; trial < 100; trial++) {
        check_one(m, rng, 0.6, -0.1, +1);  /* the seed's first kink, forwards */
        check_one(m, rng, -0.1, 0.6, -1);  /* and rolling back over it */
        check_one(m, rng, -0.1, 0.4, +1);  /* the valley kink */
        check_one(m, rng, 0.3, 0.3, +1);   /* smooth boundary: no impulse */
        check_one(m, rng, -2.0, 3.0, +1);  /* a sharp kink */
    }
    /* the seed's kinks as the model lists them: 0.6 -> -0.1 at x = 60, -0.1 -> 0.4 at 100 */
    CHECK(m->nkink == 2);
    CHECK_NEAR(m->kink[0].x, 60, 0);
    CHECK_NEAR(m->kink[0].slope_in, 0.6, 1e-12);
    CHECK_NEAR(m->kink[0].slope_out, -0.1, 1e-12);
    CHECK_NEAR(m->kink[1].x, 100, 0);
    CHECK_NEAR(m->kink[1].slope_in, -0.1, 1e-12);
    CHECK_NEAR(m->kink[1].slope_out, 0.4, 1e-12);
    gsl_rng_free(rng);
    zp_model_free(m);
    return CHECK_DONE();
}
