/* The survival constraint in parts, for a polish that holds them apart: the margin and each
   [limits] value on zp_eval.cons's scale. Their largest is cons, a max that kinks where two of
   them bind at once, and a linear model of it (COBYLA's) cannot follow the edge where they meet:
   on the seed under max_g 12 and 90 km/h the fastest schedules lie along such an edge. */
#ifndef ZP_CONS_PARTS_H
#define ZP_CONS_PARTS_H

#include "objective.h"

#define ZP_CONS_PARTS_MAX (1 + ZP_LIMIT_COUNT)

/* The parts a polish of ob holds apart: 1 + the [limits] values set, or 1 (cons whole) without
   limits or with a scenario set (a robust candidate's constraint is its worst scenario's). */
int zp_cons_parts_count(const zp_objective *ob);
/* The zp_cons_parts_count(ob) parts of e, the evaluation of run r: the margin, then each limit
   set in the order of zp_limit_kind; every part is cons for a run that did not finish. */
void zp_cons_parts_eval(const zp_objective *ob, const zp_eval *e, const zp_result *r, double *c);

#endif
