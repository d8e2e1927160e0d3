/* The still frames and the animation of one run's figures (plot.c writes the rest). Internal to
   the io floor. */
#ifndef ZP_PLOT_ANIM_H
#define ZP_PLOT_ANIM_H

#include "plot_data.h"
#include "plot_opts.h"

/* frames.gp and plot_frames.dat: one still frame per reached position or time (the run's
   frames, the first n of o->frame_at); returns how many were drawn */
int zp_plot_anim_frames(FILE *gp, FILE *dat, const zp_model *m, const zp_row *frames, int n,
                   const zp_plot_opts *o);
/* run.gp, plot_anim.dat and plot_anim_label.dat: the body followed along the course, and
   where it is on the whole course (extent course); returns the animation's frames */
int zp_plot_anim(FILE *gp, FILE *dat, FILE *lab, const zp_model *m, const zp_row_store *rows,
                 const zp_result *r, const zp_plot_opts *o, zp_plot_box course, int mp4);

#endif
