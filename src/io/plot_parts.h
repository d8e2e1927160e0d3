/* What the parts of one run's figures share (plot.h): the pose at a chosen moment and the
   extents (plot_data.c, which also writes the data files), the script heads and labels
   (plot.c) and the still frames and the animation (plot_anim.c). Internal to the io floor. */
#ifndef ZP_PLOT_PARTS_H
#define ZP_PLOT_PARTS_H

#include <math.h>
#include <stdio.h>

#include "plot.h"

#define ZP_PLOT_DEG (180.0 / M_PI)

/* A body pose: the trolley and link end points P_0..P_N, the centres of mass. */
typedef struct zp_plot_pose {
    double t, speed; /* s, m/s */
    int sec;         /* 0-based */
    double p[ZP_MAX_LINKS + 1][2];
    double com[ZP_MAX_LINKS + 1][2];
} zp_plot_pose;

typedef struct zp_plot_box {
    double x0, x1, y0, y1; /* m */
} zp_plot_box;

/* one colour per link, top to bottom; the trolley is black */
extern const char *const zp_plot_link_color[ZP_MAX_LINKS];

/* the pose of one row (a still frame: the simulator's state at the asked moment) */
zp_plot_pose zp_plot_pose_of_row(const zp_model *m, const zp_row *r);
/* the pose at time t (within the rows' span) between the two rows around it */
zp_plot_pose zp_plot_pose_at_t(const zp_model *m, const zp_row_store *rows, double t);
/* b grown to hold (x, y) */
void zp_plot_grow(zp_plot_box *b, double x, double y);
/* plot_course.dat: the course, one block per section; returns its extent */
zp_plot_box zp_plot_write_course(FILE *f, const zp_model *m);
/* plot_run.dat: one line per trajectory row, named columns; returns the extent of the
   centres-of-mass paths */
zp_plot_box zp_plot_write_run(FILE *f, const zp_model *m, const zp_row_store *rows);
/* one block of a pose: a line per link "x0 y0 x1 y1 link com_x com_y" */
void zp_plot_write_pose(FILE *f, const zp_model *m, const zp_plot_pose *ps);

/* the run's outcome in words, for titles */
void zp_plot_outcome_text(const zp_result *r, char *buf, size_t len);
/* "section K (F N)", for labels */
void zp_plot_section_text(const zp_plot_opts *o, int sec, char *buf, size_t len);
/* the common head of a PNG script: terminal, output (unless several), colours */
void zp_plot_head_png(FILE *f, const zp_model *m, const char *name, const char *what, int w, int h,
                      int several);

/* frames.gp and plot_frames.dat: one still frame per reached position or time (the run's
   frames, the first n of o->frame_at); returns how many were drawn (info->nframe,
   info->nskipped) */
int zp_plot_frames(FILE *gp, FILE *dat, const zp_model *m, const zp_row *frames, int n,
                   const zp_plot_opts *o, zp_plot_info *info);
/* run.gp, plot_anim.dat and plot_anim_label.dat: the body followed along the course, and
   where it is on the whole course (extent course) */
void zp_plot_anim(FILE *gp, FILE *dat, FILE *lab, const zp_model *m, const zp_row_store *rows,
                  const zp_result *r, const zp_plot_opts *o, zp_plot_box course, int mp4,
                  zp_plot_info *info);

#endif
