/* Chain coordinates of docs/model.md, q = (x, y, theta_1..N), and what follows from them alone:
   centres of mass, the full mass matrix, kinetic and potential energy. Every formulation
   converts its own state to and from a zp_chain, so events, impulses and outputs are shared. */
#ifndef ZP_STATE_H
#define ZP_STATE_H

#include "model.h"

#define ZP_NQ (2 + ZP_MAX_LINKS)

typedef struct zp_chain {
    double q[ZP_NQ]; /* x, y (m), theta_1..N (rad from the downward vertical, ccw) */
    double v[ZP_NQ]; /* their rates: m/s, rad/s */
} zp_chain;

typedef struct zp_energy {
    double kinetic;   /* J */
    double potential; /* J, m g y of every centre of mass, y = 0 the zero */
} zp_energy;

/* The docs/model.md start: x = x_start on the course, all theta = 0, at rest. course: the
   caller's own evaluators (each thread has its own). */
void zp_state_start(const zp_model *m, const zp_course *course, zp_chain *c);
/* Centres of mass: body 0 the trolley, body i link i; xy[b][0..1] in m. */
void zp_state_com(const zp_model *m, const zp_chain *c, double xy[][2]);
/* Velocities of the centres of mass, m/s, same layout. */
void zp_state_com_vel(const zp_model *m, const zp_chain *c, double v[][2]);
/* The full (N+2)x(N+2) mass matrix M(q) of the chain coordinates, row-major in M. */
void zp_state_mass_full(const zp_model *m, const double *q, double *M);
zp_energy zp_state_energy(const zp_model *m, const zp_chain *c);
/* Relative joint angle phi_i = theta_i - theta_{i-1} (rad) and its rate w_i (rad/s). */
void zp_state_relative(const zp_model *m, const zp_chain *c, double *phi, double *w);

#endif
