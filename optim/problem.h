/* A scene's problem as every study solves it: the model, the schedule the search fills, the
   criteria (margin and [limits]) and the named run profiles, built once from the scene read.
   The search command, the library, a sweep's point, the grid schedule and tradeoff's levels
   all start here (answer.h solves it). */
#ifndef ZP_PROBLEM_H
#define ZP_PROBLEM_H

#include "objective.h"

/* zp_problem_build's flags */
enum { ZP_PROBLEM_OUTCOMES = 1 }; /* the runs shown keep no trajectory: a study's point, whose
                                     outcomes alone count (its integrator steps alike) */

typedef struct zp_problem {
    zp_scene sc;       /* the scene as read: names, lines and settings for messages */
    zp_model *m;       /* owned by what zp_problem_build filled; a copy by value borrows it */
    zp_schedule sched; /* [drive] forces with [drive] min, max as bounds, or the overrides */
    zp_limits lim;     /* [limits]; all 0: none */
    double limit;      /* rad, largest relative joint angle the search allows: death - margin */
    long max_evals;    /* simulations the search may spend: [optimize] max_evals, or
                          zp_search_default_budget's when the scene gives none */
    unsigned long seed;
    /* the run profiles */
    zp_sim_opts sim;    /* [solver]: the runs a command shows */
    zp_sim_opts answer; /* the answer's rerun: sim, the peaks [limits] judge located exactly */
    zp_sim_opts search; /* the search's runs: [optimize] method and rtol (atol = rtol / 100),
                           judged by their verdict alone (zp_problem_verdict), the peaks
                           [limits] judge located exactly */
    zp_sim_opts verify; /* the fresh scenarios' runs: search, ZP_ESTIMATE_FACTOR tighter */
} zp_problem;

/* o for runs judged by their verdict alone: no trajectory and loads sampled only where a run
   needs them (rows, events, exact peaks), neither of which moves the integrator's steps. */
zp_sim_opts zp_problem_verdict(const zp_sim_opts *o);
/* p's criteria and run profiles from p->sc (read, perhaps with problems): [solver] and
   [optimize] registry names judged, each problem added to d. 0, or -1 with a problem added. */
int zp_problem_profiles(zp_problem *p, int flags, zp_diag *d);
/* p from p->sc (read without problems): the model built, then zp_problem_profiles, the schedule,
   the limit, the scene's budget and seed; flags: ZP_PROBLEM_OUTCOMES or 0. 0, or -1 with every
   problem in d (p->m may still be set). Free with zp_problem_free. */
int zp_problem_build(zp_problem *p, int flags, zp_diag *d);
void zp_problem_free(zp_problem *p);
/* What the search and the checks of p judge a run by: the model, margin, [limits] and the
   stall time of the shown runs, the schedule's kind; no scenario set. */
zp_objective zp_problem_objective(const zp_problem *p);
/* What run r of p's model breaks first of p's criteria (zp_limits_broken with p's limit and
   [limits]); *which: the [limits] key for ZP_BREAKS_LIMIT. */
zp_breaks zp_problem_breaks(const zp_problem *p, const zp_result *r, int *which);

#endif
