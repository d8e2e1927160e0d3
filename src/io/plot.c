/* Figures of one run (plot.h, issue 5): writes the data files and gnuplot scripts, then lets
   gnuplot draw them (gnuplot.c). Every number drawn comes from the trajectory rows, the
   chain geometry of MODEL.md "Bodies" (state.c) and the run's result. */
#include "plot.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gnuplot.h"
#include "scene_read.h"
#include "state.h"

#define DEG (180.0 / M_PI)
#define FRAME_PX 640    /* px, side of a still frame */
#define FIG_W 1100      /* px, width of the time plots */
#define COURSE_W 1400   /* px, width of course.png */
#define COURSE_STEP 0.2 /* m between course samples */

/* one colour per link, top to bottom; the trolley is black */
static const char *const link_color[ZP_MAX_LINKS] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                                     "#9467bd", "#8c564b", "#e377c2", "#17becf"};

void zp_plot_opts_default(zp_plot_opts *o) {
    memset(o, 0, sizeof *o);
    o->fps = 25;
    o->width = 960;
    o->speedup = 1;
}

int zp_plot_parse_frames(const zp_model *m, const char *text, zp_plot_opts *o, char *why,
                         size_t whylen) {
    if ((text[0] != 'x' && text[0] != 't') || text[1] != '=') {
        snprintf(why, whylen, "'%s' does not start with x= or t=", text);
        return -1;
    }
    o->frame_kind = text[0] == 'x' ? ZP_PLOT_AT_X : ZP_PLOT_AT_T;
    int n = zp_scene_parse_list(text + 2, o->frame_at, ZP_PLOT_MAX_FRAMES, why, whylen);
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
    o->nframe = n;
    return 0;
}

int zp_plot_parse_size(const char *text, zp_plot_opts *o, char *why, size_t whylen) {
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

/* ---- the state at a chosen moment ---- */

/* A body pose: the trolley and link end points P_0..P_N, the centres of mass. */
typedef struct pose {
    double t, speed; /* s, m/s */
    int sec;         /* 0-based */
    double p[ZP_MAX_LINKS + 1][2];
    double com[ZP_MAX_LINKS + 1][2];
} pose;

/* the pose a fraction u of the way from row a to row b (positions interpolated linearly) */
static pose pose_between(const zp_model *m, const zp_row *a, const zp_row *b, double u) {
    pose ps;
    zp_chain c;
    for (int k = 0; k < 2 + m->nlink; k++) {
        c.q[k] = a->c.q[k] + u * (b->c.q[k] - a->c.q[k]);
        c.v[k] = a->c.v[k] + u * (b->c.v[k] - a->c.v[k]);
    }
    ps.t = a->t + u * (b->t - a->t);
    ps.sec = u < 0.5 ? a->sec : b->sec;
    ps.speed = hypot(c.v[0], c.v[1]);
    ps.p[0][0] = c.q[0];
    ps.p[0][1] = c.q[1];
    for (int i = 0; i < m->nlink; i++) {
        ps.p[i + 1][0] = ps.p[i][0] + m->len[i] * sin(c.q[2 + i]);
        ps.p[i + 1][1] = ps.p[i][1] - m->len[i] * cos(c.q[2 + i]);
    }
    zp_state_com(m, &c, ps.com);
    return ps;
}

/* the pose when the trolley first reaches x (kind X) or at time t (kind T); 0 if reached */
static int pose_at(const zp_model *m, const zp_row *rows, int n, zp_plot_at kind, double at,
                   pose *ps) {
    for (int k = 0; k < n; k++) {
        double v = kind == ZP_PLOT_AT_X ? rows[k].c.q[0] : rows[k].t;
        if (v >= at) {
            double prev = k ? (kind == ZP_PLOT_AT_X ? rows[k - 1].c.q[0] : rows[k - 1].t) : v;
            double u = k && v > prev ? (at - prev) / (v - prev) : 1;
            *ps = pose_between(m, &rows[k ? k - 1 : 0], &rows[k], u);
            return 0;
        }
    }
    return -1;
}

/* ---- data files ---- */

typedef struct box {
    double x0, x1, y0, y1; /* m */
} box;

static void grow(box *b, double x, double y) {
    b->x0 = fmin(b->x0, x);
    b->x1 = fmax(b->x1, x);
    b->y0 = fmin(b->y0, y);
    b->y1 = fmax(b->y1, y);
}

/* plot_course.dat: the course, one block per section; returns its extent */
static box write_course(FILE *f, const zp_model *m) {
    box b = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    fputs("x y section\n", f);
    for (int k = 0; k < m->nsec; k++) {
        int npt = 1 + (int)ceil((m->xb[k + 1] - m->xb[k]) / COURSE_STEP);
        for (int j = 0; j <= npt; j++) {
            double x = m->xb[k] + (m->xb[k + 1] - m->xb[k]) * j / npt;
            double y = zp_course_eval(m->course, k, x).f;
            fprintf(f, "%.6g %.6g %d\n", x, y, k + 1);
            grow(&b, x, y);
        }
        fputc('\n', f);
    }
    return b;
}

/* plot_run.dat: one line per trajectory row, named columns; returns the extent of the
   centres-of-mass paths */
static box write_run(FILE *f, const zp_model *m, const zp_row *rows, int n) {
    box b = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    fputs("t section x y speed", f);
    for (int i = 0; i <= m->nlink; i++) {
        fprintf(f, " com%d_x com%d_y", i, i);
    }
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, " phi%d", i);
    }
    fputs(" kinetic potential total drive_work damper_loss kink_loss balance normal", f);
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, " joint%d", i);
    }
    fputc('\n', f);
    double e0 = 0;
    for (int k = 0; k < n; k++) {
        const zp_row *r = &rows[k];
        zp_row_view v;
        zp_row_derive(m, r, &v);
        double total = v.e.kinetic + v.e.potential;
        if (k == 0) {
            e0 = total - r->w_drive + r->w_damp + r->e_impulse;
        }
        fprintf(f, "%.9g %d %.9g %.9g %.9g", r->t, r->sec + 1, r->c.q[0], r->c.q[1], v.speed);
        for (int i = 0; i <= m->nlink; i++) {
            fprintf(f, " %.9g %.9g", v.com[i][0], v.com[i][1]);
            grow(&b, v.com[i][0], v.com[i][1]);
        }
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, " %.9g", v.phi[i] * DEG);
        }
        fprintf(f, " %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g", v.e.kinetic, v.e.potential, total,
                r->w_drive, r->w_damp, r->e_impulse, e0 + r->w_drive - r->w_damp - r->e_impulse,
                r->loads.normal);
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, " %.9g", v.joint[i]);
        }
        fputc('\n', f);
    }
    return b;
}

/* one block of a pose: a line per link "x0 y0 x1 y1 link com_x com_y" */
static void write_pose(FILE *f, const zp_model *m, const pose *ps) {
    for (int i = 0; i < m->nlink; i++) {
        fprintf(f, "%.9g %.9g %.9g %.9g %d %.9g %.9g\n", ps->p[i][0], ps->p[i][1], ps->p[i + 1][0],
                ps->p[i + 1][1], i + 1, ps->com[i + 1][0], ps->com[i + 1][1]);
    }
    fputs("\n\n", f);
}

/* ---- scripts ---- */

static void outcome_text(const zp_result *r, char *buf, size_t len) {
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

static void section_text(const zp_plot_opts *o, int sec, char *buf, size_t len) {
    if (o->sched) {
        char drive[32];
        zp_schedule_label(o->sched, sec, drive, sizeof drive);
        snprintf(buf, len, "section %d (%s)", sec + 1, drive);
    } else {
        snprintf(buf, len, "section %d", sec + 1);
    }
}

/* the common head of a PNG script: terminal, output (unless several), colours */
static void head_png(FILE *f, const zp_model *m, const char *name, const char *what, int w, int h,
                     int several) {
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
        fprintf(f, "set linetype %d lc rgb '%s' lw 2\n", i + 1, link_color[i]);
    }
}

/* the sections as shaded bands with their names along the top */
static void section_bands(FILE *f, const zp_model *m, const zp_plot_opts *o) {
    for (int k = 0; k < m->nsec; k++) {
        char name[64];
        section_text(o, k, name, sizeof name);
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
                          box b, const zp_row *last) {
    double pad = 0.04 * (b.y1 - b.y0) + 1;
    b.y0 -= pad;
    b.y1 += 3 * pad; /* room for the section names */
    b.x0 -= 2;
    b.x1 += 2;
    int h = (int)((COURSE_W - 110) * (b.y1 - b.y0) / (b.x1 - b.x0)) + 150;
    char what[160];
    outcome_text(r, what, sizeof what);
    head_png(f, m, "course", "the course and every centre-of-mass path", COURSE_W, h, 0);
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
        pose ps = pose_between(m, last, last, 0);
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
    head_png(f, m, "energy", "energy terms and cumulative work against time", FIG_W, 560, 0);
    fputs("set title 'Energy: kinetic + potential = E(0) + drive work − damper and kink losses'\n"
          "set xlabel 't (s)'\nset ylabel 'energy (J)'\n"
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
          "title 'kink losses'\n",
          f);
}

static void script_angles(FILE *f, const zp_model *m, const zp_result *r, const kinks *kk,
                          const zp_plot_opts *o, const zp_row *last) {
    double dmax = m->phi_max * DEG, keep = (m->phi_max - o->margin) * DEG;
    head_png(f, m, "angles", "relative joint angles against time", FIG_W, 560, 0);
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
                keep, keep, -keep, -keep, keep, o->margin * DEG, keep);
    }
    kink_lines(f, kk);
    fputs("plot ", f);
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, "%s'plot_run.dat' using 't':'phi%d' with lines lt %d title 'joint %d'",
                i > 1 ? ", \\\n     " : "", i, i, i);
    }
    if (r->outcome == ZP_OUTCOME_DIED && last) {
        double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
        zp_state_relative(m, &last->c, phi, w);
        int i = r->died_link;
        fprintf(f,
                ", \\\n     '+' using (%.9g):(%.9g):('joint %d looped at t = %.2f s') every ::0::0 "
                "with labels point pt 7 ps 2 lc rgb '#d62728' right offset -1.5, %d "
                "tc rgb '#d62728' title 'death'",
                r->time, phi[i - 1] * DEG, i, r->time, phi[i - 1] > 0 ? -2 : 2);
    }
    fputc('\n', f);
}

static void script_loads(FILE *f, const zp_model *m, const zp_result *r, const kinks *kk) {
    head_png(f, m, "loads", "joint reactions and normal force against time", FIG_W, 720, 0);
    fputs("set multiplot layout 2, 1 title 'Loads'\n"
          "set lmargin 12\nset rmargin 4\n"
          "set key inside left top opaque box lc rgb '#cccccc'\n",
          f);
    kink_lines(f, kk);
    death_line(f, r);
    fputs("set ylabel 'joint reaction (N)'\nset format x ''\n", f);
    fputs("plot ", f);
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, "%s'plot_run.dat' using 't':'joint%d' with lines lt %d title 'joint %d'",
                i > 1 ? ", \\\n     " : "", i, i, i);
    }
    fputs("\nset ylabel 'normal force (N)'\nset xlabel 't (s)'\nset format x '%g'\n"
          "plot 'plot_run.dat' using 't':'normal' with lines lw 2 lc rgb '#222222' "
          "title 'course on trolley'\n"
          "unset multiplot\n",
          f);
}

/* the course, the paths and the body at a pose: shared by the still frames and the animation */
static void pose_plot(FILE *f, const zp_model *m, const char *course, const char *pose_file,
                      const char *index, const char *labels, int paths) {
    fprintf(f, "plot %s with lines lw 3 lc rgb '#555555' notitle", course);
    for (int i = 1; paths && i <= m->nlink; i++) {
        fprintf(f,
                ", \\\n     'plot_run.dat' using 'com%d_x':'com%d_y' with lines lw 1 "
                "lc rgb '#cccccc' notitle",
                i, i);
    }
    fprintf(f,
            ", \\\n     '%s' index %s using 1:2:($3-$1):($4-$2):5 with vectors nohead lw 5 "
            "lc variable notitle, \\\n"
            "     '' index %s using 3:4:5 with points pt 7 ps 1.2 lc variable notitle, \\\n"
            "     '' index %s using 6:7 with points pt 6 ps 1 lc rgb 'black' notitle, \\\n"
            "     '' index %s every ::0::0 using 1:2 with points pt 5 ps 2.2 lc rgb 'black' "
            "notitle",
            pose_file, index, index, index, index);
    if (labels) {
        fprintf(f, ", \\\n     %s", labels);
    }
    fputc('\n', f);
}

static void frame_name(const zp_plot_opts *o, int i, char *buf, size_t len) {
    snprintf(buf, len, "frame_%c%g", o->frame_kind == ZP_PLOT_AT_X ? 'x' : 't', o->frame_at[i]);
}

/* frames.gp and plot_frames.dat: one still frame per reached position or time */
static int write_frames(FILE *gp, FILE *dat, const zp_model *m, const zp_row *rows, int n,
                        const zp_plot_opts *o, zp_plot_info *info) {
    double reach = 0;
    for (int i = 0; i < m->nlink; i++) {
        reach += m->len[i];
    }
    head_png(gp, m, "frames", "still frames of the body on the course (frame_*.png)", FRAME_PX,
             FRAME_PX, 1);
    fputs("set size ratio -1\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nunset key\n", gp);
    int drawn = 0;
    for (int i = 0; i < o->nframe; i++) {
        pose ps;
        if (pose_at(m, rows, n, o->frame_kind, o->frame_at[i], &ps)) {
            info->nskipped++;
            continue;
        }
        char name[64], sec[64];
        frame_name(o, i, name, sizeof name);
        section_text(o, ps.sec, sec, sizeof sec);
        write_pose(dat, m, &ps);
        /* one scale for every frame, centred on the body */
        box b = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
        for (int k = 0; k <= m->nlink; k++) {
            grow(&b, ps.p[k][0], ps.p[k][1]);
        }
        double half = 0.5 * fmax(1.3 * reach, fmax(b.x1 - b.x0, b.y1 - b.y0)) + 1.5;
        double cx = 0.5 * (b.x0 + b.x1), cy = 0.5 * (b.y0 + b.y1);
        fprintf(gp,
                "set output '%s.png'\n"
                "set title 't = %.2f s    x = %.2f m    speed %.2f m/s    %s'\n"
                "set xrange [%g:%g]\nset yrange [%g:%g]\n",
                name, ps.t, ps.p[0][0], ps.speed, sec, cx - half, cx + half, cy - half, cy + half);
        char index[16];
        snprintf(index, sizeof index, "%d", drawn++);
        pose_plot(gp, m, "'plot_course.dat' using 'x':'y'", "plot_frames.dat", index, NULL, 1);
    }
    info->nframe = drawn;
    return drawn;
}

/* run.gp, plot_anim.dat and plot_anim_label.dat: above, the body followed along the course;
   below, where it is on the whole course */
static void write_anim(FILE *gp, FILE *dat, FILE *lab, const zp_model *m, const zp_row *rows, int n,
                       const zp_result *r, const zp_plot_opts *o, box course, int mp4,
                       zp_plot_info *info) {
    double t0 = rows[0].t, t1 = rows[n - 1].t, dt = o->speedup / o->fps;
    int nf = (int)floor((t1 - t0) / dt) + 1;
    nf += t0 + (nf - 1) * dt < t1; /* the last pose too */
    char text[256], sec[64];
    for (int j = 0; j < nf; j++) {
        pose ps;
        pose_at(m, rows, n, ZP_PLOT_AT_T, fmin(t0 + j * dt, t1), &ps);
        write_pose(dat, m, &ps);
        section_text(o, ps.sec, sec, sizeof sec);
        if (j == nf - 1) {
            outcome_text(r, text, sizeof text);
        } else {
            snprintf(text, sizeof text, "t = %5.2f s   x = %6.2f m   speed %5.2f m/s   %s", ps.t,
                     ps.p[0][0], ps.speed, sec);
        }
        fprintf(lab, "%d \"%s\"\n", j, text);
    }
    info->anim_frames = nf;
    double reach = 0;
    for (int i = 0; i < m->nlink; i++) {
        reach += m->len[i];
    }
    int w = o->width, h = o->height ? o->height : (int)lround(0.6 * w);
    /* the followed view: the body's reach below the trolley, half of it above; as wide as
       the panel's shape allows at equal scales */
    double below = reach + 1, above = 0.5 * reach + 1;
    double half_w = 0.5 * (below + above) * w / (0.75 * h);
    fprintf(gp,
            "# run.gif: the body along the course, %g s of run per s. Written by zipopt; run\n"
            "# `gnuplot run.gp` here to redraw.\n"
            "mp4 = %d  # 1: also run.mp4, made from run.gif by ffmpeg\n"
            "set terminal gif animate delay %d loop 0 size %d,%d noenhanced font 'DejaVuSans,11'\n"
            "set output 'run.gif'\n"
            "set encoding utf8\n",
            o->speedup, mp4, (int)lround(100 / o->fps), w, h);
    for (int i = 0; i < m->nlink; i++) {
        fprintf(gp, "set linetype %d lc rgb '%s' lw 2\n", i + 1, link_color[i]);
    }
    fputs("unset key\nunset tics\nset margins 0, 0, 0, 0\n", gp);
    for (int k = 1; k < m->nsec; k++) {
        fprintf(gp, "set arrow from %g, graph 0 to %g, graph 1 nohead lc rgb '#cccccc'\n", m->xb[k],
                m->xb[k]);
    }
    fputs("# the course, read once\n"
          "set table $course\nplot 'plot_course.dat' using 'x':'y' with table\nunset table\n",
          gp);
    fprintf(
        gp,
        "NF = %d  # frames\n"
        "HOLD = %d  # extra frames holding the end\n"
        "do for [i = 0:NF + HOLD - 1] {\n"
        "    j = i < NF ? i : NF - 1\n"
        "    # cx, cy: the trolley\n"
        "    stats 'plot_anim.dat' index j every ::0::0 using (cx = $1, cy = $2) nooutput\n"
        "    set multiplot\n"
        "    # the body, followed\n"
        "    set size ratio -1 1, 0.75\n    set origin 0, 0.25\n    set border lc rgb '#bbbbbb'\n"
        "    set xrange [cx - %g:cx + %g]\n    set yrange [cy - %g:cy + %g]\n",
        nf, (int)ceil(o->fps), half_w, half_w, below, above);
    char labels[256];
    snprintf(labels, sizeof labels,
             "'plot_anim_label.dat' every ::j::j using (cx - %g):(cy + %g):2 with labels left "
             "font ',13' notitle",
             0.97 * half_w, above - 0.07 * (above + below));
    fputs("    ", gp);
    pose_plot(gp, m, "$course", "plot_anim.dat", "j", labels, 0);
    fprintf(gp,
            "    # where it is on the whole course\n"
            "    set size ratio -1 1, 0.25\n    set origin 0, 0\n    unset border\n"
            "    set xrange [%g:%g]\n    set yrange [%g:%g]\n"
            "    plot $course with lines lw 2 lc rgb '#555555', \\\n"
            "         '+' using (cx):(cy) every ::0::0 with points pt 7 ps 1.5 lc rgb '#d62728'\n"
            "    unset multiplot\n"
            "}\n"
            "unset output\n"
            "if (mp4) {\n"
            "    system('ffmpeg -y -loglevel error -i run.gif -preset veryfast -pix_fmt yuv420p "
            "-vf \"pad=ceil(iw/2)*2:ceil(ih/2)*2\" run.mp4')\n"
            "}\n",
            course.x0 - 1, course.x1 + 1, course.y0 - 1, course.y1 + 1);
}

zp_status zp_plot_run(const char *dir, const zp_model *m, const zp_sim *s, const zp_result *r,
                      const zp_plot_opts *o, zp_plot_info *info, char *err, size_t errlen) {
    memset(info, 0, sizeof *info);
    int n;
    const zp_row *rows = zp_sim_rows(s, &n);
    kinks kk;
    kk.c = zp_sim_crossings(s, &kk.n);
    if (n < 1) {
        snprintf(err, errlen, "the run has no trajectory rows to plot (output_dt <= 0?)");
        return ZP_ERR_IO;
    }
    zp_gnuplot g;
    if (zp_gnuplot_begin(&g, dir, err, errlen)) {
        return ZP_ERR_IO;
    }
    /* data first, then each figure's script */
    FILE *course = zp_gnuplot_open(&g, "plot_course.dat", 0, err, errlen);
    FILE *run = course ? zp_gnuplot_open(&g, "plot_run.dat", 0, err, errlen) : NULL;
    if (!run) {
        zp_gnuplot_abort(&g);
        return ZP_ERR_IO;
    }
    box cb = write_course(course, m);
    box pb = write_run(run, m, rows, n);
    box both = cb;
    grow(&both, pb.x0, pb.y0);
    grow(&both, pb.x1, pb.y1);
    const zp_row *last = &rows[n - 1];
    const char *names[] = {"course.gp", "energy.gp", "angles.gp", "loads.gp"};
    FILE *gp[4];
    for (int k = 0; k < 4; k++) {
        gp[k] = zp_gnuplot_open(&g, names[k], 1, err, errlen);
        if (!gp[k]) {
            zp_gnuplot_abort(&g);
            return ZP_ERR_IO;
        }
    }
    script_course(gp[0], m, r, o, both, last);
    script_energy(gp[1], m, r, &kk);
    script_angles(gp[2], m, r, &kk, o, last);
    script_loads(gp[3], m, r, &kk);
    if (o->nframe) {
        FILE *fg = zp_gnuplot_open(&g, "frames.gp", 1, err, errlen);
        FILE *fd = fg ? zp_gnuplot_open(&g, "plot_frames.dat", 0, err, errlen) : NULL;
        if (!fd) {
            zp_gnuplot_abort(&g);
            return ZP_ERR_IO;
        }
        write_frames(fg, fd, m, rows, n, o, info);
    }
    if (o->animate) {
        FILE *ag = zp_gnuplot_open(&g, "run.gp", 1, err, errlen);
        FILE *ad = ag ? zp_gnuplot_open(&g, "plot_anim.dat", 0, err, errlen) : NULL;
        FILE *al = ad ? zp_gnuplot_open(&g, "plot_anim_label.dat", 0, err, errlen) : NULL;
        if (!al) {
            zp_gnuplot_abort(&g);
            return ZP_ERR_IO;
        }
        info->mp4 = zp_gnuplot_have("ffmpeg");
        write_anim(ag, ad, al, m, rows, n, r, o, cb, info->mp4, info);
    }
    zp_status st = zp_gnuplot_finish(&g, &info->no_gnuplot, err, errlen);
    if (info->mp4) { /* ffmpeg's own failure does not stop the other figures */
        char mp4[1100];
        snprintf(mp4, sizeof mp4, "%s/run.mp4", dir);
        FILE *f = fopen(mp4, "rb");
        info->mp4 = f != NULL;
        if (f) {
            fclose(f);
        }
    }
    return st;
}
