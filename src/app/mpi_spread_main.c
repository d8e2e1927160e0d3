/* A command run on every rank of an MPI job, rank 0 speaking for it (mpi_spread.h). */
#include <stdio.h>

#include "cli.h"
#include "mpi_queue.h"
#include "mpi_spread.h"

int zp_mpi_spread_main(const char *name, int (*body)(int, char **, const zp_spread *), int argc,
                       char **argv) {
    char err[256];
    if (zp_mpi_queue_start(err, sizeof err)) {
        fprintf(stderr, "zipopt %s: %s\n", name, err);
        return ZP_EXIT_FAIL;
    }
    zp_spread sp;
    zp_mpi_spread_fill(&sp);
    if (sp.rank != 0) { /* rank 0 speaks for the job */
        freopen("/dev/null", "w", stdout);
        freopen("/dev/null", "w", stderr);
    }
    int status = body(argc, argv, &sp);
    /* a failure one rank alone met (out of memory, a file) may leave the others waiting for
       it in an exchange, where leaving MPI would wait for them: the job ends here instead;
       bad input stops every rank alike before any exchange */
    if (status == ZP_EXIT_FAIL && sp.size > 1) {
        fflush(NULL);
        zp_mpi_spread_abort(status);
    }
    zp_mpi_queue_end();
    return status;
}
