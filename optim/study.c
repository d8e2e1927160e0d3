/* One point of a design study (study.h): the scene's model, then the search with its answer
   re-run at the scene's tolerance, or one simulation; everything reduced to a row. */
#include "study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robust.h"
#include "search.h"
#include "sim_opts.h"
#include "verify.h"

#define DEG (180.0 / M_PI)
#define ACTIVE_DEG 0.01 /* deg: a margin this close to [optimize] margin is the binding limit */
#define ACTIVE_REL_LIMIT 1e-3 /* a [limits] value reached this close (relative) binds */
#define ACTIVE_REL 1e-9 /* a force this close (relative to the range) to a bound lies on it */

static const char *const kind_names[ZP_STUDY_KIND_COUNT] = {"search", "simulate"};

const char *zp_study_kind_name(zp_study_kind k) {
    return kind_names[k];
}

int zp_study_kind_find(const char *name) {
    for (int k = 0; k < ZP_STUDY_KIND_COUNT; k++) {
        if (!strcmp(name, kind_names[k])) {
            return k;
        }
    }
    return -1;
}

static void fail(zp_study_row *row, const char *why) {
    row->failed = 1;
    snprintf(row->message, sizeof row->message, "%.*s", (int)sizeof row->message - 1, why);
}

/* outcome, time, margin and the limited quantities of the answer's run r; the limit that
   decides the row: the scene's margin and [limits] judge every row, searched or simulated */
static void fill(const zp_scene *sc, const zp_model *m, const zp_schedule *sh, const zp_result *r,
                 zp_study_row *row) {
    double angle = zp_model_angle_used(m, r->max_rel_angle);
    row->outcome = r->outcome;
    row->time = r->time;
    row->margin = sc->death_angle - angle * DEG;
    zp_limits lim;
    zp_limits_from_scene(sc, &lim);
    zp_limits_reached(m, r, row->reached);
    if (!row->found) {
        /* nothing broken in the nominal run: a held scenario broke it */
        static const char *const said[] = {[ZP_BREAKS_NOTHING] = "scenarios",
                                           [ZP_BREAKS_DEATH] = "death",
                                           [ZP_BREAKS_STALL] = "t_max",
                                           [ZP_BREAKS_MARGIN] = "margin"};
        int which;
        zp_breaks b =
            zp_limits_broken(m, &lim, m->phi_max - sc->margin * M_PI / 180, r, &which);
        snprintf(row->limit, sizeof row->limit, "%s",
                 b == ZP_BREAKS_LIMIT ? zp_limit_name(which) : said[b]);
        return;
    }
    int at_max = 0, at_min = 0;
    for (int k = 0; k < row->np; k++) {
        double eps = ACTIVE_REL * fmax(sh->hi[k] - sh->lo[k], 1);
        at_max |= row->force[k] >= sh->hi[k] - eps;
        at_min |= row->force[k] <= sh->lo[k] + eps;
    }
    snprintf(row->limit, sizeof row->limit, "%s%s%s%s%s",
             row->margin - sc->margin < ACTIVE_DEG ? "margin" : "",
             row->margin - sc->margin < ACTIVE_DEG && at_max ? "+" : "", at_max ? "drive.max" : "",
             (row->margin - sc->margin < ACTIVE_DEG || at_max) && at_min ? "+" : "",
             at_min ? "drive.min" : "");
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (lim.max[i] > 0 && row->reached[i] >= (1 - ACTIVE_REL_LIMIT) * lim.max[i]) {
            size_t n = strlen(row->limit);
            snprintf(row->limit + n, sizeof row->limit - n, "%s%s", n ? "+" : "",
                     zp_limit_name(i));
        }
    }
    if (!row->limit[0]) {
        snprintf(row->limit, sizeof row->limit, "none");
    }
}

static void run_search(const zp_scene *sc, const zp_model *m, const zp_schedule *sched,
                       const zp_sim_opts *so, double max_time, zp_study_row *row) {
    /* the search's runs as `zipopt SCENE.ini` makes them: no trajectory, no load peaks, the
       [optimize] integrator and tolerance */
    zp_sim_opts search = *so, fast;
    search.track_loads = 0;
    search.output_dt = 0;
    search.method = zp_method_find(sc->search_method);
    search.rtol = sc->search_rtol;
    search.atol = sc->search_rtol / 100;
    zp_search_opts o = {.max_evals = sc->max_evals, .seed = sc->seed, .max_time = max_time};
    zp_search_result *res = malloc(sizeof *res);
    zp_robust_problem *pb = malloc(sizeof *pb); /* large: off the stack */
    char err[512] = "";
    /* the limit exactly as the search command sets it, so a point equals `zipopt SCENE`; with
       [robust] ranges, the robust search as that command runs it */
    double limit = m->phi_max - sc->margin * M_PI / 180;
    if (!res || !pb || zp_robust_setup(pb, sc, m, limit, sched, so, &search, &fast)) {
        fail(row, "out of memory for the search");
    } else if (zp_robust_solve(pb, sc, &fast, sched->lo, sched->hi, &o, res, err,
                               sizeof err)) {
        fail(row, err);
    } else {
        row->found = res->found;
        row->evals = res->evals;
        memcpy(row->force, res->force, sizeof *row->force * (size_t)row->np);
        zp_objective ob = pb->ob; /* the nominal scene: the scenarios were checked above */
        ob.set = NULL;
        zp_sim_opts solver = *so;
        solver.peaks = 1; /* the row's limited quantities, exact whether a limit is set or not */
        zp_verify v;
        zp_sim *best = NULL;
        if (zp_verify_run(&ob, &solver, res->force, sc->seed, 0, 0, &best, &v, NULL, NULL, err,
                          sizeof err)) {
            fail(row, err);
        } else {
            row->verified = v.agree;
            fill(sc, m, sched, v.run, row);
        }
        zp_verify_free(&v);
        zp_sim_free(best);
    }
    if (pb) {
        zp_robust_problem_free(pb);
    }
    free(pb);
    free(res);
}

static void run_simulate(const zp_scene *sc, const zp_model *m, const zp_objective *ob,
                         const zp_sim_opts *so, zp_study_row *row) {
    zp_result *r = malloc(sizeof *r); /* large: off the stack */
    zp_sim *s = zp_sim_create(m, so);
    if (!s || !r) {
        fail(row, "out of memory for the simulator");
    } else {
        memcpy(row->force, ob->shape->p, sizeof *row->force * (size_t)row->np);
        zp_eval e;
        zp_objective_eval(ob, s, ob->shape->p, &e, r);
        row->evals = 1;
        if (e.failed) {
            fail(row, r->message);
        } else {
            row->found = zp_objective_feasible(&e);
            fill(sc, m, ob->shape, r, row);
        }
    }
    zp_sim_free(s);
    free(r);
}

void zp_study_run(const zp_scene *sc, zp_study_kind kind, double max_time, zp_study_row *row) {
    memset(row, 0, sizeof *row);
    zp_schedule sched = zp_schedule_of_scene(sc);
    row->np = sched.np;
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = zp_model_build(sc, &d);
    zp_sim_opts so;
    if (!m || zp_sim_opts_from_scene(sc, &so, &d)) {
        fail(row, d.n ? d.text[0] : "the scene does not build");
        zp_model_free(m);
        return;
    }
    so.output_dt = 0; /* outcomes only: output requests never change the integrator's steps */
    if (kind == ZP_STUDY_SEARCH) {
        run_search(sc, m, &sched, &so, max_time, row);
    } else {
        /* the limit exactly as the search command sets it */
        zp_objective ob = {.m = m, .limit = m->phi_max - sc->margin * M_PI / 180,
                           .t_max = so.t_max, .shape = &sched};
        zp_limits_from_scene(sc, &ob.lim); /* judged as the search judges a candidate */
        so.peaks = 1;                      /* the row's limited quantities, exact */
        run_simulate(sc, m, &ob, &so, row);
    }
    zp_model_free(m);
}
