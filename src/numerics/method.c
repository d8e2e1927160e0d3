/* The integrator registry: names typed in [solver] method, with their docs; and where a
   component of the dense output crosses a level. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "method.h"

#define ZP_METHOD(id, obj) extern const zp_method obj;
#include "methods.def"
#undef ZP_METHOD

static const zp_method *const registry[ZP_METHOD_COUNT] = {
#define ZP_METHOD(id, obj) [ZP_METHOD_##id] = &obj,
#include "methods.def"
#undef ZP_METHOD
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

typedef struct crossing_fn {
    const zp_method *meth;
    void *w;
    int comp;
    double level;
    double *y; /* the interpolated state */
} crossing_fn;

/* NaN where the dense output fails: Brent then stops with an error (main turns GSL's abort
   off) */
static double component_minus_level(double t, void *p) {
    crossing_fn *c = p;
    return c->meth->interpolate(c->w, t, c->y) ? NAN : c->y[c->comp] - c->level;
}

int zp_method_dense_crossing(const zp_method *meth, void *w, int comp, double level, double ta,
                             double tb, double *t, double *y) {
    crossing_fn c = {meth, w, comp, level, y};
    gsl_function F = {component_minus_level, &c};
    double ga = component_minus_level(ta, &c), gb = component_minus_level(tb, &c);
    *t = fabs(ga) < fabs(gb) ? ta : tb;
    if (!(ga < 0 && gb >= 0)) {
        return -1;
    }
    gsl_root_fsolver *brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    int bad = !brent || gsl_root_fsolver_set(brent, &F, ta, tb);
    double ttol = 4 * DBL_EPSILON * fmax(fabs(ta), fabs(tb));
    for (int it = 0; it < 200 && !bad; it++) {
        bad = gsl_root_fsolver_iterate(brent) != GSL_SUCCESS;
        double lo = gsl_root_fsolver_x_lower(brent), hi = gsl_root_fsolver_x_upper(brent);
        *t = gsl_root_fsolver_root(brent);
        if (gsl_root_test_interval(lo, hi, ttol, 0) == GSL_SUCCESS) {
            break;
        }
    }
    gsl_root_fsolver_free(brent);
    return bad || meth->interpolate(w, *t, y) ? -1 : 0;
}
