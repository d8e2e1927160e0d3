/* Scene -> model, options and schedule in one pass: each stage adds its problems to one list,
   so a user fixes a file in one round, registry names included. Prints nothing. */
#include "prep.h"

#include "search.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene_read.h"
#include "sim_opts.h"

/* [optimize] method: the search's integrator, judged with the [solver] names */
static void search_opts(zp_setup *st, zp_diag *d) {
    const zp_scene *sc = &st->sc;
    st->search = st->sim;
    st->search.output_dt = 0;
    st->search.track_loads = 0;
    st->search.method = zp_method_find(sc->search_method);
    st->search.rtol = sc->search_rtol;
    st->search.atol = sc->search_rtol / 100;
    if (st->search.method < 0) {
        zp_diag_add(d, sc->path, sc->line_search_method, "optimize", "method",
                    "unknown method '%s'; expected one of those listed by zipopt --help",
                    sc->search_method);
    }
}

/* --schedule FILE, then --force: each replaces the schedule's parameters */
static void overrides(const char *cmd, zp_setup *st, const zp_overrides *ov, zp_diag *d) {
    zp_scene *sc = &st->sc;
    if (ov->schedule) {
        zp_scene_overlay_schedule(ov->schedule, sc, d);
    }
    st->sched = zp_schedule_of_scene(sc);
    char why[256];
    if (ov->force && zp_drive_parse(&st->sched, ov->force, &st->sched, why, sizeof why)) {
        zp_diag_add(d, NULL, 0, NULL, NULL, "zipopt %s: --force: %s", cmd, why);
    }
    st->seed = ov->has_seed ? ov->seed : sc->seed;
    st->max_evals = ov->max_evals > 0   ? ov->max_evals
                    : sc->line_max_evals ? sc->max_evals
                                         : zp_search_default_budget(st->sched.np);
}

int zp_prep_load(const char *cmd, const char *path, const char *text, const zp_overrides *ov,
                 zp_setup *st, zp_diag *d) {
    zp_scene *sc = &st->sc;
    st->m = NULL;
    int read_ok = 1;
    if (text) {
        read_ok = zp_scene_load_text(text, strlen(text), path ? path : "<string>",
                                     !ov->unnamed_ok, sc, d) == ZP_OK;
    } else if (path) {
        read_ok = zp_scene_load_file(path, !ov->unnamed_ok, sc, d) == ZP_OK;
    } else {
        zp_scene_seed(sc);
    }
    if (read_ok) {
        st->m = zp_model_build(sc, d);
    }
    zp_sim_opts_from_scene(sc, &st->sim, d);
    search_opts(st, d);
    if (st->m) {
        overrides(cmd, st, ov, d);
        st->limit = st->m->phi_max - sc->margin * M_PI / 180;
    }
    if (d->n + d->dropped == 0 && st->m) {
        return 0;
    }
    zp_prep_free(st);
    return -1;
}

void zp_prep_free(zp_setup *st) {
    zp_model_free(st->m);
    st->m = NULL;
}
