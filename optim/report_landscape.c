/* The landscape's files, windows and JSON (report_landscape.h). */
#include "report_landscape.h"

#include <math.h>

#include "out_json.h"

static const char *outcome_name(const zp_landscape_point *p) {
    return p->failed ? "failed" : zp_sim_outcome_name(p->outcome);
}

/* what keeps p from being survivable: "" when it finished with the margin (limit, rad) and
   every [limits] value kept; else its outcome, "margin", or the limit it exceeds most */
static const char *binding(const zp_landscape_point *p, double limit, const zp_limits *lim) {
    if (p->failed || p->outcome != ZP_OUTCOME_FINISHED) {
        return outcome_name(p);
    }
    if (p->max_rel_angle > limit) {
        return "margin";
    }
    int worst;
    double excess = zp_limits_excess_of(lim, p->reached, &worst);
    return worst >= 0 && excess > 0 ? zp_limits_name(worst) : "";
}

/* the result columns' header: the outcome, then what the run reached of each limit set */
static void write_header(FILE *f, const zp_limits *lim) {
    fputs("outcome,stall_reason,time,x,died_link,max_rel_angle_deg,kept,binding", f);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (lim->max[i] > 0) {
            fprintf(f, ",%s_reached_", zp_limits_name(i));
            for (const char *u = zp_limits_unit(i); *u; u++) { /* km/h -> km_h: a plain name */
                fputc(*u == '/' || *u == ' ' ? '_' : *u, f);
            }
        }
    }
    fputc('\n', f);
}

/* one CSV row's result columns */
static void write_point(FILE *f, const zp_landscape_point *p, double limit, const zp_limits *lim) {
    const char *why = binding(p, limit, lim);
    fprintf(f, ",%s,%s,%.9g,%.9g,%d,%.6g,%d,%s", outcome_name(p),
            p->failed || p->outcome != ZP_OUTCOME_STALLED ? "" : zp_sim_stall_name(p->stall),
            p->time, p->x, p->died_link, p->max_rel_angle * 180 / M_PI, !*why, why);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (lim->max[i] > 0) {
            fprintf(f, ",%.9g", p->failed ? NAN : p->reached[i]);
        }
    }
    fputc('\n', f);
}

/* landscape.csv: the constant pushes */
static void write_pushes(FILE *f, const zp_report_landscape *L) {
    const zp_fig_axis *r = &L->plan->push;
    fputs("force,", f);
    write_header(f, L->lim);
    for (int k = 0; k < r->n; k++) {
        fprintf(f, "%.9g", zp_fig_landscape_at(r, k));
        write_point(f, &L->pt[k], L->limit, L->lim);
    }
}

/* landscape_slice.csv: the two parameters of each run of the slice */
static void write_slice(FILE *f, const zp_report_landscape *L) {
    const zp_landscape_plan *p = L->plan;
    int np = L->base->np, n1 = p->push.n;
    fprintf(f, "f%d,f%d,", p->si + 1, p->sj + 1);
    write_header(f, L->lim);
    for (int k = 0; k < zp_landscape_slice_runs(p); k++) {
        const double *run = L->param + (size_t)(n1 + k) * np;
        fprintf(f, "%.9g,%.9g", run[p->si], run[p->sj]);
        write_point(f, &L->pt[n1 + k], L->limit, L->lim);
    }
}

/* 1 when some constant push finished or died: the figure's time panel has a point */
static int any_timed(const zp_report_landscape *L) {
    for (int k = 0; k < L->plan->push.n; k++) {
        const zp_landscape_point *pt = &L->pt[k];
        if (!pt->failed && (pt->outcome == ZP_OUTCOME_FINISHED || pt->outcome == ZP_OUTCOME_DIED)) {
            return 1;
        }
    }
    return 0;
}

int zp_report_landscape_files(zp_tx *t, const zp_report_landscape *L, char *err, size_t errlen) {
    const char *names[] = {"landscape.csv", "landscape.gp", "landscape_slice.csv",
                           "landscape_slice.gp"};
    const zp_landscape_plan *p = L->plan;
    int slice = zp_landscape_slice_runs(p) > 0;
    FILE *f[4];
    if (zp_tx_open_set(t, names, f, slice ? 4 : 2, err, errlen)) {
        return -1;
    }
    write_pushes(f[0], L);
    zp_fig_landscape_1d(f[1], L->scene, &p->push, any_timed(L));
    if (slice) {
        write_slice(f[2], L);
        zp_fig_landscape_2d(f[3], L->scene, L->base, p->si, p->sj, &p->rx, &p->ry, L->base_name);
    }
    return 0;
}

static int finishes(const zp_landscape_point *p) {
    return !p->failed && p->outcome == ZP_OUTCOME_FINISHED;
}

/* the survival windows are runs of consecutive finishing pushes: where one starts, ends */
static int window_starts(const zp_landscape_point *p, int k) {
    return finishes(&p[k]) && (k == 0 || !finishes(&p[k - 1]));
}

static int window_ends(const zp_fig_axis *r, const zp_landscape_point *p, int k) {
    return finishes(&p[k]) && (k == r->n - 1 || !finishes(&p[k + 1]));
}

/* the fastest push that finishes (survivable: that also keeps the margin and every [limits]
   value), or -1 */
static int fastest(const zp_report_landscape *L, int survivable) {
    const zp_landscape_point *p = L->pt;
    int best = -1;
    for (int k = 0; k < L->plan->push.n; k++) {
        if (finishes(&p[k]) && (!survivable || !*binding(&p[k], L->limit, L->lim)) &&
            (best < 0 || p[k].time < p[best].time)) {
            best = k;
        }
    }
    return best;
}

/* one window, points i..j: listed as the points it is, since pushes between two sampled
   points were never run */
static void window_text(FILE *f, const zp_fig_axis *r, int i, int j, int first) {
    fprintf(f, "%s %g", first ? "" : ";", zp_fig_landscape_at(r, i));
    if (j == i + 1) {
        fprintf(f, ", %g", zp_fig_landscape_at(r, j));
    } else if (j > i + 1) {
        fprintf(f, ", %g, .., %g", zp_fig_landscape_at(r, i + 1), zp_fig_landscape_at(r, j));
    }
    fprintf(f, " N");
    if (j > i + 1) {
        fprintf(f, " (%d points)", j - i + 1);
    }
}

void zp_report_landscape_windows(FILE *f, const zp_report_landscape *L) {
    const zp_fig_axis *r = &L->plan->push;
    const zp_landscape_point *p = L->pt;
    int nwin = 0, start = 0, best = fastest(L, 1), quick = fastest(L, 0);
    const char *limits = zp_limits_any(L->lim) ? " and every [limits] value" : "";
    fprintf(f, "constant push from %g to %g N (%d runs, every %g N): finishes at", r->a, r->b, r->n,
            (r->b - r->a) / (r->n - 1));
    for (int k = 0; k < r->n; k++) {
        start = window_starts(p, k) ? k : start;
        if (window_ends(r, p, k)) {
            window_text(f, r, start, k, !nwin++);
        }
    }
    fprintf(f, "%s\n", quick < 0 ? " no push in the range" : "");
    if (best < 0) {
        fprintf(f, "fastest: no push in the range keeps the margin%s\n", limits);
    } else {
        fprintf(f, "fastest: %g N, finished in %.3f s, keeping the margin%s\n",
                zp_fig_landscape_at(r, best), p[best].time, limits);
    }
    if (quick >= 0 && quick != best) {
        fprintf(f, "fastest finishing push: %g N, %.3f s, breaks %s\n",
                zp_fig_landscape_at(r, quick), p[quick].time, binding(&p[quick], L->limit, L->lim));
    }
}

/* "windows": [[from, to], ..], "fastest" and "fastest_finish" of the constant push */
static void windows_json(FILE *f, const zp_report_landscape *L) {
    const zp_fig_axis *r = &L->plan->push;
    const zp_landscape_point *p = L->pt;
    fprintf(f, "\"windows\": [");
    for (int k = 0, nwin = 0; k < r->n; k++) {
        if (window_starts(p, k)) {
            fprintf(f, "%s[%.17g, ", nwin++ ? ", " : "", zp_fig_landscape_at(r, k));
        }
        if (window_ends(r, p, k)) {
            fprintf(f, "%.17g]", zp_fig_landscape_at(r, k));
        }
    }
    int best = fastest(L, 1), quick = fastest(L, 0);
    if (best < 0) {
        fprintf(f, "], \"fastest\": null");
    } else {
        fprintf(f, "], \"fastest\": {\"force\": %.17g, ", zp_fig_landscape_at(r, best));
        zp_out_json_key(f, "time", p[best].time, "}");
    }
    if (quick < 0) {
        fprintf(f, ", \"fastest_finish\": null");
    } else {
        fprintf(f, ", \"fastest_finish\": {\"force\": %.17g, ", zp_fig_landscape_at(r, quick));
        zp_out_json_key(f, "time", p[quick].time, ", ");
        zp_out_json_key_string(f, "breaks", binding(&p[quick], L->limit, L->lim), "}");
    }
}

void zp_report_landscape_json(FILE *f, const zp_report_landscape *L, double wall, const char *dir,
                              int figures) {
    const zp_landscape_plan *p = L->plan;
    int n2 = zp_landscape_slice_runs(p);
    fprintf(f, "{\"scene\": ");
    zp_out_json_string(f, L->scene);
    fprintf(f, ", \"force_from\": %.17g, \"force_to\": %.17g, \"points\": %d, ", p->push.a,
            p->push.b, p->push.n);
    windows_json(f, L);
    if (n2) {
        fprintf(f, ", \"slice\": {\"%s\": [%d, %d], \"points\": %d}",
                zp_drive_param_noun(L->base, 1), p->si + 1, p->sj + 1, n2);
    } else {
        fprintf(f, ", \"slice\": null");
    }
    fprintf(f, ", \"runs\": %d, \"wall_s\": %.6g, \"out_dir\": ", p->push.n + n2, wall);
    zp_out_json_string(f, dir);
    fprintf(f, ", \"figures\": %s}\n", figures ? "true" : "false");
}
