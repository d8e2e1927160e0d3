/* The figures' options (plot_opts.h): the defaults, --frames-at and --size parsed, and the
   still frames asked of the run. */
#include "plot_opts.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_load.h"

void zp_plot_opts_default(zp_plot_opts *o) {
    memset(o, 0, sizeof *o);
    o->fps = 25;
    o->width = 960;
    o->speedup = 1;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int zp_plot_opts_parse_frames(const zp_model *m, const char *text, zp_plot_opts *o, char *why,
                              size_t whylen) {
    if ((text[0] != 'x' && text[0] != 't') || text[1] != '=') {
        snprintf(why, whylen, "'%s' does not start with x= or t=", text);
        return -1;
    }
    o->frame_kind = text[0] == 'x' ? ZP_PLOT_AT_X : ZP_PLOT_AT_T;
    int n = zp_scene_values_parse_list(text + 2, o->frame_at, ZP_PLOT_MAX_FRAMES, why, whylen);
    if (n < 0) {
        return -1;
    }
    double lo = o->frame_kind == ZP_PLOT_AT_X ? m->xb[0] : 0;
    double hi = o->frame_kind == ZP_PLOT_AT_X ? m->xb[m->nsec] : HUGE_VAL;
    for (int i = 0; i < n; i++) {
        if (!(o->frame_at[i] >= lo && o->frame_at[i] <= hi)) {
            if (o->frame_kind == ZP_PLOT_AT_X) {
                snprintf(why, whylen, "x = %g is off the course [%g, %g] m", o->frame_at[i], lo,
                         hi);
            } else {
                snprintf(why, whylen, "t = %g is negative", o->frame_at[i]);
            }
            return -1;
        }
    }
    qsort(o->frame_at, n, sizeof *o->frame_at, cmp_double);
    o->nframe = 0;
    for (int i = 0; i < n; i++) { /* a moment asked for twice is one frame */
        if (!o->nframe || o->frame_at[i] != o->frame_at[o->nframe - 1]) {
            o->frame_at[o->nframe++] = o->frame_at[i];
        }
    }
    return 0;
}

void zp_plot_opts_frames_input(const zp_plot_opts *o, zp_input *in) {
    in->frame_at = o->frame_at;
    in->nframe = o->nframe;
    in->frame_at_x = o->frame_kind == ZP_PLOT_AT_X;
}

int zp_plot_opts_parse_size(const char *text, zp_plot_opts *o, char *why, size_t whylen) {
    int w, h, used = 0;
    if (sscanf(text, "%dx%d%n", &w, &h, &used) != 2 || text[used] || w < 200 || w > 4000 ||
        h < 100 || h > 4000) {
        snprintf(why, whylen, "'%s' is not WxH with W in 200..4000 and H in 100..4000 px", text);
        return -1;
    }
    o->width = w;
    o->height = h;
    return 0;
}
