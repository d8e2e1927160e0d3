/* The sensitivity run's workspace, shared by its loop (sens.c) and its equations and jumps
   (sens_rhs.c). Internal to the core floor. Augmented state: ya = (y, s_1, .., s_np), each s_k
   of y's n entries. */
#ifndef ZP_SENS_INT_H
#define ZP_SENS_INT_H

#include "sim_int.h"

/* the relative step of the five-point stencils: O(h^4) truncation against O(eps / h) round-off
   (sens_rhs.c's design note) */
#define ZP_SENS_STEP 1e-3
/* the relative step of the rates' central differences: O(h^2) truncation against the
   round-off of the rates' own noise over h (sens_rhs.c's design note) */
#define ZP_SENS_CENTRAL_STEP 1e-4

typedef struct zp_sens {
    zp_sim *sim;            /* owned: the equations, course and drive of the plain run */
    zp_rhs_fn rhs;          /* the plain run's rates and roots, user = sim */
    zp_root_fn root;
    zp_schedule sched;      /* the run's schedule; perturbed in place while differentiating */
    int n, np, naug;
    double *scratch;        /* owned, 4 n: perturbed states and their rates */
    long rates;             /* plain rate evaluations made so far: the run's work */
} zp_sens;

/* The plain rates at y as the sensitivity run reads them (the course on the integrator's piece). */
int zp_sens_rhs_rates(zp_sens *c, double t, const double *y, double *f);
/* Rates of the augmented state: the plain rates, and for each k the derivative of the rates
   along (s_k, e_k) in (state, parameters), J s_k + df/dp_k. user = zp_sens. */
int zp_sens_rhs(double t, const double *ya, double *yd, void *user);
/* The plain roots on ya's state part. user = zp_sens. */
int zp_sens_rhs_root(double t, const double *ya, double *g, void *user);
/* The kink map y+ = h(y-) into section `to` (docs/model.md: onto the boundary, the impulse):
   y_out from y_in, on the current section. Nonzero where the mass matrix is not positive
   definite. */
int zp_sens_rhs_kink_map(zp_sens *c, const double *y_in, int to, double *y_out);
/* 1 when s (n entries) is 0 in every one: a parameter of a section not reached yet, whose
   stencil zp_sens_rhs skips. */
int zp_sens_rhs_zero(const double *s, int n);
/* m/s: the trolley's speed change |v+ - v-| across that kink, as the plain run's kink_dv. */
int zp_sens_rhs_kink_dv(zp_sens *c, const double *y_in, int to, double *dv);
/* m/s: the trolley's speed at y on the current section. */
double zp_sens_rhs_speed(zp_sens *c, const double *y);
/* The plain run's histories at (t, y), on the integrator's piece: into v (unless NULL) felt g
   per link then force per joint (zp_row_loads), and into *power the drive's |F_applied v| (W).
   Uses the scratch's third n. */
int zp_sens_rhs_histories(zp_sens *c, double t, const double *y, double *v, double *power);
/* dh: the derivative of the kink map at y along u (n entries). */
int zp_sens_rhs_kink_deriv(zp_sens *c, const double *y, const double *u, int to, double *dh);

#endif
