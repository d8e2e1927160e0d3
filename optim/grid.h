/* The schedule that survives across a design study's grid: the search held to every corner of
   the grid (each corner's scene its own model and criteria), then checked at every point. */
#ifndef ZP_GRID_H
#define ZP_GRID_H

#include "sweep.h"

/* What the grid schedule came to. Plain data (no pointers): copied as bytes between ranks. */
typedef struct zp_grid_result {
    int failed;  /* 1: it could not be searched for; message says why */
    int found;   /* a schedule keeps the limits at the nominal and every corner */
    int nominal; /* the grid point whose finish time is minimised: the middle one */
    int ncorner; /* distinct corners held to, the nominal not counted */
    int nscen;   /* scenarios in all: the corners, with their [robust] scenarios */
    long evals;  /* candidates the search ran */
    int np;      /* the parameters of the scene's kind of schedule */
    double force[ZP_SCHED_MAX_PARAMS]; /* the answer's (or closest candidate's) parameters */
    double time;   /* s, its finish (or stop) at the nominal point with that point's [solver] */
    double margin; /* deg there: death_angle minus the largest |relative joint angle| */
    int worst;     /* the corner (a grid point) nearest to breaking it */
    double worst_margin; /* deg there */
    int survived;        /* grid points where it finishes with the point's margin and limits kept */
    unsigned char ok[(ZP_SWEEP_MAX_POINTS + 7) / 8]; /* bit p set: point p survived */
    char message[200];
} zp_grid_result;

/* The middle point of s: index (n - 1) / 2 along each varied key (the centre for odd n). */
int zp_grid_nominal(const zp_sweep *s);
/* The search over the scene's schedule (its kind and [drive] bounds, each corner's bounds
   kept) for the fastest at the nominal point that keeps, at the nominal and at each corner
   of the grid, that point's margin and [limits]; with a [robust] scene, also at each of those
   points' robust scenarios. The search's budget, seed and integrator are the nominal's. Then
   the answer is simulated at every point with the point's [solver]. base is the scene text
   (path names it in messages); the result depends on nothing else, never on the process or
   the thread count. A failure is a result with failed = 1. */
void zp_grid_run(const zp_sweep *s, const char *base, const char *path, zp_grid_result *g);
int zp_grid_survived_at(const zp_grid_result *g, int p);

#endif
