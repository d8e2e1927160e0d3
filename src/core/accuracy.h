/* Accuracy on request ([solver] accuracy, s on the finish/death time): the method and rtol
   picked from the measured work-precision table (docs/trade.md), then checked against the
   error estimate and tightened until the estimate meets the request. */
#ifndef ZP_ACCURACY_H
#define ZP_ACCURACY_H

#include "estimate.h"
#include "sim.h"

/* the table's errors are those of the seed; a pick must beat the request by this factor, since
   CVODE's error is not monotone in rtol and other scenes differ (docs/trade.md) */
#define ZP_ACCURACY_MARGIN 10.0
/* N m s/rad: joint damping above this makes a scene stiff; the pick then reads the table's
   stiff column (docs/trade.md: rk8pd and Adams are stability-bound there) */
#define ZP_ACCURACY_STIFF_DAMPING 1e3

/* What an answer met: the request, the settings that met it, and the estimate. */
typedef struct zp_accuracy {
    double requested; /* s */
    double met;       /* s, the error estimate of the answer; NAN if the tighter run failed */
    int ok;           /* 1: met <= requested */
    int method;       /* zp_method_id of the answer's run */
    double rtol;      /* of the answer's run (atol = rtol / 100) */
    int reruns;       /* runs the request cost beyond the first pick */
} zp_accuracy;

/* The cheapest (method, rtol) of the table whose measured time error, ZP_ACCURACY_MARGIN
   below acc, meets acc; method >= 0 restricts the pick to that method. stiff: read the stiff
   column. None meets it: the most accurate entry. Sets o->method, o->rtol, o->atol. */
void zp_accuracy_pick(double acc, int method, int stiff, zp_sim_opts *o);
/* 1 when a scene's joint damping makes it stiff for the table */
int zp_accuracy_stiff(const zp_scene *sc);

/* Runs in at *o and estimates its error (zp_estimate_run); while the estimate exceeds acc (or
   the tighter run failed or the verdict is sensitive), tightens rtol and atol by
   ZP_ESTIMATE_FACTOR and runs again, down to ZP_RTOL_MIN. Leaves in *o the options of the
   answer, in *s the simulator that made it (its trajectory and samples are the answer's; free
   it with zp_sim_free, also on error), in r, e and a its result, estimate and what it met.
   Returns ZP_OK, or the error of the run that failed (r->message says why). */
zp_status zp_accuracy_run(const zp_model *m, zp_sim_opts *o, const zp_input *in, double acc,
                          zp_sim **s, zp_result *r, zp_estimate *e, zp_accuracy *a);

#endif
