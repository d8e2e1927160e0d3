/* The smallest margin over the scenarios the answer was held to: each run again at the
   verification's tolerance, in parallel, reduced in the set's index order so the result is
   the same on any thread count. */
#include "held.h"

#include <math.h>
#include <stdlib.h>

#include "pool.h"
#include "scen_set.h"
#include "state.h"

#define DEG (180.0 / M_PI)

typedef struct held_batch {
    const zp_objective *ob;
    const zp_box *b;
    const zp_robust_worst *w; /* NULL: no adversary's worst */
    zp_schedule sched;
    zp_chain c0;    /* the nominal docs/model.md start */
    double *margin; /* per run, deg; NAN: did not finish */
} held_batch;

/* run i: 0 the nominal scene, 1..n the set's scenario i - 1, n + 1 the adversary's worst */
static void held_job(void *user, int i, zp_sim *s, zp_result *r) {
    held_batch *hb = user;
    const zp_objective *ob = hb->ob;
    const zp_scen_set *set = ob->set;
    int n = set ? set->n : 0;
    zp_input in = {.sched = &hb->sched};
    const zp_model *m = ob->m;
    const zp_objective *oj = ob;
    zp_scenario sc;
    zp_model mw;
    zp_chain start;
    if (i >= 1 && i <= n) {
        int j = i - 1;
        m = &set->m[j];
        oj = set->judge && set->judge[j].m ? &set->judge[j] : ob;
        in.force_scale = set->sc[j].force;
        in.start = &set->start[j];
    } else if (i == n + 1) {
        zp_box_scenario(hb->b, hb->w->u, &sc);
        zp_scenario_model(ob->m, &sc, &mw);
        zp_scenario_start(&hb->c0, mw.nlink, &sc, &start);
        m = &mw;
        in.force_scale = sc.force;
        in.start = &start;
    }
    zp_eval e;
    zp_objective_eval_run(oj, m, s, &in, &e, r);
    hb->margin[i] =
        !e.failed && e.outcome == ZP_OUTCOME_FINISHED ? (m->phi_max - e.angle) * DEG : NAN;
}

zp_status zp_held_check(const zp_objective *ob, const zp_box *b, const zp_robust_worst *w,
                        const zp_sim_opts *so, const double *p, int nthreads, zp_held *h) {
    int n = ob->set ? ob->set->n : 0;
    int adv = w && b && isfinite(w->cons);
    int nrun = 1 + n + adv;
    *h = (zp_held){.runs = nrun, .worst_margin_deg = INFINITY, .worst = -1};
    held_batch hb = {ob, b, adv ? w : NULL, zp_objective_schedule(ob, p), {{0}, {0}}, NULL};
    zp_state_start(ob->m, ob->m->course, &hb.c0);
    hb.margin = malloc(sizeof *hb.margin * (size_t)nrun);
    zp_pool *pool = hb.margin ? zp_pool_create(ob->m, so, nthreads) : NULL;
    if (!pool) {
        free(hb.margin);
        return ZP_ERR_NOMEM;
    }
    zp_pool_map(pool, nrun, held_job, &hb, NULL, NULL);
    for (int i = 0; i < nrun; i++) {
        if (isnan(hb.margin[i])) {
            continue;
        }
        h->finished++;
        if (hb.margin[i] < h->worst_margin_deg) {
            h->worst_margin_deg = hb.margin[i];
            h->worst = i - 1;
        }
    }
    zp_pool_free(pool);
    free(hb.margin);
    return ZP_OK;
}
