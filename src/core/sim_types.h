/* What goes into one simulation and what comes out of it: the options, the input, the outcome
   with its loads and kink crossings (sim.h runs it). Apart from sim.h so that the run's parts
   (sim_*.c) see them without the run loop's header. */
#ifndef ZP_SIM_TYPES_H
#define ZP_SIM_TYPES_H

#include "formulation.h"
#include "method.h"
#include "model.h"
#include "row.h"

typedef enum {
    ZP_OUTCOME_FINISHED,
    ZP_OUTCOME_DIED,
    ZP_OUTCOME_STALLED,
    ZP_OUTCOME_COUNT
} zp_outcome;

typedef enum {
    ZP_STALL_NONE,
    ZP_STALL_T_MAX,
    ZP_STALL_ROLLED_BACK,
    ZP_STALL_TRAPPED_AT_KINK,
    ZP_STALL_HELD_BY_FRICTION,
    ZP_STALL_COUNT
} zp_stall;

#define ZP_MAX_CROSSINGS 1000 /* kink crossings kept per run; more means trapped at the kink */

typedef struct zp_sim_opts {
    int method;       /* zp_method_id */
    int formulation;  /* zp_form_id */
    double rtol, atol;
    double t_max;     /* s */
    double output_dt; /* s between trajectory rows; <= 0: no trajectory */
    long max_steps;   /* bound on integrator steps per run */
    int track_loads;  /* 1: load and speed peaks sampled at every step (one rhs call a
                         step); 0: loads only at rows, samples and events, no max_speed */
    int peaks;        /* 1: the peaks of felt acceleration and joint force located exactly
                         (each step's midpoint, then Brent's method on the dense output where
                         a step holds a maximum), for [limits]; 0: as track_loads says */
} zp_sim_opts;

typedef struct zp_input {
    const zp_schedule *sched; /* borrowed; the drive force at (t, x, x', section) */
    const double *force_scale; /* borrowed, may be NULL: a factor on each section's force (a
                                  scenario's force error) */
    const zp_chain *start; /* borrowed; NULL: the docs/model.md start. Its x must lie in section 1
                              and its y on the course; for tests and split runs */
    const double *sample_t; /* borrowed; s, ascending sample times (may be NULL) */
    int nsample;
    /* borrowed, may be NULL: ascending still-frame moments, times (s) or, with frame_at_x,
       positions (m): the state where the trolley first reaches each x; at a section boundary
       the state after the kink impulse. Frames come from the dense output like samples but
       leave the run, its load peaks included, exactly as without them */
    const double *frame_at;
    int nframe, frame_at_x;
} zp_input;

typedef struct zp_crossing {
    double t;           /* s */
    double x;           /* m */
    int from, to;       /* sections, 0-based */
    double impulse;     /* N s, Lambda of docs/model.md */
    double energy_lost; /* J */
} zp_crossing;

/* Extremes of the loads (docs/model.md forces) over a run, taken wherever the simulator evaluates
   them: the start, every integrator step, every output row and sample, and the state just
   after each kink impulse. */
typedef struct zp_load_peaks {
    double joint[ZP_MAX_LINKS];    /* N, largest |force of the parent on link i| at joint i */
    double normal_min, normal_max; /* N, course on trolley along (-f', 1)/|.|: + pushes up */
    double acc_g[ZP_MAX_LINKS];    /* g, largest felt acceleration |a - g| of link i's centre */
    double kink_dv;                /* m/s, largest |v+ - v-| of the trolley at a kink */
} zp_load_peaks;

/* Extremes of the loads on one rounded kink's arc (x in [x1, x2]), or in the brake zone,
   sampled like the peaks. */
typedef struct zp_arc_peaks {
    int visited;                   /* 1 once a load was sampled on the arc */
    double normal_min, normal_max; /* N */
    double acc_g;                  /* g, largest felt acceleration of any link's centre */
} zp_arc_peaks;

typedef struct zp_result {
    zp_outcome outcome;
    zp_stall stall;
    double time;    /* s: finish, death or stall */
    double x;       /* m, trolley x then */
    double v;       /* m/s, trolley speed then */
    int died_link;  /* 1-based, 0 when nobody died */
    double max_rel_angle[ZP_MAX_LINKS]; /* rad, largest |phi_i| over the run */
    double max_speed;                   /* m/s, largest trolley speed at a step (track_loads) */
    int ncross;                         /* kink crossings (all of them; the first
                                           ZP_MAX_CROSSINGS are in zp_sim_crossings) */
    double e_initial, e_final;          /* J, the bodies' energy */
    double pi_initial, pi_final;        /* J, the cable's own potential Pi_c ([cable]; else 0) */
    double x_min, x_max;                /* m, the trolley's x visited, at the steps' ends */
    double w_drive, w_damp, e_impulse;  /* J: drive work, damper loss, impulse loss */
    double w_effect[ZP_EFFECT_NWORK];   /* J: work taken out by each effect with a work
                                           integral (ZP_EFFECT_W_*; [physics]) */
    double brake_speed_in;              /* m/s, the trolley's speed on entering the brake zone
                                           (the first time; 0: never entered) */
    double brake_g_in;                  /* g, the largest felt acceleration of any link's
                                           centre then, the brake acting */
    double constraint_residual;         /* m */
    double drive_peak_power;            /* W, largest |F_applied v| at a step's end */
    double drive_time_at_cap;           /* s, time the drive's power cap bound: the trapezoid
                                           rule on the indicator at the steps' ends (off by at
                                           most half a step at each switch) */
    zp_load_peaks peaks;                /* the kink impulses are in zp_sim_crossings */
    double env_longest[8]; /* s, per [limits] g_envelope level: the longest time felt g (of
                              the judged links) stayed above it at once (o.peaks) */
    long steps, rhs_evals;
    long rejected; /* steps the integrator's error test rejected (each cost a step's rhs_evals) */
    double wall_s;
    char message[256]; /* why a run failed (status ZP_ERR_NUMERIC) */
} zp_result;

typedef struct zp_sim zp_sim;

#endif
