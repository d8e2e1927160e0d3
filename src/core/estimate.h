/* The numerical error of a run's answer (docs/trade.md): the same run at a tolerance 100x
   tighter. The difference in the finish/death time estimates the error; a verdict that
   differs between the two runs is flagged as sensitive. */
#ifndef ZP_ESTIMATE_H
#define ZP_ESTIMATE_H

#include "sim.h"

#define ZP_ESTIMATE_FACTOR 100.0   /* how much tighter the second run is (estimate, verify) */
#define ZP_ESTIMATE_RTOL_MIN 1e-14 /* tighter than this is below round-off for every method */
#define ZP_VERIFY_DT 1e-4          /* s: finish times at the two tolerances must agree to this */

typedef struct zp_estimate {
    double rtol, atol;  /* of the tighter run */
    int ok;             /* 0: the tighter run failed; message says why */
    zp_outcome outcome; /* of the tighter run */
    int died_link;      /* of the tighter run, 1-based or 0 */
    double time;        /* s, of the tighter run */
    double time_error;  /* s, |r->time - time| */
    int sensitive;      /* 1: outcome, dead link or stall reason differ between the runs */
    char message[256];
} zp_estimate;

/* The options of the tighter run: o's tolerances ZP_ESTIMATE_FACTOR tighter (rtol no tighter
   than ZP_ESTIMATE_RTOL_MIN, atol in proportion), no trajectory, no load peaks. */
zp_sim_opts zp_estimate_tighter(const zp_sim_opts *o);
/* Runs in (its schedule and start; no outputs) again at tolerances ZP_ESTIMATE_FACTOR tighter
   than o (rtol no tighter than ZP_ESTIMATE_RTOL_MIN) and compares with r, the run at o. */
void zp_estimate_run(const zp_model *m, const zp_sim_opts *o, const zp_input *in,
                     const zp_result *r, zp_estimate *e);

#endif
