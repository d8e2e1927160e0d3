/* A command on every rank of an MPI job: rank 0 speaks and writes, the others lend their cores
   through a zp_spread (spread.h). Built without MPI, the command runs alone. */
#ifndef ZP_MPI_SPREAD_H
#define ZP_MPI_SPREAD_H

#include "spread.h"

/* The ranks of the job joined by zp_mpi_queue_start (rank 0 of 1 when started without a
   launcher): the exchanges wait without spinning a core. */
void zp_mpi_spread_fill(zp_spread *sp);
/* Ends every rank of the job with status (MPI_Abort); returns only without MPI. */
void zp_mpi_spread_abort(int status);

/* Joins the job (zp_mpi_queue_start), runs body on every rank with the ranks' spread, the
   ranks other than 0 silenced (stdout and stderr to /dev/null), and leaves it. Returns body's
   exit status; ZP_EXIT_FAIL when MPI cannot start (said under name). */
int zp_mpi_spread_main(const char *name, int (*body)(int, char **, const zp_spread *), int argc,
                       char **argv);

#endif
