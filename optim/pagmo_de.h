/* Self-adaptive differential evolution from pagmo2 (sade: jDE's adaptation of F and CR), one
   population evolved serially on the calling thread, behind a C interface: the search keeps no
   optimizer of its own. A population is seeded, so the same seed and the same fitness values
   give the same generations. */
#ifndef ZP_PAGMO_DE_H
#define ZP_PAGMO_DE_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct zp_pagmo_de zp_pagmo_de;

/* the value to minimise at x (n values), on the thread that evolves */
typedef double (*zp_pagmo_de_fitness)(void *user, const double *x);

/* a population of popsize members over the box [lo, hi] (n values each, copied), evolved by
   sade's mutation variant (1 to 18, as pagmo numbers them), with its seed; nothing evaluated
   yet. NULL when out of memory. */
zp_pagmo_de *zp_pagmo_de_create(int n, const double *lo, const double *hi, int popsize, int variant,
                                unsigned long seed);
void zp_pagmo_de_free(zp_pagmo_de *d);

/* up to gens generations (popsize evaluations each) through fit; the first call first draws
   the population (popsize evaluations), and so does the call after the population has
   collapsed (every member within 1e-6 of the first's value and 1e-3 of it in each parameter:
   the generation that found it so ends the call), with the next seed. 0, or -1 when pagmo
   refused. */
int zp_pagmo_de_evolve(zp_pagmo_de *d, int gens, zp_pagmo_de_fitness fit, void *user);

#ifdef __cplusplus
}
#endif

#endif
