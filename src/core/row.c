/* A row's derived quantities, computed by one function for every reader. */
#include "row.h"

#include <math.h>

void zp_row_loads(const zp_model *m, const zp_loads *loads, double *joint, double *acc_g) {
    for (int i = 0; i < m->nlink; i++) {
        joint[i] = hypot(loads->joint[i][0], loads->joint[i][1]);
        acc_g[i] = hypot(loads->acc[i + 1][0], loads->acc[i + 1][1] + m->g) / m->g;
    }
}

void zp_row_derive(const zp_model *m, const zp_row *r, zp_row_view *v) {
    v->speed = hypot(r->c.v[0], r->c.v[1]);
    zp_state_com(m, &r->c, v->com);
    zp_state_relative(m, &r->c, v->phi, v->w);
    v->e = zp_state_energy(m, &r->c);
    zp_row_loads(m, &r->loads, v->joint, v->acc_g);
}
