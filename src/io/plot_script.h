/* What every gnuplot script of one run's figures shares: the time plots and the course (plot.c)
   and the still frames and the animation (plot_anim.c). Internal to the io floor. */
#ifndef ZP_PLOT_SCRIPT_H
#define ZP_PLOT_SCRIPT_H

#include <stdio.h>

#include "plot_opts.h"

/* one colour per link, top to bottom; the trolley is black */
extern const char *const zp_plot_script_link_color[ZP_MAX_LINKS];

/* the run's outcome in words, for titles */
void zp_plot_script_outcome(const zp_result *r, char *buf, size_t len);
/* "section K (F N)", for labels */
void zp_plot_script_section(const zp_plot_opts *o, int sec, char *buf, size_t len);
/* the common head of a PNG script: terminal, output (unless several), colours */
void zp_plot_script_head_png(FILE *f, const zp_model *m, const char *name, const char *what, int w,
                             int h, int several);

#endif
