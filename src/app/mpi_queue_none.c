/* The queue without MPI (mpi_queue.h): one rank, every item computed here in order. */
#include "mpi_queue.h"

#include <stdio.h>
#include <stdlib.h>

int zp_mpi_queue_start(char *err, size_t errlen) {
    (void)err;
    (void)errlen;
    return 0;
}

void zp_mpi_queue_end(void) {}

int zp_mpi_queue_rank(void) {
    return 0;
}

int zp_mpi_queue_size(void) {
    return 1;
}

zp_status zp_mpi_queue_run(const int *todo, int ntodo, size_t size, zp_mpi_queue_work work,
                           zp_mpi_queue_done done, void *user, char *err, size_t errlen) {
    void *res = malloc(size);
    if (!res) {
        snprintf(err, errlen, "out of memory");
        return ZP_ERR_NOMEM;
    }
    for (int i = 0; i < ntodo; i++) {
        work(user, todo[i], res);
        done(user, todo[i], res);
    }
    free(res);
    return ZP_OK;
}
