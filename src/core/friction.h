/* docs/model.md's stick rule for rolling resistance ([physics] rolling) and the friction brake
   ([brake] friction): at rest the tangential force F_t that keeps the trolley still, against
   mu |N| plus the brake's grip in its zone; a held trolley's chain settling. */
#ifndef ZP_FRICTION_H
#define ZP_FRICTION_H

#include "formulation.h"

/* a held trolley ends the run once its chain's motion energy is below this share of the
   scene's energy scale (docs/model.md) */
#define ZP_FRICTION_SETTLED 1e-9

typedef struct zp_friction_hold {
    double tangential; /* N, F_t: the course's force along (1, f')/|.| keeping x'' = 0 */
    double normal;     /* N, the normal force then */
    double margin;     /* N, mu |N| + grip - |F_t|: >= 0 sticks, < 0 moves off toward -F_t */
} zp_friction_hold;

/* The hold at state y of formulation form (its workspace fwork; ydot: n scratch rates), dn the
   drive and course there. 0, or the rhs's nonzero status (the hold then unset). */
int zp_friction_hold_at(const zp_model *m, const zp_formulation *form, void *fwork, zp_drive_now dn,
                        const double *y, double *ydot, zp_friction_hold *h);
/* 1 when the chain under a held trolley has settled: its kinetic energy plus its potential
   energy above hanging straight down, g sum_j B_j (1 - cos theta_j), below ZP_FRICTION_SETTLED
   of m_tot g (sum of link lengths). */
int zp_friction_settled(const zp_model *m, const zp_chain *c);

#endif
