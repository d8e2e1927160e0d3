/* The spread over MPI (mpi_spread.h), compiled only with MPI: the exchanges are nonblocking
   collectives polled with naps, so a rank that waits (for rank 0's search, or for slower
   ranks) leaves its core to the threads that compute instead of busy-polling it. */
#include "mpi_spread.h"

#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#include "mpi_queue.h"
#include "mpi_wait.h"

static int allgather(void *user, void *all, const int *count, size_t rec) {
    (void)user;
    if (!all) {
        fputs("zipopt: out of memory for the exchange between MPI ranks\n", stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    int size = zp_mpi_queue_size();
    int *displ = malloc(sizeof *displ * (size_t)size);
    if (!displ) {
        return -1;
    }
    for (int r = 0, k = 0; r < size; k += count[r++]) {
        displ[r] = k;
    }
    /* records as one type: the byte count may pass INT_MAX where the record count does not */
    MPI_Datatype t;
    MPI_Request req;
    if (MPI_Type_contiguous((int)rec, MPI_BYTE, &t) != MPI_SUCCESS) {
        free(displ);
        return -1;
    }
    MPI_Type_commit(&t);
    int ok = MPI_Iallgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, all, count, displ, t,
                             MPI_COMM_WORLD, &req) == MPI_SUCCESS &&
             !zp_mpi_queue_wait_napping(&req);
    MPI_Type_free(&t);
    free(displ);
    return ok ? 0 : -1;
}

static int bcast(void *user, void *buf, size_t len) {
    (void)user;
    MPI_Request req;
    return MPI_Ibcast(buf, (int)len, MPI_BYTE, 0, MPI_COMM_WORLD, &req) == MPI_SUCCESS
               ? zp_mpi_queue_wait_napping(&req)
               : -1;
}

void zp_mpi_spread_fill(zp_spread *sp) {
    *sp = (zp_spread){zp_mpi_queue_rank(), zp_mpi_queue_size(), allgather, bcast, NULL};
}

void zp_mpi_spread_abort(int status) {
    MPI_Abort(MPI_COMM_WORLD, status);
}
