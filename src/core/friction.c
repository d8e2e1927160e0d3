/* docs/model.md "Rolling resistance": the stick test at rest (the simulator locates each stop,
   x' = 0, as a root and applies it there); docs/friction.md. */
#include "friction.h"

#include <math.h>

int zp_friction_hold_at(const zp_model *m, const zp_formulation *form, void *fwork, zp_drive_now dn,
                        const double *y, double *ydot, zp_friction_hold *h) {
    zp_loads ld;
    dn.hold = 1;
    int rc = form->rhs(m, fwork, &dn, y, ydot, &ld);
    if (rc == 0) {
        h->tangential = ld.hold;
        h->normal = ld.normal;
        /* rolling resistance's grip and the friction brake's hold together */
        h->margin = m->mu * fabs(ld.normal) + (dn.zone ? m->brake_friction : 0) - fabs(ld.hold);
    }
    return rc;
}

int zp_friction_settled(const zp_model *m, const zp_chain *c) {
    /* design note: not the kinetic energy alone, which a swinging link passes through zero
       at every turning point; the motion energy above the hanging rest only decays */
    double motion = zp_state_energy(m, c).kinetic, length = 0;
    for (int j = 0; j < m->nlink; j++) {
        motion += m->g * m->B[j] * (1 - cos(c->q[2 + j]));
        length += m->len[j];
    }
    return motion < ZP_FRICTION_SETTLED * m->mtot * m->g * length;
}
