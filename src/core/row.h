/* One trajectory row and what follows from it alone (centres of mass, relative angles, energy,
   joint reactions, felt acceleration), derived in one place for the simulator's load peaks,
   the CSV, the figures and any new writer. */
#ifndef ZP_ROW_H
#define ZP_ROW_H

#include "formulation.h"

/* One sampled instant: the state in chain coordinates plus what the outputs need. */
typedef struct zp_row {
    double t; /* s */
    int sec;  /* 0-based */
    zp_chain c;
    double w_drive, w_damp, e_impulse; /* J, cumulative */
    zp_loads loads;
} zp_row;

/* What a row implies, every quantity a writer shows. */
typedef struct zp_row_view {
    double speed;                    /* m/s, trolley */
    double com[ZP_MAX_LINKS + 1][2]; /* m, centres of mass: body 0 the trolley, body i link i */
    double phi[ZP_MAX_LINKS];        /* rad, relative joint angles theta_i - theta_{i-1} */
    double w[ZP_MAX_LINKS];          /* rad/s, their rates */
    zp_energy e;                     /* J */
    double joint[ZP_MAX_LINKS];      /* N, |force of the parent on link i| at joint i */
    double acc_g[ZP_MAX_LINKS];      /* g, felt (proper) acceleration |a - g| / g of link i's
                                        centre: 1 hanging at rest */
} zp_row_view;

/* The load magnitudes of loads: joint reactions (N) and felt accelerations (g), per link. */
void zp_row_loads(const zp_model *m, const zp_loads *loads, double *joint, double *acc_g);
/* Everything r implies. */
void zp_row_derive(const zp_model *m, const zp_row *r, zp_row_view *v);

#endif
