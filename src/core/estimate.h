/* The numerical error of a run's answer (docs/trade.md): the same run at a tolerance 100x
   tighter. The difference in the finish/death time estimates the error; a verdict that
   differs between the two runs is flagged as sensitive. */
#ifndef ZP_ESTIMATE_H
#define ZP_ESTIMATE_H

#include "sim.h"

#define ZP_ESTIMATE_FACTOR 100.0   /* how much tighter the second run is (estimate, verify) */
#define ZP_ESTIMATE_RTOL_MIN 1e-14 /* tighter than this is below round-off for every method */
#define ZP_VERIFY_DT 1e-4          /* s: finish times at the two tolerances must agree to this */
/* an energy audit residual above this fraction of the energies involved flags the run: the
   tolerances let the integrator drift (atol of the size of the state itself) */
#define ZP_ESTIMATE_ENERGY_REL 1e-3

typedef struct zp_estimate {
    double rtol, atol;  /* of the tighter run */
    int ok;             /* 0: the tighter run failed; message says why */
    zp_outcome outcome; /* of the tighter run */
    int died_link;      /* of the tighter run, 1-based or 0 */
    double time;        /* s, of the tighter run */
    double time_error;  /* s, |r->time - time| */
    int sensitive;      /* 1: outcome, dead link or stall reason differ between the runs */
    double energy_residual; /* J, the work-energy audit of the run at o */
    int energy_large;       /* 1: that residual is large against the energy scale */
    char message[256];
} zp_estimate;

/* The work-energy audit of docs/model.md (J): E_final - E_initial - W_drive + W_damp + E_impulse
   + the work each effect took out (W_drag + W_friction), 0 up to the integration error. */
double zp_estimate_energy_residual(const zp_result *r);
/* The options of the tighter run: o's tolerances ZP_ESTIMATE_FACTOR tighter (rtol no tighter
   than ZP_ESTIMATE_RTOL_MIN, atol by the whole factor), no trajectory, no load peaks. */
zp_sim_opts zp_estimate_tighter(const zp_sim_opts *o);
/* Runs in (its schedule and start; no outputs) again at tolerances ZP_ESTIMATE_FACTOR tighter
   than o (rtol no tighter than ZP_ESTIMATE_RTOL_MIN, atol always) and compares with r, the run
   at o; flags r's energy audit residual when large against its energies. */
void zp_estimate_run(const zp_model *m, const zp_sim_opts *o, const zp_input *in,
                     const zp_result *r, zp_estimate *e);

#endif
