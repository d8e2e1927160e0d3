/* The study's summary sentence, figure script and summary.json (report_sweep.h). */
#include "report_sweep.h"

#include <math.h>
#include <string.h>

#include "out_json.h"
#include "sweep_csv.h"

typedef struct tally {
    int found, infeasible, failed;
    int fastest, slowest; /* points, -1 when nothing was found */
    double tmin, tmax;    /* s, over the points found */
} tally;

static tally count(const zp_report_sweep *o) {
    tally t = {.fastest = -1, .slowest = -1};
    for (int p = 0; p < o->s->npoint; p++) {
        const zp_study_row *r = &o->rows[p];
        t.failed += r->failed;
        t.infeasible += !r->failed && !r->found;
        if (!r->failed && r->found) {
            t.found++;
            if (t.fastest < 0 || r->time < t.tmin) {
                t.fastest = p;
                t.tmin = r->time;
            }
            if (t.slowest < 0 || r->time > t.tmax) {
                t.slowest = p;
                t.tmax = r->time;
            }
        }
    }
    return t;
}

#define ADD(...)                                                                                   \
    do {                                                                                           \
        if (len < cap) {                                                                           \
            len += (size_t)snprintf(out + len, cap - len, __VA_ARGS__);                            \
        }                                                                                          \
    } while (0)

/* the points with bit set in g (up to max of them, else their count): "A; B; C" */
static size_t points_list(const zp_report_sweep *o, int (*bit)(const zp_grid_result *, int), int want,
                          int max, char *out, size_t cap) {
    size_t len = 0;
    int n = 0;
    char at[512];
    for (int p = 0; p < o->s->npoint; p++) {
        n += bit(o->grid, p) == want;
    }
    if (n > max) {
        ADD("%d points", n);
        return len;
    }
    for (int p = 0, shown = 0; p < o->s->npoint; p++) {
        if (bit(o->grid, p) == want) {
            zp_sweep_describe(o->s, p, at, sizeof at);
            ADD("%s%s", shown++ ? "; " : "", at);
        }
    }
    return len;
}

/* why the rounds ended with points broken */
static const char *why_broken(const zp_grid_result *g) {
    return !g->last_found ? "held to the points it breaks too, the search found none"
           : g->rounds >= ZP_GRID_SEARCHES ? "the searches ran out"
                                           : "it breaks only points held to already";
}

/* the grid schedule's sentence; the length written (as snprintf counts) */
static size_t grid_summary(const zp_report_sweep *o, char *out, size_t cap) {
    const zp_grid_result *g = o->grid;
    size_t len = 0;
    char at[512];
    if (g->failed) {
        ADD(" No schedule across the grid: %s.", g->message);
        return len;
    }
    zp_sweep_describe(o->s, g->nominal, at, sizeof at);
    ADD(" %s schedule that the grid's %d corner%s", g->found ? "Fastest" : "No", g->ncorner,
        g->ncorner == 1 ? "" : "s");
    if (g->nheld) {
        ADD(", its middle and %d point%s added all survive", g->nheld, g->nheld == 1 ? "" : "s");
    } else {
        ADD(" and its middle all survive");
    }
    ADD(g->found ? ":" : " was found (the closest:");
    for (int k = 0; k < g->np; k++) {
        ADD("%s %.4g", k ? "," : "", g->force[k]);
    }
    ADD(" N, %.4f s at the middle, %s", g->time, at);
    if (g->worst >= 0) {
        zp_sweep_describe(o->s, g->worst, at, sizeof at);
        ADD(", worst corner %s (margin %.2f deg)", at, g->worst_margin);
    }
    int broken = o->s->npoint - g->survived;
    ADD("%s; it keeps the limits at %d of %d points", g->found ? "" : ")", g->survived,
        o->s->npoint);
    if (broken && broken <= 3) {
        ADD(" (not at ");
        len += points_list(o, zp_grid_survived_at, 0, 3, out + len, len < cap ? cap - len : 0);
        ADD(")");
    }
    if (g->rounds > 1) {
        ADD(", after %d searches (added as an answer broke them: ", g->rounds);
        len += points_list(o, zp_grid_added_at, 1, 4, out + len, len < cap ? cap - len : 0);
        ADD(")");
    }
    if (broken && g->found) {
        ADD("; no schedule was found for all %d points: %s", o->s->npoint, why_broken(g));
    }
    ADD(".");
    return len;
}

void zp_report_sweep_summary(const zp_report_sweep *o, char *out, size_t cap) {
    const zp_sweep *s = o->s;
    tally t = count(o);
    size_t len = 0;
    char at[512];
    ADD("%s over ", o->scene);
    for (int v = 0; v < s->nvary; v++) {
        const zp_sweep_vary *va = &s->vary[v];
        const char *x = va->kind == ZP_VARY_SCALE ? "x" : "";
        ADD("%s%s.%s %s%g to %s%g", v ? " by " : "", va->section, va->key, x, va->a, x, va->b);
    }
    ADD(" (%d point%s): %s at %d of them", s->npoint, s->npoint == 1 ? "" : "s",
        s->kind == ZP_STUDY_SEARCH ? "a schedule keeps the margin and the [limits]"
                                   : "the scene's schedule finishes with the margin and the "
                                     "[limits] kept",
        t.found);
    if (t.found) {
        zp_sweep_describe(s, t.fastest, at, sizeof at);
        ADD("; fastest %.4f s at %s", t.tmin, at);
        if (t.tmax > t.tmin) {
            zp_sweep_describe(s, t.slowest, at, sizeof at);
            ADD(", slowest %.4f s at %s", t.tmax, at);
        }
    }
    if (t.infeasible) {
        ADD("; none at %d point%s", t.infeasible, t.infeasible == 1 ? "" : "s");
        for (int p = 0, shown = 0; p < s->npoint && t.infeasible <= 3; p++) {
            if (!o->rows[p].failed && !o->rows[p].found) {
                zp_sweep_describe(s, p, at, sizeof at);
                ADD("%s%s", shown++ ? "; " : " (", at);
            }
        }
        ADD("%s", t.infeasible <= 3 ? ")" : "");
    }
    if (t.failed) {
        ADD("; %d failed (the message column of sweep.csv says why)", t.failed);
    }
    ADD(".");
    if (o->grid) {
        len += grid_summary(o, out + len, len < cap ? cap - len : 0);
    }
}

int zp_report_sweep_has_figure(const zp_report_sweep *o) {
    return o->s->nvary <= 2;
}

/* half a grid step of vary v (a tenth of the value, or 0.5, for a single value) */
static double half_step(const zp_sweep_vary *v) {
    if (v->n > 1 && v->b > v->a) {
        return 0.5 * (v->b - v->a) / (v->n - 1);
    }
    return fabs(v->a) > 0 ? 0.1 * fabs(v->a) : 0.5;
}

/* the axis of vary v in the designer's units: the value's unit, or for a scaled list the
   scene's own values the factor multiplies */
static void axis(FILE *f, const char *ax, const zp_sweep_vary *v) {
    double h = half_step(v);
    char what[200];
    if (v->kind == ZP_VARY_SCALE && v->base[0]) {
        snprintf(what, sizeof what, ": factor on %s%s%s (the scene)", v->base, v->unit[0] ? " " : "",
                 v->unit);
    } else if (v->kind == ZP_VARY_SCALE) {
        snprintf(what, sizeof what, " (factor on the values in the scene%s%s)",
                 v->unit[0] ? ", " : "", v->unit);
    } else {
        snprintf(what, sizeof what, "%s%s%s", v->unit[0] ? " (" : "", v->unit,
                 v->unit[0] ? ")" : "");
    }
    fprintf(f, "set %slabel '[%s] %s%s' noenhanced\nset %srange [%.9g:%.9g]\n", ax, v->section,
            v->key, what, ax, v->a - h, v->b + h);
}

static void script_line(FILE *f, const zp_report_sweep *o, const char *col, const tally *t) {
    double span = fmax(t->tmax - t->tmin, fmax(0.02 * fabs(t->tmax), 1e-3));
    double lo = t->found ? t->tmin - 0.2 * span : 0, hi = t->found ? t->tmax + 0.1 * span : 1;
    double mark = t->found ? t->tmin - 0.12 * span : 0.5; /* where unfound points are marked */
    axis(f, "x", &o->s->vary[0]);
    fprintf(f,
            "set ylabel 'finish time (s)'\nset yrange [%.9g:%.9g]\n"
            "set key outside below horizontal\n"
            "plot 'sweep.csv' using '%s':(strcol('found') eq '1' ? column('time_s') : NaN) "
            "with linespoints pt 7 ps 0.8 lw 2 lc rgb '#2ca02c' title '%s', \\\n"
            "     '' using '%s':(strcol('status') eq 'ok' && strcol('found') eq '0' ? %.9g : NaN) "
            "with points pt 2 ps 1.6 lw 2 lc rgb '#d62728' title '%s', \\\n"
            "     '' using '%s':(strcol('status') eq 'failed' ? %.9g : NaN) "
            "with points pt 8 ps 1.6 lw 2 lc rgb 'black' title 'failed'\n",
            lo, hi, col,
            o->s->kind == ZP_STUDY_SEARCH ? "fastest schedule that keeps the limits"
                                          : "the [drive] forces",
            col, mark,
            o->s->kind == ZP_STUDY_SEARCH ? "no schedule keeps the limits"
                                          : "does not finish with the margin kept",
            col, mark);
}

static void script_heat(FILE *f, const zp_report_sweep *o, const char *c1, const char *c2) {
    double dx = half_step(&o->s->vary[0]), dy = half_step(&o->s->vary[1]);
    axis(f, "x", &o->s->vary[0]);
    axis(f, "y", &o->s->vary[1]);
    fprintf(f,
            "set cblabel 'finish time (s)'\n"
            "set palette defined (0 '#fde725', 1 '#5ec962', 2 '#21918c', 3 '#3b528b', "
            "4 '#440154')\n"
            "set style fill solid 1 noborder\n"
            "set key outside below horizontal\nunset grid\n"
            "plot 'sweep.csv' using '%s':'%s':(%.9g):(%.9g):(strcol('found') eq '1' ? "
            "column('time_s') : NaN) with boxxyerror lc palette notitle, \\\n"
            "     '' using (strcol('status') eq 'ok' && strcol('found') eq '0' ? column('%s') : "
            "NaN):'%s':(%.9g):(%.9g) with boxxyerror lc rgb '#8c2d2d' title '%s', \\\n"
            "     '' using (strcol('status') eq 'failed' ? column('%s') : NaN):'%s':(%.9g):(%.9g) "
            "with boxxyerror lc rgb 'black' title 'failed'\n",
            c1, c2, dx, dy, c1, c2, dx, dy,
            o->s->kind == ZP_STUDY_SEARCH ? "no schedule keeps the limits"
                                          : "does not finish with the margin kept",
            c1, c2, dx, dy);
}

static void zp_report_sweep_script(FILE *f, const zp_report_sweep *o) {
    tally t = count(o);
    char c1[64], c2[64], name[128];
    size_t k = 0;
    for (; o->scene[k] && k + 1 < sizeof name; k++) { /* nothing in a name ends the string */
        name[k] = o->scene[k] == '\'' || o->scene[k] == '\\' ? '`' : o->scene[k];
    }
    name[k] = '\0';
    zp_sweep_column(&o->s->vary[0], c1, sizeof c1);
    fprintf(f,
            "# sweep.png (zipopt sweep); sweep.csv is its data. Run `gnuplot sweep.gp` here to "
            "redraw.\n"
            "set terminal pngcairo size 1000,700 noenhanced font 'DejaVu Sans,11' linewidth 1.3\n"
            "set output 'sweep.png'\nset encoding utf8\nset datafile separator comma\n"
            "set border lc rgb '#555555'\nset grid lc rgb '#e6e6e6' lt 1 lw 0.8\n"
            "set title 'Design study of %s: %s'\n",
            name,
            o->s->kind == ZP_STUDY_SEARCH ? "finish time of the fastest schedule that keeps "
                                            "the limits"
                                          : "finish time of the [drive] forces");
    if (o->s->nvary == 1) {
        script_line(f, o, c1, &t);
    } else {
        zp_sweep_column(&o->s->vary[1], c2, sizeof c2);
        script_heat(f, o, c1, c2);
    }
}

static void values_json(FILE *f, const zp_sweep *s, int p) {
    fputs("[", f);
    for (int v = 0; v < s->nvary; v++) {
        fputs(v ? ", " : "", f);
        zp_out_json_number(f, zp_sweep_value(s, v, p));
    }
    fputs("]", f);
}

static void forces_json(FILE *f, const double *force, int np) {
    fputs("[", f);
    for (int k = 0; k < np; k++) {
        fputs(k ? ", " : "", f);
        zp_out_json_number(f, force[k]);
    }
    fputs("]", f);
}

/* the points p with bit(p) == want, as a JSON array (empty for a failed grid schedule) */
static void points_json(FILE *f, const zp_report_sweep *o, int (*bit)(const zp_grid_result *, int),
                        int want) {
    fputc('[', f);
    for (int p = 0, n = 0; p < o->s->npoint && !o->grid->failed; p++) {
        if (bit(o->grid, p) == want) {
            fprintf(f, "%s%d", n++ ? ", " : "", p);
        }
    }
    fputc(']', f);
}

static void grid_json(FILE *f, const zp_report_sweep *o) {
    const zp_grid_result *g = o->grid;
    if (!g) {
        fputs("null", f);
        return;
    }
    fprintf(f, "{\"found\": %s, \"failed\": %s, \"message\": ", g->found ? "true" : "false",
            g->failed ? "true" : "false");
    zp_out_json_string(f, g->message);
    fprintf(f, ",\n    \"nominal\": {\"point\": %d, \"values\": ", g->nominal);
    values_json(f, o->s, g->nominal);
    fputs(", \"time\": ", f);
    zp_out_json_number(f, g->time);
    fputs(", \"margin_deg\": ", f);
    zp_out_json_number(f, g->margin);
    fputs("},\n    \"forces\": ", f);
    forces_json(f, g->force, g->failed ? 0 : g->np);
    fputs(",\n    \"worst_corner\": ", f);
    if (g->worst >= 0) {
        fprintf(f, "{\"point\": %d, \"values\": ", g->worst);
        values_json(f, o->s, g->worst);
        fputs(", \"margin_deg\": ", f);
        zp_out_json_number(f, g->worst_margin);
        fputs("}", f);
    } else {
        fputs("null", f);
    }
    fprintf(f,
            ",\n    \"corners\": %d, \"scenarios\": %d, \"evals\": %ld, \"rounds\": %d, "
            "\"answer_round\": %d, \"added\": ",
            g->ncorner, g->nscen, g->evals, g->rounds, g->kept);
    points_json(f, o, zp_grid_added_at, 1);
    fprintf(f, ",\n    \"points_survived\": %d, \"points_broken\": ", g->failed ? 0 : g->survived);
    points_json(f, o, zp_grid_survived_at, 0);
    fputs("}", f);
}

static void point_json(FILE *f, const zp_report_sweep *o, int p) {
    if (p < 0) {
        fputs("null", f);
        return;
    }
    fprintf(f, "{\"point\": %d, \"time\": ", p);
    zp_out_json_number(f, o->rows[p].time);
    fputs(", \"values\": ", f);
    values_json(f, o->s, p);
    fputs(", \"forces\": ", f);
    forces_json(f, o->rows[p].force, o->np);
    fputs("}", f);
}

void zp_report_sweep_json(FILE *f, const zp_report_sweep *o, const char *summary) {
    tally t = count(o);
    fputs("{\n  \"scene\": ", f);
    zp_out_json_string(f, o->scene);
    fprintf(f, ",\n  \"run\": \"%s\",\n  \"points\": %d,\n  \"vary\": [",
            zp_study_kind_name(o->s->kind), o->s->npoint);
    for (int v = 0; v < o->s->nvary; v++) {
        const zp_sweep_vary *va = &o->s->vary[v];
        fprintf(f, "%s{\"key\": \"%s.%s\", \"factor\": %s, \"from\": ", v ? ", " : "", va->section,
                va->key, va->kind == ZP_VARY_SCALE ? "true" : "false");
        zp_out_json_number(f, va->a);
        fputs(", \"to\": ", f);
        zp_out_json_number(f, va->b);
        fprintf(f, ", \"values\": %d}", va->n);
    }
    fprintf(f, "],\n  \"found\": %d,\n  \"infeasible\": %d,\n  \"failed\": %d,\n  \"fastest\": ",
            t.found, t.infeasible, t.failed);
    point_json(f, o, t.fastest);
    fputs(",\n  \"slowest\": ", f);
    point_json(f, o, t.slowest);
    fputs(",\n  \"grid_schedule\": ", f);
    grid_json(f, o);
    fputs(",\n  \"summary\": ", f);
    zp_out_json_string(f, summary);
    fputs("\n}\n", f);
}

int zp_report_sweep_files(zp_tx *t, const zp_report_sweep *o, const char *summary, char *err,
                          size_t errlen) {
    const char *names[] = {"sweep.csv", "summary.json", "sweep.gp"};
    FILE *f[3];
    if (zp_tx_open_set(t, names, f, zp_report_sweep_has_figure(o) ? 3 : 2, err, errlen)) {
        return -1;
    }
    zp_sweep_csv_header(f[0], o->s, o->np);
    for (int p = 0; p < o->s->npoint; p++) {
        zp_sweep_csv_row(f[0], o->s, p, &o->rows[p]);
    }
    zp_report_sweep_json(f[1], o, summary);
    if (zp_report_sweep_has_figure(o)) {
        zp_report_sweep_script(f[2], o);
    }
    return 0;
}
