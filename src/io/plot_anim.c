/* Still frames and the animation of one run (plot_anim.h): the body drawn at chosen
   positions or times, and followed along the course in run.gif. */
#include "plot_anim.h"

#include <math.h>

#include "plot_script.h"

#define FRAME_PX 640 /* px, side of a still frame */

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

int zp_plot_anim_frames(FILE *gp, FILE *dat, const zp_model *m, const zp_row *frames, int n,
                   const zp_plot_opts *o) {
    double reach = 0;
    for (int i = 0; i < m->nlink; i++) {
        reach += m->len[i];
    }
    zp_plot_script_head_png(gp, m, "frames", "still frames of the body on the course (frame_*.png)",
                            FRAME_PX, FRAME_PX, 1);
    fputs("set size ratio -1\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nunset key\n", gp);
    int drawn = 0;
    for (int i = 0; i < n; i++) {
        zp_plot_pose ps = zp_plot_data_pose_of_row(m, &frames[i]);
        char name[64], sec[64];
        frame_name(o, i, name, sizeof name);
        zp_plot_script_section(o, ps.sec, sec, sizeof sec);
        zp_plot_data_pose(dat, m, &ps);
        /* one scale for every frame, centred on the body */
        zp_plot_box b = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
        for (int k = 0; k <= m->nlink; k++) {
            zp_plot_data_grow(&b, ps.p[k][0], ps.p[k][1]);
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
    return drawn;
}

/* plot_anim.dat and plot_anim_label.dat: the pose and its label every speedup / fps s of the
   run, and the last; returns how many */
static int anim_data(FILE *dat, FILE *lab, const zp_model *m, const zp_row_store *rows,
                     const zp_result *r, const zp_plot_opts *o) {
    double t0 = zp_row_store_t(rows, 0), t1 = zp_row_store_t(rows, rows->n - 1),
           dt = o->speedup / o->fps;
    int nf = (int)floor((t1 - t0) / dt) + 1;
    nf += t0 + (nf - 1) * dt < t1; /* the last pose too */
    char text[256], sec[64];
    for (int j = 0; j < nf; j++) {
        zp_plot_pose ps = zp_plot_data_pose_at_t(m, rows, fmin(t0 + j * dt, t1));
        zp_plot_data_pose(dat, m, &ps);
        zp_plot_script_section(o, ps.sec, sec, sizeof sec);
        if (j == nf - 1) {
            zp_plot_script_outcome(r, text, sizeof text);
        } else {
            snprintf(text, sizeof text, "t = %5.2f s   x = %6.2f m   speed %5.2f m/s   %s", ps.t,
                     ps.p[0][0], ps.speed, sec);
        }
        fprintf(lab, "%d \"%s\"\n", j, text);
    }
    return nf;
}

int zp_plot_anim(FILE *gp, FILE *dat, FILE *lab, const zp_model *m, const zp_row_store *rows,
                 const zp_result *r, const zp_plot_opts *o, zp_plot_box course, int mp4) {
    int nf = anim_data(dat, lab, m, rows, r, o);
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
        fprintf(gp, "set linetype %d lc rgb '%s' lw 2\n", i + 1, zp_plot_script_link_color[i]);
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
    return nf;
}
