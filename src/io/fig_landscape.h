/* The survival landscape's figures: gnuplot scripts for landscape.png (outcome over one
   constant push) and landscape_slice.png (outcome over two parameters of a schedule), reading
   landscape.csv and landscape_slice.csv beside them. */
#ifndef ZP_FIG_LANDSCAPE_H
#define ZP_FIG_LANDSCAPE_H

#include <stdio.h>

#include "drive.h"

typedef struct zp_fig_axis {
    double a, b; /* N */
    int n;       /* points, a and b included */
} zp_fig_axis;

/* point k of r (0 .. n-1: a .. b) */
double zp_fig_landscape_at(const zp_fig_axis *r, int k);
/* landscape.gp, for scene (its name, in the title) over the constant pushes r; timed: 1 when
   some push finished or died (0: the time panel has nothing to scale its axis by) */
void zp_fig_landscape_1d(FILE *f, const char *scene, const zp_fig_axis *r, int timed);
/* landscape_slice.gp: parameters si and sj (0-based) of the schedule base over r1 and r2, the
   others at base's (named base_name in the label) */
void zp_fig_landscape_2d(FILE *f, const char *scene, const zp_schedule *base, int si, int sj,
                         const zp_fig_axis *r1, const zp_fig_axis *r2, const char *base_name);

#endif
