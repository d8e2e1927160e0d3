/* The optional effects of docs/model.md ([physics]): each written once, in a file of its own
   (effect_<name>.c), and listed once (effects.def). The scene's keys turn an effect on (its
   build); it then gives forces on the bodies, which every formulation only projects onto its
   equations (J^T f in lagrange, the momentum rows in newton-euler), or lays a course of its own
   under the trolley (a course provider, which the simulator reads through zp_model_track). Its
   power, integrated in its work slot at the state's end, enters the energy audit and every
   output under the names its entry gives.
   Design note: as MuJoCo writes its passive forces once for every integrator. Rolling
   resistance's force depends on the normal force, which only a formulation's own solve gives:
   its entry has no force function, and each formulation solves for it (ZP_PHYS_ROLLING). */
#ifndef ZP_EFFECT_H
#define ZP_EFFECT_H

#include <math.h>
#include <stdio.h>

#include "course.h"
#include "scene.h"

typedef struct zp_model zp_model;

/* ZP_EFFECT_<ID>: an effect's index in effects.def */
enum {
#define ZP_EFFECT(id, obj, work) ZP_EFFECT_##id,
#include "effects.def"
#undef ZP_EFFECT
    ZP_EFFECT_COUNT
};

/* ZP_PHYS_<ID>: its bit in zp_model.physics */
enum {
#define ZP_EFFECT(id, obj, work) ZP_PHYS_##id = 1 << ZP_EFFECT_##id,
#include "effects.def"
#undef ZP_EFFECT
};

/* ZP_EFFECT_W_<NAME>: the work integrals of the effects that have one, in effects.def order */
#define ZP_WORK(name) ZP_EFFECT_W_##name,
#define ZP_OWN_WORK(name) ZP_EFFECT_W_##name,
#define ZP_NO_WORK
enum {
#define ZP_EFFECT(id, obj, work) work
#include "effects.def"
#undef ZP_EFFECT
    ZP_EFFECT_NWORK
};
#undef ZP_OWN_WORK
#undef ZP_WORK
#undef ZP_NO_WORK

/* The work integrals at the state's end (zp_model.nwork of them): the drive's work and the
   dampers' loss, then the effects' (J, taken out) at ZP_W_EFFECTS + ZP_EFFECT_W_*: the
   [physics] effects' slots (ZP_WORK) all of them when any of those effects is on, and an
   effect with a slot of its own (ZP_OWN_WORK) up to its own slot when it is on, the slots
   before it held at 0 so that every slot keeps its index. Design note: the integrator's error
   norm counts every entry, so one slot more or fewer moves every step: a scene keeps the
   layout its answers were made with whatever effects are added after it. */
enum { ZP_W_DRIVE, ZP_W_DAMP, ZP_W_EFFECTS, ZP_W_MAX = ZP_W_EFFECTS + ZP_EFFECT_NWORK };

/* The bodies' motion as an effect's forces read it: body 0 the trolley, body i link i's centre
   of mass, world frame; the trolley's place on the course. */
typedef struct zp_effect_motion {
    int zone;                      /* 1: the trolley is in the brake zone (zp_drive_now) */
    double tangent[2];             /* the course's unit tangent (1, f')/|.| under the trolley
                                      (set in the brake zone only) */
    int slide;                     /* the way the trolley slides along the course, which a
                                      friction opposes: +1, -1, or 0 at rest (held, or not yet
                                      judged by the stick rule: no friction force then) */
    int nbody;                     /* links + 1 */
    double x;                      /* m, the trolley's x (a conservative force's position) */
    double v[ZP_MAX_LINKS + 1][2]; /* m/s */
} zp_effect_motion;

/* The trolley's place in mo from the simulator's view (zp_drive_now): zone as it says; slide
   0 held, else the way it keeps from one stop to the next (so a friction never flips inside a
   step), else the sign of x' (xd); the tangent of the course of slope fp, set only in the
   zone, the one place an effect reads it (a scene without one pays nothing for it). */
static inline void zp_effect_place(zp_effect_motion *mo, int zone, int hold, int slide, double xd,
                                   double fp) {
    mo->zone = zone;
    mo->slide = hold ? 0 : slide ? slide : (xd > 0) - (xd < 0);
    if (zone) {
        double sq = sqrt(1 + fp * fp);
        mo->tangent[0] = 1 / sq;
        mo->tangent[1] = fp / sq;
    }
}

/* A course provider: the course an effect lays under the trolley, read in pieces. f'' may jump
   where the piece changes, so the simulator reads one piece between restarts, and a step that
   overshoots a piece's end sees no jump before its root is found; a course laid everywhere (a
   sagging cable) is one piece. */
typedef struct zp_effect_course {
    /* the piece under x on section sec: >= 0 one of the provider's, -1 the scene's course */
    int (*piece)(const zp_model *m, int sec, double x);
    /* the course on piece (>= 0; continued past its ends) at x on section sec; course: the
       caller's evaluators of the scene's course */
    zp_track (*on_piece)(const zp_model *m, const zp_course *course, int sec, int piece, double x);
} zp_effect_course;

/* The names of an effect's work integral (J, taken out: minus its power integrated). */
typedef struct zp_effect_work {
    const char *column; /* trajectory.csv column and summary.json "energy" key */
    const char *plot;   /* plot_run.dat column */
    const char *key;    /* the C library's run key (zipopt.h) */
    const char *words;  /* in prose and figure legends */
    const char *brief;  /* the effect in a list of losses */
} zp_effect_work;

typedef struct zp_effect {
    const char *name;
    /* Reads the effect's scene keys into m (its course checked, its kinks found): 1 when they
       turn it on, 0 when not, -1 with why in d when they do not fit the model. */
    int (*build)(zp_model *m, const zp_scene *sc, zp_diag *d);
    /* `check`'s words for the effect as m has it (on), on the line after "physics:" */
    void (*describe)(const zp_model *m, const zp_scene *sc, FILE *f);
    zp_effect_work work; /* an effect with ZP_WORK in effects.def */
    /* The force on every body (N, world frame, at its centre of mass) into f from the bodies'
       motion; returns the power it takes out (W). NULL: none. An effect with forces has a
       work integral, so the energy audit accounts for them. */
    double (*forces)(const zp_model *m, const zp_effect_motion *mo, double (*f)[2]);
    /* A conservative force (the sagging cable's -dPi_c/dx): the same, but with no work integral,
       its potential being in the energy audit instead (zp_model_cable_energy); it returns 0.
       NULL: none. */
    double (*conservative)(const zp_model *m, const zp_effect_motion *mo, double (*f)[2]);
    const zp_effect_course *course; /* NULL: the course stays the scene's */
} zp_effect;

/* The entry of effect id (ZP_EFFECT_*), NULL out of range. */
const zp_effect *zp_effect_get(int id);
/* Every effect's build over m, in effects.def order: the ZP_PHYS_* bits of those on, or -1
   (why in d). */
int zp_effect_build(zp_model *m, const zp_scene *sc, zp_diag *d);
/* How many work integrals the state ends with when the effects physics are on. */
int zp_effect_nwork(unsigned physics);
/* 1 when the outputs show work integral k (ZP_EFFECT_W_*) with the effects physics on: a
   scene naming any [physics] effect shows every [physics] effect's (0 for those off), so its
   columns do not hang on which of them it turns on; an effect with a slot of its own shows
   it when on. */
int zp_effect_work_shown(unsigned physics, int k);
/* The names of work integral k (ZP_EFFECT_W_*). */
const zp_effect_work *zp_effect_work_names(int k);
/* The bits of the effects in physics that give forces on the bodies. */
unsigned zp_effect_with_forces(unsigned physics);
/* The forces of the effects in physics that give some: their sum on each body into f (set
   whole), each one's power into power[ZP_EFFECT_W_*] (the other entries left). */
void zp_effect_forces(unsigned physics, const zp_model *m, const zp_effect_motion *mo,
                      double (*f)[2], double *power);
/* The course provider of the effects in physics (the first of them that lays a course), NULL
   for the scene's own course. Design note: one provider at a time; two course effects on at
   once would need a provider that lays one over the other. */
const zp_effect_course *zp_effect_course_of(unsigned physics);

#endif
