/* Handling what a run's step ended on (sim.c classifies it): a kink crossed with its impulse, an
   arc's tangent point, the trolley at rest under rolling resistance (docs/model.md's stick rule),
   and the events that end the run. The handlers (stick, kink, rest, end) change the state where
   the equations change and return 0 for the run to go on from there (the caller restarts the
   integrator), 1 when the run ended (r filled) or -1 when it failed (r's message). */
#ifndef ZP_SIM_EVENTS_H
#define ZP_SIM_EVENTS_H

#include "events.h"
#include "sim_output.h"

/* Which way the trolley leaves x at state y: its velocity, or from rest its acceleration. */
int zp_sim_events_departure(zp_sim *s, double t, const double *y);
/* docs/model.md's stick rule for the trolley at rest at t (the start, a stop, a jump of the drive
   while held): held (|F_t| <= mu |N|), it stays while the chain swings on (s->stuck) and the
   run ends at once when the chain has settled; otherwise it slides off toward -F_t, *dir.
   Fails where the forces cannot be computed, or sliding friction has no consistent motion
   there (Painleve). */
int zp_sim_events_stick(zp_sim *s, double t, zp_result *r, int *dir);
/* Whether the chain under the held trolley has settled at t, and the drive's applied force
   caught up with the schedule (zp_sim_rhs_drive_settled), which ends the hold. */
int zp_sim_events_settled(zp_sim *s, double t);
/* A hold that lasted: stalled, held_by_friction, at the time the hold began (docs/model.md). */
void zp_sim_events_held(zp_sim *s, zp_result *r, double t);
/* The kink into section `to` at t: the impulse, the outputs just after it; trapped at the kink
   (bouncing ever closer, or sent back) ends the run. */
int zp_sim_events_kink(zp_sim *s, const zp_input *in, zp_result *r, double t, int to,
                       zp_sim_output_cursor *oc);
/* An arc's tangent point: the trolley put one bit past it, the way it moves. */
void zp_sim_events_tangent(zp_sim *s);
/* An end of the brake zone: the trolley put one bit past it, the way it moves. */
void zp_sim_events_zone(zp_sim *s);
/* Where the trolley at x moving at xd = x' (m/s) is, as the simulator holds it from one
   restart to the next: the course piece it reads (s->arc) and whether the brake zone acts on
   it (s->zone: inside it, or on an end moving in; a zone's end may be a section's, whose kink
   takes the root). */
void zp_sim_events_place(zp_sim *s, double x, double xd);
/* A run's start from chain c: not held, sliding the way it moves, placed. */
void zp_sim_events_start(zp_sim *s, const zp_chain *c);
/* The trolley's velocity along the course at 0 at t: held, a release; else a stop, judged by
   the stick rule. */
int zp_sim_events_rest(zp_sim *s, double t, zp_result *r);
/* Death (of link link, 0-based), finish or roll-back at t: the run's end. */
int zp_sim_events_end(zp_sim *s, const zp_input *in, zp_result *r, double t, zp_event ev, int link,
                      zp_sim_output_cursor *oc);

#endif
