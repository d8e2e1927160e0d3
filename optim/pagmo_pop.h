/* A population evolved by one of pagmo2's algorithms, serially on the calling thread, behind a
   C interface: the search keeps no optimizer of its own. A population is seeded, so the same
   seed and the same fitness values give the same generations. */
#ifndef ZP_PAGMO_POP_H
#define ZP_PAGMO_POP_H

#ifdef __cplusplus
extern "C" {
#endif

/* the algorithm that evolves a population */
typedef enum {
    ZP_PAGMO_SADE,  /* self-adaptive differential evolution (sade: best/1/bin, jDE's F and CR) */
    ZP_PAGMO_CMAES, /* CMA-ES (Hansen's 2006 "comparing review" version), pagmo's defaults */
} zp_pagmo_algo;

typedef struct zp_pagmo_pop zp_pagmo_pop;

/* the value to minimise at x (n values), on the thread that evolves */
typedef double (*zp_pagmo_pop_fitness)(void *user, const double *x);

/* a population of popsize members over the box [lo, hi] (n values each, copied), evolved by
   algo, with its seed; nothing evaluated yet. NULL when out of memory. */
zp_pagmo_pop *zp_pagmo_pop_create(zp_pagmo_algo algo, int n, const double *lo, const double *hi,
                                  int popsize, unsigned long seed);
/* CMA-ES over the box [lo, hi] (n values each, copied) started at x0, whose value is f0: its
   popsize members all x0, so the mean sits there, with a first step of sigma0 of the box;
   nothing evaluated by creating it. A population drawn afresh after a collapse is drawn over
   the box, as zp_pagmo_pop_create's are. NULL when out of memory. */
zp_pagmo_pop *zp_pagmo_pop_create_at(int n, const double *lo, const double *hi, int popsize,
                                     unsigned long seed, const double *x0, double f0,
                                     double sigma0);
void zp_pagmo_pop_free(zp_pagmo_pop *p);

/* up to gens generations (popsize evaluations each) through fit; the first call first draws
   the population (popsize evaluations), and so does the call after the population has
   collapsed (every member within 1e-6 of the first's value and 1e-3 of it in each parameter:
   the generation that found it so ends the call), with the next seed. 0, or -1 when pagmo
   refused. */
int zp_pagmo_pop_evolve(zp_pagmo_pop *p, int gens, zp_pagmo_pop_fitness fit, void *user);

/* the population's best member into x (its n values) and its value into *value: 0, or -1 when
   none is drawn (before the first evolution, or after a collapse) */
int zp_pagmo_pop_best(const zp_pagmo_pop *p, double *x, double *value);

#ifdef __cplusplus
}
#endif

#endif
