/* The trajectory's columns (docs/commands.md "Files"): every quantity a row shows, in
   trajectory.csv's order, named once for the CSV and for the C library, which hands out those
   with a library name, in SI units (radians where the CSV shows degrees). */
#ifndef ZP_OUT_COLUMNS_H
#define ZP_OUT_COLUMNS_H

#include "row.h"

/* the columns of the largest chain, every effect's work shown */
#define ZP_OUT_COLUMNS_MAX (14 + 8 * ZP_MAX_LINKS + ZP_EFFECT_NWORK)
#define ZP_OUT_COLUMN_NAME 24

typedef struct zp_out_column {
    char csv[ZP_OUT_COLUMN_NAME]; /* trajectory.csv's header */
    char lib[ZP_OUT_COLUMN_NAME]; /* the C library's name (zipopt.h), "": not handed out */
    double csv_scale;             /* SI to the CSV's unit: degrees for angles, else 1 */
} zp_out_column;

/* m's columns into col (room for ZP_OUT_COLUMNS_MAX); returns how many. */
int zp_out_columns(const zp_model *m, zp_out_column *col);
/* Row r's value of every column, in order, SI units. */
void zp_out_columns_values(const zp_model *m, const zp_row *r, double *v);

#endif
