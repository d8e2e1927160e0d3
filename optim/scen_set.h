/* The scenarios every candidate is held to (corners of the box first, then quasi-random points
   fixed by the seed, then those the adversary adds), with their derived models and starts: built,
   grown and ordered here; the type is objective.h's, which evaluates a candidate over them. */
#ifndef ZP_SCEN_SET_H
#define ZP_SCEN_SET_H

#include "box.h"
#include "objective.h"



/* samples scenarios of b around nom: every corner when 2^d fits in samples (else samples/2
   corners picked by quasi-random signs), then Sobol (Halton past 40 coordinates) points
   shifted by a seeded random vector. ZP_OK or ZP_ERR_NOMEM. */
zp_status zp_scen_set_build(zp_scen_set *set, const zp_box *b, const zp_model *nom, int samples,
                            unsigned long seed);
zp_status zp_scen_set_add(zp_scen_set *set, const zp_box *b, const zp_model *nom,
                          const double *u);
/* Adds the scenario sc (its force factors) on the model m itself, borrowed and copied as a
   struct (it must outlive the set and run on workspaces of the search's nominal model: the
   same links, sections, course and effects), from start (NULL: m's own docs/model.md start turned
   to sc's angles), judged by judge (copied; NULL: the search's objective). ZP_OK or
   ZP_ERR_NOMEM. */
zp_status zp_scen_set_add_model(zp_scen_set *set, const zp_model *m, const zp_scenario *sc,
                                const zp_chain *start, const zp_objective *judge);
/* Sorts the order by the scenarios' fail counts so far (most first; ties by index). */
void zp_scen_set_reorder(zp_scen_set *set);
void zp_scen_set_free(zp_scen_set *set);

#endif
