/* The formulation registry: names typed in [solver] formulation, with their docs. */
#include <string.h>

#include "formulation.h"

extern const zp_formulation zp_form_lagrange, zp_form_newton;

static const zp_formulation *const registry[ZP_FORM_COUNT] = {
    [ZP_FORM_LAGRANGE] = &zp_form_lagrange,
    [ZP_FORM_NEWTON] = &zp_form_newton,
};

const zp_formulation *zp_formulation_get(int id) {
    return id >= 0 && id < ZP_FORM_COUNT ? registry[id] : NULL;
}

int zp_formulation_find(const char *name) {
    for (int i = 0; i < ZP_FORM_COUNT; i++) {
        if (!strcmp(name, registry[i]->name)) {
            return i;
        }
    }
    return -1;
}
