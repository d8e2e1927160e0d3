/* The search's view of one simulation: a schedule's
   parameters in; the finish time and a continuous survival constraint out, always finite. */
#ifndef ZP_OBJECTIVE_H
#define ZP_OBJECTIVE_H

#include "scenario.h"
#include "sim.h"

struct zp_scen_set;

/* One evaluated schedule. */
typedef struct zp_eval {
    zp_outcome outcome;
    int failed;   /* the integrator broke down (ZP_ERR_NUMERIC): treated as deadly */
    double time;  /* s: finish, death or stall */
    double x;     /* m, trolley x then */
    double angle; /* rad, largest |relative joint angle| over all joints and the run */
    double obj;   /* s: the finish time; past t_max for runs that do not finish */
    double cons;  /* deg: <= 0 when the run finishes with the margin kept */
    double score; /* s: obj plus a penalty for cons > 0, for algorithms without constraints */
    int scenario; /* the scenario (index in the set) that broke the run, -1: none did */
} zp_eval;

/* What every evaluation of one search shares. */
typedef struct zp_objective {
    const zp_model *m; /* borrowed */
    double limit;      /* rad, largest |relative joint angle| allowed: death angle - margin */
    double t_max;      /* s, the stall time of the runs */
    const zp_schedule *shape; /* borrowed: the kind the parameters fill; NULL: per-section
                                 constants (N) */
    zp_limits lim;            /* [limits]; all 0: none */
    struct zp_scen_set *set;  /* borrowed, NULL: the nominal scene only; else every candidate
                                 that survives the nominal scene is held to each scenario */
    int slowest; /* [optimize] objective = slowest: obj is the slowest of the nominal run
                    and the set's scenarios run (a throughput: the line's slowest rider) */
} zp_objective;

/* The scenarios every candidate is held to, with their derived models and starts (built,
   grown and ordered by scen_set.h). */
typedef struct zp_scen_set {
    int n, cap;
    int ncorner;         /* the first ncorner are corners of the box */
    double *u;           /* owned, cap x ZP_BOX_MAX: each scenario's point */
    zp_scenario *sc;     /* owned, cap */
    zp_model *m;         /* owned, cap: sharing the nominal model's course */
    zp_chain *start;     /* owned, cap */
    int *order;          /* owned, n: the order of evaluation, worst first */
    long *fails;         /* owned, cap: candidates each scenario stopped, for the order */
    zp_objective *judge; /* owned, cap, or NULL (every scenario judged by the search's
                            objective): scenario j's own criteria (limit, t_max, [limits]) where
                            zp_scen_set_add_model gave one, judge[j].m == NULL where not */
    long runs;           /* scenario simulations so far (the search counts candidates) */
} zp_scen_set;

/* How many parameters the search varies: ob->shape's, or one force per section. */
static inline int zp_objective_nparams(const zp_objective *ob) {
    return ob->shape ? ob->shape->np : ob->m->nsec;
}
/* The schedule the search's parameters p stand for (ob->shape with p). */
zp_schedule zp_objective_schedule(const zp_objective *ob, const double *p);
/* Runs the schedule of parameters p on the workspace s and scores it: in the nominal scene,
   then (a survivor, with a set) in each scenario of the set in its order, stopping at the first
   that breaks the margin or a limit; cons is the worst over the runs. r receives the last run. */
void zp_objective_eval(const zp_objective *ob, zp_sim *s, const double *p, zp_eval *e,
                       zp_result *r);
/* The same, and the constraint's parts (zp_objective_parts_count, below) into parts, each the worst
   over the runs (NULL: none). */
void zp_objective_eval_parts(const zp_objective *ob, zp_sim *s, const double *p, zp_eval *e,
                             zp_result *r, double *parts);
/* The scenarios a survivor is held to: ob->set's, 0 without a set. */
int zp_objective_nscenarios(const zp_objective *ob);
/* The parts of zp_objective_eval, for a caller that shares a survivor's scenarios out: the
   nominal run of sched scored into e, and its parts into parts when not NULL (1: a survivor
   with a set, the scenarios follow); the
   constraint of the scenario at position i of the set's order (and in *obj, may be NULL, its
   objective: its finish time, or past t_max; in parts, may be NULL, its parts); and, once positions
   [0, nrun) ran with their constraints folded into e->cons in order (and with ob->slowest their
   objectives into e->obj; broke: the last one broke), the counts and the score as the serial loop
   leaves them. */
int zp_objective_eval_nominal(const zp_objective *ob, zp_sim *s, const zp_schedule *sched,
                              zp_eval *e, zp_result *r, double *parts);
double zp_objective_scenario(const zp_objective *ob, int i, const zp_schedule *sched, zp_sim *s,
                             zp_result *r, double *obj, double *parts);
void zp_objective_eval_close(const zp_objective *ob, int nrun, int broke, zp_eval *e);
/* One run of in on model m (ob->m or a scenario's model), scored without the set. */
void zp_objective_eval_run(const zp_objective *ob, const zp_model *m, zp_sim *s, const zp_input *in,
                           zp_eval *e, zp_result *r);
/* e's constraint as a scenario's: a run that does not finish breaks it too. */
double zp_objective_scenario_cons(const zp_objective *ob, const zp_eval *e);
/* The parts of a finished nominal run's constraint, each on cons's scale (deg, <= 0: kept;
   e->cons is the largest of them), for a polish that holds them apart: the margin alone, and
   [limits] value i (set in ob->lim) alone at the value v it reached (zp_limits_reached's),
   with in *per_unit its derivative in v. */
double zp_objective_margin_cons(const zp_objective *ob, const zp_eval *e);
double zp_objective_limit_cons(const zp_objective *ob, int i, double v, double *per_unit);
/* The survival constraint in parts, for a polish that holds them apart: the margin and each
   [limits] value on zp_eval.cons's scale. Their largest is cons, a max that kinks where two of
   them bind at once, and a linear model of it (COBYLA's) cannot follow the edge where they meet:
   on the seed under max_g 12 and 90 km/h the fastest schedules lie along such an edge. */
#define ZP_OBJECTIVE_PARTS_MAX (1 + ZP_LIMIT_COUNT)

/* The parts a polish of ob holds apart: 1 + the [limits] values set, or 1 (cons whole) without
   limits or where scenarios are judged by criteria of their own. With a scenario set each part
   is the worst over the runs of a candidate (the nominal one and its scenarios up to the first
   that broke): under [robust] the fastest schedules lie where one limit binds in one scenario
   and another in another (the heaviest rider's arrival speed and the lightest's). */
int zp_objective_parts_count(const zp_objective *ob);
/* The zp_objective_parts_count(ob) parts of e, the evaluation of run r on model m (ob->m or a
   scenario's): the margin, then each limit set in the order of zp_limit_id; every part is
   e->cons for a run that did not finish. */
void zp_objective_parts_of(const zp_objective *ob, const zp_model *m, const zp_eval *e,
                           const zp_result *r, double *c);
/* acc[k] = max(acc[k], c[k]) for the zp_objective_parts_count(ob) parts */
void zp_objective_parts_fold(const zp_objective *ob, double *acc, const double *c);

/* 1 when e finished with the margin kept. */
int zp_objective_feasible(const zp_eval *e);
/* 1 when a is better than b: feasible before infeasible, then lower score, then lower obj. */
int zp_objective_better(const zp_eval *a, const zp_eval *b);

#endif
