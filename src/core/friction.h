/* MODEL.md's stick rule for rolling resistance ([physics] rolling): at rest the tangential
   force F_t that keeps the trolley still, against mu |N|. */
#ifndef ZP_FRICTION_H
#define ZP_FRICTION_H

#include "formulation.h"

typedef struct zp_friction_hold {
    double tangential; /* N, F_t: the course's force along (1, f')/|.| keeping x'' = 0 */
    double normal;     /* N, the normal force then */
    double margin;     /* N, mu |N| - |F_t|: >= 0 sticks, < 0 moves off toward -F_t */
} zp_friction_hold;

/* The hold at state y of formulation form (its workspace fwork; ydot: n scratch rates), dn the
   drive and course there. 0, or the rhs's nonzero status (the hold then unset). */
int zp_friction_hold_at(const zp_model *m, const zp_formulation *form, void *fwork, zp_drive_now dn,
                        const double *y, double *ydot, zp_friction_hold *h);

#endif
