/* The root functions of a run (docs/model.md "Outcomes"), one layout for every formulation and
   method: section ends, death per joint, and the extrema of each relative joint angle. */
#ifndef ZP_EVENTS_H
#define ZP_EVENTS_H

#include "model.h"

/* g layout: [0] x - left end, [1] x - right end, [2+i] phi_max - |phi_i|, [2+N+i] w_i, with
   rolling resistance then the trolley's x' (filled by the simulator), with rounded kinks
   then x less the section's two arc tangent points (where f'' jumps), with a brake zone then
   x less its start and its end (where its force starts and stops) */
enum { ZP_ROOT_LEFT = 0, ZP_ROOT_RIGHT = 1, ZP_ROOT_DEATH = 2 };
#define ZP_EVENTS_MAX (7 + 2 * ZP_MAX_LINKS) /* roots at most */

typedef enum {
    ZP_EVENT_NONE,   /* only extrema of joint angles: keep going */
    ZP_EVENT_DEATH,
    ZP_EVENT_FINISH,
    ZP_EVENT_ROLLBACK,
    ZP_EVENT_KINK,
    ZP_EVENT_REST, /* the trolley's velocity along the course passes zero */
    ZP_EVENT_TANGENT, /* the trolley passes an arc's tangent point: the integrator restarts */
    ZP_EVENT_ZONE,    /* the trolley passes an end of the brake zone: the integrator restarts */
    ZP_EVENT_COUNT
} zp_event;

int zp_events_count(const zp_model *m);
/* Index of the root on the trolley's x' (rolling resistance only). */
int zp_events_rest(const zp_model *m);
/* Index of the first tangent-point root (rounded kinks only). */
int zp_events_tangent(const zp_model *m);
/* Index of the brake zone's start root, its end's after it (a brake zone only). */
int zp_events_zone(const zp_model *m);
/* Directions that matter: leaving through either end, |phi| rising through phi_max. */
void zp_events_directions(const zp_model *m, int *dir);
/* 1 for the roots whose time matters only through the state there (the extrema: phi is
   stationary at w = 0), 0 for the others. */
void zp_events_state_only(const zp_model *m, int *flag);
void zp_events_eval(const zp_model *m, int sec, double x, const double *phi, const double *w,
                    double *g);
/* What the roots found on section sec mean, in priority order death > finish > roll-back >
   kink > rest > tangent > zone. Sets *link (0-based, death) or *to (entered section, kink). */
zp_event zp_events_classify(const zp_model *m, int sec, const int *roots, int *link, int *to);

#endif
