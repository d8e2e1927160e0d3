/* The formulation registry: names typed in [solver] formulation, with their docs. */
#include <string.h>

#include "formulation.h"

#define ZP_FORM(id, obj) extern const zp_formulation obj;
#include "formulations.def"
#undef ZP_FORM

static const zp_formulation *const registry[ZP_FORM_COUNT] = {
#define ZP_FORM(id, obj) [ZP_FORM_##id] = &obj,
#include "formulations.def"
#undef ZP_FORM
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
