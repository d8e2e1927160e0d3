/* The brake zone's rules that the simulator and the formulations share (effect_brake.c). */
#ifndef ZP_EFFECT_BRAKE_H
#define ZP_EFFECT_BRAKE_H

#include "model.h"

/* 1 when the brake acts on the trolley at x (m) moving at xd = x' (m/s): inside m's zone, or
   on one of its ends moving in (or at rest there) */
int zp_effect_brake_entered(const zp_model *m, double x, double xd);

#endif
