/* Exact gradients of a run (zipopt simulate --gradient): the derivatives of the finish time,
   of the margin angle (the largest relative joint angle reached) and of each [limits] value
   with respect to the schedule's parameters, from forward sensitivities s_k = dy/dp_k
   integrated beside the state, with their jumps (saltation) at every event: kinks (the
   impulse), section switches, arc tangent points and the run's end. A run of its own beside
   zp_sim_run; the plain run is untouched. */
#ifndef ZP_SENS_H
#define ZP_SENS_H

#include "drive.h"
#include "limit.h"
#include "sens_limits.h"
#include "sim_types.h"

typedef struct zp_sens_result {
    zp_outcome outcome;
    zp_stall stall;
    int np;                                /* the schedule's parameters */
    double time;                           /* s: finish, death or stall */
    double dtime[ZP_SCHED_MAX_PARAMS];     /* s per parameter unit: d time / d p_k */
    double margin_angle;                   /* rad: the largest |phi_i| reached */
    int margin_link;                       /* 0-based joint that reached it */
    double margin_t;                       /* s, when */
    double dmargin[ZP_SCHED_MAX_PARAMS];   /* rad per parameter unit */
    int ncross;                            /* kink crossings */
    zp_sens_limits limits;                 /* the [limits] values and theirs */
    int smooth; /* 1: every event met is one whose jump the sensitivities carry exactly; 0: the
                   run met one where the outputs are not differentiable (why_not) */
    char why_not[160];
    long steps, rhs_evals; /* the integrator's, of the augmented rates */
    long rates; /* plain rate evaluations, the stencils' and the events' included: the run's
                   work in a plain run's units (a plain run makes its rhs_evals of them) */
    double wall_s;
    char message[256]; /* why the run failed (ZP_ERR_NUMERIC) */
} zp_sens_result;

/* The run of sched on m with options o (its trajectory, samples and peaks are not taken), with
   the sensitivities of the state to each of sched's parameters, and the values of the limits
   lim sets (NULL: none) with theirs. */
zp_status zp_sens_run(const zp_model *m, const zp_sim_opts *o, const zp_schedule *sched,
                      const zp_limits *lim, zp_sens_result *r);

#endif
