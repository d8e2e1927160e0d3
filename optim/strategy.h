/* A strategy of the search, in the manner of GSL's gsl_multimin_fminimizer_type: its name, the
   phase it serves and its functions. A global strategy adds points to the archive in each round
   of the search; a local one polishes a leg from its start. strategies.def pairs a global and a
   local strategy into each --algorithm: a new strategy is its own file optim/strategy_NAME.c
   (defining its const zp_strategy) plus the line there that offers it. */
#ifndef ZP_STRATEGY_H
#define ZP_STRATEGY_H

#include "leg.h"

typedef enum { ZP_STRATEGY_GLOBAL, ZP_STRATEGY_LOCAL, ZP_STRATEGY_PHASE_COUNT } zp_strategy_phase;

typedef struct zp_strategy {
    const char *name; /* as messages name it */
    zp_strategy_phase phase;
    int variant; /* its file's choice among the algorithms it adapts (NLopt's: nlopt_algorithm) */
    /* global: its own state for the search S (NULL: out of memory), created once the state
       has started and freed when the search ends */
    void *(*create)(const struct zp_strategy *self, const zp_search_state *S);
    void (*free)(void *state);
    /* global: the points of round `round` (0-based) into S's archive (zp_search_state_batch, or
       legs with archive set), between that round's constant pushes and its lines. ZP_OK, or an
       error with why in err */
    zp_status (*explore)(void *state, zp_search_state *S, int round, char *err, size_t errlen);
    /* local: one polish of the leg from its start (how: this strategy), on the calling thread;
       several run at once, each on its own leg */
    zp_leg_run polish;
} zp_strategy;

/* the strategies strategies.def names */
#define ZP_ALGORITHM(name, doc, global, local) extern const zp_strategy global, local;
#include "strategies.def"
#undef ZP_ALGORITHM

#endif
