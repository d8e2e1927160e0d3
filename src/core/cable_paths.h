/* The loaded-cable paths of one cable, one per load (MODEL.md "A cable that sags": every rider
   rides their own path): each built on the first ask for its load, then shared read-only by
   every model that carries that load, in any thread, until the set is freed. */
#ifndef ZP_CABLE_PATHS_H
#define ZP_CABLE_PATHS_H

#include <stddef.h>

#include "cable.h"
#include "cable_path.h"

typedef struct zp_cable_paths zp_cable_paths;

/* A set for cable c (copied), every path built over [x_lo, x_hi] (zp_cable_path_create's
   interval); NULL when out of memory. */
zp_cable_paths *zp_cable_paths_create(const zp_cable *c, double x_lo, double x_hi);
/* Frees the set and every path it built. */
void zp_cable_paths_free(zp_cable_paths *ps);
/* The path under load W (N): the one built for exactly that load, else a new one. NULL with
   why filled when it cannot be built. Thread-safe: a path is built outside the set's lock, and
   of two threads building the same load one keeps its own and the other's is freed. */
const zp_cable_path *zp_cable_paths_get(zp_cable_paths *ps, double load, char *why,
                                        size_t whylen);
/* The cable of the set, and its interval. */
const zp_cable *zp_cable_paths_cable(const zp_cable_paths *ps);

#endif
