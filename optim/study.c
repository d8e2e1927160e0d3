/* One point of a design study (study.h): the scene's model, then the search with its answer
   re-run at the scene's tolerance, or one simulation; everything reduced to a row. */
#include "study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "answer.h"

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
static void fill(const zp_problem *p, const zp_result *r, zp_study_row *row) {
    const zp_scene *sc = &p->sc;
    const zp_schedule *sh = &p->sched;
    double angle = zp_model_angle_used(p->m, r->max_rel_angle);
    row->outcome = r->outcome;
    row->time = r->time;
    row->margin = sc->death_angle - angle * DEG;
    zp_limits_reached(p->m, r, row->reached);
    if (!row->found) {
        /* nothing broken in the nominal run: a held scenario broke it */
        static const char *const said[] = {[ZP_BREAKS_NOTHING] = "scenarios",
                                           [ZP_BREAKS_DEATH] = "death",
                                           [ZP_BREAKS_STALL] = "t_max",
                                           [ZP_BREAKS_MARGIN] = "margin"};
        int which;
        zp_breaks b = zp_problem_breaks(p, r, &which);
        snprintf(row->limit, sizeof row->limit, "%s",
                 b == ZP_BREAKS_LIMIT ? zp_limits_name(which) : said[b]);
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
        if (p->lim.max[i] > 0 && row->reached[i] >= (1 - ACTIVE_REL_LIMIT) * p->lim.max[i]) {
            size_t n = strlen(row->limit);
            snprintf(row->limit + n, sizeof row->limit - n, "%s%s", n ? "+" : "",
                     zp_limits_name(i));
        }
    }
    if (!row->limit[0]) {
        snprintf(row->limit, sizeof row->limit, "none");
    }
}

/* the search as `zipopt SCENE.ini` runs it (with [robust] ranges, the robust search), its
   answer rerun with the point's [solver] and checked tighter */
static void run_search(const zp_problem *p, double max_time, zp_study_row *row) {
    zp_answer_opts o = zp_answer_opts_of(p, ZP_ANSWER_VERIFIED);
    /* [optimize] max_evals as the scene holds it: 5000 when not given, where the command
       (p->max_evals) spends 5000 per section */
    o.search.max_evals = p->sc.max_evals;
    o.search.max_time = max_time;
    zp_answer *a = malloc(sizeof *a); /* large: off the stack */
    char err[512] = "";
    if (!a) {
        fail(row, "out of memory for the search");
        return;
    }
    if (zp_answer_solve(p, &o, a, err, sizeof err)) {
        fail(row, err);
    } else {
        row->found = a->res.found; /* the search's own verdict; verified: [solver] agrees */
        row->evals = a->res.evals;
        memcpy(row->force, a->res.force, sizeof *row->force * (size_t)row->np);
        row->verified = a->v.agree;
        fill(p, a->v.run, row);
    }
    zp_answer_free(a);
    free(a);
}

/* the scene's [drive] forces, judged as the search judges a candidate */
static void run_simulate(const zp_problem *p, zp_study_row *row) {
    zp_result *r = malloc(sizeof *r); /* large: off the stack */
    zp_sim *s = zp_sim_create(p->m, &p->answer);
    zp_objective ob = zp_problem_objective(p);
    if (!s || !r) {
        fail(row, "out of memory for the simulator");
    } else {
        memcpy(row->force, p->sched.p, sizeof *row->force * (size_t)row->np);
        zp_eval e;
        zp_objective_eval(&ob, s, p->sched.p, &e, r);
        row->evals = 1;
        if (e.failed) {
            fail(row, r->message);
        } else {
            row->found = zp_objective_feasible(&e);
            fill(p, r, row);
        }
    }
    zp_sim_free(s);
    free(r);
}

void zp_study_run(const zp_scene *sc, zp_study_kind kind, double max_time, zp_study_row *row) {
    memset(row, 0, sizeof *row);
    row->np = zp_drive_of_scene(sc).np;
    zp_problem *p = malloc(sizeof *p); /* large: off the stack */
    zp_diag d;
    zp_diag_init(&d);
    if (!p) {
        fail(row, "out of memory for the model");
        return;
    }
    p->sc = *sc;
    /* outcomes only: output requests never change the integrator's steps */
    if (zp_problem_build(p, ZP_PROBLEM_OUTCOMES, &d)) {
        fail(row, d.n ? d.text[0] : "the scene does not build");
    } else {
        p->answer.peaks = 1; /* the row's limited quantities, exact whether a limit is set or not */
        if (kind == ZP_STUDY_SEARCH) {
            run_search(p, max_time, row);
        } else {
            run_simulate(p, row);
        }
    }
    zp_problem_free(p);
    free(p);
}
