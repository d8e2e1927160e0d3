/* The grid schedule (grid.h): each corner of the grid a scenario with its own model and
   criteria in the search's set, the search run at the middle point, the answer checked at
   every point of the grid. */
#include "grid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "events.h"
#include "robust.h"
#include "scene_read.h"
#include "search.h"

#define DEG (180.0 / M_PI)

/* one grid point as the search and the check see it */
typedef struct gpoint {
    int p;             /* its index in the grid */
    zp_model *m;       /* owned */
    zp_sim_opts so;    /* [solver], outcomes only */
    zp_schedule sched; /* the point's [drive]: its kind and bounds */
    zp_objective ob;   /* the point's criteria: margin, [limits]; no set */
    double death_angle;
    zp_scen_set set; /* its [robust] scenarios (n = 0 without) */
} gpoint;

/* the nominal's search settings */
typedef struct search_cfg {
    int method;
    double rtol;
    long max_evals;
    unsigned long seed;
} search_cfg;

int zp_grid_nominal(const zp_sweep *s) {
    int p = 0, stride = 1;
    for (int v = 0; v < s->nvary; v++) {
        p += (s->vary[v].n - 1) / 2 * stride;
        stride *= s->vary[v].n;
    }
    return p;
}

int zp_grid_survived_at(const zp_grid_result *g, int p) {
    return (g->ok[p / 8] >> (p % 8)) & 1;
}

/* the distinct corners of s other than point skip, into out (2^nvary at most); their count */
static int corners(const zp_sweep *s, int skip, int *out) {
    int n = 0;
    for (unsigned i = 0; i < 1u << s->nvary; i++) {
        int p = 0, stride = 1, dup = 0;
        for (int v = 0; v < s->nvary; v++) {
            int hi = (i >> v) & 1;
            dup |= hi && s->vary[v].n == 1; /* one value: its "high" corner is the low one */
            p += (hi ? s->vary[v].n - 1 : 0) * stride;
            stride *= s->vary[v].n;
        }
        if (!dup && p != skip) {
            out[n++] = p;
        }
    }
    return n;
}

/* point g->p: its scene into sc (scratch), its model, options, schedule and criteria, and with
   robust its [robust] scenarios; 0, or -1 with why */
static int load_point(const zp_sweep *s, const char *base, const char *path, zp_scene *sc,
                      int robust, gpoint *g, char *why, size_t whylen) {
    zp_diag d;
    zp_diag_init(&d);
    char *text = zp_sweep_point_text(s, base, g->p, why, whylen);
    if (!text) {
        return -1;
    }
    zp_status rc = zp_scene_load_string(text, path, sc, &d);
    free(text);
    if (rc == ZP_OK) {
        g->m = zp_model_build(sc, &d);
    }
    if (!g->m || zp_sim_opts_from_scene(sc, &g->so, &d)) {
        snprintf(why, whylen, "%.*s", (int)whylen - 1,
                 d.n ? d.text[0] : "the scene does not build");
        return -1;
    }
    g->so.output_dt = 0; /* outcomes only: output requests never change the integrator's steps */
    g->sched = zp_schedule_of_scene(sc);
    /* the limit exactly as the search command sets it */
    g->ob = (zp_objective){.m = g->m,
                           .limit = g->m->phi_max - sc->margin * M_PI / 180,
                           .t_max = g->so.t_max,
                           .shape = &g->sched};
    zp_limits_from_scene(sc, &g->ob.lim);
    g->death_angle = sc->death_angle;
    zp_box box;
    zp_box_from_scene(sc, g->m, &box);
    if (robust && sc->robust && box.d > 0 &&
        zp_scen_set_build(&g->set, &box, g->m, sc->robust_samples, sc->seed)) {
        snprintf(why, whylen, "out of memory for the scenarios");
        return -1;
    }
    return 0;
}

static void free_point(gpoint *g) {
    zp_scen_set_free(&g->set);
    zp_model_free(g->m);
    g->m = NULL;
}

/* the corner's model runs on the nominal's workspaces: the same state and events */
static int same_kind(const zp_model *a, const zp_model *b) {
    return a->nlink == b->nlink && a->nsec == b->nsec && a->physics == b->physics &&
           a->nwork == b->nwork && a->narc == b->narc && a->nkink == b->nkink &&
           zp_events_count(a) == zp_events_count(b);
}

/* pt[0] the nominal, pt[1..n-1] the corners: loaded, checked alike, and their scenarios in
   set (the corners first, then every point's [robust] scenarios); lo/hi the bounds all keep */
static int setup(const zp_sweep *s, const char *base, const char *path, zp_scene *sc, gpoint *pt,
                 int n, search_cfg *cfg, zp_scen_set *set, double *lo, double *hi, char *why,
                 size_t whylen) {
    for (int i = 0; i < n; i++) {
        if (load_point(s, base, path, sc, 1, &pt[i], why, whylen)) {
            return -1;
        }
        if (i == 0) {
            *cfg = (search_cfg){zp_method_find(sc->search_method), sc->search_rtol, sc->max_evals,
                                sc->seed};
        }
        char at[256];
        zp_sweep_describe(s, pt[i].p, at, sizeof at);
        if (!same_kind(pt[i].m, pt[0].m) || pt[i].sched.np != pt[0].sched.np) {
            snprintf(why, whylen,
                     "the corner at %s is another kind of model than the middle point's "
                     "([physics] effects or kinks differ)",
                     at);
            return -1;
        }
        for (int k = 0; k < pt[0].sched.np; k++) {
            lo[k] = i ? fmax(lo[k], pt[i].sched.lo[k]) : pt[i].sched.lo[k];
            hi[k] = i ? fmin(hi[k], pt[i].sched.hi[k]) : pt[i].sched.hi[k];
            if (lo[k] > hi[k]) {
                snprintf(why, whylen, "the drive bounds at %s do not overlap the others'", at);
                return -1;
            }
        }
    }
    zp_scenario nominal;
    zp_scenario_nominal(&nominal);
    zp_status st = ZP_OK;
    for (int i = 1; i < n && !st; i++) {
        st = zp_scen_set_add_model(set, pt[i].m, &nominal, NULL, &pt[i].ob);
    }
    for (int i = 0; i < n && !st; i++) {
        for (int j = 0; j < pt[i].set.n && !st; j++) {
            st = zp_scen_set_add_model(set, &pt[i].set.m[j], &pt[i].set.sc[j], &pt[i].set.start[j],
                                       &pt[i].ob);
        }
    }
    if (st) {
        snprintf(why, whylen, "out of memory for the scenarios");
        return -1;
    }
    return 0;
}

/* the search at the nominal held to set; 0, or -1 with why */
static int search(gpoint *pt, int n, const search_cfg *cfg, zp_scen_set *set, const double *lo,
                  const double *hi, zp_grid_result *g, char *why, size_t whylen) {
    zp_search_result *res = malloc(sizeof *res); /* large: off the stack */
    if (!res) {
        snprintf(why, whylen, "out of memory for the search");
        return -1;
    }
    /* the search's runs as a point's: no trajectory, no load peaks unless a limit needs them,
       the [optimize] integrator and tolerance */
    zp_sim_opts fast = pt[0].so;
    fast.track_loads = 0;
    fast.method = cfg->method;
    fast.rtol = cfg->rtol;
    fast.atol = cfg->rtol / 100;
    fast.peaks = 0;
    for (int i = 0; i < n; i++) {
        fast.peaks |= zp_limits_need_peaks(&pt[i].ob.lim);
    }
    zp_objective ob = pt[0].ob;
    ob.set = set;
    zp_search_opts o = {.max_evals = cfg->max_evals, .seed = cfg->seed};
    int rc = zp_search_run(&ob, &fast, lo, hi, &o, res, why, whylen) ? -1 : 0;
    if (!rc) {
        g->found = res->found;
        g->evals = res->evals;
        memcpy(g->force, res->force, sizeof *g->force * (size_t)g->np);
    }
    free(res);
    return rc;
}

/* MODEL.md's survivable: finished with the margin and every [limits] value kept (without the
   search's slack: this is the answer's judgement, not the search's) */
static int survives(const gpoint *q, const zp_eval *e, const zp_result *r, int *which) {
    return !e->failed && e->outcome == ZP_OUTCOME_FINISHED && e->angle <= q->ob.limit &&
           (!zp_limits_any(&q->ob.lim) || zp_limits_excess(&q->ob.lim, q->m, r, which) <= 0);
}

/* the answer simulated at every point with the point's [solver] */
static void check(const zp_sweep *s, const char *base, const char *path, zp_scene *sc,
                  const int *corner, int ncorner, zp_grid_result *g) {
    zp_result *r = malloc(sizeof *r); /* large: off the stack */
    double worst_cons = -INFINITY;
    for (int p = 0; r && p < s->npoint; p++) {
        gpoint q = {.p = p};
        char why[256];
        zp_sim *sim = NULL;
        if (!load_point(s, base, path, sc, 0, &q, why, sizeof why) &&
            (sim = zp_sim_create(q.m, &q.so)) != NULL) {
            zp_eval e;
            zp_objective_eval(&q.ob, sim, g->force, &e, r);
            int which, ok = survives(&q, &e, r, &which);
            g->survived += ok;
            g->ok[p / 8] |= (unsigned char)(ok << (p % 8));
            double margin = q.death_angle - e.angle * DEG;
            if (p == g->nominal) {
                g->time = e.time;
                g->margin = margin;
            }
            for (int c = 0; c < ncorner; c++) {
                if (corner[c] == p && e.cons > worst_cons) {
                    worst_cons = e.cons;
                    g->worst = p;
                    g->worst_margin = margin;
                }
            }
        }
        zp_sim_free(sim);
        free_point(&q);
    }
    free(r);
}

void zp_grid_run(const zp_sweep *s, const char *base, const char *path, zp_grid_result *g) {
    memset(g, 0, sizeof *g);
    g->nominal = zp_grid_nominal(s);
    g->worst = -1;
    g->time = g->margin = g->worst_margin = NAN;
    int corner[1 << ZP_SWEEP_MAX_VARY];
    int nc = corners(s, g->nominal, corner), n = nc + 1;
    g->ncorner = nc;
    gpoint *pt = calloc((size_t)n, sizeof *pt);
    zp_scene *sc = malloc(sizeof *sc); /* large: off the stack */
    zp_scen_set set = {0};
    search_cfg cfg;
    double lo[ZP_SCHED_MAX_PARAMS], hi[ZP_SCHED_MAX_PARAMS];
    char why[512] = "out of memory";
    int rc = pt && sc ? 0 : -1;
    for (int i = 0; !rc && i < n; i++) {
        pt[i].p = i ? corner[i - 1] : g->nominal;
    }
    if (!rc && !(rc = setup(s, base, path, sc, pt, n, &cfg, &set, lo, hi, why, sizeof why))) {
        g->np = pt[0].sched.np;
        g->nscen = set.n;
        rc = search(pt, n, &cfg, &set, lo, hi, g, why, sizeof why);
    }
    zp_scen_set_free(&set); /* before the points: it borrows their models */
    for (int i = 0; pt && i < n; i++) {
        free_point(&pt[i]);
    }
    free(pt);
    if (rc) {
        g->failed = 1;
        snprintf(g->message, sizeof g->message, "%.*s", (int)sizeof g->message - 1, why);
    } else {
        check(s, base, path, sc, corner, nc, g);
    }
    free(sc);
}
