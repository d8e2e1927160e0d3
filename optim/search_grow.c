/* The search held to a growing set (search.h): a search, then, while the caller grows the set,
   a warm restart from what the last one found. */
#include "search.h"

/* a survivable answer faster than the best constant push */
static int beats_push(const zp_search_result *res) {
    return res->found && (!res->base_found || res->best.time < res->base.time);
}

zp_status zp_search_grow(const zp_objective *ob, const zp_sim_opts *so, const double *lo,
                         const double *hi, const zp_search_opts *o, zp_search_result *res,
                         zp_search_grow_fn grow, void *user, zp_search_grown *info, char *err,
                         size_t errlen) {
    *info = (zp_search_grown){0};
    zp_search_opts ro = *o; /* the progress says which restart it reports */
    zp_status st = ZP_OK;
    for (int grown = 1; !st && grown;) {
        int k = info->searches;
        ro.restart = k;
        int lost = 0;
        if (k) {
            long before = res->evals; /* the warm restart adds to the counts */
            int had = beats_push(res);
            st = zp_search_warm(ob, so, lo, hi, &ro, res, err, errlen);
            info->evals += res->evals - before;
            lost = had && !beats_push(res);
        }
        /* afresh: the first search, or when the warm restart keeps nothing faster than the
           constant push (tower at 10x: the polishes from the answer, its ends and islands all
           still broke the grown set, and the answer fell from 14.46 s to the push's 16.05 s) */
        if (!st && (!k || ((!res->found || lost) && !res->interrupted))) {
            /* the counts and the time go on from the searches before it */
            long evals = k ? res->evals : 0, feasible = k ? res->nfeasible : 0;
            long failed = k ? res->nfailed : 0;
            double wall = k ? res->wall_s : 0;
            st = zp_search_run(ob, so, lo, hi, &ro, res, err, errlen);
            info->evals += res->evals;
            res->evals += evals;
            res->nfeasible += feasible;
            res->nfailed += failed;
            res->wall_s += wall;
        }
        info->searches++;
        grown = 0;
        if (!st) {
            st = grow(user, res, info->searches, &grown, err, errlen);
        }
    }
    return st;
}
