/* Items dealt out over the ranks of a job and gathered back (spread.h). */
#include "spread.h"

#include <stdlib.h>
#include <string.h>

int zp_spread_active(const zp_spread *sp) {
    return sp && sp->size > 1;
}

/* rank's items are rank, rank + size, ..: job j of the rank's batch is item rank + j size */
typedef struct dealt {
    zp_pool_job job;
    void *user;
    int rank, size;
} dealt;

static void dealt_job(void *user, int j, zp_sim *s, zp_result *r) {
    const dealt *d = user;
    d->job(d->user, d->rank + j * d->size, s, r);
}

zp_status zp_spread_map(const zp_spread *sp, zp_pool *p, int n, zp_pool_job job, void *user,
                        void *out, size_t rec, zp_pool_done done, void *done_user) {
    if (!zp_spread_active(sp)) {
        zp_pool_map(p, n, job, user, done, done_user);
        return ZP_OK;
    }
    int size = sp->size;
    /* the exchange's layout: rank after rank, each rank's items in its own order */
    int *count = malloc(sizeof *count * (size_t)size);
    char *all = malloc(rec * (size_t)(n > 0 ? n : 1)), *o = out;
    if (!count || !all) {
        free(count);
        free(all);
        sp->allgather(sp->user, NULL, NULL, rec); /* ends the job: the others wait for us */
        return ZP_ERR_NOMEM;
    }
    size_t first = 0; /* this rank's first record in all */
    for (int r = 0; r < size; r++) {
        count[r] = n > r ? (n - r + size - 1) / size : 0;
        first += r < sp->rank ? (size_t)count[r] : 0;
    }
    dealt d = {job, user, sp->rank, size};
    zp_pool_map(p, count[sp->rank], dealt_job, &d, done, done_user);
    for (int j = 0; j < count[sp->rank]; j++) {
        memcpy(all + (first + j) * rec, o + (size_t)(sp->rank + j * size) * rec, rec);
    }
    zp_status st = sp->allgather(sp->user, all, count, rec) ? ZP_ERR_IO : ZP_OK;
    for (int r = 0, k = 0; !st && r < size; r++) {
        for (int j = 0; j < count[r]; j++, k++) {
            memcpy(o + (size_t)(r + j * size) * rec, all + (size_t)k * rec, rec);
        }
    }
    free(count);
    free(all);
    return st;
}
