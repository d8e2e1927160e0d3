/* The physics of docs/model.md built once from a scene: SI units, radians, derived constants.
   Nothing writes a model after zp_model_build; every run reads it through a const pointer. */
#ifndef ZP_MODEL_H
#define ZP_MODEL_H

#include "cable_paths.h"
#include "course.h"
#include "diag.h"
#include "drive.h"
#include "effect.h"
#include "scene.h"

typedef struct zp_kink {
    int left;         /* section on the left (0-based); the kink is at xb[left + 1] */
    double x, y;      /* m */
    double slope_in;  /* f' of the left section at the boundary */
    double slope_out; /* f' of the right section at the boundary */
} zp_kink;

/* A rounded kink (docs/model.md "Optional effects"): the circle of radius r tangent to the section
   on the left at x1 and to the one on the right at x2, x1 < b < x2. */
typedef struct zp_arc {
    int kink;        /* index into zp_model.kink */
    double x1, x2;   /* m, where the circle touches the sections */
    double cx, cy;   /* m, its centre */
    double r;        /* m */
    double side;     /* +1: centre above (the slope rises through the arc), -1: below */
} zp_arc;

typedef struct zp_model {
    double g; /* m/s^2, acts in -y */

    int nsec;
    double xb[ZP_MAX_SECTIONS + 1];    /* m, section k (0-based) spans [xb[k], xb[k+1]] */
    char expr[ZP_MAX_SECTIONS][ZP_EXPR_MAX]; /* f(x) text per section */
    zp_course *course;                 /* owned; for single-threaded use (check, reports) */
    int nkink;
    zp_kink kink[ZP_MAX_SECTIONS];     /* boundaries where the slope jumps */

    double m0; /* kg, trolley */
    int nlink;
    double len[ZP_MAX_LINKS];     /* m, l_i */
    double half[ZP_MAX_LINKS];    /* m, d_i = l_i / 2 */
    double mass[ZP_MAX_LINKS];    /* kg */
    double inertia[ZP_MAX_LINKS]; /* kg m^2, m l^2 / 12 about the centre of mass */
    double damp[ZP_MAX_LINKS];    /* N m s/rad, joint i joins link i to its parent */
    double phi_max;               /* rad, the largest joint's death angle */
    double phi_max_j[ZP_MAX_LINKS]; /* rad, each joint's death angle */
    zp_drive_dir drive;
    double drive_response;        /* s, tau of the applied force's lag ([drive] response), 0 */
    int ndrive;                   /* the drive's own states after the work integrals
                                     (zp_drive_nstate): 1 with a response time, else 0 */
    unsigned g_links;             /* bit i: link i's felt g is judged ([limits] g_links); all set
                                     when the scene names none */
    unsigned scale_links;         /* bit i: [robust] mass_range and length_range scale link i */
    int nenv;                     /* [limits] g_envelope levels, 0: none */
    double env_g[8], env_s[8];    /* g, s: felt g above env_g[l] for at most env_s[l] at a time */

    /* [physics]: physics is the ZP_PHYS_* bits of the effects on (effects.def), chosen once
       here, each term evaluated only where its bit is set; below, each effect's settings */
    int physics;
    double drag_k[ZP_MAX_LINKS + 1]; /* kg/m, rho CdA / 2 of the trolley, then each link */
    double wind;                     /* m/s, +x */
    double mu;                       /* rolling-resistance coefficient */
    double brake_zone[2];            /* m, [brake] start and end: the zone's x */
    double brake_eddy;               /* N s/m, eddy-current brake: force eddy * speed */
    double brake_friction;           /* N, friction brake: force against the motion */
    int stick;                       /* 1: a friction holds the trolley at rest (rolling
                                        resistance, a friction brake): the stick rule's
                                        stops, holds and releases are simulated */
    int nwork;                       /* work integrals at the state's end (ZP_W_*) */
    int narc;
    zp_arc arc[ZP_MAX_SECTIONS];
    int arc_at[ZP_MAX_SECTIONS + 1]; /* index of the arc around boundary xb[k], or -1 */
    const zp_effect_course *course_provider; /* the course an effect lays (zp_model_track),
                                                NULL: the scene's own */
    /* [cable] (docs/model.md "A cable that sags"): the course is the path the cable takes under
       this model's load W = g mtot; both NULL without a cable */
    zp_cable_paths *cable_paths;     /* owned by the built model, borrowed by its scenarios */
    const zp_cable_path *cable_path; /* W's path (zp_model_derive), read-only and shared; NULL
                                        when it could not be built: every run then fails */

    /* derived for the equations of motion (docs/model.md chain coordinates) */
    double mtot;                                 /* kg, trolley + links */
    double B[ZP_MAX_LINKS];                      /* kg m, m_j d_j + l_j sum_{i>j} m_i */
    double C[ZP_MAX_LINKS][ZP_MAX_LINKS];        /* kg m^2, coefficient of cos(th_j - th_k) */
} zp_model;

/* Builds the model: compiles the course, checks continuity (naming the boundary and the jump)
   and finds the kinks. Returns NULL and fills d on bad input. */
zp_model *zp_model_build(const zp_scene *sc, zp_diag *d);
void zp_model_free(zp_model *m);
/* 1 when the boundary after section left (0-based) is a kink: the slope jumps there. */
int zp_model_is_kink(const zp_model *m, int left);
/* The one course provider the simulator and the figures ask: the course under the trolley on
   section sec at x, as the model's effects lay it (the rounded kinks' arcs), or the scene's
   own; course: the caller's evaluators. */
zp_track zp_model_track(const zp_model *m, const zp_course *course, int sec, double x);
/* Which piece zp_model_track reads at x on section sec: an effect's (an arc's index), or -1
   for the scene's own course. */
int zp_model_piece(const zp_model *m, int sec, double x);
/* The course as read on one piece (zp_effect_course), continued past the piece's ends, or
   with piece -1 the scene's course of section sec: so a step that overshoots a piece's end
   sees no jump of f'' before its root is found. */
zp_track zp_model_track_piece(const zp_model *m, const zp_course *course, int sec, int piece,
                              double x);
/* The largest |relative angle| of a run (max_rel_angle, per joint) as the margin judges it:
   measured against phi_max, each joint's angle raised by how much its own death angle lies
   below phi_max, so that phi_max - the result is the smallest margin of any joint (with one
   death angle for every joint: the largest angle itself). */
double zp_model_angle_used(const zp_model *m, const double *max_rel_angle);
/* Recomputes mtot, B and C from m0, len, half, mass and inertia (after changing them), and with
   a cable the path of the load g mtot (built once per load, then shared). */
void zp_model_derive(zp_model *m);
/* The cable's own potential energy Pi_c (J) with the trolley at x (docs/model.md "A cable that
   sags"); 0 without a cable, NaN off the path. */
double zp_model_cable_energy(const zp_model *m, double x);
/* A course for one simulating thread (zp_course_for_thread: compiled code shared by all),
   owned by the caller; NULL with why in e. */
zp_course *zp_model_course(const zp_model *m, zp_course_err *e);

#endif
