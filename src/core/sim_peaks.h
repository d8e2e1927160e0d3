/* A run's load peaks: every evaluation of the loads counted in the run's peaks (whole run and per
   arc), and with o.peaks the exact peaks and the felt-g envelope located on the integrator's
   dense output (peaks.c, envelope.c). */
#ifndef ZP_SIM_PEAKS_H
#define ZP_SIM_PEAKS_H

#include "sim_int.h"

/* The row at (t, y), its loads counted in the run's peaks. */
zp_row zp_sim_peaks_row(zp_sim *s, double t, const double *y);
/* Called with o.peaks only, as are the next two: the run starts at t, no peak located yet, the
   envelope's clocks at 0. */
void zp_sim_peaks_start(zp_sim *s, double t);
/* The integrator (re)starts at (t, s->y): the peak locator starts a new interval there, and
   felt g may have jumped (an impulse). */
void zp_sim_peaks_restart(zp_sim *s, double t);
/* The step that ended at (t, s->y), on a root when adv says so: the peaks and the envelope's
   times inside it. */
void zp_sim_peaks_step(zp_sim *s, double t, zp_adv adv);
/* The run starts at (t, y): the drive's power there is the first of its peak, and the time at
   its cap counts from t. */
void zp_sim_peaks_drive_start(zp_sim *s, double t, const double *y, zp_result *r);
/* The step that ended at (t, y) in r's extremes: the drive's peak power and time at its cap, the largest joint angles, with o.track_loads
   the loads and the trolley's speed, the largest constraint residual. */
void zp_sim_peaks_extremes(zp_sim *s, double t, const double *y, zp_result *r);

#endif
