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
/* The drive on the course point tr (the caller's piece) at (t, y), held and sliding as the
   simulator is; with a response time the drive's states' rates into ydot (the simulator's
   state's rates). */
zp_drive_now zp_sim_rhs_drive_on(const zp_sim *s, zp_track tr, double t, const double *y,
                                 double *ydot);
/* The drive's states of a run's start into y: the applied force starts at 0. */
void zp_sim_rhs_drive_start(const zp_sim *s, double *y);
/* 1 unless the applied force still lags the schedule at (t, y) by a force that counts against
   the weight (ZP_FRICTION_SETTLED of it): a held trolley whose drive still ramps up may yet be
   released. */
int zp_sim_rhs_drive_settled(const zp_sim *s, double t, const double *y);
/* N, the force the drive applies at st (y's drive state with a response time, else the capped
   schedule's). */
double zp_sim_rhs_drive_applied(const zp_sim *s, const zp_drive_state *st, const double *y);
/* The chain of state y on the current section. */
zp_chain zp_sim_rhs_chain(const zp_sim *s, const double *y);
/* The row at (t, y), touching nothing of the run (its loads count in no peak). */
zp_row zp_sim_rhs_row(zp_sim *s, double t, const double *y);

#endif
