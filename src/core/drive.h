/* The drive schedule (docs/scene-file.md [drive]): the force the trolley's drive applies at an
   instant, from the state it needs (time, position, speed, section), and the way it points; its
   parameters as the search, the verification, the reports and the library see them (count,
   unit, labels, bounds, the section whose force error scales each); its family of "the same
   push everywhere"; its text. A new kind of schedule is a zp_sched_kind and an entry of
   drive.c's kind table; a cap on the applied force (a drive's power) is written in
   zp_drive_force; a response time, the applied force a lagging state of the simulator, in
   zp_drive_lag_rate. Nothing outside drive.c depends on the kind. */
#ifndef ZP_DRIVE_H
#define ZP_DRIVE_H

#include <math.h>
#include <stddef.h>

#include "scene.h"

/* The way the force points (docs/scene-file.md [drive] direction). */
typedef enum { ZP_DRIVE_HORIZONTAL, ZP_DRIVE_TANGENT, ZP_DRIVE_COUNT } zp_drive_dir;

typedef enum {
    ZP_SCHED_SECTIONS, /* kind constant: one constant force per section (N): p[sec] */
    ZP_SCHED_PROFILE,  /* kind profile: knots forces per section at evenly spaced x from its
                          start to its end, linear in x between them (N): p[sec * knots + j] */
    ZP_SCHED_KIND_COUNT
} zp_sched_kind;

/* The most parameters a schedule may have (scene.h: room for several per section). */
#define ZP_SCHED_MAX_PARAMS ZP_MAX_DRIVE_PARAMS
/* The most knots per section of a profile (docs/scene-file.md [drive] knots). */
#define ZP_DRIVE_MAX_KNOTS 32

/* The most break times (s) a schedule may have: instants where its force jumps in time. */
#define ZP_SCHED_MAX_BREAKS ZP_SCHED_MAX_PARAMS

typedef struct zp_schedule {
    zp_sched_kind kind;
    int nsec;                       /* sections of the course it drives */
    int np;                         /* parameters */
    double p[ZP_SCHED_MAX_PARAMS];  /* the parameters, in the kind's unit */
    double lo[ZP_SCHED_MAX_PARAMS]; /* search bounds of each parameter */
    double hi[ZP_SCHED_MAX_PARAMS];
    int knots;                      /* forces per section: 1 (constant), profile's knots */
    double power;                   /* W, the cap |F_applied v| <= power; 0: no cap */
    double xb[ZP_MAX_SECTIONS + 1]; /* m, the sections' boundaries: where a profile's knots
                                       lie (0s where the schedule has no course) */
} zp_schedule;

/* What the drive's scheduled force may depend on at one instant. The applied force is that
   force at once, or with a response time a state of the simulator of its own (the drive's
   states, after the work integrals: zp_drive_nstate, zp_drive_lag_rate). */
typedef struct zp_drive_state {
    double t; /* s */
    double x; /* m, the trolley's x */
    double v; /* m/s, the trolley's velocity along the drive's direction: x' (horizontal) or
                 along the course, x' sqrt(1 + f'^2) (tangent); what a power P caps the force
                 by, |F| <= P / |v| */
    int sec;  /* 0-based section under the trolley */
} zp_drive_state;

/* Per-section constant forces (N), every one bounded by [lo, hi]; force NULL: all 0. */
zp_schedule zp_drive_sections(int nsec, const double *force, double lo, double hi);
/* The same shape (kind, sections, bounds) with the parameters p (sh->np of them). */
zp_schedule zp_drive_with(const zp_schedule *sh, const double *p);
/* The schedule the scene's [drive] describes (kind, knots, power, forces, min, max; all forces
   0 when none are given). */
zp_schedule zp_drive_of_scene(const zp_scene *sc);
/* A profile of knots forces per section on the course whose sections end at x_end (x_start
   before the first), every one bounded by [lo, hi]; force NULL: all 0. knots = 1 drives as
   zp_drive_sections does, bit for bit. */
zp_schedule zp_drive_profile(int nsec, int knots, double x_start, const double *x_end,
                             const double *force, double lo, double hi);
/* The schedule of shape pushing F (N) everywhere: the one-parameter family of constant pushes
   the search's baseline, the landscape and the benchmarks run. */
zp_schedule zp_drive_constant(const zp_schedule *shape, double F);
/* N, the constant pushes every parameter's bounds allow: the largest lo, the smallest hi. */
void zp_drive_constant_bounds(const zp_schedule *shape, double *lo, double *hi);

/* The schedule whose parameters are s's, each times the scale of the section it acts on
   (scale: one factor per section, a drive off by a known factor: a scenario's force error). */
zp_schedule zp_drive_scaled(const zp_schedule *s, const double *scale);
/* N, the force the drive applies at st, along its direction: the kind's force, capped at
   power / |v| where s has a power (pushing and braking alike; at rest no cap binds). */
double zp_drive_force(const zp_schedule *s, const zp_drive_state *st);
/* 1 when the cap binds at st: the kind's force asks for more than power / |v|. */
int zp_drive_capped(const zp_schedule *s, const zp_drive_state *st);
/* The drive's state at an instant (v along its direction, what a power caps). */
static inline zp_drive_state zp_drive_state_at(zp_drive_dir d, double t, double x, double xdot,
                                               int sec, double fp) {
    return (zp_drive_state){t, x, d == ZP_DRIVE_TANGENT ? xdot * sqrt(1 + fp * fp) : xdot, sec};
}

/* The applied force F (N) as a force on the trolley (fx, fy), pointing as d says on a course
   of slope fp. */
static inline void zp_drive_split(zp_drive_dir d, double F, double fp, double *fx, double *fy) {
    if (d == ZP_DRIVE_TANGENT) {
        double norm = sqrt(1 + fp * fp);
        *fx = F / norm;
        *fy = F * fp / norm;
    } else {
        *fx = F;
        *fy = 0;
    }
}

/* N, that force on the trolley (fx, fy) at time t (s), the trolley at x (m) moving at xdot = x'
   (m/s) on section sec, the course's slope there fp, pointing as d says. Inline: every
   evaluation of the equations of motion asks for it. */
static inline void zp_drive_push(const zp_schedule *s, zp_drive_dir d, double t, double x,
                                 double xdot, int sec, double fp, double *fx, double *fy) {
    zp_drive_state st = zp_drive_state_at(d, t, x, xdot, sec, fp);
    zp_drive_split(d, zp_drive_force(s, &st), fp, fx, fy);
}

/* How many states a drive with response time tau (s; [drive] response) adds to the
   simulator's, after its work integrals: with tau > 0 one, the applied force F_a (N), which
   starts at 0 and follows the capped schedule as a first-order lag; none at once. */
static inline int zp_drive_nstate(double tau) {
    return tau > 0;
}
/* N/s, the applied force's rate F_a' = (F_s - F_a) / tau, F_s the capped schedule at st
   (docs/model.md "A real drive"). */
double zp_drive_lag_rate(const zp_schedule *s, double tau, const zp_drive_state *st,
                         double applied);

/* The instants (s, ascending, at most max) where the force jumps in time; returns how many.
   The simulator stops its integrator there. 0 for per-section constants. */
int zp_drive_breaks(const zp_schedule *s, double *t, int max);

/* Parameter k (0-based) of s: the section it acts on, whose force error scales it (0-based);
   its label ("section 2"); the stretch of course [*from, *to] (m) where it acts, xb the
   sections' boundaries (nsec + 1 of them). */
int zp_drive_param_section(const zp_schedule *s, int k);
void zp_drive_param_label(const zp_schedule *s, int k, char *buf, size_t cap);
void zp_drive_param_span(const zp_schedule *s, int k, const double *xb, double *from, double *to);
/* What one parameter of s is called, plural 0 or 1 ("section", "sections"): labels are it and
   the 1-based index. */
const char *zp_drive_param_noun(const zp_schedule *s, int plural);
/* The unit of s's parameters ("N"). */
const char *zp_drive_unit(const zp_schedule *s);

/* Reads the text of [drive] forces as shape's parameters into s (shape with them): 0, or -1
   with why ("item 2 is empty", ..), -2 for the wrong count ("2 values, expected 3 (one per
   section)"). */
int zp_drive_parse(const zp_schedule *shape, const char *text, zp_schedule *s, char *why,
                   size_t whylen);
/* The same for per-section constants on a course of nsec sections (bounds left 0). */
int zp_drive_parse_sections(const char *text, int nsec, zp_schedule *s, char *why, size_t whylen);
/* Writes the text zp_drive_parse_sections reads back bit for bit; returns snprintf's count. */
int zp_drive_format(const zp_schedule *s, char *buf, size_t cap);
/* A short label of section sec's drive for figures and reports ("59.6 N"). */
void zp_drive_section_label(const zp_schedule *s, int sec, char *buf, size_t cap);

/* 1 for the drive every scene had before kinds and a power: constant per section, no cap (its
   outputs keep their old shape). */
int zp_drive_plain(const zp_schedule *s);

/* Names of the kinds ([drive] kind: "constant", "profile") and lookup (-1 if unknown). */
const char *zp_drive_kind_name(zp_sched_kind k);
int zp_drive_kind_find(const char *name);

/* Names of the drive directions and lookup (-1 if unknown). */
const char *zp_drive_dir_name(zp_drive_dir d);
int zp_drive_dir_find(const char *name);

#endif
