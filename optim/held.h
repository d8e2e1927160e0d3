/* The answer on everything the robust search held it to: the nominal scene, every scenario of
   the set (corners, quasi-random points, those the adversary added) and the adversary's last
   worst scenario, rerun at the verification's tolerance. */
#ifndef ZP_HELD_H
#define ZP_HELD_H

#include "box.h"
#include "objective.h"

typedef struct zp_held {
    int runs;                /* the nominal scene, the set's scenarios and the adversary's worst */
    int finished;            /* of them, finished */
    double worst_margin_deg; /* smallest margin over the finishing runs; INFINITY: none */
    int worst;               /* where: -1 the nominal scene, 0..n-1 the set's scenario, n the
                                adversary's worst */
} zp_held;

/* Reruns the schedule of parameters p on ob's nominal model and on each scenario of ob->set
   (each judged by its own criteria where the set gives them), and on the adversary's worst
   point w of b (NULL or not finite: none), with workspaces from so over nthreads (0: OpenMP's
   default). ZP_OK or ZP_ERR_NOMEM. */
zp_status zp_held_check(const zp_objective *ob, const zp_box *b, const zp_robust_worst *w,
                        const zp_sim_opts *so, const double *p, int nthreads, zp_held *h);

#endif
