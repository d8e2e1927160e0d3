/* The perfectly plastic, frictionless kink impulse of docs/model.md, in chain coordinates
   q = (x, y, theta): the only place that changes velocities discontinuously. */
#include "impulse.h"

#include <gsl/gsl_linalg.h>

int zp_impulse_apply(const zp_model *m, double slope_in, zp_chain *c, zp_impulse *out) {
    int n = m->nlink + 2;
    double M[ZP_NQ * ZP_NQ], z[ZP_NQ], a[ZP_NQ] = {0};
    zp_state_mass_full(m, c->q, M);
    a[0] = -slope_in;
    a[1] = 1.0;
    /* z = M^-1 A^T by Cholesky (M is overwritten by its factor) */
    gsl_matrix_view Mv = gsl_matrix_view_array(M, n, n);
    gsl_vector_view av = gsl_vector_view_array(a, n), zv = gsl_vector_view_array(z, n);
    if (gsl_linalg_cholesky_decomp1(&Mv.matrix) ||
        gsl_linalg_cholesky_solve(&Mv.matrix, &av.vector, &zv.vector)) {
        return 1;
    }
    double av_dot = 0.0, az = 0.0;
    for (int i = 0; i < n; i++) {
        av_dot += a[i] * c->v[i];
        az += a[i] * z[i];
    }
    double lambda = -av_dot / az;
    for (int i = 0; i < n; i++) {
        c->v[i] += z[i] * lambda;
    }
    /* v+^T M v+ = v^T M v - (A v)^2 / (A M^-1 A^T): the loss is 1/2 Lambda^2 A M^-1 A^T >= 0 */
    out->lambda = lambda;
    out->energy_lost = 0.5 * lambda * lambda * az;
    return 0;
}
