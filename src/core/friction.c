/* MODEL.md "Rolling resistance": the stick test at rest (the simulator locates each stop,
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
        h->margin = m->mu * fabs(ld.normal) - fabs(ld.hold);
    }
    return rc;
}
