/* The integrator registry: names typed in [solver] method, with their docs. */
#include <string.h>

#include "method.h"

extern const zp_method zp_method_cvode_adams, zp_method_cvode_bdf;
extern const zp_method zp_method_gsl_rk8pd, zp_method_gsl_rk4imp;

static const zp_method *const registry[ZP_METHOD_COUNT] = {
    [ZP_METHOD_CVODE_ADAMS] = &zp_method_cvode_adams,
    [ZP_METHOD_CVODE_BDF] = &zp_method_cvode_bdf,
    [ZP_METHOD_GSL_RK8PD] = &zp_method_gsl_rk8pd,
    [ZP_METHOD_GSL_RK4IMP] = &zp_method_gsl_rk4imp,
};

const zp_method *zp_method_get(int id) {
    return id >= 0 && id < ZP_METHOD_COUNT ? registry[id] : NULL;
}

int zp_method_find(const char *name) {
    for (int i = 0; i < ZP_METHOD_COUNT; i++) {
        if (!strcmp(name, registry[i]->name)) {
            return i;
        }
    }
    return -1;
}
