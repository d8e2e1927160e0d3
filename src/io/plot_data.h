/* The data files of one run's figures and the geometry they share: the pose of the body at a
   chosen moment, the extents, the course and the trajectory written for gnuplot. Internal to
   the io floor. */
#ifndef ZP_PLOT_DATA_H
#define ZP_PLOT_DATA_H

#include <math.h>
#include <stdio.h>

#include "sim.h"

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

/* the pose of one row (a still frame: the simulator's state at the asked moment) */
zp_plot_pose zp_plot_data_pose_of_row(const zp_model *m, const zp_row *r);
/* the pose at time t (within the rows' span) between the two rows around it */
zp_plot_pose zp_plot_data_pose_at_t(const zp_model *m, const zp_row_store *rows, double t);
/* b grown to hold (x, y) */
void zp_plot_data_grow(zp_plot_box *b, double x, double y);
/* plot_course.dat: the course, one block per section; returns its extent */
zp_plot_box zp_plot_data_course(FILE *f, const zp_model *m);
/* plot_run.dat: one line per trajectory row, named columns (with sched, the run's schedule,
   also the drive's speed and applied force: drive_speed, drive_force); returns the extent of
   the centres-of-mass paths */
zp_plot_box zp_plot_data_run(FILE *f, const zp_model *m, const zp_row_store *rows,
                             const zp_schedule *sched);
/* one block of a pose: a line per link "x0 y0 x1 y1 link com_x com_y" */
void zp_plot_data_pose(FILE *f, const zp_model *m, const zp_plot_pose *ps);

#endif
