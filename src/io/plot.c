/* Figures of one run (plot.h): the scripts of the time plots and the course, and the whole set
   written into the transaction and drawn by gnuplot (gnuplot.c); the options are plot_opts.c's,
   what the scripts share plot_script.c's, the data files plot_data.c's, the frames and the
   animation plot_anim.c's. */
#include "plot.h"

#include <math.h>
#include <string.h>
#include <unistd.h>

#include "gnuplot.h"
#include "plot_anim.h"
#include "plot_data.h"
#include "plot_script.h"
#include "state.h"

#define FIG_W 1100    /* px, width of the time plots */
#define COURSE_W 1400 /* px, width of course.png */

/* the sections as shaded bands with their names along the top */
static void section_bands(FILE *f, const zp_model *m, const zp_plot_opts *o) {
    for (int k = 0; k < m->nsec; k++) {
        char name[64];
        zp_plot_script_section(o, k, name, sizeof name);
        fprintf(f,
                "set object %d rect from %g, graph 0 to %g, graph 1 fc rgb '%s' "
                "fs solid 1 noborder behind\n"
                "set label %d '%s' at %g, graph 0.955 center tc rgb '#666666'\n",
                k + 1, m->xb[k], m->xb[k + 1], k % 2 ? "#f2f2f2" : "#fafafa", k + 1, name,
                0.5 * (m->xb[k] + m->xb[k + 1]));
    }
}

/* the run's kink crossings (zp_sim_crossings) */
typedef struct kinks {
    const zp_crossing *c;
    int n;
} kinks;

/* dotted vertical lines at every kink crossing, and the kink's x at its first crossing */
static void kink_lines(FILE *f, const kinks *kk) {
    const zp_crossing *c = kk->c;
    for (int k = 0; k < kk->n; k++) {
        fprintf(f, "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 3 lc rgb '#999999'\n",
                c[k].t, c[k].t);
        int first = 1;
        for (int j = 0; j < k; j++) {
            first &= c[j].x != c[k].x;
        }
        if (first) {
            fprintf(f,
                    "set label 'kink x = %g m' at %.9g, graph 0.98 rotate by 90 right "
                    "offset -0.6, 0 font ',9' tc rgb '#777777'\n",
                    c[k].x, c[k].t);
        }
    }
}

/* a dashed red line at the moment of death */
static void death_line(FILE *f, const zp_result *r) {
    if (r->outcome == ZP_OUTCOME_DIED) {
        fprintf(f,
                "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lw 1.5 "
                "lc rgb '#d62728' front\n",
                r->time, r->time);
    }
}

static void script_course(FILE *f, const zp_model *m, const zp_result *r, const zp_plot_opts *o,
                          zp_plot_box b, const zp_row *last) {
    double pad = 0.04 * (b.y1 - b.y0) + 1;
    b.y0 -= pad;
    b.y1 += 3 * pad; /* room for the section names */
    b.x0 -= 2;
    b.x1 += 2;
    int h = (int)((COURSE_W - 110) * (b.y1 - b.y0) / (b.x1 - b.x0)) + 150;
    char what[160];
    zp_plot_script_outcome(r, what, sizeof what);
    zp_plot_script_head_png(f, m, "course", "the course and every centre-of-mass path", COURSE_W, h,
                            0);
    fprintf(f,
            "set title 'The course and the centre-of-mass paths: %s' noenhanced\n"
            "set xlabel 'x (m)'\nset ylabel 'y (m)'\n"
            "set size ratio -1\n"
            "set xrange [%g:%g]\nset yrange [%g:%g]\n"
            "set key outside below horizontal maxrows 1\n"
            "set style textbox opaque noborder margins 1, 1\n",
            what, b.x0, b.x1, b.y0, b.y1);
    section_bands(f, m, o);
    fputs("$kinks << EOD\n", f);
    for (int k = 0; k < m->nkink; k++) {
        fprintf(f, "%.9g %.9g \"kink: slope %.3g → %.3g\"\n", m->kink[k].x, m->kink[k].y,
                m->kink[k].slope_in, m->kink[k].slope_out);
    }
    fputs("EOD\n", f);
    fputs(
        "plot 'plot_course.dat' using 'x':'y' with lines lw 7 lc rgb '#c0c0c0' title 'course', \\\n"
        "     'plot_run.dat' using 'com0_x':'com0_y' with lines lw 1.5 lc rgb 'black' "
        "title 'trolley', \\\n",
        f);
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, "     '' using 'com%d_x':'com%d_y' with lines lt %d title 'link %d%s', \\\n", i,
                i, i, i,
                i == 1          ? " (top)"
                : i == m->nlink ? " (bottom)"
                                : "");
    }
    fputs("     $kinks using 1:2 with points pt 7 ps 1.6 lc rgb '#d62728' notitle, \\\n"
          "     $kinks using 1:2:3 with labels boxed center offset 0, 1.6 font ',10' notitle",
          f);
    if (r->outcome == ZP_OUTCOME_DIED && last) {
        zp_plot_pose ps = zp_plot_data_pose_of_row(m, last);
        int i = r->died_link;
        fprintf(f,
                ", \\\n     '+' using (%.9g):(%.9g) every ::0::0 with points pt 2 ps 3 lw 3 "
                "lc rgb '#d62728' title 'death (link %d)'",
                ps.com[i][0], ps.com[i][1], i);
    }
    /* the long paths also as a vector image, to zoom into one stretch of the course */
    fprintf(f,
            "\nset terminal svg size %d,%d dynamic enhanced font 'DejaVu Sans,11' linewidth 1.3 "
            "background rgb 'white'\nset output 'course.svg'\nreplot\n",
            COURSE_W, h);
}

static void script_energy(FILE *f, const zp_model *m, const zp_result *r, const kinks *kk) {
    zp_plot_script_head_png(f, m, "energy", "energy terms and cumulative work against time", FIG_W,
                            560, 0);
    /* the title names every term of the balance the figure draws */
    fputs("set title 'Energy: kinetic + potential = E(0) + drive work − damper", f);
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        if (zp_effect_work_shown(m->physics, k)) {
            fprintf(f, ", %s", zp_effect_work_names(k)->brief);
        }
    }
    fputs(" and kink losses'\nset xlabel 't (s)'\nset ylabel 'energy (J)'\n"
          "set key outside right top box lc rgb '#cccccc'\n",
          f);
    kink_lines(f, kk);
    death_line(f, r);
    fputs("plot 'plot_run.dat' using 't':'kinetic' with lines lw 2 lc rgb '#1f77b4' "
          "title 'kinetic', \\\n"
          "     '' using 't':'potential' with lines lw 2 lc rgb '#2ca02c' title 'potential', \\\n"
          "     '' using 't':'total' with lines lw 4 lc rgb '#222222' title 'total', \\\n"
          "     '' using 't':'balance' with lines lw 1.5 dt 2 lc rgb '#ffdd55' "
          "title 'E(0) + work − losses', \\\n"
          "     '' using 't':'drive_work' with lines lw 2 lc rgb '#ff7f0e' "
          "title 'drive work', \\\n"
          "     '' using 't':'damper_loss' with lines lw 2 lc rgb '#9467bd' "
          "title 'damper loss', \\\n"
          "     '' using 't':'kink_loss' with lines lw 2 lc rgb '#d62728' "
          "title 'kink losses'",
          f);
    /* a colour per effect's work, in effects.def order */
    static const char *const colour[] = {"#17becf", "#8c564b", "#bcbd22", "#e377c2"};
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        const zp_effect_work *w = zp_effect_work_names(k);
        if (!zp_effect_work_shown(m->physics, k)) {
            continue;
        }
        fprintf(f, ", \\\n     '' using 't':'%s' with lines lw 2 lc rgb '%s' title '%s'",
                w->plot, colour[k % (int)(sizeof colour / sizeof *colour)], w->words);
    }
    fputc('\n', f);
}

/* one plotted line per joint: column <what><i> of plot_run.dat against column axis */
static void joint_series(FILE *f, int nlink, const char *axis, const char *what) {
    for (int i = 1; i <= nlink; i++) {
        fprintf(f, "%s'plot_run.dat' using '%s':'%s%d' with lines lt %d title 'joint %d'",
                i > 1 ? ", \\\n     " : "", axis, what, i, i, i);
    }
}

static void script_angles(FILE *f, const zp_model *m, const zp_result *r, const kinks *kk,
                          const zp_plot_opts *o, const zp_row *last) {
    double dmax = m->phi_max * ZP_PLOT_DEG, keep = (m->phi_max - o->margin) * ZP_PLOT_DEG;
    zp_plot_script_head_png(f, m, "angles", "relative joint angles against time", FIG_W, 560, 0);
    fprintf(f,
            "set title 'Relative joint angles φ_i = θ_i − θ_{i−1}'\n"
            "set xlabel 't (s)'\nset ylabel 'angle (deg)'\n"
            "set yrange [%g:%g]\nset ytics 45\n"
            "set key outside right top box lc rgb '#cccccc'\n",
            -dmax - 20, dmax + 20);
    fprintf(f,
            "set arrow from graph 0, first %g to graph 1, first %g nohead lw 2 lc rgb '#d62728'\n"
            "set arrow from graph 0, first %g to graph 1, first %g nohead lw 2 lc rgb '#d62728'\n"
            "set label 'death angle ±%g°' at graph 0.01, first %g offset 0, 0.7 "
            "tc rgb '#d62728'\n",
            dmax, dmax, -dmax, -dmax, dmax, dmax);
    if (o->margin > 0) {
        fprintf(f,
                "set arrow from graph 0, first %g to graph 1, first %g nohead dt 2 lw 1.5 "
                "lc rgb '#ff7f0e'\n"
                "set arrow from graph 0, first %g to graph 1, first %g nohead dt 2 lw 1.5 "
                "lc rgb '#ff7f0e'\n"
                "set label 'search limit ±%g° (margin %g°)' at graph 0.01, first %g "
                "offset 0, -0.8 tc rgb '#ff7f0e'\n",
                keep, keep, -keep, -keep, keep, o->margin * ZP_PLOT_DEG, keep);
    }
    kink_lines(f, kk);
    fputs("plot ", f);
    joint_series(f, m->nlink, "t", "phi");
    if (r->outcome == ZP_OUTCOME_DIED && last) {
        double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
        zp_state_relative(m, &last->c, phi, w);
        int i = r->died_link;
        fprintf(f,
                ", \\\n     '+' using (%.9g):(%.9g):('joint %d looped at t = %.2f s') every ::0::0 "
                "with labels point pt 7 ps 2 lc rgb '#d62728' right offset -1.5, %d "
                "tc rgb '#d62728' title 'death'",
                r->time, phi[i - 1] * ZP_PLOT_DEG, i, r->time, phi[i - 1] > 0 ? -2 : 2);
    }
    fputc('\n', f);
}

static void script_loads(FILE *f, const zp_model *m, const zp_result *r, const kinks *kk) {
    zp_plot_script_head_png(f, m, "loads", "joint reactions and normal force against time", FIG_W,
                            720, 0);
    fputs("set multiplot layout 2, 1 title 'Loads'\n"
          "set lmargin 12\nset rmargin 4\n"
          "set key inside left top opaque box lc rgb '#cccccc'\n",
          f);
    kink_lines(f, kk);
    death_line(f, r);
    fputs("set ylabel 'joint reaction (N)'\nset format x ''\n", f);
    fputs("plot ", f);
    joint_series(f, m->nlink, "t", "joint");
    fputs("\nset ylabel 'normal force (N)'\nset xlabel 't (s)'\nset format x '%g'\n"
          "plot 'plot_run.dat' using 't':'normal' with lines lw 2 lc rgb '#222222' "
          "title 'course on trolley'\n"
          "unset multiplot\n",
          f);
}

/* the ride against distance, where a designer places brakes and towers: the relative joint
   angles, the felt g and the joint reactions over x, each kink a dotted line at its x */
static void script_along(FILE *f, const zp_model *m, const zp_result *r, const zp_plot_opts *o) {
    double dmax = m->phi_max * ZP_PLOT_DEG, keep = (m->phi_max - o->margin) * ZP_PLOT_DEG;
    zp_plot_script_head_png(
        f, m, "along", "joint angles, felt g and joint reactions against distance", FIG_W, 900, 0);
    fputs("set multiplot layout 3, 1 title 'The ride against distance'\n"
          "set lmargin 12\nset rmargin 4\n"
          "set key inside right top opaque box lc rgb '#cccccc'\n",
          f);
    for (int k = 0; k < m->nkink; k++) {
        double x = m->xb[m->kink[k].left + 1];
        fprintf(f, "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 3 lc rgb '#999999'\n",
                x, x);
    }
    if (r->outcome == ZP_OUTCOME_DIED) {
        fprintf(f, "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead lw 2 lc rgb '#d62728'\n",
                r->x, r->x);
    }
    fprintf(f,
            "set format x ''\nset ylabel 'joint angle (deg)'\nset yrange [%g:%g]\n"
            "set arrow 101 from graph 0, first %g to graph 1, first %g nohead dt 2 "
            "lc rgb '#ff7f0e'\n"
            "set arrow 102 from graph 0, first %g to graph 1, first %g nohead dt 2 "
            "lc rgb '#ff7f0e'\n"
            "plot ",
            -dmax - 20, dmax + 20, keep, keep, -keep, -keep);
    joint_series(f, m->nlink, "x", "phi");
    fputs("\nunset arrow 101\nunset arrow 102\nset autoscale y\nset ylabel 'felt g (g)'\n"
          "plot 'plot_run.dat' using 'x':'felt_g' with lines lw 2 lc rgb '#9467bd' "
          "title 'largest felt g of the links'\n"
          "set format x '%g'\nset xlabel 'x (m)'\nset ylabel 'joint reaction (N)'\nplot ",
          f);
    joint_series(f, m->nlink, "x", "joint");
    fputs("\nunset multiplot\n", f);
}

/* felt g of the judged links against time, each [limits] g_envelope level drawn with its
   allowance and the longest time the run stayed above it */
static void script_envelope(FILE *f, const zp_model *m, const zp_result *r, const kinks *kk) {
    zp_plot_script_head_png(f, m, "envelope", "felt g against time with the g-duration envelope",
                            FIG_W, 480, 0);
    fputs("set key inside right top opaque box lc rgb '#cccccc'\n"
          "set xlabel 't (s)'\nset ylabel 'felt g (g)'\n",
          f);
    kink_lines(f, kk);
    death_line(f, r);
    for (int l = 0; l < m->nenv; l++) {
        fprintf(f,
                "set arrow from graph 0, first %.9g to graph 1, first %.9g nohead dt 2 lw 1.5 "
                "lc rgb '#d62728'\n"
                "set label 'above %g g: at most %g s allowed, longest %.3g s' at graph 0.01, "
                "first %.9g offset 0, 0.6 tc rgb '#d62728'\n",
                m->env_g[l], m->env_g[l], m->env_g[l], m->env_s[l], r->env_longest[l], m->env_g[l]);
    }
    fputs("plot 'plot_run.dat' using 't':'felt_g' with lines lw 2 lc rgb '#1f77b4' "
          "title 'felt g (judged links)'\n",
          f);
}

/* the drive a designer buys a motor from: the applied force against distance (each section's
   end dotted) and against the speed along the drive, with the run's peak power (unless it
   is the cap's), and the cap when the drive has one, as the curves F = P / v */
static void script_drive(FILE *f, const zp_model *m, const zp_result *r, const zp_plot_opts *o) {
    zp_plot_script_head_png(f, m, "drive",
                            "the drive's applied force against distance and against speed", FIG_W,
                            800, 0);
    fputs("set multiplot layout 2, 1 title 'The drive'\nset lmargin 12\nset rmargin 4\n"
          "set key inside right top opaque box lc rgb '#cccccc'\n"
          "stats 'plot_run.dat' using 'drive_force' name 'F' nooutput\n"
          "set yrange [F_min < 0 ? 1.15 * F_min : 0 : F_max > 0 ? 1.15 * F_max : 1]\n",
          f);
    for (int k = 1; k < m->nsec; k++) {
        fprintf(f, "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 3 lc rgb '#999999'\n",
                m->xb[k], m->xb[k]);
    }
    fputs("set xlabel 'x (m)'\nset ylabel 'applied force (N)'\n"
          "plot 'plot_run.dat' using 'x':'drive_force' with lines lw 2 lc rgb '#1f77b4' "
          "title 'applied force'\n"
          "unset arrow\nset xlabel 'speed along the drive (m/s)'\nset samples 400\n"
          "plot 'plot_run.dat' using 'drive_speed':'drive_force' with lines lw 2 "
          "lc rgb '#1f77b4' title 'applied force'",
          f);
    if (r->drive_peak_power > 0 && !(r->drive_peak_power >= 0.999 * o->sched->power)) {
        fprintf(f,
                ", (abs(x) > 0 ? %.9g / abs(x) : 1/0) with lines dt 2 lw 1.5 lc rgb '#ff7f0e' "
                "title 'peak power %.0f W'",
                r->drive_peak_power, r->drive_peak_power);
    }
    if (o->sched->power > 0) {
        fprintf(f,
                ", (abs(x) > 0 ? %.9g / abs(x) : 1/0) with lines lw 1.5 lc rgb '#d62728' "
                "title 'power cap %.0f W'",
                o->sched->power, o->sched->power);
    }
    fputs("\nunset multiplot\n", f);
}

/* opens name in the transaction and, for a script, lists it to be drawn */
static FILE *open_file(zp_tx *t, const char *name, const char **scripts, int *nscript, char *err,
                       size_t errlen) {
    if (scripts) {
        scripts[(*nscript)++] = name;
    }
    return zp_tx_open(t, name, err, errlen);
}

zp_status zp_plot_start(zp_tx *t, const zp_model *m, const zp_sim *s, const zp_result *r,
                        const zp_plot_opts *o, zp_plot_info *info, zp_gnuplot_job *j, char *err,
                        size_t errlen) {
    memset(j, 0, sizeof *j);
    memset(info, 0, sizeof *info);
    const zp_row_store *rows = zp_sim_rows(s);
    kinks kk;
    kk.c = zp_sim_crossings(s, &kk.n);
    if (rows->n < 1) {
        snprintf(err, errlen, "the run has no trajectory rows to plot (output_dt <= 0?)");
        return ZP_ERR_IO;
    }
    const char *scripts[10];
    int ns = 0;
    /* data first, then each figure's script */
    FILE *course = zp_tx_open(t, "plot_course.dat", err, errlen);
    FILE *run = course ? zp_tx_open(t, "plot_run.dat", err, errlen) : NULL;
    if (!run) {
        return ZP_ERR_IO;
    }
    zp_plot_box cb = zp_plot_data_course(course, m);
    zp_plot_box pb = zp_plot_data_run(run, m, rows, o->sched);
    zp_plot_box both = cb;
    zp_plot_data_grow(&both, pb.x0, pb.y0);
    zp_plot_data_grow(&both, pb.x1, pb.y1);
    zp_row end, *last = &end;
    zp_row_store_get(rows, rows->n - 1, last);
    const char *names[] = {"course.gp", "energy.gp", "angles.gp", "loads.gp", "along.gp"};
    FILE *gp[5];
    for (int k = 0; k < 5; k++) {
        gp[k] = open_file(t, names[k], scripts, &ns, err, errlen);
        if (!gp[k]) {
            return ZP_ERR_IO;
        }
    }
    script_course(gp[0], m, r, o, both, last);
    script_energy(gp[1], m, r, &kk);
    script_angles(gp[2], m, r, &kk, o, last);
    script_loads(gp[3], m, r, &kk);
    script_along(gp[4], m, r, o);
    if (m->nenv > 0) {
        FILE *ge = open_file(t, "envelope.gp", scripts, &ns, err, errlen);
        if (!ge) {
            return ZP_ERR_IO;
        }
        script_envelope(ge, m, r, &kk);
        info->envelope = 1;
    }
    if (o->sched) {
        FILE *gd = open_file(t, "drive.gp", scripts, &ns, err, errlen);
        if (!gd) {
            return ZP_ERR_IO;
        }
        script_drive(gd, m, r, o);
    }
    if (o->nframe) {
        FILE *fg = open_file(t, "frames.gp", scripts, &ns, err, errlen);
        FILE *fd = fg ? zp_tx_open(t, "plot_frames.dat", err, errlen) : NULL;
        if (!fd) {
            return ZP_ERR_IO;
        }
        int nf;
        const zp_row *frames = zp_sim_frames(s, &nf);
        info->nframe = zp_plot_anim_frames(fg, fd, m, frames, nf, o);
        info->nskipped = o->nframe - nf;
    }
    if (o->animate) {
        FILE *ag = open_file(t, "run.gp", scripts, &ns, err, errlen);
        FILE *ad = ag ? zp_tx_open(t, "plot_anim.dat", err, errlen) : NULL;
        FILE *al = ad ? zp_tx_open(t, "plot_anim_label.dat", err, errlen) : NULL;
        if (!al) {
            return ZP_ERR_IO;
        }
        info->mp4 = zp_gnuplot_have("ffmpeg");
        info->anim_frames = zp_plot_anim(ag, ad, al, m, rows, r, o, cb, info->mp4);
    }
    zp_status st = zp_gnuplot_start(t, scripts, ns, o->procs, j, err, errlen);
    info->no_gnuplot = j->missing;
    return st;
}

zp_status zp_plot_finish(zp_tx *t, zp_gnuplot_job *j, zp_plot_info *info, char *err,
                         size_t errlen) {
    zp_status st = zp_gnuplot_wait(t, j, err, errlen);
    if (info->mp4) { /* ffmpeg's own failure does not stop the other figures */
        info->mp4 = !info->no_gnuplot && zp_gnuplot_whole(zp_tx_workdir(t), "run.mp4");
        if (!info->mp4) { /* cut short or half made: not committed */
            unlinkat(zp_tx_workdir(t), "run.mp4", 0);
        }
    }
    return st;
}

zp_status zp_plot_run(zp_tx *t, const zp_model *m, const zp_sim *s, const zp_result *r,
                      const zp_plot_opts *o, zp_plot_info *info, char *err, size_t errlen) {
    zp_gnuplot_job j;
    zp_status st = zp_plot_start(t, m, s, r, o, info, &j, err, errlen);
    return st ? st : zp_plot_finish(t, &j, info, err, errlen);
}
