/* The headroom past the [robust] box (docs/scene-file.md safety_factor; docs/commands.md
   robust.headroom): the box widened about the nominal, and how far along the worst direction found
   the answer holds. */
#ifndef ZP_HEADROOM_H
#define ZP_HEADROOM_H

#include "robust.h"

/* b widened by factor f about the nominal: force error and start angle times f, each range
   [lo, hi] to [1 + f (lo - 1), 1 + f (hi - 1)], the wind's about the nominal wind. */
void zp_box_widen(const zp_box *b, double f, zp_box *out);
/* The headroom of the schedule of parameters p in the stated box b along the direction from
   the nominal to the scenario at wu, a point of the held box `hold` (the adversary's worst;
   NULL: every varied quantity at its upper end): for each varied range alone and for the whole
   box, the factor on the stated box up to which the run (workspace from so) finishes with the
   margin and every limit kept, by bisection. */
void zp_headroom_find(const zp_objective *ob, const zp_box *b, const zp_box *hold, const double *wu,
                      const zp_sim_opts *so, const double *p, zp_headroom *h);
/* The range's name as report.md writes it ("force error", ..., "the whole box"). */
const char *zp_headroom_range_name(int range);

#endif
