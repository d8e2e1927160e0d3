/* Work spread over MPI ranks by a dynamic queue: rank 0 hands out items one at a time to
   whichever rank is free (itself included) and collects the results. Built without MPI, the
   same calls run every item in this process. */
#ifndef ZP_MPI_QUEUE_H
#define ZP_MPI_QUEUE_H

#include <stddef.h>

#include "diag.h"

/* Computes item into result (size bytes); runs on any rank, one item at a time per rank. */
typedef void (*zp_mpi_queue_work)(void *user, int item, void *result);
/* Takes item's result; runs on rank 0 only, one call at a time, in the order items finish. */
typedef void (*zp_mpi_queue_done)(void *user, int item, const void *result);

/* Joins the ranks an MPI launcher (mpirun, srun) started; a process started without one is
   rank 0 of 1 and leaves MPI alone. 0, or -1 with why. */
int zp_mpi_queue_start(char *err, size_t errlen);
/* Leaves MPI; after the last zp_mpi_queue_run. */
void zp_mpi_queue_end(void);
int zp_mpi_queue_rank(void);
int zp_mpi_queue_size(void);
/* Called by every rank: the items todo[ntodo] (read on rank 0 only) are computed by work on
   some rank and handed to done on rank 0. Results travel as bytes (the ranks run the same
   program). Returns when every item is done; ZP_ERR_NOMEM or ZP_ERR_IO with why in err. */
zp_status zp_mpi_queue_run(const int *todo, int ntodo, size_t size, zp_mpi_queue_work work,
                           zp_mpi_queue_done done, void *user, char *err, size_t errlen);

#endif
