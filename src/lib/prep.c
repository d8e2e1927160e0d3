/* Scene -> problem in one pass: reading, building and the overrides each add their problems to
   one list, so a user fixes a file in one round, registry names included. Prints nothing. */
#include "prep.h"

#include <string.h>

#include "scene_load.h"

/* --schedule FILE, then --force: each replaces the schedule's parameters; --seed, --max-evals */
static void overrides(const char *cmd, zp_problem *p, const zp_overrides *ov, zp_diag *d) {
    zp_scene *sc = &p->sc;
    if (ov->schedule) {
        zp_scene_load_overlay_schedule(ov->schedule, sc, d);
        p->sched = zp_drive_of_scene(sc);
    }
    char why[256];
    if (ov->force && zp_drive_parse(&p->sched, ov->force, &p->sched, why, sizeof why)) {
        zp_diag_add(d, NULL, 0, NULL, NULL, "zipopt %s: --force: %s", cmd, why);
    }
    if (ov->has_seed) {
        p->seed = ov->seed;
    }
    if (ov->max_evals > 0) {
        p->max_evals = ov->max_evals;
    }
}

int zp_prep_load(const char *cmd, const char *path, const char *text, const zp_overrides *ov,
                 zp_problem *p, zp_diag *d) {
    zp_scene *sc = &p->sc;
    p->m = NULL;
    int read_ok = 1;
    if (text) {
        read_ok = zp_scene_load_text(text, strlen(text), path ? path : "<string>",
                                     !ov->unnamed_ok, sc, d) == ZP_OK;
    } else if (path) {
        read_ok = zp_scene_load_file(path, !ov->unnamed_ok, sc, d) == ZP_OK;
    } else {
        zp_scene_load_seed(sc);
    }
    if (read_ok) {
        zp_problem_build(p, 0, d);
    } else {
        zp_problem_profiles(p, 0, d); /* the registry names' problems too, in the same round */
    }
    if (p->m) {
        overrides(cmd, p, ov, d);
    }
    if (d->n + d->dropped == 0 && p->m) {
        return 0;
    }
    zp_problem_free(p);
    return -1;
}
