/* The grid schedule (grid.h): each corner of the grid a scenario with its own model and
   criteria in the search's set, the search run at the middle point, the answer checked at
   every point of the grid. */
#include "grid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "events.h"
#include "problem.h"
#include "robust.h"
#include "scene_load.h"
#include "search.h"

#define DEG (180.0 / M_PI)

/* one grid point as the search and the check see it */
typedef struct gpoint {
    int p;           /* its index in the grid */
    zp_problem *pb;  /* owned: the point's scene, model, [drive] schedule (its kind and bounds)
                        and run profiles, outcomes only */
    zp_objective ob; /* the point's criteria: margin, [limits]; no set */
    zp_scen_set set; /* its [robust] scenarios (n = 0 without) */
} gpoint;

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

int zp_grid_added_at(const zp_grid_result *g, int p) {
    return (g->added[p / 8] >> (p % 8)) & 1;
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

/* point g->p: its problem (scene, model, options, schedule), its criteria as the search
   command sets them, and with robust its [robust] scenarios; 0, or -1 with why */
static int load_point(const zp_sweep *s, const char *base, const char *path, int robust,
                      gpoint *g, char *why, size_t whylen) {
    zp_diag d;
    zp_diag_init(&d);
    char *text = zp_sweep_point_text(s, base, g->p, why, whylen);
    if (!text) {
        return -1;
    }
    g->pb = malloc(sizeof *g->pb); /* large: off the stack */
    if (!g->pb) {
        snprintf(why, whylen, "out of memory for the point's model");
        free(text);
        return -1;
    }
    g->pb->m = NULL;
    zp_scene *sc = &g->pb->sc;
    zp_status rc = zp_scene_load_string(text, path, sc, &d);
    free(text);
    /* outcomes only: output requests never change the integrator's steps */
    if (rc != ZP_OK || zp_problem_build(g->pb, ZP_PROBLEM_OUTCOMES, &d)) {
        snprintf(why, whylen, "%.*s", (int)whylen - 1,
                 d.n ? d.text[0] : "the scene does not build");
        return -1;
    }
    g->ob = zp_problem_objective(g->pb);
    zp_box box;
    zp_box_from_scene(sc, g->pb->m, &box);
    if (robust && sc->robust && box.d > 0 &&
        zp_scen_set_build(&g->set, &box, g->pb->m, sc->robust_samples, sc->seed)) {
        snprintf(why, whylen, "out of memory for the scenarios");
        return -1;
    }
    return 0;
}

static void free_point(gpoint *g) {
    zp_scen_set_free(&g->set);
    if (g->pb) {
        zp_problem_free(g->pb);
    }
    free(g->pb);
    g->pb = NULL;
}

/* the corner's model runs on the nominal's workspaces: the same state and events */
static int same_kind(const zp_model *a, const zp_model *b) {
    return a->nlink == b->nlink && a->nsec == b->nsec && a->physics == b->physics &&
           a->nwork == b->nwork && a->ndrive == b->ndrive && a->narc == b->narc &&
           a->nkink == b->nkink && zp_events_count(a) == zp_events_count(b);
}

/* the search and what it is held to, over the rounds */
typedef struct grid_run {
    const zp_sweep *s;
    const char *base, *path; /* the scene text and its file name */
    gpoint *pt; /* npoint: [0] the nominal, then the corners, then the points added; the set
                   borrows their models and criteria, so they never move */
    int n;      /* points held to */
    zp_scen_set set;
    double lo[ZP_SCHED_MAX_PARAMS], hi[ZP_SCHED_MAX_PARAMS]; /* the bounds all keep */
    zp_search_result *res;                                   /* the last search's */
    char why[512];
} grid_run;

/* pt[r->n] (its p set) loaded, checked against the nominal and held to: its model as a
   scenario with its own criteria (not the nominal's: that is the search's objective), then
   its [robust] scenarios; 0, or -1 with why */
static int hold(grid_run *r) {
    int i = r->n++; /* freed with the others from here on, loaded or not */
    gpoint *q = &r->pt[i], *nom = &r->pt[0];
    if (load_point(r->s, r->base, r->path, 1, q, r->why, sizeof r->why)) {
        return -1;
    }
    const zp_schedule *sched = &q->pb->sched;
    char at[256];
    zp_sweep_describe(r->s, q->p, at, sizeof at);
    if (!same_kind(q->pb->m, nom->pb->m) || sched->np != nom->pb->sched.np) {
        snprintf(r->why, sizeof r->why,
                 "the point at %s is another kind of model than the middle point's "
                 "([physics] effects or kinks differ)",
                 at);
        return -1;
    }
    for (int k = 0; k < sched->np; k++) {
        r->lo[k] = i ? fmax(r->lo[k], sched->lo[k]) : sched->lo[k];
        r->hi[k] = i ? fmin(r->hi[k], sched->hi[k]) : sched->hi[k];
        if (r->lo[k] > r->hi[k]) {
            snprintf(r->why, sizeof r->why, "the drive bounds at %s do not overlap the others'",
                     at);
            return -1;
        }
    }
    zp_scenario nominal;
    zp_scenario_nominal(&nominal);
    zp_status st = i ? zp_scen_set_add_model(&r->set, q->pb->m, &nominal, NULL, &q->ob) : ZP_OK;
    for (int j = 0; j < q->set.n && !st; j++) {
        st = zp_scen_set_add_model(&r->set, &q->set.m[j], &q->set.sc[j], &q->set.start[j], &q->ob);
    }
    if (st) {
        snprintf(r->why, sizeof r->why, "out of memory for the scenarios");
        return -1;
    }
    return 0;
}

/* the search's runs: the nominal's search profile, with the load peaks located where any
   point held to needs them for its [limits] */
static void search_opts(const grid_run *r, zp_sim_opts *fast) {
    *fast = r->pt[0].pb->search;
    for (int i = 0; i < r->n; i++) {
        fast->peaks |= zp_limits_need_peaks(&r->pt[i].ob.lim);
    }
}

/* docs/model.md's survivable: finished with the margin and every [limits] value kept (without the
   search's slack: this is the answer's judgement, not the search's) */
static int survives(const gpoint *q, const zp_eval *e, const zp_result *r) {
    int which;
    return !e->failed && zp_problem_breaks(q->pb, r, &which) == ZP_BREAKS_NOTHING;
}

/* g's answer simulated at every point with the point's [solver]; the corners are
   pt[1..ncorner]; each point's constraint value (> 0: broken) into cons */
static void check(grid_run *r, int ncorner, zp_grid_result *g, double *cons) {
    zp_result *res = malloc(sizeof *res); /* large: off the stack */
    double worst_cons = -INFINITY;
    g->survived = 0;
    g->worst = -1;
    g->time = g->margin = g->worst_margin = NAN;
    memset(g->ok, 0, sizeof g->ok);
    for (int p = 0; res && p < r->s->npoint; p++) {
        gpoint q = {.p = p};
        char why[256];
        zp_sim *sim = NULL;
        cons[p] = INFINITY; /* a point that cannot run breaks it most */
        if (!load_point(r->s, r->base, r->path, 0, &q, why, sizeof why) &&
            (sim = zp_sim_create(q.pb->m, &q.pb->sim)) != NULL) {
            zp_eval e;
            zp_objective_eval(&q.ob, sim, g->force, &e, res);
            int ok = survives(&q, &e, res);
            g->survived += ok;
            g->ok[p / 8] |= (unsigned char)(ok << (p % 8));
            cons[p] = e.cons;
            double margin = q.pb->sc.death_angle - e.angle * DEG;
            if (p == g->nominal) {
                g->time = e.time;
                g->margin = margin;
            }
            for (int c = 1; c <= ncorner; c++) {
                if (r->pt[c].p == p && e.cons > worst_cons) {
                    worst_cons = e.cons;
                    g->worst = p;
                    g->worst_margin = margin;
                }
            }
        }
        zp_sim_free(sim);
        free_point(&q);
    }
    free(res);
}

/* the points g's answer breaks that are not held to yet (the ZP_GRID_ADD_MAX it breaks most,
   by cons, when more), held to from the next search on, in the grid's order; how many */
static int hold_broken(grid_run *r, zp_grid_result *g, const double *cons) {
    int pick[ZP_GRID_ADD_MAX], npick = 0;
    for (int p = 0; p < r->s->npoint; p++) {
        int held = 0;
        for (int i = 0; i < r->n && !held; i++) {
            held = r->pt[i].p == p;
        }
        if (held || zp_grid_survived_at(g, p)) {
            continue;
        }
        /* an insertion into pick, kept sorted by cons, most first (ties: the earlier point) */
        int k = npick < ZP_GRID_ADD_MAX ? npick++ : ZP_GRID_ADD_MAX;
        for (; k > 0 && cons[p] > cons[pick[k - 1]]; k--) {
            if (k < ZP_GRID_ADD_MAX) {
                pick[k] = pick[k - 1];
            }
        }
        if (k < ZP_GRID_ADD_MAX) {
            pick[k] = p;
        }
    }
    for (int p = 0; p < r->s->npoint; p++) {
        for (int k = 0; k < npick; k++) {
            if (pick[k] == p) {
                r->pt[r->n].p = p;
                if (hold(r)) {
                    return -1;
                }
                g->added[p / 8] |= (unsigned char)(1u << (p % 8));
            }
        }
    }
    g->nadded += npick;
    return npick;
}

/* between the searches: the answer kept and checked at every point; while some point breaks
   it and searches are left, the broken points not held to yet are held to from the next search
   on (grid_turn is the user of zp_search_grow) */
typedef struct grid_turn {
    grid_run *r;
    int ncorner;
    zp_grid_result *g;
    double *cons;    /* per grid point, the constraint of the answer checked */
    zp_sim_opts *so; /* the search's runs, as the points held to need them */
} grid_turn;

static zp_status grid_grow(void *user, const zp_search_result *res, int searches, int *grown,
                           char *err, size_t errlen) {
    (void)err; /* r->why is err */
    (void)errlen;
    grid_turn *t = user;
    grid_run *r = t->r;
    zp_grid_result *g = t->g;
    g->rounds = searches;
    if (!res->found && g->kept) {
        return ZP_OK; /* held to more points, none survives all: the answer before stands */
    }
    g->found = res->found;
    memcpy(g->force, res->force, sizeof *g->force * (size_t)g->np);
    g->kept = g->rounds;
    g->nheld = g->nadded;
    g->nscen = r->set.n;
    check(r, t->ncorner, g, t->cons);
    if (!g->found || g->survived == r->s->npoint || g->rounds >= ZP_GRID_SEARCHES) {
        return ZP_OK;
    }
    /* worst first, as the robust search orders its set between rounds */
    zp_scen_set_reorder(&r->set);
    int added = hold_broken(r, g, t->cons);
    if (added < 0) {
        return ZP_ERR_INPUT; /* why in r->why */
    }
    /* none added: it breaks only points held to (the search's slack, their [solver]) */
    *grown = added > 0;
    search_opts(r, t->so);
    return ZP_OK;
}

/* the searches and checks, round after round; 0, or -1 with r->why */
static int rounds(grid_run *r, int ncorner, zp_grid_result *g) {
    double *cons = malloc(sizeof *cons * (size_t)r->s->npoint);
    if (!cons) {
        return -1;
    }
    const zp_problem *nom = r->pt[0].pb;
    zp_objective ob = r->pt[0].ob;
    ob.set = &r->set;
    zp_sim_opts fast;
    search_opts(r, &fast);
    /* the budget as the scene holds it */
    zp_search_opts o = {.max_evals = nom->sc.max_evals, .seed = nom->seed};
    grid_turn turn = {r, ncorner, g, cons, &fast};
    zp_search_grown grown;
    zp_status st = zp_search_grow(&ob, &fast, r->lo, r->hi, &o, r->res, grid_grow, &turn, &grown,
                                  r->why, sizeof r->why);
    g->rounds = grown.searches;
    g->evals = grown.evals;
    g->last_found = r->res->found;
    free(cons);
    return st ? -1 : 0;
}

void zp_grid_run(const zp_sweep *s, const char *base, const char *path, zp_grid_result *g) {
    memset(g, 0, sizeof *g);
    g->nominal = zp_grid_nominal(s);
    g->worst = -1;
    g->time = g->margin = g->worst_margin = NAN;
    int corner[1 << ZP_SWEEP_MAX_VARY];
    int nc = corners(s, g->nominal, corner);
    g->ncorner = nc;
    grid_run r = {.s = s, .base = base, .path = path, .why = "out of memory"};
    r.pt = calloc((size_t)s->npoint, sizeof *r.pt); /* each point held to at most once */
    r.res = malloc(sizeof *r.res);                  /* large: off the stack */
    int rc = r.pt && r.res ? 0 : -1;
    for (int i = 0; !rc && i <= nc; i++) {
        r.pt[r.n].p = i ? corner[i - 1] : g->nominal;
        rc = hold(&r);
    }
    if (!rc) {
        g->np = r.pt[0].pb->sched.np;
        rc = rounds(&r, nc, g);
    }
    zp_scen_set_free(&r.set); /* before the points: it borrows their models */
    for (int i = 0; i < r.n; i++) {
        free_point(&r.pt[i]);
    }
    free(r.pt);
    free(r.res);
    if (rc) {
        g->failed = 1;
        snprintf(g->message, sizeof g->message, "%.*s", (int)sizeof g->message - 1, r.why);
    }
}
