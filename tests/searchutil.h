/* Shared by the search's tests: a whole search over the scene's box, and the check that a
   larger budget's history opens with a smaller one's. */
#ifndef ZP_SEARCHUTIL_H
#define ZP_SEARCHUTIL_H

#include "check.h"
#include "search.h"
#include "testutil.h"

/* the search of algorithm algo (an index of zp_search_algo_get) over sc's box on nthreads
   threads, with sc's budget and seed, into r */
static inline void tu_search_with(const zp_objective *ob, const zp_sim_opts *o, const zp_scene *sc,
                                  int algo, int nthreads, zp_search_result *r) {
    zp_search_opts so = {
        .algo = algo, .max_evals = sc->max_evals, .seed = sc->seed, .nthreads = nthreads};
    char err[256];
    double lo[ZP_MAX_SECTIONS], hi[ZP_MAX_SECTIONS];
    tu_scene_box(sc, lo, hi);
    CHECK(zp_search_run(ob, o, lo, hi, &so, r, err, sizeof err) == ZP_OK);
}

/* big, a search at a larger budget than small: the history ends at its answer, however many
   improvements came before it, and small's improvements, at the same simulation counts, open
   it: the same runs in the same order (every improvement kept, so the comparison sees them
   all) */
static inline void tu_history_extends(const zp_search_result *big, const zp_search_result *small) {
    CHECK(!big->found || (big->nhist > 0 && big->hist[big->nhist - 1].time == big->best.time));
    CHECK(big->hist_halvings == 0);
    CHECK(big->nhist >= small->nhist);
    for (int i = 0; i < small->nhist && i < big->nhist; i++) {
        CHECK(big->hist[i].evals == small->hist[i].evals &&
              big->hist[i].time == small->hist[i].time);
    }
}

#endif
