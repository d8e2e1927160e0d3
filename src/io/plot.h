/* Figures of one run: the course with every centre-of-mass path, energy, joint
   angles, loads, still frames and an animation. Each image comes with its data file and the
   gnuplot script that draws it, so a user can restyle it. */
#ifndef ZP_PLOT_H
#define ZP_PLOT_H

#include "gnuplot.h"
#include "out_file.h"
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

/* What zp_plot_run made. */
typedef struct zp_plot_info {
    int no_gnuplot;  /* 1: gnuplot is not on PATH; data and scripts written, no images */
    int nframe;      /* still frames drawn */
    int nskipped;    /* still frames asked for that the run never reached */
    int anim_frames; /* frames in run.gif */
    int mp4;         /* 1: run.mp4 was made too */
    int envelope;    /* 1: envelope.png (felt g against [limits] g_envelope) was drawn too */
} zp_plot_info;

/* The defaults: margin 0, no frames, no animation, 25 fps, 960 px wide, speed-up 1. */
void zp_plot_opts_default(zp_plot_opts *o);
/* Parses --frames-at text, "x=0,20,60" (m, on m's course) or "t=1,2" (s, >= 0), into o
   (ascending, each once); 0, or -1 with why. */
int zp_plot_parse_frames(const zp_model *m, const char *text, zp_plot_opts *o, char *why,
                         size_t whylen);
/* Asks the run of in for o's still frames (the simulator's state at exactly each moment):
   zp_plot_run draws the frames of the run it is given. */
void zp_plot_frames_input(const zp_plot_opts *o, zp_input *in);
/* Parses --size text "WxH" (px) into o; 0, or -1 with why. */
int zp_plot_parse_size(const char *text, zp_plot_opts *o, char *why, size_t whylen);

/* Draws the last run of s (its trajectory rows and kink crossings; r: its result, for the
   death) into the transaction t: course.png, energy.png, angles.png, loads.png,
   frame_x<X>.png / frame_t<T>.png (the frames s's run was asked for, see
   zp_plot_frames_input) and run.gif as o asks, each with its .gp script, and the
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
