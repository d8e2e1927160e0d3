/* The drive schedule (docs/scene-file.md [drive]): which force the trolley's drive applies at time
   t, position x, on section sec; its parameters and bounds as the search sees them; its text. A new
   kind of schedule is a new zp_sched_kind handled in drive.c and nowhere else. */
#ifndef ZP_DRIVE_H
#define ZP_DRIVE_H

#include <stddef.h>

#include "scene.h"

/* The way the force points (docs/scene-file.md [drive] direction). */
typedef enum { ZP_DRIVE_HORIZONTAL, ZP_DRIVE_TANGENT, ZP_DRIVE_COUNT } zp_drive_dir;

typedef enum {
    ZP_SCHED_SECTIONS, /* one constant force per section (N): p[sec] */
    ZP_SCHED_KIND_COUNT
} zp_sched_kind;

/* The most parameters a schedule may have (scene.h: room for several per section). */
#define ZP_SCHED_MAX_PARAMS ZP_MAX_DRIVE_PARAMS
/* The most break times (s) a schedule may have: instants where its force jumps in time. */
#define ZP_SCHED_MAX_BREAKS ZP_SCHED_MAX_PARAMS

typedef struct zp_schedule {
    zp_sched_kind kind;
    int nsec;                       /* sections of the course it drives */
    int np;                         /* parameters */
    double p[ZP_SCHED_MAX_PARAMS];  /* the parameters, in the kind's units */
    double lo[ZP_SCHED_MAX_PARAMS]; /* search bounds of each parameter */
    double hi[ZP_SCHED_MAX_PARAMS];
} zp_schedule;

/* Per-section constant forces (N), every one bounded by [lo, hi]. */
zp_schedule zp_schedule_sections(int nsec, const double *force, double lo, double hi);
/* The same shape (kind, sections, bounds) with the parameters p (sh->np of them). */
zp_schedule zp_schedule_with(const zp_schedule *sh, const double *p);
/* The schedule the scene's [drive] describes (forces, min, max; all 0 when no forces). */
zp_schedule zp_schedule_of_scene(const zp_scene *sc);

/* The schedule whose force on each section sec is s's times scale[sec] (a drive off by a
   known factor per section: a scenario's force error). */
zp_schedule zp_schedule_scaled(const zp_schedule *s, const double *scale);
/* N, the drive force at time t (s) with the trolley at x (m) on section sec (0-based). */
double zp_schedule_force(const zp_schedule *s, double t, double x, int sec);
/* The instants (s, ascending, at most max) where the force jumps in time; returns how many.
   The simulator stops its integrator there. 0 for per-section constants. */
int zp_schedule_breaks(const zp_schedule *s, double *t, int max);

/* Reads the text of [drive] forces for a course of nsec sections into s (bounds left 0).
   0, or -1 with why ("2 values, expected 3 (one per section)", "item 2 is empty", ..). */
int zp_schedule_parse(const char *text, int nsec, zp_schedule *s, char *why, size_t whylen);
/* Writes the text zp_schedule_parse reads back bit for bit; returns snprintf's count. */
int zp_schedule_format(const zp_schedule *s, char *buf, size_t cap);
/* A short label of section sec's drive for figures and reports ("59.6 N"). */
void zp_schedule_label(const zp_schedule *s, int sec, char *buf, size_t cap);

/* Names of the drive directions and lookup (-1 if unknown). */
const char *zp_drive_dir_name(zp_drive_dir d);
int zp_drive_dir_find(const char *name);

#endif
