/* Exact gradients of a run (zipopt simulate --gradient): the derivatives of the finish time and
   of the margin angle (the largest relative joint angle reached) with respect to the schedule's
   parameters, from forward sensitivities s_k = dy/dp_k integrated beside the state, with their
   jumps (saltation) at every event: kinks (the impulse), section switches, arc tangent points
   and the run's end. A run of its own beside zp_sim_run; the plain run is untouched. */
#ifndef ZP_SENS_H
#define ZP_SENS_H

#include "drive.h"
#include "limit.h"
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
    /* each [limits] value the scene sets (zp_limits_reached's units, the peaks located exactly:
       the drive's power too, which the plain run samples at its steps' ends), and with
       limit_has its derivatives (unit per parameter unit); limit_why_not says why not, or why
       they are not smooth there ("": they are) */
    double limit[ZP_LIMIT_COUNT];
    double limit_t[ZP_LIMIT_COUNT]; /* s, where it was reached */
    double dlimit[ZP_LIMIT_COUNT][ZP_SCHED_MAX_PARAMS];
    int limit_set[ZP_LIMIT_COUNT], limit_has[ZP_LIMIT_COUNT];
    char limit_why_not[ZP_LIMIT_COUNT][96];
    int smooth; /* 1: every event met is one whose jump the sensitivities carry exactly; 0: the
                   run met one where the outputs are not differentiable (why_not) */
    char why_not[160];
    long steps, rhs_evals;
    double wall_s;
    char message[256]; /* why the run failed (ZP_ERR_NUMERIC) */
} zp_sens_result;

/* The run of sched on m with options o (its trajectory, samples and peaks are not taken), with
   the sensitivities of the state to each of sched's parameters, and the values of the limits
   lim sets (NULL: none) with theirs. */
zp_status zp_sens_run(const zp_model *m, const zp_sim_opts *o, const zp_schedule *sched,
                      const zp_limits *lim, zp_sens_result *r);

#endif
