/* What the figures of one run are asked for (plot.h draws them): the options, their defaults,
   the command line's --frames-at and --size, and the still frames asked of the run. */
#ifndef ZP_PLOT_OPTS_H
#define ZP_PLOT_OPTS_H

#include "sim.h"

#define ZP_PLOT_MAX_FRAMES 64

typedef enum { ZP_PLOT_AT_X, ZP_PLOT_AT_T } zp_plot_at;

typedef struct zp_plot_opts {
    double margin; /* rad below the death angle that the search keeps (a line on angles.png) */
    zp_plot_at frame_kind;
    int nframe;                          /* still frames; 0: none */
    double frame_at[ZP_PLOT_MAX_FRAMES]; /* m (trolley x) or s (time), per frame_kind;
                                            ascending */
    int animate;                         /* 1: run.gif, and run.mp4 when ffmpeg is on PATH */
    double fps;                          /* animation frames per second, 1 to 100 */
    int width, height;                   /* px, animation size; height 0: from the course's shape */
    double speedup;                      /* simulated seconds shown per second of animation */
    const zp_schedule *sched; /* borrowed, may be NULL: each section's drive in the labels */
    int procs; /* gnuplot processes, 0: one per core (fewer when the caller computes meanwhile) */
} zp_plot_opts;

/* The defaults: margin 0, no frames, no animation, 25 fps, 960 px wide, speed-up 1. */
void zp_plot_opts_default(zp_plot_opts *o);
/* Parses --frames-at text, "x=0,20,60" (m, on m's course) or "t=1,2" (s, >= 0), into o
   (ascending, each once); 0, or -1 with why. */
int zp_plot_opts_parse_frames(const zp_model *m, const char *text, zp_plot_opts *o, char *why,
                              size_t whylen);
/* Asks the run of in for o's still frames (the simulator's state at exactly each moment):
   zp_plot_run draws the frames of the run it is given. */
void zp_plot_opts_frames_input(const zp_plot_opts *o, zp_input *in);
/* Parses --size text "WxH" (px) into o; 0, or -1 with why. */
int zp_plot_opts_parse_size(const char *text, zp_plot_opts *o, char *why, size_t whylen);

#endif
