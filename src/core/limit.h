/* [limits] (docs/model.md "Uncertainty and limits"): each value a run reaches, judged against
   the scene's limits on the run's result. */
#ifndef ZP_LIMIT_H
#define ZP_LIMIT_H

#include "sim.h"

/* [limits] (docs/scene-file.md): each 0 when off. */
typedef enum {
    ZP_LIMIT_G,
    ZP_LIMIT_JOINT,
    ZP_LIMIT_ARRIVAL,
    ZP_LIMIT_KINK_DV,
    ZP_LIMIT_G_ENVELOPE, /* the longest excursion over its allowance, at the worst level */
    ZP_LIMIT_MIN_ARRIVAL, /* a floor: every rider arrives at least this fast */
    ZP_LIMIT_DRIVE_POWER, /* W, the drive's peak |F_applied v| (at the steps' ends) */
    ZP_LIMIT_CABLE_TENSION, /* N, [cable]: the largest tension at an anchor over the x visited */
    ZP_LIMIT_COUNT
} zp_limit_id;

typedef struct zp_limits {
    double max[ZP_LIMIT_COUNT]; /* g, N, km/h, m/s, 1 (its allowance) for the g envelope, km/h,
                                   W, N; 0: off */
} zp_limits;

void zp_limits_from_scene(const zp_scene *sc, zp_limits *l);
int zp_limits_any(const zp_limits *l);
/* 1 when a limit needs the load peaks located exactly (zp_sim_opts.peaks). */
int zp_limits_need_peaks(const zp_limits *l);
/* The key name of limit i ("max_g", ...) and its unit. */
const char *zp_limits_name(int i);
const char *zp_limits_unit(int i);
/* 0 when run r never reached what limit i measures (the arrival speed of a ride that did not
   arrive): neither kept nor broken there. */
int zp_limits_reached_in(const zp_result *r, int i);
/* What run r reached, in each limit's unit: the largest felt acceleration (over the judged
   links, zp_model.g_links) and joint force (over links and the run), the arrival speed (0
   unless finished), the largest kink dv, the drive's peak power, with [cable] the largest
   anchor tension over the x the run visited (the cable is quasi-static: a function of x alone,
   from exact equilibria, as simulate --json's cable.anchor_tension_max; 0 without a cable), and
   for the g envelope the longest excursion above a level over that level's allowance, the
   worst level's (zp_limits_envelope_worst). */
void zp_limits_reached(const zp_model *m, const zp_result *r, double v[ZP_LIMIT_COUNT]);
/* With [cable]: the largest anchor tension over the x run r visited from the path's fitted
   series, to about 1e-13 of zp_limits_reached's exact value at a hundredth of its cost (a
   population's spread); 0 without a cable. zp_limits_excess judges max_cable_tension with it,
   and with the exact value within 1e-9 of the limit. */
double zp_limits_anchor_tension(const zp_model *m, const zp_result *r);
/* With [cable]: the anchor tension every finishing ride reaches (N), the largest over the
   x from the start to the finish, exact; a schedule cannot change it, the cable being
   quasi-static, so a max_cable_tension below it is kept by no schedule. 0 without a cable,
   NaN when an equilibrium fails. */
double zp_limits_cable_floor(const zp_model *m);
/* What run r reached as l's limits judge it: zp_limits_reached's values, but with a
   max_cable_tension set the anchor tension fitted (zp_limits_anchor_tension), exact within
   1e-9 of the limit, and 0 without one: what zp_limits_excess compares, at a search's cost. */
void zp_limits_judged(const zp_limits *l, const zp_model *m, const zp_result *r,
                      double v[ZP_LIMIT_COUNT]);
/* The worst excess over the limits set, reached / limit - 1 (<= 0: all kept; -1 with no
   limit set), and in *which the limit that gave it (-1: none set). */
double zp_limits_excess(const zp_limits *l, const zp_model *m, const zp_result *r, int *which);
/* What run r of model m breaks first of what survivable means, judged as the search judges
   it (limit: rad, the largest joint angle allowed, zp_model_angle_used's scale): nothing, a
   death, a stall, the margin, or a [limits] value (the one exceeded most, in *which). */
typedef enum {
    ZP_BREAKS_NOTHING,
    ZP_BREAKS_DEATH,
    ZP_BREAKS_STALL,
    ZP_BREAKS_MARGIN,
    ZP_BREAKS_LIMIT
} zp_breaks;
zp_breaks zp_limits_broken(const zp_model *m, const zp_limits *lim, double limit,
                           const zp_result *r, int *which);
/* The same for values v already reached (zp_limits_reached's). */
double zp_limits_excess_of(const zp_limits *l, const double v[ZP_LIMIT_COUNT], int *which);
/* Whether value v (zp_limits_reached's) keeps limit i at max (> 0): below a ceiling, or at or
   above min_arrival_speed, the one floor. */
int zp_limits_kept(int i, double v, double max);
/* The envelope level (index) whose longest excursion is largest against its allowance; -1: no
   envelope. */
int zp_limits_envelope_worst(const zp_model *m, const zp_result *r);

#endif
