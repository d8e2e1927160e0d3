/* The full mass matrix of state.c against the kinetic energy summed body by body from the
   centres' velocities (two independent routes to T), and the potential energy in closed form. */
#include <gsl/gsl_rng.h>
#include <math.h>

#include "check.h"
#include "testutil.h"

/* T = 1/2 v^T M v agrees with the body sum to round-off (kg m^2/s^2 scale ~ 1e4) */
#define TOL_REL_ENERGY 1e-12

int main(void) {
    zp_scene sc;
    zp_scene_load_seed(&sc);
    sc.nlink = 4;
    sc.lengths[3] = 1.5;
    sc.masses[3] = 7;
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = zp_model_build(&sc, &d);
    CHECK(m != NULL);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    int n = m->nlink + 2;
    for (int trial = 0; trial < 200; trial++) {
        zp_chain c;
        for (int i = 0; i < n; i++) {
            c.q[i] = 6 * gsl_rng_uniform(rng) - 3;
            c.v[i] = 10 * gsl_rng_uniform(rng) - 5;
        }
        double M[ZP_NQ * ZP_NQ], T = 0;
        zp_state_mass_full(m, c.q, M);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                T += 0.5 * c.v[i] * M[i * n + j] * c.v[j];
                CHECK(M[i * n + j] == M[j * n + i]);
            }
        }
        zp_energy e = zp_state_energy(m, &c);
        CHECK_REL(T, e.kinetic, TOL_REL_ENERGY);
        /* potential: y of each centre walked down the chain by hand */
        double py = c.q[1], U = m->m0 * m->g * py;
        for (int i = 0; i < m->nlink; i++) {
            U += m->mass[i] * m->g * (py - m->half[i] * cos(c.q[2 + i]));
            py -= m->len[i] * cos(c.q[2 + i]);
        }
        CHECK_REL(U, e.potential, 1e-12);
    }
    gsl_rng_free(rng);
    zp_model_free(m);
    return CHECK_DONE();
}
