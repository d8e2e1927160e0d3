/* The equations of a run at one state (sim_int.h's workspace): the rates and event functions
   the integrator calls, the drive there, and the state as a row with its loads. */
#ifndef ZP_SIM_RHS_H
#define ZP_SIM_RHS_H

#include "sim_int.h"

/* Chooses the course evaluator (s->track) and the rates and event functions the integrator
   calls for m's [physics]. */
void zp_sim_rhs_pick(zp_sim *s, const zp_model *m, zp_rhs_fn *rhs, zp_root_fn *root);
/* The rates on the plain course; named, not static, so profiles show the equations' share. */
int zp_sim_rhs(double t, const double *y, double *ydot, void *user);
/* The rates with rolling resistance (held or sliding as s->stuck and s->slide say); where the
   friction has no consistent solution, that t and x noted in s for the failure's message. */
int zp_sim_rhs_rolling(double t, const double *y, double *ydot, void *user);
/* The drive now, for outputs and decisions: held, the trolley's rates and loads at rest. */
zp_drive_now zp_sim_rhs_drive_now(const zp_sim *s, double t, const double *y);
/* The chain of state y on the current section. */
zp_chain zp_sim_rhs_chain(const zp_sim *s, const double *y);
/* The row at (t, y), touching nothing of the run (its loads count in no peak). */
zp_row zp_sim_rhs_row(zp_sim *s, double t, const double *y);

#endif
