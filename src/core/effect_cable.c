/* A cable that sags (docs/model.md, scene section [cable]): a course provider whose one piece is
   the loaded-cable path under the model's load, and the cable's own potential Pi_c as a
   conservative horizontal force -dPi_c/dx on the trolley. */
#include <math.h>

#include "effect.h"
#include "model.h"

/* the path is built past the ride at both ends, so an integrator's trial stage a little before
   x_start or past x_end still finds it; never past the anchors, where it has no meaning */
#define ZP_CABLE_MARGIN 0.5 /* of the gap between the ride and each anchor */

static int cable_build(zp_model *m, const zp_scene *sc, zp_diag *d) {
    if (!sc->cable) {
        return 0;
    }
    zp_cable_def def = zp_cable_def_of_scene(sc);
    zp_cable cable;
    char why[256];
    if (zp_cable_build(&def, &cable, why, sizeof why) != ZP_OK) {
        zp_diag_add(d, sc->path, sc->line_cable, "cable", NULL, "the cable does not hang: %s", why);
        return -1;
    }
    double x_end = m->xb[m->nsec];
    double lo = m->xb[0] - ZP_CABLE_MARGIN * (m->xb[0] - cable.xa);
    double hi = x_end + ZP_CABLE_MARGIN * (cable.xb - x_end);
    m->cable_paths = zp_cable_paths_create(&cable, lo, hi);
    if (!m->cable_paths) {
        zp_diag_add(d, sc->path, sc->line_cable, "cable", NULL, "out of memory");
        return -1;
    }
    m->cable_path = zp_cable_paths_get(m->cable_paths, m->g * m->mtot, why, sizeof why);
    if (!m->cable_path) {
        zp_diag_add(d, sc->path, sc->line_cable, "cable", NULL,
                    "the path under the rider's weight %g N could not be built: %s",
                    m->g * m->mtot, why);
        return -1;
    }
    return 1;
}

static void cable_describe(const zp_model *m, const zp_scene *sc, FILE *f) {
    (void)sc;
    const zp_cable *c = zp_cable_paths_cable(m->cable_paths);
    fprintf(f, " cable from (%g, %g) to (%g, %g) m, L0 %.6g m, %g N/m, EA %g N;", c->xa, c->ya,
            c->xb, c->yb, c->length, c->weight, c->ea);
}

/* -dPi_c/dx on the trolley, horizontal; conservative: its potential is in the audit, so no
   power is returned */
static double cable_forces(const zp_model *m, const zp_effect_motion *mo, double (*f)[2]) {
    zp_cable_path_value v;
    int off = !m->cable_path || zp_cable_path_eval(m->cable_path, mo->x, &v);
    f[0][0] = off ? NAN : -v.denergy;
    f[0][1] = 0;
    for (int b = 1; b < mo->nbody; b++) {
        f[b][0] = f[b][1] = 0;
    }
    return 0;
}

static int cable_piece(const zp_model *m, int sec, double x) {
    (void)m;
    (void)sec;
    (void)x;
    return 0; /* the path is smooth over every section: one piece */
}

static zp_track cable_on_piece(const zp_model *m, const zp_course *course, int sec, int piece,
                               double x) {
    (void)course;
    (void)sec;
    (void)piece;
    double t[3] = {NAN, NAN, NAN};
    if (m->cable_path) {
        zp_cable_path_track(m->cable_path, x, t); /* NaN off the path: the step is refused */
    }
    return (zp_track){t[0], t[1], t[2]};
}

static const zp_effect_course path = {cable_piece, cable_on_piece};

const zp_effect zp_effect_cable = {
    .name = "cable",
    .build = cable_build,
    .describe = cable_describe,
    .conservative = cable_forces,
    .course = &path,
};
