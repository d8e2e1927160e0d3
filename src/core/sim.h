/* One simulation: a schedule of forces in, an outcome out (docs/model.md "Outcomes").
   zp_sim is the workspace, created once per (model, options) and reused for every run. */
#ifndef ZP_SIM_H
#define ZP_SIM_H

#include "sim_types.h"

zp_sim *zp_sim_create(const zp_model *m, const zp_sim_opts *o);
void zp_sim_free(zp_sim *s);
/* Runs one schedule from the docs/model.md start. m is the model s was created for, or one derived
   from it by zp_scenario_model (same course and links). ZP_OK with r filled (any outcome), or
   ZP_ERR_NUMERIC with r->message naming t, x and the cause. */
zp_status zp_sim_run(const zp_model *m, zp_sim *s, const zp_input *in, zp_result *r);
/* Trajectory rows (every output_dt and the end; zp_row_store_get reads them) and samples of the
   last run; valid until the next run. */
const zp_row_store *zp_sim_rows(const zp_sim *s);
const zp_row *zp_sim_samples(const zp_sim *s, int *n);
/* The still frames of the last run: one per reached frame_at value, in its order (those never
   reached are the tail of frame_at); valid until the next run. */
const zp_row *zp_sim_frames(const zp_sim *s, int *n);
/* Kink crossings of the last run, in time order (at most ZP_MAX_CROSSINGS); valid until the
   next run. */
const zp_crossing *zp_sim_crossings(const zp_sim *s, int *n);
/* Load peaks of the last run on each arc of a model with rounded kinks (zp_model.narc). */
const zp_arc_peaks *zp_sim_arc_peaks(const zp_sim *s, int *n);
/* The load peaks in the brake zone of the last run (visited 0: never in it or no brake). */
const zp_arc_peaks *zp_sim_zone_peaks(const zp_sim *s);

const char *zp_sim_outcome_name(zp_outcome o);
const char *zp_sim_stall_name(zp_stall s);

#endif
