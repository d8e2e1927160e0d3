/* What `zipopt landscape` writes (docs/commands.md "landscape"): landscape.csv and
   landscape_slice.csv with their figures' scripts, the survival windows of the constant push as
   text, and the JSON object. Writers only: what a run reached is the landscape's points. */
#ifndef ZP_REPORT_LANDSCAPE_H
#define ZP_REPORT_LANDSCAPE_H

#include <stdio.h>

#include "landscape.h"
#include "tx.h"

/* A landscape that ran. */
typedef struct zp_report_landscape {
    const char *scene;             /* its name */
    const zp_schedule *base;       /* borrowed: the base schedule of the slice */
    const char *base_name;         /* where the base came from, for the slice's label */
    const zp_landscape_plan *plan; /* borrowed */
    const double *param;           /* borrowed: the runs' parameters (zp_landscape_params) */
    const zp_landscape_point *pt;  /* borrowed: the runs' points, in param's order */
    double limit;                  /* rad, the largest joint angle the margin allows */
    const zp_limits *lim;          /* borrowed: [limits] */
} zp_report_landscape;

/* landscape.csv, landscape.gp and, with a slice, landscape_slice.csv and .gp into t; 0, or -1
   with why in err. */
int zp_report_landscape_files(zp_tx *t, const zp_report_landscape *L, char *err, size_t errlen);
/* The survival windows of the constant push (runs of sampled pushes that finish), the fastest
   that keeps the margin and [limits], and the fastest that finishes when it breaks them. */
void zp_report_landscape_windows(FILE *f, const zp_report_landscape *L);
/* The run as one JSON object on one line: wall (s), the output folder dir, figures drawn. */
void zp_report_landscape_json(FILE *f, const zp_report_landscape *L, double wall, const char *dir,
                              int figures);

#endif
