/* trajectory.csv (docs/commands.md "Files"): one row per output time, writer only. */
#ifndef ZP_OUT_CSV_H
#define ZP_OUT_CSV_H

#include <stdio.h>

#include "sim.h"

void zp_out_csv_trajectory(FILE *f, const zp_model *m, const zp_row_store *rows);

#endif
