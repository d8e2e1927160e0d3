/* Work shared out over the processes of one job (the ranks of mpirun): the program that
   started them fills a zp_spread with its exchanges; optim calls them and knows no MPI. */
#ifndef ZP_SPREAD_H
#define ZP_SPREAD_H

#include <stddef.h>

#include "pool.h"

typedef struct zp_spread {
    int rank, size; /* this process and how many there are; size 1: alone */
    /* Called by every rank together: all holds n = sum of count[] records of rec bytes, rank
       after rank, this rank's count[rank] of them filled; on return every rank's are, on every
       rank. 0, or -1. all NULL: this rank ran out of memory and the job must end. */
    int (*allgather)(void *user, void *all, const int *count, size_t rec);
    /* Called by every rank together: rank 0's len bytes at buf copied into every rank's buf.
       0, or -1. */
    int (*bcast)(void *user, void *buf, size_t len);
    void *user;
} zp_spread;

/* 1 when sp shares work with other processes */
int zp_spread_active(const zp_spread *sp);

/* zp_pool_map over the ranks: job(user, i, ..) writes record i of out (n records of rec
   bytes) and runs on one rank only, item i on rank i % size (neighbours, which cost alike,
   fall to different ranks); on return every rank holds all n records. done counts this rank's
   items (total: its share). sp NULL or alone: zp_pool_map. ZP_OK, ZP_ERR_NOMEM, or ZP_ERR_IO
   when the exchange failed. */
zp_status zp_spread_map(const zp_spread *sp, zp_pool *p, int n, zp_pool_job job, void *user,
                        void *out, size_t rec, zp_pool_done done, void *done_user);

#endif
