/* The survival landscape: many schedules through the simulator in parallel, each
   reduced to its outcome and time. */
#ifndef ZP_LANDSCAPE_H
#define ZP_LANDSCAPE_H

#include "fig_landscape.h"
#include "scenario.h"
#include "sim.h"
#include "spread.h"

/* What one schedule's run came to. */
typedef struct zp_landscape_point {
    int failed; /* 1: the integrator gave up (ZP_ERR_NUMERIC); the rest is unset */
    zp_outcome outcome;
    zp_stall stall;
    double time;          /* s: finish, death or stall */
    double x;             /* m, trolley x then */
    int died_link;        /* 1-based, 0 when nobody died */
    double max_rel_angle; /* rad, largest |relative joint angle| over every joint */
    double reached[ZP_LIMIT_COUNT]; /* what the run reached of each [limits] value */
} zp_landscape_point;

/* What the landscape runs: push.n constant pushes (zp_drive_constant), then with a slice
   parameters si and sj of a base schedule over rx and ry (rx varying fastest), the others at
   the base's. */
typedef struct zp_landscape_plan {
    zp_fig_axis push;
    int si, sj; /* 0-based; si < 0: no slice */
    zp_fig_axis rx, ry;
} zp_landscape_plan;

/* The slice's runs, 0 without one. */
int zp_landscape_slice_runs(const zp_landscape_plan *p);
/* p's schedules, push.n + zp_landscape_slice_runs rows of base->np parameters (malloc'd; NULL
   when out of memory). */
double *zp_landscape_params(const zp_landscape_plan *p, const zp_schedule *base);

/* Called after each finished run, serialised; done counts runs finished so far. */
typedef void (*zp_landscape_progress)(void *user, int done, int total);

/* Runs n schedules of shape's kind (param: n rows of shape->np parameters) with options o, on
   every OpenMP thread: one workspace per thread, created one after another before any run
   (libmatheval is not thread-safe). Fills out[n]; each point is what a single zp_sim_run of
   that schedule gives. With sp (may be NULL) every rank calls it alike: each runs its share
   (zp_spread_map; progress counts that share) and every rank ends with all n points, the same
   bits as alone. ZP_OK, ZP_ERR_NOMEM with nothing run, or ZP_ERR_IO when the ranks' exchange
   failed. */
zp_status zp_landscape_sweep(const zp_model *m, const zp_sim_opts *o, const zp_schedule *shape,
                             const double *param, int n, zp_landscape_point *out,
                             zp_landscape_progress progress, void *user, const zp_spread *sp);

#endif
