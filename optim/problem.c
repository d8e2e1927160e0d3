/* A scene -> its problem (problem.h): the model, the criteria and every run profile derived in
   one place, so that each study runs the search, the answer and its checks alike. */
#include "problem.h"

#include <math.h>

#include "estimate.h"
#include "search.h"
#include "sim_opts.h"

zp_sim_opts zp_problem_verdict(const zp_sim_opts *o) {
    zp_sim_opts v = *o;
    v.output_dt = 0;
    v.track_loads = 0;
    return v;
}

/* [optimize] method: the search's integrator, judged with the [solver] names */
static void search_profile(zp_problem *p, zp_diag *d) {
    const zp_scene *sc = &p->sc;
    p->search = zp_problem_verdict(&p->sim);
    p->search.method = zp_method_find(sc->search_method);
    p->search.rtol = sc->search_rtol;
    p->search.atol = sc->search_rtol / 100;
    p->search.peaks = zp_limits_need_peaks(&p->lim);
    if (p->search.method < 0) {
        zp_diag_add(d, sc->path, sc->line_search_method, "optimize", "method",
                    "unknown method '%s'; expected one of those listed by zipopt --help",
                    sc->search_method);
    }
}

int zp_problem_profiles(zp_problem *p, int flags, zp_diag *d) {
    int before = d->n + d->dropped;
    zp_limits_from_scene(&p->sc, &p->lim);
    zp_sim_opts_from_scene(&p->sc, &p->sim, d);
    if (flags & ZP_PROBLEM_OUTCOMES) {
        p->sim.output_dt = 0;
    }
    p->answer = p->sim;
    p->answer.peaks = zp_limits_need_peaks(&p->lim);
    search_profile(p, d);
    p->verify = zp_estimate_tighter(&p->search);
    return d->n + d->dropped > before ? -1 : 0;
}

int zp_problem_build(zp_problem *p, int flags, zp_diag *d) {
    const zp_scene *sc = &p->sc;
    int before = d->n + d->dropped;
    p->m = zp_model_build(sc, d);
    zp_problem_profiles(p, flags, d);
    if (p->m) {
        p->sched = zp_drive_of_scene(sc);
        p->limit = p->m->phi_max - sc->margin * M_PI / 180;
        p->max_evals = sc->line_max_evals ? sc->max_evals : zp_search_default_budget(p->sched.np);
        p->seed = sc->seed;
    }
    return p->m && d->n + d->dropped == before ? 0 : -1;
}

void zp_problem_free(zp_problem *p) {
    zp_model_free(p->m);
    p->m = NULL;
}

zp_objective zp_problem_objective(const zp_problem *p) {
    return (zp_objective){
        .m = p->m, .limit = p->limit, .t_max = p->sim.t_max, .shape = &p->sched, .lim = p->lim};
}

zp_breaks zp_problem_breaks(const zp_problem *p, const zp_result *r, int *which) {
    return zp_limits_broken(p->m, &p->lim, p->limit, r, which);
}
