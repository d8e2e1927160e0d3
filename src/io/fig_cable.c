/* The cable's figure (fig_cable.h): every path from exact equilibria (cable_solve.h) at evenly
   spaced x, each from its neighbour; the unloaded rope is the path of a weightless trolley
   (MODEL.md: as W -> 0 the trolley rides the rope's own elastic catenary). */
#include "fig_cable.h"

#include <math.h>
#include <stdio.h>

#include "cable_solve.h"
#include "cable_text.h"

#define POINTS 400 /* intervals between the anchors: the figure's resolution, not its accuracy */
#define CURVES 4   /* unloaded, and at most three riders */

/* the height of c's path under load at x (NaN when no equilibrium), continued from *near when
 *have; *near and *have updated */
static double height(const zp_cable *c, double load, double x, zp_cable_state *near, int *have) {
    zp_cable_state st;
    char why[256];
    zp_status rc = *have ? zp_cable_solve_near(c, near, x, &st, why, sizeof why)
                         : zp_cable_solve(c, load, x, &st, why, sizeof why);
    *have = rc == ZP_OK;
    if (*have) {
        *near = st;
    }
    return *have ? st.f : NAN;
}

/* cable.dat: the anchors as the ends of every path, the interior sampled */
static void write_data(FILE *f, const zp_cable *c, const double *load, int n) {
    zp_cable_state near[CURVES];
    int have[CURVES] = {0};
    fputs("# x (m), then the trolley's height (m) on each path: unloaded", f);
    for (int k = 1; k < n; k++) {
        fprintf(f, ", rider %d (%.1f N)", k, load[k]);
    }
    fputc('\n', f);
    for (int i = 0; i <= POINTS; i++) {
        double x = c->xa + (c->xb - c->xa) * i / POINTS;
        fprintf(f, "%.9g", i == POINTS ? c->xb : x);
        for (int k = 0; k < n; k++) {
            double y = i == 0        ? c->ya
                       : i == POINTS ? c->yb
                                     : height(c, load[k], x, &near[k], &have[k]);
            fprintf(f, " %.9g", y);
        }
        fputc('\n', f);
    }
}

/* text for a gnuplot string: quotes and backslashes become backquotes */
static void gp_safe(const char *in, char *out, size_t n) {
    size_t k = 0;
    for (; in[k] && k + 1 < n; k++) {
        out[k] = in[k] == '\'' || in[k] == '"' || in[k] == '\\' ? '`' : in[k];
    }
    out[k] = '\0';
}

static void write_script(FILE *f, const zp_model *m, const zp_scene *sc, const zp_cable *c,
                         const zp_cable_text_rider *r, int nr) {
    static const char *const colour[CURVES] = {"#888888", "#1f77b4", "#2ca02c", "#d62728"};
    char name[ZP_NAME_MAX];
    gp_safe(sc->name, name, sizeof name);
    fprintf(f,
            "# cable.png (zipopt check --plot); cable.dat is its data. Run `gnuplot cable.gp` "
            "here to redraw.\n"
            "set terminal pngcairo size 1100,640 noenhanced font 'DejaVu Sans,11' linewidth 1.3\n"
            "set output 'cable.png'\n"
            "set encoding utf8\n"
            "set border lc rgb '#555555'\n"
            "set grid lc rgb '#e6e6e6' lt 1 lw 0.8\n"
            "set title 'The cable of %s: where the trolley runs, per rider (the ride from x = "
            "%g to %g m)'\n"
            "set xlabel 'x (m)'\nset ylabel 'height (m)'\n"
            "set key outside below horizontal\n"
            "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lc rgb '#aaaaaa'\n"
            "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lc rgb '#aaaaaa'\n"
            "plot 'cable.dat' using 1:2 with lines lw 1.5 dt 3 lc rgb '%s' title 'rope alone'",
            name, m->xb[0], m->xb[m->nsec], m->xb[0], m->xb[0], m->xb[m->nsec], m->xb[m->nsec],
            colour[0]);
    for (int k = 0; k < nr; k++) {
        fprintf(f, ", \\\n     '' using 1:%d with lines lw 2 lc rgb '%s' title '%s rider, %.0f N'",
                k + 3, colour[k + 1], r[k].who, r[k].load);
    }
    fprintf(f,
            ", \\\n     '-' using 1:2 with points pt 7 ps 1.2 lc rgb 'black' title 'anchors'\n"
            "%.9g %.9g\n%.9g %.9g\ne\n",
            c->xa, c->ya, c->xb, c->yb);
}

int zp_fig_cable_write(zp_tx *t, const zp_model *m, const zp_scene *sc, char *err, size_t errlen) {
    const zp_cable *c = zp_cable_paths_cable(m->cable_paths);
    zp_cable_text_rider r[3];
    int nr = zp_cable_text_riders(m, sc, r);
    double load[CURVES] = {0};
    for (int k = 0; k < nr; k++) {
        load[k + 1] = r[k].load;
    }
    static const char *const names[2] = {"cable.dat", "cable.gp"};
    FILE *f[2];
    if (zp_tx_open_set(t, names, f, 2, err, errlen)) {
        return -1;
    }
    write_data(f[0], c, load, nr + 1);
    write_script(f[1], m, sc, c, r, nr);
    return 0;
}
