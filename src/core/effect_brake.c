/* The brake zone (docs/model.md "A brake zone", [brake]): for start <= x <= end a force on the
   trolley along the course against its motion, eddy |v| + friction, which only ever takes
   energy out. The eddy part is -eddy v on the trolley (its velocity lies along the course);
   the friction part -friction t against the way it slides, and none while it is held: at rest
   the stick rule (friction.c), which rolling resistance's hold shares, judges whether the
   brake's grip holds it. */
#include "effect_brake.h"

static int brake_build(zp_model *m, const zp_scene *sc, zp_diag *d) {
    (void)d; /* the reader holds the zone to the course and the forces to >= 0 */
    if (!sc->brake) {
        return 0;
    }
    m->brake_zone[0] = sc->brake_start;
    m->brake_zone[1] = sc->brake_end;
    m->brake_eddy = sc->brake_eddy;
    m->brake_friction = sc->brake_friction;
    return m->brake_eddy > 0 || m->brake_friction > 0;
}

static void brake_describe(const zp_model *m, const zp_scene *sc, FILE *f) {
    (void)sc;
    fprintf(f, " brake zone x in [%g, %g] m: eddy %g N s/m, friction %g N;", m->brake_zone[0],
            m->brake_zone[1], m->brake_eddy, m->brake_friction);
}

int zp_effect_brake_entered(const zp_model *m, double x, double xd) {
    const double *z = m->brake_zone;
    return (x > z[0] && x < z[1]) || (x == z[0] && xd >= 0) || (x == z[1] && xd <= 0);
}

static double brake_forces(const zp_model *m, const zp_effect_motion *mo, double (*f)[2]) {
    for (int b = 0; b < mo->nbody; b++) {
        f[b][0] = f[b][1] = 0;
    }
    if (!mo->zone) {
        return 0;
    }
    double vx = mo->v[0][0], vy = mo->v[0][1], grip = m->brake_friction * mo->slide;
    f[0][0] = -m->brake_eddy * vx - grip * mo->tangent[0];
    f[0][1] = -m->brake_eddy * vy - grip * mo->tangent[1];
    return -(f[0][0] * vx + f[0][1] * vy);
}

const zp_effect zp_effect_brake = {
    .name = "brake",
    .build = brake_build,
    .describe = brake_describe,
    .work = {"brake_work", "brake_loss", "w_brake", "brake work", "brakes"},
    .forces = brake_forces,
};
