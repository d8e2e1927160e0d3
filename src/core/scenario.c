/* Scenarios derived from a built model (factors and start angles). */
#include "scenario.h"

#include <math.h>
#include <string.h>

#define KMH (3.6) /* km/h per m/s */

void zp_scenario_nominal(zp_scenario *s) {
    memset(s, 0, sizeof *s);
    for (int k = 0; k < ZP_MAX_SECTIONS; k++) {
        s->force[k] = 1;
    }
    s->mass = s->length = s->trolley = s->damping = 1;
}

void zp_scenario_model(const zp_model *nom, const zp_scenario *s, zp_model *out) {
    *out = *nom;
    out->m0 = nom->m0 * s->trolley;
    for (int i = 0; i < nom->nlink; i++) {
        /* a rider's size and weight scale the rider's links, not the rigging */
        int rider = nom->scale_links >> i & 1;
        out->len[i] = nom->len[i] * (rider ? s->length : 1);
        out->half[i] = 0.5 * out->len[i];
        out->mass[i] = nom->mass[i] * (rider ? s->mass : 1);
        out->inertia[i] = out->mass[i] * out->len[i] * out->len[i] / 12.0;
        out->damp[i] = nom->damp[i] * s->damping;
    }
    out->wind = s->wind_set ? s->wind : nom->wind;
    zp_model_derive(out);
}

void zp_scenario_start(const zp_chain *nominal, int nlink, const zp_scenario *s, zp_chain *c) {
    *c = *nominal;
    for (int i = 0; i < nlink; i++) {
        c->q[2 + i] = s->theta[i];
    }
}
