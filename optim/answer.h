/* The one path from a problem to its answer: the (robust) search, its answer on fresh
   scenarios, the answer rerun and verified 100x tighter, [solver] accuracy, and what the
   report sets beside it; everything in one zp_answer, which report.c and summary.c read. */
#ifndef ZP_ANSWER_H
#define ZP_ANSWER_H

#include "diagnose.h"
#include "problem.h"
#include "push_scan.h"
#include "robust.h"
#include "verify.h"

/* How far zp_answer_solve goes: each depth does the ones above it too. */
typedef enum zp_answer_depth {
    ZP_ANSWER_SEARCHED, /* the search and, with [robust], its answer on fresh scenarios */
    ZP_ANSWER_VERIFIED, /* the answer rerun with p->answer and 100x tighter, and judged */
    ZP_ANSWER_REPORTED  /* robustness runs, [solver] accuracy, the scene's own [drive] forces
                           and the diagnosis of the fresh scenarios failed: all a report shows */
} zp_answer_depth;

/* The stages zp_answer_solve tells its caller of, in this order (for progress and figures). */
typedef enum zp_answer_stage {
    ZP_ANSWER_RERUN,     /* the answer's run is made (v.run and best): it may be drawn */
    ZP_ANSWER_CHECKING,  /* its checks begin (tried even when the rerun failed) */
    ZP_ANSWER_CHECKED,   /* the checks and the accuracy ended, well or not */
    ZP_ANSWER_COMPARED,  /* the scene's own forces ran: what is drawn may be finished */
    ZP_ANSWER_DIAGNOSING /* the fresh scenarios the answer fails are told apart (only then) */
} zp_answer_stage;

typedef struct zp_answer zp_answer;

/* What a profile gains: the best constant-per-section schedule of the same scene, found by the
   same search (strategy, budget, seed) over one force per section and verified as the answer
   is (ZP_ANSWER_REPORTED, a profile of more than one knot only). */
typedef struct zp_answer_constant {
    int ran;                         /* 1: searched */
    int found;                       /* it holds, as zp_answer.found says of the answer */
    double time;                     /* s, its verified run's */
    int nsec;
    double force[ZP_MAX_SECTIONS];   /* N per section */
    long evals;                      /* simulations its search spent */
} zp_answer_constant;

#define ZP_ANSWER_FALLBACKS 4 /* candidates tried after the search's best when it does not hold */

/* When the search's best does not hold with [solver] (scenes without [robust] scenarios): the
   next candidates the search kept (its islands' bests and polish ends, distinct, by ranked
   time) rerun and judged alike, the first that holds the answer. */
typedef struct zp_answer_fallback {
    int tried;        /* candidates after the best rerun; 0: the best held or none was kept */
    int taken;        /* 1: the answer is the tried-th, which holds; 0: none held */
    double first_time; /* s, the best's ranked time (at [optimize]'s tolerance) */
    double first_force[ZP_SCHED_MAX_PARAMS]; /* its parameters */
    char why[256];    /* why the best does not hold with [solver] */
} zp_answer_fallback;

typedef struct zp_answer_opts {
    zp_answer_depth depth;
    zp_search_opts search;   /* the strategy, budget, seed, wall time, stop flag and progress */
    const zp_spread *spread; /* NULL, or the ranks sharing the fresh scenarios: rank 0
                                searches; the others verify their share and stop there */
    /* at each stage reached, may be NULL: nonzero stops the solve (ZP_ERR_IO, err left as
       it was: the caller said why) */
    int (*stage)(void *user, zp_answer_stage s, const zp_answer *a);
    zp_pool_done checked; /* the robustness runs' progress (done, total), may be NULL */
    void *user;
} zp_answer_opts;

struct zp_answer {
    const zp_problem *pb; /* borrowed: what was solved */
    const char *algo;     /* the strategy's name (static) */
    zp_robust_problem rp; /* the objective, the [robust] box and set, the adversary's info
                             and the fresh-scenario check (rp.check) */
    long max_evals;       /* the search's budget and seed, as they ran */
    unsigned long seed;
    zp_search_result res; /* the search's, res.found its own verdict; with a fallback taken
                             res.force and res.best are the answer's (fallback.first_*: the
                             search's best) */
    int found;            /* res.found, and from ZP_ANSWER_VERIFIED on (not interrupted):
                             the answer holds with [solver] */
    char unheld[256];     /* why res.found is not found, "" */
    zp_answer_fallback fallback; /* tried 0: nothing was tried after the search's best */
    int verified;         /* 1: v, best and run_opts are filled (rank 0, ZP_ANSWER_VERIFIED on) */
    zp_verify v;          /* v.run: the answer at the answer profile; v.tight 100x tighter */
    zp_sim *best;         /* owned: v.run's workspace (its rows and kink crossings) */
    zp_sim_opts run_opts; /* v.run's options: p->answer, or what [solver] accuracy picked */
    zp_accuracy acc;      /* with [solver] accuracy: what v.run met */
    zp_result *given;     /* owned, NULL: none; the scene's own [drive] forces (p->sched)
                             judged at the search's options, ZP_ANSWER_REPORTED */
    zp_diagnosis *diag;   /* owned, NULL: the answer keeps every fresh scenario (or the
                             depth is lower) */
    zp_answer_constant constant; /* with a profile, what it gains (ZP_ANSWER_REPORTED) */
    zp_push_scan push; /* without [robust], the best constant push's own scan
                          (ZP_ANSWER_REPORTED; push.npts 0: not run, the answer being a push
                          or the scene robust); res.base is the faster of it and the
                          search's pushes */
};

/* The options of a solve of p to depth: the first strategy, p's budget and seed, no stop, no
   progress; a caller sets what it adds. */
zp_answer_opts zp_answer_opts_of(const zp_problem *p, zp_answer_depth depth);
/* Solves p (which must outlive a) as o asks into a: ZP_OK, or a failure's status with why in
   err (nothing of a is then to be read but what zp_answer_free frees). Free with zp_answer_free
   also on failure. */
zp_status zp_answer_solve(const zp_problem *p, const zp_answer_opts *o, zp_answer *a, char *err,
                          size_t errlen);
void zp_answer_free(zp_answer *a);
/* The scenarios the answer was held to: the [robust] set's, 0 without. */
int zp_answer_scenarios(const zp_answer *a);

#endif
