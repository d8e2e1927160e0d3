/* Air drag (docs/model.md "Optional effects"): -1/2 rho CdA |v_rel| v_rel at the trolley's and
   each link's centre of mass, v_rel the velocity relative to the horizontal wind. */
#include <math.h>

#include "effect.h"
#include "model.h"

static int drag_build(zp_model *m, const zp_scene *sc, zp_diag *d) {
    (void)d;
    int on = 0;
    for (int b = 0; b < sc->ndrag; b++) {
        m->drag_k[b] = 0.5 * sc->air_density * sc->drag_area[b];
        on = on || m->drag_k[b] != 0;
    }
    m->wind = sc->wind;
    return on;
}

static void drag_describe(const zp_model *m, const zp_scene *sc, FILE *f) {
    fputs(" drag CdA", f);
    for (int b = 0; b <= m->nlink; b++) {
        fprintf(f, "%s %g", b ? "," : "", sc->drag_area[b]);
    }
    fprintf(f, " m^2 (trolley, links), air %g kg/m^3, wind %g m/s;", sc->air_density, m->wind);
}

static double drag_forces(const zp_model *m, const zp_effect_motion *mo, double (*f)[2]) {
    double pout = 0;
    for (int b = 0; b < mo->nbody; b++) {
        double vx = mo->v[b][0], vy = mo->v[b][1];
        double rx = vx - m->wind, k = m->drag_k[b] * hypot(rx, vy);
        f[b][0] = -k * rx;
        f[b][1] = -k * vy;
        pout -= f[b][0] * vx + f[b][1] * vy;
    }
    return pout;
}

const zp_effect zp_effect_drag = {
    .name = "drag",
    .build = drag_build,
    .describe = drag_describe,
    .work = {"drag_work", "drag_loss", "w_drag", "drag work", "drag"},
    .forces = drag_forces,
};
