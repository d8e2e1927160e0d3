/* What a run leaves (sim_int.h's workspace): the trajectory rows every output_dt, the samples
   and still frames asked for, each read off the integrator's dense output at its own time or at
   an event, and the result at the run's end or failure. */
#ifndef ZP_SIM_OUTPUT_H
#define ZP_SIM_OUTPUT_H

#include "sim_int.h"

/* an output time this close (s) to an event shows the state after the event */
#define ZP_EVENT_TIME_EPS 1e-9

/* where the outputs of a run stand: the next row's time, the next sample and frame */
typedef struct zp_sim_output_cursor {
    double next_row; /* s */
    int next_sample, next_frame;
    double t_prev; /* s: where the last step (or restart) ended */
} zp_sim_output_cursor;

/* Rows of the output grid, samples and frames due by time t_upto. dense: take each from the
   integrator's dense output at its own time; else all show the current state s->y (at an
   event, within ZP_EVENT_TIME_EPS of it). */
void zp_sim_output_emit(zp_sim *s, const zp_input *in, double t_upto, int dense,
                        zp_sim_output_cursor *oc);
/* Frames at x (in->frame_at_x) the trolley has reached by the step that ended at (t, s->y):
   each where the dense output first crosses it, those at or past the section's right end left
   to the kink (shown after its impulse) or the finish. */
void zp_sim_output_frames_in_step(zp_sim *s, const zp_input *in, double t,
                                  zp_sim_output_cursor *oc);
/* Frames at x up to `reached` (the start, a kink just crossed, the finish line; a root's x
   may fall short of it by the root's tolerance): they show the state s->y at t. */
void zp_sim_output_frames_here(zp_sim *s, const zp_input *in, double t, double reached,
                               zp_sim_output_cursor *oc);
/* The run ended at t (outcome o, stall st): r's end state, work and peaks, the last row. */
void zp_sim_output_finish(zp_sim *s, zp_result *r, double t, zp_outcome o, zp_stall st);
/* The run failed at t: why, in r's message (friction's Painleve paradox where it was met). */
void zp_sim_output_fail(zp_sim *s, zp_result *r, double t, const char *why);

#endif
