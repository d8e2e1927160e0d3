/* What robustness costs (`zipopt tradeoff`): the robust search of one problem at each force
   error level (the scene's other [robust] ranges as given), or at each drive power against no
   cap (what a motor buys), the levels then exchanging their answers, so that a level never
   keeps a slower answer than another level found that holds at its own. */
#ifndef ZP_TRADEOFF_H
#define ZP_TRADEOFF_H

#include "answer.h"

#define ZP_TRADEOFF_MAX_LEVELS 16
#define ZP_TRADEOFF_GIVEN -1 /* a level's answer is the schedule the problem was given */

/* One level's answer. */
typedef struct zp_tradeoff_level {
    double p; /* %: each section's force off by up to +/-p; or W: the drive's power (0: no cap) */
    int found;
    int done;       /* 1: its search finished; 0: stopped or never started */
    int from;       /* the level whose search found this answer, or ZP_TRADEOFF_GIVEN */
    double time;    /* s, nominal finish time of the answer */
    double arrival; /* km/h */
    double force[ZP_SCHED_MAX_PARAMS];
    int scenarios; /* held to */
    zp_robust_check check;
} zp_tradeoff_level;

/* The levels of one problem, each level's problem and answer kept for the exchange. */
typedef struct zp_tradeoff {
    const zp_problem *su;                  /* borrowed: the scene's problem */
    zp_problem pb[ZP_TRADEOFF_MAX_LEVELS]; /* su at the level's force error (su's model) */
    zp_answer ans[ZP_TRADEOFF_MAX_LEVELS]; /* owned: freed by zp_tradeoff_free */
    zp_tradeoff_level L[ZP_TRADEOFF_MAX_LEVELS];
    int n;           /* levels asked for, L[0] the 0 % level (the reference of the costs) */
    int ndone;       /* levels whose search ran to its end, the first ndone */
    int given;       /* su's schedule was given (scene or command line): one more candidate */
    int power;       /* the levels are drive powers (W), not force errors */
    double max_time; /* s per level's search, 0: no limit */
    volatile sig_atomic_t *stop; /* borrowed, may be NULL: nonzero stops the level under way */
} zp_tradeoff;

/* T for problem su at the n levels (%, or W with power; level[0] == 0: the reference);
   given: su's schedule is a candidate. */
void zp_tradeoff_init(zp_tradeoff *T, const zp_problem *su, const double *level, int n, int given,
                      int power);
/* Level i's robust search (progress and user as zp_search_opts' ) into T->L[i]: its answer
   and, on the nominal scene at the search's tolerance, its arrival speed. ZP_OK (L[i].done 0
   when stopped), or a failure with why in err. */
zp_status zp_tradeoff_solve(zp_tradeoff *T, int i,
                            void (*progress)(void *user, const zp_search_progress *p, int improved),
                            void *user, char *err, size_t errlen);
/* Each finished level keeps the fastest of its own answer, the others' and the given schedule
   that survives its own held scenarios; an adopted answer is checked again on the level's
   fresh scenarios. 0, or -1 with why in err. */
int zp_tradeoff_exchange(zp_tradeoff *T, char *err, size_t errlen);
/* s: what level i costs against the 0 % level (never negative once exchanged). */
double zp_tradeoff_cost(const zp_tradeoff *T, int i);
void zp_tradeoff_free(zp_tradeoff *T);

#endif
