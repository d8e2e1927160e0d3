/* The formulation interface: one way of writing the equations of motion of docs/model.md.
   State contract shared by all formulations (so events are written once), n = nstate(m):
     y[0]              trolley x (m); y[(n - nwork) / 2] its rate x' (m/s)
     y[0 .. npos)      positions, npos = (n - nwork) / 2; y[npos + i] is the rate of y[i]
     y[n - nwork ..]   the model's nwork work integrals (J), in ZP_W_* order (effect.h): drive
                       work and damper loss, then the effects' work taken out
   everything else is the formulation's own; to_chain/from_chain convert to docs/model.md's q.
   The simulator's state is this one followed by the drive's own states, y[n .. n + ndrive)
   (zp_model.ndrive, drive.h's zp_drive_nstate: the applied force of a drive with a response
   time; none without one, so such a state is exactly the formulation's). The formulations
   neither read nor write them: they see the applied force in zp_drive_now, from_chain leaves
   them as they were (every restart keeps them: they are continuous) and the simulator writes
   their rates (zp_drive_lag_rate). The drive's work integral is the applied force's work.
   Each formulation picks, once in create, equations holding only the terms the model names;
   the effects' forces on the bodies (effect.h) it only projects onto its own equations. */
#ifndef ZP_FORMULATION_H
#define ZP_FORMULATION_H

#include "state.h"

/* An rhs status: sliding friction and the normal force contradict each other (Painleve's
   paradox: every sign of N gives the other sign back); see form_lagrange.c. */
#define ZP_RHS_FRICTION_INCONSISTENT 2
/* kg m/s^2 per kg of the whole body: sliding friction's normal force beyond this times the
   total mass counts as Painleve's boundary too; N grows without bound as it is approached and
   an integrator would crawl towards it for ever (1e6 standard weights) */
#define ZP_FRICTION_NORMAL_MAX (1e6 * 9.80665)

/* The drive and the course under the trolley at this instant (set by the simulator). */
typedef struct zp_drive_now {
    zp_track tr;    /* course at the trolley's x, on the current section */
    double fx, fy;  /* N, drive force on the trolley */
    int hold;       /* with rolling resistance, 1: rates and loads with the trolley held at rest
                       (x'' = 0), the holding tangential force in zp_loads.hold */
    int slide;      /* with rolling resistance, +1 or -1: the way the trolley slides, which
                       friction opposes whatever the sign of x' (the simulator keeps it from
                       one stop to the next, so friction never flips inside a step); 0: the
                       sign of x', or from rest of the frictionless x'' */
    int zone;       /* with a brake zone, 1: the trolley is in it. The simulator keeps it from
                       one end of the zone to the next, so the brake's force never switches
                       inside a step (the ends are events) */
} zp_drive_now;

/* Loads, computed on request (outputs, not the hot path). */
typedef struct zp_loads {
    double normal;                   /* N, course on trolley along (-f', 1)/|.|: + pushes up */
    double joint[ZP_MAX_LINKS][2];   /* N, force of the parent on link i at joint i */
    double acc[ZP_MAX_LINKS + 1][2]; /* m/s^2, centre-of-mass accelerations, body 0 trolley */
    double hold; /* N, with zp_drive_now.hold: the course's force along (1, f')/|.| that keeps
                    the trolley at rest */
} zp_loads;

typedef struct zp_formulation {
    const char *name; /* as typed in [solver] formulation */
    const char *doc;  /* one line for --help */
    int (*nstate)(const zp_model *m);
    /* Workspace sized from the model (no allocation afterwards); NULL on failure. */
    void *(*create)(const zp_model *m);
    void (*free)(void *work);
    /* State from chain coordinates (positions on the constraints); the work integrals set to
       w (m->nwork entries). */
    void (*from_chain)(const zp_model *m, const zp_chain *c, const double *w, double *y);
    /* Chain coordinates of y; tr is the course at y[0] on the current section. */
    void (*to_chain)(const zp_model *m, const zp_track *tr, const double *y, zp_chain *c);
    /* Relative joint angles phi_i (rad) and rates w_i (rad/s): the root functions' inputs. */
    void (*relative)(const zp_model *m, const double *y, double *phi, double *w);
    /* Rates of every state entry. Returns 0, or >0 when y gives non-finite rates (the
       integrator may retry with a smaller step): ZP_RHS_FRICTION_INCONSISTENT where rolling
       resistance has no consistent normal force, 1 otherwise. loads may be NULL. */
    int (*rhs)(const zp_model *m, void *work, const zp_drive_now *dn, const double *y,
               double *ydot, zp_loads *loads);
    /* Largest violation of the formulation's own position constraints (m), tr the course at
       y[0]; NULL: none. */
    double (*constraint_residual)(const zp_model *m, const zp_track *tr, const double *y);
} zp_formulation;

/* ZP_FORM_<ID> for every line of formulations.def */
typedef enum {
#define ZP_FORM(id, obj) ZP_FORM_##id,
#include "formulations.def"
#undef ZP_FORM
    ZP_FORM_COUNT
} zp_form_id;

/* Not in the registry: lagrange's general path (GSL), which the tests hold the fixed-size
   path of "lagrange" to. */
extern const zp_formulation zp_form_lagrange_general;

const zp_formulation *zp_formulation_get(int id);
int zp_formulation_find(const char *name); /* -1 if unknown */

#endif
