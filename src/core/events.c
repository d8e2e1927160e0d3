/* Root functions and their meaning (MODEL.md "Outcomes", "Section boundaries"). The extrema
   roots (w_i = 0) make the largest |phi_i| exact rather than sampled at steps. */
#include "events.h"

#include <math.h>

int zp_events_count(const zp_model *m) {
    return 2 + 2 * m->nlink;
}

void zp_events_directions(const zp_model *m, int *dir) {
    dir[ZP_ROOT_LEFT] = -1;
    dir[ZP_ROOT_RIGHT] = +1;
    for (int i = 0; i < m->nlink; i++) {
        dir[ZP_ROOT_DEATH + i] = -1;
        dir[ZP_ROOT_DEATH + m->nlink + i] = 0;
    }
}

void zp_events_state_only(const zp_model *m, int *flag) {
    for (int i = 0; i < zp_events_count(m); i++) {
        flag[i] = i >= ZP_ROOT_DEATH + m->nlink;
    }
}

void zp_events_eval(const zp_model *m, int sec, double x, const double *phi, const double *w,
                    double *g) {
    g[ZP_ROOT_LEFT] = x - m->xb[sec];
    g[ZP_ROOT_RIGHT] = x - m->xb[sec + 1];
    for (int i = 0; i < m->nlink; i++) {
        g[ZP_ROOT_DEATH + i] = m->phi_max - fabs(phi[i]);
        g[ZP_ROOT_DEATH + m->nlink + i] = w[i];
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
    return ZP_EVENT_NONE;
}
