/* The answer checked: the best schedule re-simulated at a 100x tighter
   tolerance, and its robustness to perturbed parameters. */
#ifndef ZP_VERIFY_H
#define ZP_VERIFY_H

#include <signal.h>

#include "accuracy.h"
#include "estimate.h"
#include "pool.h"

#define ZP_VERIFY_LEVELS 2 /* perturbation levels: +/-2 % and +/-5 % unless the caller sets them */

typedef struct zp_robust {
    double level; /* 1: every parameter scaled by 1 + level * u, u uniform in [-1, 1] */
    int n;        /* runs */
    int survived; /* runs that finished alive */
    int kept;     /* runs that finished with the margin kept */
} zp_robust;

typedef struct zp_verify {
    zp_result *run;   /* owned: the schedule at the scene's tolerance, with its trajectory */
    zp_result *tight; /* owned: the same at rtol, atol (zp_estimate_tighter) */
    double rtol, atol; /* of the tighter run */
    int agree;        /* same outcome, finish times within ZP_VERIFY_DT, margin kept */
    double level[ZP_VERIFY_LEVELS]; /* the perturbation levels (shares, increasing): set
                                       between zp_verify_begin and _robustness; 0: 2 % and 5 % */
    zp_robust rob[ZP_VERIFY_LEVELS];
    int robust_done; /* robustness was measured (not when interrupted) */
    int kill_found;  /* some perturbation within the largest level killed */
    double kill;     /* 1: the smallest relative change of the parameters found to kill */
    int kill_param;  /* 1-based parameter whose change alone kills at `kill`, 0: a random mix */
} zp_verify;

/* The verification in steps, so the caller can judge the run before its costlier checks and
   draw it while they go: begin re-runs the schedule of parameters force (ob->shape's) at so,
   its trajectory rows in *sim_out (owned by the caller, freed with zp_sim_free, also on error)
   and its result in v->run; tight runs it at so made tighter (zp_estimate_tighter) into
   v->tight and sets v->rtol, atol and agree; robustness runs the robustness runs (nrobust per
   level, 0: none) and the bisections in one parallel batch over nthreads (0: OpenMP's
   default), progress(user, done, total) after each job (may be NULL). Each returns ZP_OK, or
   ZP_ERR_NUMERIC / ZP_ERR_NOMEM with why in err. */
zp_status zp_verify_begin(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                          zp_sim **sim_out, zp_verify *v, char *err, size_t errlen);
zp_status zp_verify_tight(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                          zp_verify *v, char *err, size_t errlen);
zp_status zp_verify_robustness(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                               unsigned long seed, int nrobust, int nthreads, zp_verify *v,
                               zp_pool_done progress, void *user, char *err, size_t errlen);
/* All steps, the tighter run in the robustness runs' batch: checks the parameters force with
   fresh workspaces from so; trajectory rows of v->run stay in *sim_out (owned by the caller,
   freed with zp_sim_free). nrobust = 0 skips robustness; progress(user, done, total) after
   each robustness job (may be NULL). Returns ZP_OK, or ZP_ERR_NUMERIC / ZP_ERR_NOMEM with why
   in err. */
zp_status zp_verify_run(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                        unsigned long seed, int nrobust, int nthreads, zp_sim **sim_out,
                        zp_verify *v, zp_pool_done progress, void *user, char *err, size_t errlen);
void zp_verify_free(zp_verify *v);
/* [solver] accuracy = acc (s) after zp_verify_tight: when the verification's estimate
   |v->run->time - v->tight->time| exceeds acc or the verdicts differ, the answer is rerun from
   one step tighter than so until its estimate meets acc (zp_accuracy_run), and v->run,
   *sim_out and v->tight (with v->rtol, atol, agree) become those of the new answer. *answer:
   the options of the answer's run; *a: what it met (reruns counted from the [solver] run).
   ZP_OK, or the failing run's status with why in err. */
zp_status zp_verify_accuracy(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                             double acc, zp_sim **sim_out, zp_verify *v, zp_sim_opts *answer,
                             zp_accuracy *a, char *err, size_t errlen);

#endif
