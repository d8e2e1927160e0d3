/* Figures of one run: the course with every centre-of-mass path, energy, joint
   angles, loads, still frames and an animation. Each image comes with its data file and the
   gnuplot script that draws it, so a user can restyle it. */
#ifndef ZP_PLOT_H
#define ZP_PLOT_H

#include "gnuplot.h"
#include "tx.h"
#include "plot_opts.h"

/* What zp_plot_run made. */
typedef struct zp_plot_info {
    int no_gnuplot;  /* 1: gnuplot is not on PATH; data and scripts written, no images */
    int nframe;      /* still frames drawn */
    int nskipped;    /* still frames asked for that the run never reached */
    int anim_frames; /* frames in run.gif */
    int mp4;         /* 1: run.mp4 was made too */
    int envelope;    /* 1: envelope.png (felt g against [limits] g_envelope) was drawn too */
} zp_plot_info;

/* Draws the last run of s (its trajectory rows and kink crossings; r: its result, for the
   death) into the transaction t: course.png, energy.png, angles.png, loads.png,
   frame_x<X>.png / frame_t<T>.png (the frames s's run was asked for, see
   zp_plot_opts_frames_input) and run.gif as o asks, each with its .gp script, and the
   plot_*.dat data they read. ZP_OK with info filled (also when gnuplot is missing:
   info->no_gnuplot), or ZP_ERR_IO with why in err: the caller then aborts t.
   Single-threaded: it evaluates m->course. */
zp_status zp_plot_run(zp_tx *t, const zp_model *m, const zp_sim *s, const zp_result *r,
                      const zp_plot_opts *o, zp_plot_info *info, char *err, size_t errlen);
/* zp_plot_run in two steps, so the caller can work while gnuplot draws: start writes every
   file and starts gnuplot (s and r may go after it), finish waits and completes info. The
   transaction must not be committed between them; its abort ends the drawing. */
zp_status zp_plot_start(zp_tx *t, const zp_model *m, const zp_sim *s, const zp_result *r,
                        const zp_plot_opts *o, zp_plot_info *info, zp_gnuplot_job *j, char *err,
                        size_t errlen);
zp_status zp_plot_finish(zp_tx *t, zp_gnuplot_job *j, zp_plot_info *info, char *err, size_t errlen);

#endif
