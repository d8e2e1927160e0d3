/* A grazing death (docs/model.md "Outcomes"): a joint that passes the death angle and comes back
   inside one integrator step leaves the death root's sign unchanged at both step ends, but its
   located extremum shows it. */
#ifndef ZP_GRAZE_H
#define ZP_GRAZE_H

#include "formulation.h"
#include "method.h"

/* Whether the state yb at tb (the end of an advance that began at ta) has a joint at or past
   the death angle; if so the first such crossing in [ta, tb], located by Brent's method on the
   integrator's dense output: *t, the state y there (n entries) and *link (0-based). Returns 1
   for a grazing death, 0 when every joint is inside its death angle at tb. */
int zp_graze_locate(const zp_model *m, const zp_formulation *f, const zp_method *meth, void *mwork,
                    double ta, double tb, const double *yb, int n, double *t, double *y, int *link);

#endif
