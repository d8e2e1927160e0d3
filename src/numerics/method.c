/* The integrator registry: names typed in [solver] method, with their docs. */
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
