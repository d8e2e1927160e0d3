/* The schedule that survives across a design study's grid: the search held to every corner of
   the grid (each corner's scene its own model and criteria), then checked at every point, the
   points it breaks added to those held to and searched again until every point survives. */
#ifndef ZP_GRID_H
#define ZP_GRID_H

#include "sweep.h"

#define ZP_GRID_SEARCHES 4 /* searches in all: the corners', then one per round of points added */
#define ZP_GRID_ADD_MAX 16 /* points added in one round: those broken most when more break */

/* What the grid schedule came to. Plain data (no pointers): copied as bytes between ranks. */
typedef struct zp_grid_result {
    int failed;     /* 1: it could not be searched for; message says why */
    int found;      /* a schedule keeps the limits at the nominal, every corner and the points
                       its search was held to */
    int nominal;    /* the grid point whose finish time is minimised: the middle one */
    int ncorner;    /* distinct corners held to, the nominal not counted */
    int nscen;      /* scenarios its search was held to: the corners and points added, with
                       their [robust] scenarios */
    long evals;     /* candidates the searches ran, all rounds */
    int rounds;     /* searches run: 1 + the rounds that added broken points */
    int kept;       /* the search (1-based) whose answer this is: the last one, unless it found
                       none where an earlier one had */
    int nheld;      /* points added to the corners before that search */
    int nadded;     /* points added in all, the last search's too */
    int last_found; /* the last search found a schedule for all it was held to */
    int np;         /* the parameters of the scene's kind of schedule */
    double force[ZP_SCHED_MAX_PARAMS]; /* the answer's (or closest candidate's) parameters */
    double time;   /* s, its finish (or stop) at the nominal point with that point's [solver] */
    double margin; /* deg there: death_angle minus the largest |relative joint angle| */
    int worst;     /* the corner (a grid point) nearest to breaking it */
    double worst_margin; /* deg there */
    int survived;        /* grid points where it finishes with the point's margin and limits kept */
    unsigned char ok[(ZP_SWEEP_MAX_POINTS + 7) / 8];    /* bit p set: point p survived */
    unsigned char added[(ZP_SWEEP_MAX_POINTS + 7) / 8]; /* bit p set: point p was added */
    char message[200];
} zp_grid_result;

/* The middle point of s: index (n - 1) / 2 along each varied key (the centre for odd n). */
int zp_grid_nominal(const zp_sweep *s);
/* The search over the scene's schedule (its kind and [drive] bounds, each corner's bounds
   kept) for the fastest at the nominal point that keeps, at the nominal and at each corner
   of the grid, that point's margin and [limits]; with a [robust] scene, also at each of those
   points' robust scenarios. The search's budget, seed and integrator are the nominal's. Then
   the answer is simulated at every point with the point's [solver]; while some point breaks it
   and fewer than ZP_GRID_SEARCHES searches ran, the broken points not yet held to (the
   ZP_GRID_ADD_MAX broken most when more; each its own model and criteria, with its robust
   scenarios) join those held to, the search restarts warm (zp_search_warm; afresh when that
   finds none) and the answer is checked again. The answer kept: the last search's, or when
   that found none, the one before it. base is the scene text (path names it in messages); the
   result depends on nothing else, never on the process or the thread count. A failure is a
   result with failed = 1. */
void zp_grid_run(const zp_sweep *s, const char *base, const char *path, zp_grid_result *g);
int zp_grid_survived_at(const zp_grid_result *g, int p);
int zp_grid_added_at(const zp_grid_result *g, int p);

#endif
