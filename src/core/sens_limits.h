/* The [limits] values of a sensitivity run and their derivatives (sens.h's result, filled by
   sens_peaks.c): apart so that the run and its peaks share it without including each other. */
#ifndef ZP_SENS_LIMITS_H
#define ZP_SENS_LIMITS_H

#include "drive.h"
#include "limit.h"

/* each [limits] value the scene sets (zp_limits_reached's units, the peaks located exactly:
   the drive's power too, which the plain run samples at its steps' ends), and with has its
   derivatives (unit per parameter unit); why_not says why not, or why they are not smooth
   there ("": they are) */
typedef struct zp_sens_limits {
    int set[ZP_LIMIT_COUNT], has[ZP_LIMIT_COUNT];
    double value[ZP_LIMIT_COUNT];
    double t[ZP_LIMIT_COUNT]; /* s, where it was reached (NaN: nowhere) */
    double d[ZP_LIMIT_COUNT][ZP_SCHED_MAX_PARAMS];
    char why_not[ZP_LIMIT_COUNT][96];
} zp_sens_limits;

#endif
