/* The effects registry (effects.def): what the effects on make of a model together, their forces
   summed, their work integrals' names. */
#include "effect.h"

#define ZP_EFFECT(id, obj, work) extern const zp_effect obj;
#include "effects.def"
#undef ZP_EFFECT

static const zp_effect *const registry[ZP_EFFECT_COUNT] = {
#define ZP_EFFECT(id, obj, work) [ZP_EFFECT_##id] = &obj,
#include "effects.def"
#undef ZP_EFFECT
};

/* each effect's work integral (ZP_EFFECT_W_*), -1 for none */
#define ZP_WORK(name) ZP_EFFECT_W_##name
#define ZP_OWN_WORK(name) ZP_EFFECT_W_##name
#define ZP_NO_WORK -1
static const int work_of[ZP_EFFECT_COUNT] = {
#define ZP_EFFECT(id, obj, work) [ZP_EFFECT_##id] = work,
#include "effects.def"
#undef ZP_EFFECT
};
#undef ZP_OWN_WORK
#undef ZP_WORK
#undef ZP_NO_WORK

/* 1 for an effect whose work slot the state holds only when it is on (ZP_OWN_WORK), 0 for the
   [physics] effects */
#define ZP_WORK(name) 0
#define ZP_OWN_WORK(name) 1
#define ZP_NO_WORK 0
static const int own_slot[ZP_EFFECT_COUNT] = {
#define ZP_EFFECT(id, obj, work) [ZP_EFFECT_##id] = work,
#include "effects.def"
#undef ZP_EFFECT
};
#undef ZP_OWN_WORK
#undef ZP_WORK
#undef ZP_NO_WORK

const zp_effect *zp_effect_get(int id) {
    return id >= 0 && id < ZP_EFFECT_COUNT ? registry[id] : NULL;
}

int zp_effect_build(zp_model *m, const zp_scene *sc, zp_diag *d) {
    int physics = 0, ok = 1;
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        int on = registry[e]->build(m, sc, d); /* each, so every misfit is named */
        ok = ok && on >= 0;
        physics |= on > 0 ? 1 << e : 0;
    }
    return ok ? physics : -1;
}

/* the ZP_PHYS_* bits of the [physics] effects (those without a slot of their own; a cable is
   a course, not [physics]) */
static unsigned physics_group(void) {
    unsigned bits = 0;
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        bits |= own_slot[e] ? 0 : 1u << e;
    }
    return bits & ~(unsigned)ZP_PHYS_CABLE;
}

int zp_effect_nwork(unsigned physics) {
    int shared = 0, n = ZP_W_EFFECTS; /* the [physics] slots, listed first */
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        shared += work_of[e] >= 0 && !own_slot[e];
    }
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        if (physics >> e & 1 && work_of[e] >= 0) {
            int end = ZP_W_EFFECTS + (own_slot[e] ? work_of[e] + 1 : shared);
            n = end > n ? end : n;
        }
    }
    return n;
}

int zp_effect_work_shown(unsigned physics, int k) {
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        if (work_of[e] == k) {
            return own_slot[e] ? (int)(physics >> e & 1) : (physics & physics_group()) != 0;
        }
    }
    return 0;
}

const zp_effect_work *zp_effect_work_names(int k) {
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        if (work_of[e] == k) {
            return &registry[e]->work;
        }
    }
    return NULL;
}

unsigned zp_effect_with_forces(unsigned physics) {
    unsigned with = 0;
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        with |= registry[e]->forces || registry[e]->conservative ? 1u << e : 0;
    }
    return physics & with;
}

void zp_effect_forces(unsigned physics, const zp_model *m, const zp_effect_motion *mo,
                      double (*f)[2], double *power) {
    int first = 1;
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        if (!(physics >> e & 1) || !(registry[e]->forces || registry[e]->conservative)) {
            continue;
        }
        /* the first sets f: one effect's forces reach the equations bit for bit its own */
        double more[ZP_MAX_LINKS + 1][2];
        if (registry[e]->forces) {
            power[work_of[e]] = registry[e]->forces(m, mo, first ? f : more);
        } else {
            registry[e]->conservative(m, mo, first ? f : more); /* a potential, no work */
        }
        for (int b = 0; !first && b < mo->nbody; b++) {
            f[b][0] += more[b][0];
            f[b][1] += more[b][1];
        }
        first = 0;
    }
}

const zp_effect_course *zp_effect_course_of(unsigned physics) {
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        if (physics >> e & 1 && registry[e]->course) {
            return registry[e]->course;
        }
    }
    return NULL;
}
