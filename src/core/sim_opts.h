/* A run's options as the scene's [solver] section asks for them: apart from the run itself
   (sim.c), since the pick for [solver] accuracy runs the simulator (accuracy.c). */
#ifndef ZP_SIM_OPTS_H
#define ZP_SIM_OPTS_H

#include "sim_types.h"

/* Options from the scene's [solver] section; its method and formulation names judged against
   their registries (into d). */
zp_status zp_sim_opts_from_scene(const zp_scene *sc, zp_sim_opts *o, zp_diag *d);

#endif
