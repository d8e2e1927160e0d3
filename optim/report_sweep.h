/* What a design study shows (docs/commands.md `zipopt sweep`): the summary sentence, the figure's
   gnuplot script (a line for one varied key, a heat map for two), summary.json, and the three
   files with sweep.csv. Writers only. */
#ifndef ZP_REPORT_SWEEP_H
#define ZP_REPORT_SWEEP_H

#include <stdio.h>

#include "grid.h"
#include "tx.h"
#include "sweep.h"

/* The study's results: rows[s->npoint], every point done. */
typedef struct zp_report_sweep {
    const zp_sweep *s;        /* borrowed */
    const zp_study_row *rows; /* borrowed */
    const char *scene;        /* the scene's name */
    int np; /* parameters of the schedule */
    const zp_grid_result *grid; /* borrowed; NULL: no grid schedule was searched for */
} zp_report_sweep;

/* A few sentences: how many points keep the limits, the fastest and slowest, where none
   does, how many failed; then the schedule that survives across the grid, if searched for. */
void zp_report_sweep_summary(const zp_report_sweep *o, char *out, size_t cap);
/* 1 when the study has a figure (one or two varied keys). */
int zp_report_sweep_has_figure(const zp_report_sweep *o);
/* summary.json: scene, run, keys varied, counts, fastest and slowest point, the grid schedule
   (null when not searched for), the summary. */
void zp_report_sweep_json(FILE *f, const zp_report_sweep *o, const char *summary);

/* sweep.csv, summary.json (with summary) and, with a figure, sweep.gp into t; 0, or -1 with
   why in err. */
int zp_report_sweep_files(zp_tx *t, const zp_report_sweep *o, const char *summary, char *err,
                          size_t errlen);

#endif
