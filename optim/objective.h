/* The search's view of one simulation (issue 4 "Objective and constraint"): a schedule's
   parameters in; the finish time and a continuous survival constraint out, always finite. */
#ifndef ZP_OBJECTIVE_H
#define ZP_OBJECTIVE_H

#include "sim.h"

/* One evaluated schedule. */
typedef struct zp_eval {
    zp_outcome outcome;
    int failed;     /* the integrator broke down (ZP_ERR_NUMERIC): treated as deadly */
    double time;    /* s: finish, death or stall */
    double x;       /* m, trolley x then */
    double angle;   /* rad, largest |relative joint angle| over all joints and the run */
    double obj;     /* s: the finish time; past t_max for runs that do not finish */
    double cons;    /* deg: <= 0 when the run finishes with the margin kept */
    double score;   /* s: obj plus a penalty for cons > 0, for algorithms without constraints */
} zp_eval;

/* What every evaluation of one search shares. */
typedef struct zp_objective {
    const zp_model *m; /* borrowed */
    double limit;      /* rad, largest |relative joint angle| allowed: death angle - margin */
    double t_max;      /* s, the stall time of the runs */
    const zp_schedule *shape; /* borrowed: the kind the parameters fill; NULL: per-section
                                 constants (N) */
} zp_objective;

/* How many parameters the search varies: ob->shape's, or one force per section. */
static inline int zp_objective_nparams(const zp_objective *ob) {
    return ob->shape ? ob->shape->np : ob->m->nsec;
}
/* The schedule the search's parameters p stand for (ob->shape with p). */
zp_schedule zp_objective_schedule(const zp_objective *ob, const double *p);
/* Runs the schedule of parameters p on the workspace s and scores it; r receives the run. */
void zp_objective_eval(const zp_objective *ob, zp_sim *s, const double *p, zp_eval *e,
                       zp_result *r);
/* 1 when e finished with the margin kept. */
int zp_objective_feasible(const zp_eval *e);
/* 1 when a is better than b: feasible before infeasible, then lower score, then lower obj. */
int zp_objective_better(const zp_eval *a, const zp_eval *b);

#endif
