/* The simulator's workspace, shared by the run loop (sim.c) and its parts: the equations as the
   integrator sees them (sim_rhs.c), the load peaks (sim_peaks.c), the outputs (sim_output.c)
   and the handling of events (sim_events.c). Internal to the core floor. */
#ifndef ZP_SIM_INT_H
#define ZP_SIM_INT_H

#include "envelope.h"
#include "peaks.h"
#include "sim_types.h"

typedef zp_track (*track_fn)(const zp_model *m, const zp_course *c, int sec, double x);

struct zp_sim {
    const zp_model *m; /* borrowed */
    zp_sim_opts o;
    const zp_formulation *form;
    void *fwork; /* owned */
    const zp_method *meth;
    void *mwork;       /* owned */
    zp_course *course; /* owned: this workspace's own evaluators */
    int n, nroot;
    double *y, *ydot, *yout; /* owned, n: state, rates scratch, dense output scratch */
    int *roots;       /* owned, nroot */

    /* the run under way */
    const zp_schedule *sched; /* borrowed */
    zp_schedule scaled;       /* the run's schedule times zp_input.force_scale, when given */
    double breaks[ZP_SCHED_MAX_BREAKS]; /* s, where the force jumps in time */
    int nbreak;
    int sec;
    double e_impulse; /* J, cumulative */
    zp_row_store rows; /* owned; cap 0 without a trajectory */
    zp_row *samples; /* owned, cap_samples */
    int nsamples, cap_samples;
    zp_row *frames; /* owned, cap_frames */
    int nframes, cap_frames;
    zp_load_peaks peaks; /* so far; every evaluation of the loads updates them */

    zp_crossing *cross;  /* owned, ZP_MAX_CROSSINGS */
    int ncross;          /* kept in cross (the result counts all) */
    zp_peaks *pk;        /* owned when o.peaks */
    zp_envelope env;     /* felt g against [limits] g_envelope (o.peaks; env.n 0: none) */

    /* [physics] */
    track_fn track; /* the course the model's course provider lays (zp_model_track) */
    int stuck;      /* rolling resistance: 1 while static friction holds the trolley */
    int slide;      /* +1, -1: the way it slides since the last stop, kink or start */
    int zone;       /* 1: in the brake zone since the start or its last end crossed */
    double hold_t;  /* s, when that hold began */
    double inconsistent_t, inconsistent_x; /* s, m: the last evaluation since the last step
                                              where friction had no solution (NaN: none) */
    int inconsistent_steps; /* steps in a row that met such an evaluation */
    int w0;         /* index of the first work integral in the state */
    int wd;         /* index of the drive's own states (m->ndrive, after the work integrals:
                       formulation.h) */
    zp_arc_peaks arc_peaks[ZP_MAX_SECTIONS]; /* load peaks on each arc */
    zp_arc_peaks zone_peaks;                 /* load peaks in the brake zone */
    double drive_t;   /* s, the last accepted step's end, where the drive was last looked at */
    int drive_capped; /* 1: the drive's power cap bound there */
    int arc; /* the piece the integrator reads since its last restart: an effect's (an arc),
                or -1 the plain course (zp_model_track_piece) */
};

#endif
