/* Root functions and their meaning (docs/model.md "Outcomes", "Section boundaries"). The extrema
   roots (w_i = 0) make the largest |phi_i| exact rather than sampled at steps. */
#include "events.h"

#include <math.h>

int zp_events_count(const zp_model *m) {
    return zp_events_zone(m) + (m->physics & ZP_PHYS_BRAKE ? 2 : 0);
}

int zp_events_zone(const zp_model *m) {
    return zp_events_tangent(m) + (m->physics & ZP_PHYS_ROUNDED ? 2 : 0);
}

int zp_events_tangent(const zp_model *m) {
    return 2 + 2 * m->nlink + (m->stick ? 1 : 0);
}

int zp_events_rest(const zp_model *m) {
    return 2 + 2 * m->nlink;
}

void zp_events_directions(const zp_model *m, int *dir) {
    dir[ZP_ROOT_LEFT] = -1;
    dir[ZP_ROOT_RIGHT] = +1;
    for (int i = 0; i < m->nlink; i++) {
        dir[ZP_ROOT_DEATH + i] = -1;
        dir[ZP_ROOT_DEATH + m->nlink + i] = 0;
    }
    if (m->stick) {
        dir[zp_events_rest(m)] = 0;
    }
    if (m->physics & ZP_PHYS_ROUNDED) {
        dir[zp_events_tangent(m)] = dir[zp_events_tangent(m) + 1] = 0;
    }
    if (m->physics & ZP_PHYS_BRAKE) {
        dir[zp_events_zone(m)] = dir[zp_events_zone(m) + 1] = 0;
    }
}

void zp_events_state_only(const zp_model *m, int *flag) {
    for (int i = 0; i < zp_events_count(m); i++) {
        flag[i] = i >= ZP_ROOT_DEATH + m->nlink && i < zp_events_rest(m);
    }
}

void zp_events_eval(const zp_model *m, int sec, double x, const double *phi, const double *w,
                    double *g) {
    g[ZP_ROOT_LEFT] = x - m->xb[sec];
    g[ZP_ROOT_RIGHT] = x - m->xb[sec + 1];
    for (int i = 0; i < m->nlink; i++) {
        g[ZP_ROOT_DEATH + i] = m->phi_max_j[i] - fabs(phi[i]);
        g[ZP_ROOT_DEATH + m->nlink + i] = w[i];
    }
    /* the arcs' tangent points inside the section: the end of the arc around its left end,
       the start of the one around its right end (a constant 1 where there is none) */
    if (m->physics & ZP_PHYS_ROUNDED) {
        int lo = m->arc_at[sec], hi = m->arc_at[sec + 1], it = zp_events_tangent(m);
        g[it] = lo >= 0 ? x - m->arc[lo].x2 : 1;
        g[it + 1] = hi >= 0 ? x - m->arc[hi].x1 : 1;
    }
    /* the brake zone's ends, where its force starts and stops */
    if (m->physics & ZP_PHYS_BRAKE) {
        g[zp_events_zone(m)] = x - m->brake_zone[0];
        g[zp_events_zone(m) + 1] = x - m->brake_zone[1];
    }
}

zp_event zp_events_classify(const zp_model *m, int sec, const int *roots, int *link, int *to) {
    for (int i = 0; i < m->nlink; i++) {
        if (roots[ZP_ROOT_DEATH + i]) {
            *link = i;
            return ZP_EVENT_DEATH;
        }
    }
    if (roots[ZP_ROOT_RIGHT]) {
        if (sec + 1 == m->nsec) {
            return ZP_EVENT_FINISH;
        }
        *to = sec + 1;
        return ZP_EVENT_KINK;
    }
    if (roots[ZP_ROOT_LEFT]) {
        if (sec == 0) {
            return ZP_EVENT_ROLLBACK;
        }
        *to = sec - 1;
        return ZP_EVENT_KINK;
    }
    if (m->stick && roots[zp_events_rest(m)]) {
        return ZP_EVENT_REST;
    }
    if (m->physics & ZP_PHYS_ROUNDED &&
        (roots[zp_events_tangent(m)] || roots[zp_events_tangent(m) + 1])) {
        return ZP_EVENT_TANGENT;
    }
    if (m->physics & ZP_PHYS_BRAKE && (roots[zp_events_zone(m)] || roots[zp_events_zone(m) + 1])) {
        return ZP_EVENT_ZONE;
    }
    return ZP_EVENT_NONE;
}
