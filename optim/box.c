/* The [robust] box (box.h): a scene's ranges as coordinates, the scenario at a point, the box
   widened. */
#include "box.h"

#include <math.h>
#include <string.h>

#define DEG (180.0 / M_PI)

void zp_box_from_scene(const zp_scene *sc, const zp_model *m, zp_box *b) {
    memset(b, 0, sizeof *b);
    b->nlink = m->nlink;
    if (sc->force_error > 0) {
        b->nforce = m->nsec;
        b->force_error = sc->force_error / 100;
        b->d = m->nsec;
    }
    const double *ranges[4] = {sc->mass_range, sc->length_range, sc->trolley_mass_range,
                               sc->damping_range};
    for (int q = 0; q < 4; q++) {
        b->dim[q] = -1;
        if (ranges[q][0] != 100 || ranges[q][1] != 100) {
            b->dim[q] = b->d++;
            b->range[q][0] = ranges[q][0] / 100;
            b->range[q][1] = ranges[q][1] / 100;
        }
    }
    b->theta0 = -1;
    if (sc->start_angle > 0) {
        b->theta0 = b->d;
        b->theta_max = sc->start_angle / DEG;
        b->d += m->nlink;
    }
    b->wind_dim = -1;
    b->wind0 = m->wind;
    if (sc->wind_varied) {
        b->wind_dim = b->d++;
        b->wind[0] = sc->wind_range[0];
        b->wind[1] = sc->wind_range[1];
    }
}

void zp_box_scenario(const zp_box *b, const double *u, zp_scenario *s) {
    zp_scenario_nominal(s);
    for (int k = 0; k < b->nforce; k++) {
        s->force[k] = 1 + b->force_error * u[k];
    }
    double *fac[4] = {&s->mass, &s->length, &s->trolley, &s->damping};
    for (int q = 0; q < 4; q++) {
        if (b->dim[q] >= 0) {
            double w = 0.5 * (u[b->dim[q]] + 1);
            *fac[q] = b->range[q][0] + w * (b->range[q][1] - b->range[q][0]);
        }
    }
    for (int i = 0; b->theta0 >= 0 && i < b->nlink; i++) {
        s->theta[i] = b->theta_max * u[b->theta0 + i];
    }
    if (b->wind_dim >= 0) {
        s->wind_set = 1;
        s->wind = b->wind[0] + 0.5 * (u[b->wind_dim] + 1) * (b->wind[1] - b->wind[0]);
    }
}

void zp_box_widen(const zp_box *b, double f, zp_box *out) {
    *out = *b;
    out->force_error = f * b->force_error;
    for (int q = 0; q < 4; q++) {
        for (int e = 0; e < 2; e++) {
            out->range[q][e] = 1 + f * (b->range[q][e] - 1);
        }
    }
    out->theta_max = f * b->theta_max;
    for (int e = 0; e < 2; e++) {
        out->wind[e] = b->wind0 + f * (b->wind[e] - b->wind0);
    }
}
