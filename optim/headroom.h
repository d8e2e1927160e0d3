/* The headroom past the [robust] box (docs/scene-file.md safety_factor; docs/commands.md
   robust.headroom): the box widened about the nominal, and how far along the worst direction found
   the answer holds. */
#ifndef ZP_HEADROOM_H
#define ZP_HEADROOM_H

#include "box.h"
#include "objective.h"

/* How far past the stated box the answer still holds (headroom.c): per range and for the box
   as a whole, along the worst direction found, as a factor on the stated range about the
   nominal. */
enum { ZP_HEADROOM_LINES = 8 }; /* force, mass, length, trolley, damping, start angle, wind; the
                                   box */
typedef struct zp_headroom_line {
    int range;      /* 0..6 the range in that order, 7 the whole box; -1: not varied */
    double holds;   /* the largest factor found holding (bisected; 0: even the nominal breaks) */
    double breaks;  /* the first factor found breaking; INFINITY: none up to the search's cap */
    char limited_by[32]; /* what breaks there: died, stalled, margin, a [limits] key */
    double alive;   /* the largest factor found at which the rider still finishes alive */
    double dies;    /* the first factor found where not; INFINITY: none up to the cap */
    char ends_by[32]; /* how the ride ends there: died, stalled */
} zp_headroom_line;
typedef struct zp_headroom {
    double safety_factor;                 /* the box held: the stated one widened this much */
    zp_headroom_line line[ZP_HEADROOM_LINES];
} zp_headroom;

/* The headroom of the schedule of parameters p in the stated box b along the direction from
   the nominal to the scenario at wu, a point of the held box `hold` (the adversary's worst;
   NULL: every varied quantity at its upper end): for each varied range alone and for the whole
   box, the factor on the stated box up to which the run (workspace from so) finishes with the
   margin and every limit kept, by bisection. */
void zp_headroom_find(const zp_objective *ob, const zp_box *b, const zp_box *hold, const double *wu,
                      const zp_sim_opts *so, const double *p, zp_headroom *h);
/* The range's name as report.md writes it ("force error", ..., "the whole box"). */
const char *zp_headroom_range_name(int range);
/* The whole box's line when it breaks inside the stated ranges (a factor below 1: a scenario
   they hold that the answer does not survive), else NULL. */
const zp_headroom_line *zp_headroom_inside(const zp_headroom *h);

#endif
