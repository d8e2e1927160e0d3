/* What a design study shows (docs/commands.md `zipopt sweep`): the summary sentence, the figure's
   gnuplot script (a line for one varied key, a heat map for two) and summary.json. Writers only. */
#ifndef ZP_SWEEP_OUT_H
#define ZP_SWEEP_OUT_H

#include <stdio.h>

#include "grid.h"
#include "sweep.h"

/* The study's results: rows[s->npoint], every point done. */
typedef struct zp_sweep_out {
    const zp_sweep *s;        /* borrowed */
    const zp_study_row *rows; /* borrowed */
    const char *scene;        /* the scene's name */
    int np; /* parameters of the schedule */
    const zp_grid_result *grid; /* borrowed; NULL: no grid schedule was searched for */
} zp_sweep_out;

/* A few sentences: how many points keep the limits, the fastest and slowest, where none
   does, how many failed; then the schedule that survives across the grid, if searched for. */
void zp_sweep_out_summary(const zp_sweep_out *o, char *out, size_t cap);
/* 1 when the study has a figure (one or two varied keys). */
int zp_sweep_out_has_figure(const zp_sweep_out *o);
/* sweep.gp: draws sweep.png from sweep.csv, infeasible and failed points marked. */
void zp_sweep_out_script(FILE *f, const zp_sweep_out *o);
/* summary.json: scene, run, keys varied, counts, fastest and slowest point, the grid schedule
   (null when not searched for), the summary. */
void zp_sweep_out_json(FILE *f, const zp_sweep_out *o, const char *summary);

#endif
