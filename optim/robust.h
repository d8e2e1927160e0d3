/* The robust search (docs/model.md "Uncertainty and limits"): the [robust] box of scenarios, the
   scenario sets every candidate is held to (corners first, then quasi-random points fixed by
   the seed), the adversarial growth of the set, and the verification on fresh scenarios. */
#ifndef ZP_ROBUST_H
#define ZP_ROBUST_H

#include "headroom.h"
#include "scen_set.h"
#include "search.h"
#include "spread.h"

#define ZP_ROBUST_STREAM_VERIFY 0x7e1fUL

/* One end of the spread over the fresh scenarios: its value and the scenario that gives it. */
typedef struct zp_spread_end {
    double value;         /* s or km/h; NAN: no scenario finished */
    int sample;           /* index of the fresh scenario, -1: none */
    double u[ZP_BOX_MAX]; /* its point in the stated box */
} zp_spread_end;

/* The answer on fresh random scenarios (a stream apart from the set's). */
typedef struct zp_robust_check {
    int samples;
    int survived;    /* finished alive */
    int margin_kept; /* finished with the margin kept */
    int limits_kept; /* finished with every [limits] value kept */
    int all_kept;    /* both: survivable (docs/model.md) */
    double lower_95; /* 95 % lower confidence bound of P(survivable), Clopper-Pearson */
    double worst_margin_deg; /* smallest margin over the finishing scenarios; after
                                zp_robust_solve also over those of held_margin_deg */
    double held_margin_deg;  /* zp_robust_solve: smallest margin over the nominal scene, every
                                scenario held and the adversary's worst, rerun alike (held.h) */
    int held_worst;          /* where (zp_held.worst) */
    zp_headroom headroom;    /* zp_robust_solve: past the stated box */
    /* the population's spread over the finishing fresh scenarios: fastest and slowest finish
       (s), lowest and highest arrival speed (km/h) */
    zp_spread_end fastest, slowest, arrival_low, arrival_high;
    zp_spread_end tension_high; /* [cable]: the highest anchor tension (N) of those rides */
} zp_robust_check;

typedef struct zp_robust_info {
    int rounds;        /* rounds run (1 + scenarios added by the adversary) */
    int added;         /* scenarios the adversary added */
    long sims;         /* simulations of the adversary */
    zp_robust_worst worst; /* of the answer, from the last adversarial search */
} zp_robust_info;

/* The robust search: ob (with ob->set built) searched as zp_search_run does; then, while the
   answer exists and the adversary finds a scenario of b that breaks it, that scenario joins
   the set and the search restarts warm from what it found (zp_search_warm; afresh only when
   no warm start survives the grown set), at most max_rounds rounds in all. */
zp_status zp_robust_search(zp_objective *ob, const zp_box *b, const zp_sim_opts *so,
                           const double *lo, const double *hi, const zp_search_opts *o,
                           int max_rounds, zp_search_result *res, zp_robust_info *info, char *err,
                           size_t errlen);
/* The schedule of parameters p checked on n fresh scenarios of b with workspaces from so (the
   caller passes the tighter verification tolerance); nthreads 0: OpenMP's default. Scenario i is
   the point of coordinates 2 U - 1, U the next b->d uniforms of gsl_rng_mt19937 seeded with seed ^
   ZP_ROBUST_STREAM_VERIFY (a stream apart from the set's and the adversary's). With sp (may be
   NULL) every rank calls it alike, runs its share of the scenarios and ends with the same c, bit
   for bit, as one process alone. ZP_OK, ZP_ERR_NOMEM or ZP_ERR_IO (the exchange). */
zp_status zp_robust_verify(const zp_objective *ob, const zp_box *b, const zp_sim_opts *so,
                           const double *p, int n, unsigned long seed, int nthreads,
                           const zp_spread *sp, zp_robust_check *c);
/* zp_robust_verify, with each scenario's point and verdict in each[n] as well (may be NULL). */
zp_status zp_robust_verify_each(const zp_objective *ob, const zp_box *b, const zp_sim_opts *so,
                                const double *p, int n, unsigned long seed, int nthreads,
                                const zp_spread *sp, zp_robust_check *c, zp_robust_worst *each);
/* A scene's problem as the search sees it: the objective (margin, limits, and the set when
   the scene has [robust] ranges), the box and the set, then what the robust search found. */
typedef struct zp_robust_problem {
    zp_objective ob;
    int robust;          /* the scene has [robust] ranges: ob.set = &set */
    zp_box box;          /* the stated box: fresh scenarios and reports */
    zp_box hold;         /* the box held: box widened by [robust] safety_factor */
    zp_scen_set set;
    zp_robust_info info;
    zp_robust_check check; /* samples 0: not verified */
    /* NULL, or the ranks sharing the verification: rank 0 searches while the others wait
       (without spinning), then every rank verifies its share of the scenarios */
    const zp_spread *spread;
} zp_robust_problem;

#define ZP_ROBUST_ROUNDS 4 /* rounds at most: the adversary adds up to 3 scenarios */

/* p for sc and m: the objective (limit: rad, the largest joint angle allowed; shape: the
   schedule kind the parameters fill; t_max of the [solver] options so), and fast = search (the
   search's runs) with exact load peaks when a limit needs them. ZP_OK or ZP_ERR_NOMEM. */
zp_status zp_robust_setup(zp_robust_problem *p, const zp_scene *sc, const zp_model *m,
                          double limit, const zp_schedule *shape, const zp_sim_opts *so,
                          const zp_sim_opts *search, zp_sim_opts *fast);
/* The (robust) search over the box [lo[k], hi[k]] (one per parameter) with the adversary,
   then, unless interrupted, the answer verified on sc->verify_samples fresh scenarios at the
   search's runs' tolerance (fast) made tighter as zp_estimate_tighter does. With p->spread
   every rank calls it: rank 0 searches; the others get its answer (res->force only) and their
   share of the verification, and end with the same p->check. */
zp_status zp_robust_solve(zp_robust_problem *p, const zp_scene *sc, const zp_sim_opts *fast,
                          const double *lo, const double *hi,
                          const zp_search_opts *o, zp_search_result *res, char *err,
                          size_t errlen);
/* Rank 0 stopping before zp_robust_solve sends the other ranks of sp (NULL: none) home. */
void zp_robust_release(const zp_spread *sp);
void zp_robust_problem_free(zp_robust_problem *p);

/* The one-sided 95 % Clopper-Pearson lower bound of a probability with k successes in n. */
double zp_robust_clopper_pearson_lower(int k, int n, double alpha);

#endif
