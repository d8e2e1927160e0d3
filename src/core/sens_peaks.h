/* The [limits] values of a sensitivity run and their derivatives (sens.h): each value is found
   where the plain run finds it (a peak of a load history or of the drive's power over the run, a
   kink's speed change, the arrival speed, the g envelope's excursions between their crossings
   of a level), and its point kept with the sensitivities there. At the end each point's value
   is differentiated along (s_k, e_k) in (state, parameters); at an interior maximum the
   point's own shift in time adds nothing (the value's rate is 0 there), at an event (a kink's
   either side, the finish, the start) the event's time shift dt_e/dp moves the point along the
   rates of its side: d/dp = D Q (dt_e, s_k + f dt_e, e_k); a crossing of an envelope level
   moves by -(D g) / (d g / d t). Internal to the core floor. */
#ifndef ZP_SENS_PEAKS_H
#define ZP_SENS_PEAKS_H

#include "limit.h"
#include "sens_int.h"
#include "sens_limits.h"

typedef struct zp_sens_peaks zp_sens_peaks;

/* A workspace for the limits lim sets, reading the dense output of meth's mwork (the
   augmented state); NULL when lim sets none or memory is short (*nomem then 1). */
zp_sens_peaks *zp_sens_peaks_create(zp_sens *c, const zp_limits *lim, const zp_method *meth,
                                    void *mwork, int *nomem);
void zp_sens_peaks_free(zp_sens_peaks *P);
/* The integrator (re)starts at (t, ya) after an event whose time moved by dt (NULL: a fixed
   time, the start or a break of the schedule): the values there may jump. */
void zp_sens_peaks_restart(zp_sens_peaks *P, double t, const double *ya, const double *dt);
/* The step that ended at (t, ya): the maxima inside it. */
void zp_sens_peaks_step(zp_sens_peaks *P, double t, const double *ya);
/* The step's end at t is an event whose time moves by dt: points taken there move with it. */
void zp_sens_peaks_event(zp_sens_peaks *P, double t, const double *dt);
/* A kink into section `to` at (t, ya), ya before the impulse, its time moving by dt. */
void zp_sens_peaks_kink(zp_sens_peaks *P, double t, const double *ya, int to, const double *dt);
/* The run ends at (t, ya), finished or not; its time moves by dt. */
void zp_sens_peaks_finish(zp_sens_peaks *P, double t, const double *ya, const double *dt,
                          int finished);
/* The values and their derivatives into l. */
void zp_sens_peaks_result(zp_sens_peaks *P, zp_sens_limits *l);

#endif
