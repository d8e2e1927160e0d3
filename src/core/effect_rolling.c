/* Rolling resistance (docs/model.md "Optional effects", docs/friction.md): mu |N| along the
   course against the trolley's motion. Its force hangs on the normal force N, which hangs on it
   in turn, so it has no force function of its own: each formulation solves the two together
   (friction_terms in form_lagrange.c, newton_friction in form_newton.c), friction.c holds the
   stick rule at rest. Here: when the scene turns it on, its words and its work. */
#include "effect.h"
#include "model.h"

static int rolling_build(zp_model *m, const zp_scene *sc, zp_diag *d) {
    (void)d;
    m->mu = sc->rolling;
    return m->mu > 0;
}

static void rolling_describe(const zp_model *m, const zp_scene *sc, FILE *f) {
    (void)sc;
    fprintf(f, " rolling resistance %g;", m->mu);
}

const zp_effect zp_effect_rolling = {
    .name = "rolling",
    .build = rolling_build,
    .describe = rolling_describe,
    .work = {"friction_work", "friction_loss", "w_fric", "friction work", "friction"},
};
