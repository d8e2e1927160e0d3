/* Chain coordinates q = (x, y, theta_1..N) of docs/model.md "Bodies" and "Energy": centres of mass,
   the full mass matrix and the energy, shared by every formulation, event and output. */
#include "state.h"

#include <math.h>
#include <string.h>

void zp_state_start(const zp_model *m, const zp_course *course, zp_chain *c) {
    memset(c, 0, sizeof *c);
    c->q[0] = m->xb[0];
    c->q[1] = zp_model_track(m, course, 0, m->xb[0]).f;
}

void zp_state_com(const zp_model *m, const zp_chain *c, double xy[][2]) {
    double px = c->q[0], py = c->q[1]; /* joint above the current link */
    xy[0][0] = px;
    xy[0][1] = py;
    for (int i = 0; i < m->nlink; i++) {
        double s = sin(c->q[2 + i]), co = cos(c->q[2 + i]);
        xy[i + 1][0] = px + m->half[i] * s;
        xy[i + 1][1] = py - m->half[i] * co;
        px += m->len[i] * s;
        py -= m->len[i] * co;
    }
}

void zp_state_com_vel(const zp_model *m, const zp_chain *c, double v[][2]) {
    double px = c->v[0], py = c->v[1]; /* velocity of the joint above the current link */
    v[0][0] = px;
    v[0][1] = py;
    for (int i = 0; i < m->nlink; i++) {
        double w = c->v[2 + i], s = sin(c->q[2 + i]), co = cos(c->q[2 + i]);
        v[i + 1][0] = px + m->half[i] * co * w;
        v[i + 1][1] = py + m->half[i] * s * w;
        px += m->len[i] * co * w;
        py += m->len[i] * s * w;
    }
}

void zp_state_mass_full(const zp_model *m, const double *q, double *M) {
    int n = m->nlink + 2;
    memset(M, 0, sizeof(double) * n * n);
    M[0] = M[n + 1] = m->mtot;
    for (int j = 0; j < m->nlink; j++) {
        M[2 + j] = M[(2 + j) * n] = m->B[j] * cos(q[2 + j]);
        M[n + 2 + j] = M[(2 + j) * n + 1] = m->B[j] * sin(q[2 + j]);
        for (int k = 0; k < m->nlink; k++) {
            M[(2 + j) * n + 2 + k] = m->C[j][k] * cos(q[2 + j] - q[2 + k]);
        }
    }
}

zp_energy zp_state_energy(const zp_model *m, const zp_chain *c) {
    double vel[ZP_MAX_LINKS + 1][2], pos[ZP_MAX_LINKS + 1][2];
    zp_state_com(m, c, pos);
    zp_state_com_vel(m, c, vel);
    zp_energy e = {0.5 * m->m0 * (vel[0][0] * vel[0][0] + vel[0][1] * vel[0][1]),
                   m->m0 * m->g * pos[0][1]};
    for (int i = 0; i < m->nlink; i++) {
        double w = c->v[2 + i];
        e.kinetic +=
            0.5 * m->mass[i] * (vel[i + 1][0] * vel[i + 1][0] + vel[i + 1][1] * vel[i + 1][1]) +
            0.5 * m->inertia[i] * w * w;
        e.potential += m->mass[i] * m->g * pos[i + 1][1];
    }
    return e;
}

void zp_state_relative(const zp_model *m, const zp_chain *c, double *phi, double *w) {
    double th_prev = 0, w_prev = 0; /* the trolley does not rotate */
    for (int i = 0; i < m->nlink; i++) {
        phi[i] = c->q[2 + i] - th_prev;
        w[i] = c->v[2 + i] - w_prev;
        th_prev = c->q[2 + i];
        w_prev = c->v[2 + i];
    }
}
