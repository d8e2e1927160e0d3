/* The [robust] ranges as a box of scenarios (docs/model.md "Uncertainty and limits"): a point
   u in [-1, 1]^d is one scenario; the box widened about the nominal for the headroom; the worst
   point found for a schedule. Below the scenario sets, the objective and the robust search. */
#ifndef ZP_BOX_H
#define ZP_BOX_H

#include "scenario.h"

#define ZP_BOX_MAX (ZP_MAX_SECTIONS + 5 + ZP_MAX_LINKS)

/* The [robust] ranges as a box [-1, 1]^d: one coordinate per varied quantity. */
typedef struct zp_box {
    int d;
    int nforce;           /* sections with a force coordinate (the first nforce), 0: none */
    double force_error;   /* share, u = 1 scales a force by 1 + force_error */
    int dim[4];           /* coordinate of mass, length, trolley, damping; -1: not varied */
    double range[4][2];   /* their factors at u = -1 and u = +1 */
    int theta0;           /* first start-angle coordinate (one per link), -1: none */
    double theta_max;     /* rad */
    int nlink;
    int wind_dim;         /* coordinate of the wind, -1: not varied */
    double wind[2];       /* m/s at u = -1 and u = +1 */
    double wind0;         /* m/s, the nominal wind ([physics] wind) */
} zp_box;

void zp_box_from_scene(const zp_scene *sc, const zp_model *m, zp_box *b);
/* The scenario at u (d coordinates in [-1, 1]). */
void zp_box_scenario(const zp_box *b, const double *u, zp_scenario *s);
/* b widened by factor f about the nominal: force error and start angle times f, each range
   [lo, hi] to [1 + f (lo - 1), 1 + f (hi - 1)], the wind's about the nominal wind. */
void zp_box_widen(const zp_box *b, double f, zp_box *out);


/* The worst scenario found for a schedule, and what limited it. */
typedef struct zp_robust_worst {
    double u[ZP_BOX_MAX];
    double cons;      /* deg, the constraint there (> 0: broken) */
    double margin_deg;
    int outcome;      /* zp_outcome */
    int joint;        /* 1-based joint with the largest angle */
    int limit;        /* zp_limit_id with the largest excess, -1: none set */
    double excess;    /* that excess, reached / limit - 1 (> 0: broken; -1: none set) */
    double time;      /* s: finish, death or stall */
    double arrival_kmh; /* km/h at the finish, 0 when it does not finish */
    double anchor_tension; /* N, [cable], in the verification: the largest anchor tension over
                              the ride (zp_limits_anchor_tension); else 0 */
} zp_robust_worst;

#endif
