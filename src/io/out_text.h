/* The text of one simulation on stdout (docs/commands.md "simulate"): outcome, time, x, speed,
   angles, the energy audit, the [limits] reached, the samples asked for, the error estimate and
   the accuracy met. Writer only; zipopt simulate --json writes the same run as out_json.h. */
#ifndef ZP_OUT_TEXT_H
#define ZP_OUT_TEXT_H

#include <stdio.h>

#include "out_json.h"

/* r, the last run of workspace s (its samples), with what meta says of it (lim NULL: no
   [limits]; estimate and accuracy NULL: not shown). */
void zp_out_text_result(FILE *f, const zp_model *m, const zp_result *r, const zp_sim *s,
                        const zp_run_meta *meta);

#endif
