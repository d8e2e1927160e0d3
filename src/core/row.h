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
    double w_effect[ZP_EFFECT_NWORK];  /* J, cumulative, taken out by each effect with a work
                                          integral (ZP_EFFECT_W_*; 0 without them) */
    double f_applied; /* N, the drive's applied force, a state with a response time (0 without
                         one: the schedule's force then, not kept) */
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

/* A run's trajectory rows, packed: each keeps only its model's entries (2 + nlink coordinates
   and rates, nwork work integrals, ndrive drive states, nlink joint and nlink + 1 body loads),
   so a run writes a
   fraction of the fresh memory whole zp_rows would (for 3 links 31 doubles of 63). */
typedef struct zp_row_store {
    double *v; /* owned, cap x stride */
    int n, cap;
    int stride, nlink, nwork, ndrive;
} zp_row_store;

/* The load magnitudes of loads: joint reactions (N) and felt accelerations (g), per link. */
void zp_row_loads(const zp_model *m, const zp_loads *loads, double *joint, double *acc_g);
/* The running maxima joint[i] (N) and acc_g[i] (g) taken over loads: bit for bit fmax of each
   with zp_row_loads' value, whose hypot is skipped where the sum of squares shows it below. */
void zp_row_loads_max(const zp_model *m, const zp_loads *loads, double *joint, double *acc_g);
/* Everything r implies. */
void zp_row_derive(const zp_model *m, const zp_row *r, zp_row_view *v);

/* Room for cap rows of m's size (no memory is touched before a row is put); 0, or -1 out of
   memory. zp_row_store_free(t) on a zeroed or initialized t frees it. */
int zp_row_store_init(zp_row_store *t, const zp_model *m, int cap);
void zp_row_store_free(zp_row_store *t);
/* Appends r, a row of the model t was made for (its entries beyond nlink zero, as every row the
   simulator makes): t->n < t->cap is the caller's to check. */
void zp_row_store_put(zp_row_store *t, const zp_row *r);
/* Row k (0 <= k < t->n) exactly as it was put. */
void zp_row_store_get(const zp_row_store *t, int k, zp_row *r);
/* The time of row k, s. */
double zp_row_store_t(const zp_row_store *t, int k);

#endif
