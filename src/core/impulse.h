/* The kink impulse of docs/model.md "Section boundaries", in chain coordinates. */
#ifndef ZP_IMPULSE_H
#define ZP_IMPULSE_H

#include "state.h"

typedef struct zp_impulse {
    double lambda;      /* N s, Lambda of docs/model.md (along (-f', 1, 0..)) */
    double energy_lost; /* J, kinetic energy before minus after */
} zp_impulse;

/* Knocks the chain's velocity onto the entered section, whose slope at the boundary is
   slope_in: A = (-slope_in, 1, 0..), Lambda = -(A v)/(A M^-1 A^T), v += M^-1 A^T Lambda.
   Positions are unchanged. Returns nonzero if M(q) is not positive definite. */
int zp_impulse_apply(const zp_model *m, double slope_in, zp_chain *c, zp_impulse *out);

#endif
