/* The trajectory's columns (docs/commands.md "Files"): every quantity a row shows, in
   trajectory.csv's order, named once for the CSV and for the C library, which hands out those
   with a library name, in SI units (radians where the CSV shows degrees). */
#ifndef ZP_OUT_COLUMNS_H
#define ZP_OUT_COLUMNS_H

#include "row.h"

/* the columns of the largest chain, every effect's work shown */
#define ZP_OUT_COLUMNS_MAX (15 + 8 * ZP_MAX_LINKS + ZP_EFFECT_NWORK)
#define ZP_OUT_COLUMN_NAME 24

/* The quantities a row shows, each an entry of the table (one column, or one per link, per body
   or per effect's work integral). */
typedef enum zp_out_quantity {
    ZP_OUT_Q_T,
    ZP_OUT_Q_SECTION,
    ZP_OUT_Q_X,
    ZP_OUT_Q_Y,
    ZP_OUT_Q_SPEED,
    ZP_OUT_Q_THETA,
    ZP_OUT_Q_OMEGA,
    ZP_OUT_Q_PHI,
    ZP_OUT_Q_COM_X,
    ZP_OUT_Q_COM_Y,
    ZP_OUT_Q_KINETIC,
    ZP_OUT_Q_POTENTIAL,
    ZP_OUT_Q_ENERGY,
    ZP_OUT_Q_DRIVE,
    ZP_OUT_Q_F_APPLIED,
    ZP_OUT_Q_DAMP,
    ZP_OUT_Q_IMPULSE,
    ZP_OUT_Q_NORMAL,
    ZP_OUT_Q_WORK,
    ZP_OUT_Q_JOINT_X,
    ZP_OUT_Q_JOINT_Y,
    ZP_OUT_Q_ACC,
    ZP_OUT_Q_COUNT
} zp_out_quantity;

typedef struct zp_out_column {
    char csv[ZP_OUT_COLUMN_NAME]; /* trajectory.csv's header */
    char lib[ZP_OUT_COLUMN_NAME]; /* the C library's name (zipopt.h), "": not handed out */
    double csv_scale;             /* SI to the CSV's unit: degrees for angles, else 1 */
} zp_out_column;

/* m's columns into col (room for ZP_OUT_COLUMNS_MAX); returns how many. */
int zp_out_columns(const zp_model *m, zp_out_column *col);
/* The first of quantity q's columns in zp_out_columns' order, *n of them (q an entry of its own,
   not one of a pair such as a centre of mass's x and y); -1 and *n = 0 when m shows none. */
int zp_out_columns_find(const zp_model *m, zp_out_quantity q, int *n);
/* Row r's value of every column, in order, SI units. */
void zp_out_columns_values(const zp_model *m, const zp_row *r, double *v);

#endif
