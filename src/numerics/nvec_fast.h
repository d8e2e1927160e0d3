/* Optimised serial N_Vector operations for the few CVODE calls that dominate small systems. */
#ifndef ZP_NVEC_FAST_H
#define ZP_NVEC_FAST_H

#include <nvector/nvector_serial.h>

/* Installs them in v's operations table; CVODE's clones of v inherit them. */
void zp_nvec_fast_install(N_Vector v);

#endif
