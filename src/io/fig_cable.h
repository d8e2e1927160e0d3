/* `check --plot`'s figure of a cable scene (docs/model.md "A cable that sags"): the rope as it
   hangs alone and the path each rider's trolley runs on (the nominal rider, and with [robust]
   mass ranges the lightest and the heaviest) from anchor to anchor, with the ride's ends. */
#ifndef ZP_FIG_CABLE_H
#define ZP_FIG_CABLE_H

#include <stddef.h>

#include "model.h"
#include "tx.h"

/* cable.dat (x, then the height of each path: unloaded, nominal, lightest, heaviest; NaN where
   a path has no equilibrium) and cable.gp, which draws cable.png from it, into t. 0, or -1 with
   why in err (the caller aborts t). */
int zp_fig_cable_write(zp_tx *t, const zp_model *m, const zp_scene *sc, char *err, size_t errlen);

#endif
