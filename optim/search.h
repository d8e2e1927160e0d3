/* The search: the fastest survivable schedule of parameters within bounds, in rounds of a
   scan that extends in order and local polishes, so a larger budget never gives a worse answer. */
#ifndef ZP_SEARCH_H
#define ZP_SEARCH_H

#include "search_types.h"

/* The strategies --algorithm offers (strategies.def): a global phase, then a local polish,
   each a zp_strategy (strategy.h). */
typedef struct zp_search_algo {
    const char *name;                 /* as typed after --algorithm */
    const char *doc;                  /* one line for --help */
    const struct zp_strategy *global; /* its global phase */
    const struct zp_strategy *local;  /* its polish */
} zp_search_algo;

int zp_search_algo_count(void);
const zp_search_algo *zp_search_algo_get(int i);
int zp_search_algo_find(const char *name); /* -1 if unknown */
/* The strategy a search runs when none is named: portfolio-cobyla on a box of
   ZP_SEARCH_PORTFOLIO_SECTIONS sections or more held to no [robust] scenarios, where its
   populations found islands the scan's map missed (up to 6 % faster on the multi-section scenes
   measured), scan-cobyla otherwise: on smaller boxes the map covers the box and the
   populations only take budget from the polishes (the seed at +/-2 % fell to a 10.7 % slower
   island). docs/search.md has the measurements. */
#define ZP_SEARCH_PORTFOLIO_SECTIONS 4
int zp_search_algo_default(int nsec, int robust);

/* Whether a search's populations (the portfolio's; res->npops > 0) ran a survivable schedule
   within ZP_SEARCH_REACH of its best: 0 too when it evolves none. */
int zp_search_populations_reached(const zp_search_result *res);

/* The default budget for n parameters: ZP_SCENE_EVALS_PER_SECTION simulations each. */
long zp_search_default_budget(int n);

/* Searches the box [lo[k], hi[k]] (one per section, N) for the fastest schedule that keeps
   ob's limit. Creates one workspace per thread from (m, so) before any parallel work. Every
   simulation a smaller max_evals would run is also run with a larger one (same seed), so the
   best is never worse; the answer does not depend on the number of threads. ZP_OK, or
   ZP_ERR_NOMEM / ZP_ERR_INPUT (an NLopt setup failure) with why in err. */
zp_status zp_search_run(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                        const double *hi, const zp_search_opts *o, zp_search_result *res, char *err,
                        size_t errlen);

/* A warm restart after ob's scenario set grew: res holds a search's result for the smaller set
   (zp_search_run's or this one's) and receives this one's. COBYLA (the algorithm's polish) runs
   from the answer, from the distinct survivable polish ends within ZP_SEARCH_WARM_REACH of its
   time and from the fastest point of each island res reports, each with a budget fixed in
   advance, all in parallel; the best constant push is kept while it survives the grown set,
   else polished again from where it was. found = 0: no start was made survivable (the caller
   searches afresh). The answer, its counts (added to the earlier ones) and the ends are the
   warm ones; the evidence of convergence (rounds, polishes, basins, islands, history) stays the
   full search's. Same seed and set, same bits on any thread count. */
#define ZP_SEARCH_WARM_REACH 1e-3
zp_status zp_search_warm(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                         const double *hi, const zp_search_opts *o, zp_search_result *res,
                         char *err, size_t errlen);

/* How a search held to a growing set went: the searches run (the first, then one per growth)
   and the simulations they spent in all. */
typedef struct zp_search_grown {
    int searches;
    long evals;
} zp_search_grown;

/* After each search that did not fail (searches: how many ran so far; res: the last one's
   result), the caller's turn: *grown = 1 when it added to what ob is held to (ob's set, and
   the options so if they depend on it), so the search restarts; 0 to end. ZP_OK, or an error
   (with why in err) that ends the loop. */
typedef zp_status (*zp_search_grow_fn)(void *user, const zp_search_result *res, int searches,
                                       int *grown, char *err, size_t errlen);

/* The loop "grow the held-to set and restart warm", shared by the robust search's adversary and
   the grid schedule: zp_search_run, then after each growth zp_search_warm from what the last
   search found (afresh only when no warm start survives the grown set and the search was not
   interrupted); opts.restart says which search this is. ob and so are read anew for each
   search. The first failing search's status or grow's. */
zp_status zp_search_grow(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                         const double *hi, const zp_search_opts *o, zp_search_result *res,
                         zp_search_grow_fn grow, void *user, zp_search_grown *info, char *err,
                         size_t errlen);

#endif
