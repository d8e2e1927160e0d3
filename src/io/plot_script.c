/* What every gnuplot script of a run's figures shares (plot_script.h): the link colours, the PNG
   head, and the labels of the outcome and of a section. */
#include "plot_script.h"

const char *const zp_plot_script_link_color[ZP_MAX_LINKS] = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

void zp_plot_script_outcome(const zp_result *r, char *buf, size_t len) {
    if (r->outcome == ZP_OUTCOME_FINISHED) {
        snprintf(buf, len, "finished in %.2f s", r->time);
    } else if (r->outcome == ZP_OUTCOME_DIED) {
        snprintf(buf, len, "died at t = %.2f s, x = %.1f m: joint %d looped", r->time, r->x,
                 r->died_link);
    } else {
        snprintf(buf, len, "stalled (%s) at t = %.2f s, x = %.1f m", zp_sim_stall_name(r->stall),
                 r->time, r->x);
    }
}

void zp_plot_script_section(const zp_plot_opts *o, int sec, char *buf, size_t len) {
    if (o->sched) {
        char drive[32];
        zp_drive_section_label(o->sched, sec, drive, sizeof drive);
        snprintf(buf, len, "section %d (%s)", sec + 1, drive);
    } else {
        snprintf(buf, len, "section %d", sec + 1);
    }
}

void zp_plot_script_head_png(FILE *f, const zp_model *m, const char *name, const char *what, int w,
                             int h, int several) {
    fprintf(f,
            "# %s%s: %s. Written by zipopt; run `gnuplot %s.gp` here to redraw.\n"
            "set terminal pngcairo size %d,%d enhanced font 'DejaVu Sans,11' linewidth 1.3\n"
            "set encoding utf8\n"
            "set border lc rgb '#555555'\n"
            "set grid lc rgb '#e6e6e6' lt 1 lw 0.8\n",
            name, several ? "" : ".png", what, name, w, h);
    if (!several) {
        fprintf(f, "set output '%s.png'\n", name);
    }
    for (int i = 0; i < m->nlink; i++) {
        fprintf(f, "set linetype %d lc rgb '%s' lw 2\n", i + 1, zp_plot_script_link_color[i]);
    }
}
