/* The landscape's figures (fig_landscape.h): gnuplot scripts that read the CSV files as they
   are, so a user can restyle them. */
#include "fig_landscape.h"

/* user text (scene name, file name) for a gnuplot string: quotes and backslashes become
   backquotes, so no name can end the string early */
static const char *gp_safe(const char *in, char *out, size_t n) {
    size_t k = 0;
    for (; in[k] && k + 1 < n; k++) {
        out[k] = in[k] == '\'' || in[k] == '"' || in[k] == '\\' ? '`' : in[k];
    }
    out[k] = '\0';
    return out;
}

double zp_fig_landscape_at(const zp_fig_axis *r, int k) {
    return r->a + (r->b - r->a) * k / (r->n - 1);
}

/* the gnuplot head both figures share */
static void head(FILE *f, const char *name, int w, int h) {
    fprintf(f,
            "# %s.png (zipopt landscape); %s.csv is its data. Run `gnuplot %s.gp` here to "
            "redraw.\n"
            "set terminal pngcairo size %d,%d noenhanced font 'DejaVu Sans,11' linewidth 1.3\n"
            "set output '%s.png'\n"
            "set encoding utf8\n"
            "set datafile separator comma\n"
            "set border lc rgb '#555555'\n"
            "set grid lc rgb '#e6e6e6' lt 1 lw 0.8\n",
            name, name, name, w, h, name);
}

void zp_fig_landscape_1d(FILE *f, const char *scene, const zp_fig_axis *r, int timed) {
    double step = (r->b - r->a) / (r->n - 1);
    char name[ZP_NAME_MAX];
    head(f, "landscape", 1100, 640);
    if (!timed) { /* gnuplot refuses to autoscale an axis with no point on it */
        fputs("set yrange [0:1]\n", f);
    }
    fprintf(f,
            "set multiplot title 'Survival landscape of %s: one constant push in every section'\n"
            "set lmargin 12\nset rmargin 4\n"
            "set xrange [%g:%g]\n"
            "# top: finish time and time of death\n"
            "set origin 0, 0.25\nset size 1, 0.7\nset bmargin 0\nset format x ''\n"
            "set ylabel 'time (s)'\n"
            "set key inside right top opaque box lc rgb '#cccccc'\n"
            "plot 'landscape.csv' using 'force':(column('kept') == 1 ? "
            "column('time') : NaN) with linespoints pt 7 ps 0.6 lw 2 lc rgb '#2ca02c' "
            "title 'survivable: finish time', \\\n"
            "     '' using 'force':(strcol('outcome') eq 'finished' && column('kept') == 0 ? "
            "column('time') : NaN) with points pt 7 ps 0.6 lc rgb '#ff7f0e' "
            "title 'finished, margin or a limit broken', \\\n"
            "     '' using 'force':(strcol('outcome') eq 'died' ? column('time') : NaN) "
            "with points pt 2 ps 0.8 lw 1.5 lc rgb '#d62728' title 'died: time of death'\n"
            "# bottom: the outcome of each push as a strip\n"
            "set origin 0, 0\nset size 1, 0.25\nset tmargin 0\nset bmargin 5.5\n"
            "set format x '%%g'\nset xlabel 'constant push F (N), the same in every section'\n"
            "set ylabel 'outcome'\nset yrange [0:1]\nunset ytics\nunset grid\n"
            "set style fill solid 1 noborder\n"
            "set key outside below horizontal\n"
            "plot 'landscape.csv' using 'force':(column('kept') == 1 ? 1 : NaN):"
            "(%g) with boxes lc rgb '#2ca02c' title 'survivable', \\\n"
            "     '' using 'force':(strcol('outcome') eq 'finished' && column('kept') == 0 ? 1 "
            ": NaN):(%g) with boxes lc rgb '#ff7f0e' title 'finished, broken', \\\n"
            "     '' using 'force':(strcol('outcome') eq 'died' ? 1 : NaN):(%g) with boxes "
            "lc rgb '#d62728' title 'died', \\\n"
            "     '' using 'force':(strcol('outcome') eq 'stalled' ? 1 : NaN):(%g) with boxes "
            "lc rgb '#aaaaaa' title 'stalled', \\\n"
            "     '' using 'force':(strcol('outcome') eq 'failed' ? 1 : NaN):(%g) with boxes "
            "lc rgb 'black' title 'integrator failed'\n"
            "unset multiplot\n",
            gp_safe(scene, name, sizeof name), r->a - step / 2, r->b + step / 2, 1.05 * step,
            1.05 * step, 1.05 * step, 1.05 * step, 1.05 * step);
}

void zp_fig_landscape_2d(FILE *f, const char *scene, const zp_schedule *base, int si, int sj,
                         const zp_fig_axis *r1, const zp_fig_axis *r2, const char *base_name) {
    double dx = (r1->b - r1->a) / (r1->n - 1), dy = (r2->b - r2->a) / (r2->n - 1);
    char name[1024], li[64], lj[64];
    const char *unit = zp_drive_unit(base);
    zp_drive_param_label(base, si, li, sizeof li);
    zp_drive_param_label(base, sj, lj, sizeof lj);
    head(f, "landscape_slice", 900, 760);
    fprintf(f,
            "set title 'Survival landscape of %s: forces of %s %d and %d, the others at "
            "the base schedule'\n"
            "set xlabel 'F%d, %s (%s)'\nset ylabel 'F%d, %s (%s)'\n"
            "set xrange [%g:%g]\nset yrange [%g:%g]\n"
            "set size square\n"
            "set cblabel 'finish time (s)'\n"
            "set palette defined (0 '#fde725', 1 '#5ec962', 2 '#21918c', 3 '#3b528b', "
            "4 '#440154')\n"
            "set style fill solid 1 noborder\n"
            "set key outside below horizontal\n"
            "set bmargin 6\n"
            "unset grid\n",
            gp_safe(scene, name, sizeof name), zp_drive_param_noun(base, 1), si + 1, sj + 1, si + 1,
            li, unit, sj + 1, lj, unit, r1->a - dx / 2, r1->b + dx / 2, r2->a - dy / 2,
            r2->b + dy / 2);
    /* the base schedule's label on the side with more room */
    const double *p = base->p;
    int right = p[si] > 0.5 * (r1->a + r1->b), upper = p[sj] > 0.5 * (r2->a + r2->b);
    fputs("set style textbox opaque\n", f);
    fprintf(f, "$base << EOD\n%.9g,%.9g,\"%s (", p[si], p[sj],
            gp_safe(base_name, name, sizeof name));
    for (int k = 0; k < base->np; k++) {
        fprintf(f, "%s%g", k ? ", " : "", p[k]);
    }
    fprintf(f,
            ") %s\"\nEOD\n"
            "plot 'landscape_slice.csv' using 'f%d':'f%d':(column('kept') == 1 ? "
            "column('time') : NaN) with image notitle, \\\n"
            "     '' using 'f%d':'f%d':(%g):(strcol('outcome') eq 'finished' && "
            "column('kept') == 0 ? %g : NaN) with boxxyerror lc rgb '#f4a582' "
            "title 'finished, margin or a limit broken', \\\n"
            "     '' using 'f%d':'f%d':(%g):(strcol('outcome') eq 'died' ? %g : NaN) "
            "with boxxyerror lc rgb '#8c2d2d' title 'died', \\\n"
            "     '' using 'f%d':'f%d':(%g):(strcol('outcome') eq 'stalled' ? %g : NaN) "
            "with boxxyerror lc rgb '#bbbbbb' title 'stalled', \\\n"
            "     '' using 'f%d':'f%d':(%g):(strcol('outcome') eq 'failed' ? %g : NaN) "
            "with boxxyerror lc rgb 'black' title 'integrator failed', \\\n"
            "     $base using 1:2 with points pt 3 ps 3 lw 3 lc rgb 'white' notitle, \\\n"
            "     $base using 1:2 with points pt 3 ps 2.4 lw 1.5 lc rgb 'black' "
            "title 'base schedule', \\\n"
            "     $base using 1:2:3 with labels %s offset %g, %g tc rgb 'black' boxed "
            "font ',10' notitle\n",
            unit, si + 1, sj + 1, si + 1, sj + 1, 0.51 * dx, 0.51 * dy, si + 1, sj + 1, 0.51 * dx,
            0.51 * dy, si + 1, sj + 1, 0.51 * dx, 0.51 * dy, si + 1, sj + 1, 0.51 * dx, 0.51 * dy,
            right ? "right" : "left", right ? -1.5 : 1.5, upper ? -1.2 : 1.2);
}
