/* Waiting for a nonblocking MPI operation without spinning a core, for the files compiled with
   MPI (mpi_queue.c, mpi_spread.c): a rank that waits leaves its core to those still at work. */
#ifndef ZP_MPI_WAIT_H
#define ZP_MPI_WAIT_H

#include <mpi.h>

/* 0 when req completed, napping 1 ms between tests (the most a wait overruns); -1 on an MPI
   error */
int zp_mpi_queue_wait_napping(MPI_Request *req);

#endif
