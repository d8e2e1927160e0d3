/* zp_spread_map without MPI: three "ranks" as threads of one process, their exchange an
   allgather made of a shared buffer and a barrier. Every item runs exactly once over the ranks,
   and every rank ends with every record, whatever n is against the rank count. */
#include <pthread.h>
#include <string.h>

#include "check.h"
#include "spread.h"
#include "testutil.h"

#define RANKS 3
#define NMAX 64

typedef struct rec {
    int item;
    double v;
} rec;

static rec world[NMAX];  /* the exchange's buffer, rank after rank */
static int ran[NMAX];    /* times each item ran, over every rank */
static int ran_by[NMAX]; /* the rank that ran it */
static pthread_barrier_t gate;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

/* MPI_Allgatherv in place, over threads: every rank puts its block in world, then takes all */
static int fake_allgather(void *user, void *all, const int *count, size_t size) {
    int rank = *(const int *)user, first = 0, n = 0;
    for (int r = 0; r < RANKS; r++) {
        first += r < rank ? count[r] : 0;
        n += count[r];
    }
    memcpy((char *)world + first * size, (char *)all + first * size, count[rank] * size);
    pthread_barrier_wait(&gate);
    memcpy(all, world, n * size);
    pthread_barrier_wait(&gate); /* nobody refills world before all have read it */
    return 0;
}

typedef struct job_ctx {
    rec *out;
    int rank;
} job_ctx;

static void job(void *user, int i, zp_sim *s, zp_result *r) {
    job_ctx *c = user;
    (void)s;
    (void)r;
    c->out[i] = (rec){i, 1.5 * i + 0.25};
    pthread_mutex_lock(&lock);
    ran[i]++;
    ran_by[i] = c->rank;
    pthread_mutex_unlock(&lock);
}

typedef struct rank_ctx {
    int rank, n, status;
    zp_pool *pool;
    rec out[NMAX];
} rank_ctx;

static void *rank_main(void *arg) {
    rank_ctx *rc = arg;
    zp_spread sp = {rc->rank, RANKS, fake_allgather, NULL, &rc->rank};
    job_ctx c = {rc->out, rc->rank};
    rc->status = zp_spread_map(&sp, rc->pool, rc->n, job, &c, rc->out, sizeof(rec), NULL, NULL);
    return NULL;
}

static void spread_n(zp_pool **pools, int n) {
    static rank_ctx rc[RANKS];
    pthread_t th[RANKS];
    memset(ran, 0, sizeof ran);
    for (int r = 0; r < RANKS; r++) {
        rc[r] = (rank_ctx){.rank = r, .n = n, .pool = pools[r]};
        memset(rc[r].out, 0xff, sizeof rc[r].out); /* no record is right by chance */
        pthread_create(&th[r], NULL, rank_main, &rc[r]);
    }
    for (int r = 0; r < RANKS; r++) {
        pthread_join(th[r], NULL);
    }
    for (int r = 0; r < RANKS; r++) {
        CHECK(rc[r].status == ZP_OK);
        for (int i = 0; i < n; i++) {
            CHECK(rc[r].out[i].item == i && rc[r].out[i].v == 1.5 * i + 0.25);
        }
    }
    for (int i = 0; i < n; i++) {
        CHECK(ran[i] == 1);
        CHECK(ran_by[i] == i % RANKS); /* dealt out in turn: neighbours on different ranks */
    }
}

int main(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-6);
    zp_pool *pools[RANKS];
    for (int r = 0; r < RANKS; r++) {
        pools[r] = zp_pool_create(m, &o, 2);
        CHECK(pools[r] != NULL);
    }
    pthread_barrier_init(&gate, NULL, RANKS);
    int ns[] = {0, 1, 2, 3, 10, NMAX};
    for (size_t k = 0; k < sizeof ns / sizeof *ns; k++) {
        spread_n(pools, ns[k]);
    }
    /* alone (NULL, or one rank): zp_pool_map */
    rec out[NMAX];
    job_ctx c = {out, 0};
    memset(ran, 0, sizeof ran);
    CHECK(zp_spread_map(NULL, pools[0], 10, job, &c, out, sizeof *out, NULL, NULL) == ZP_OK);
    for (int i = 0; i < 10; i++) {
        CHECK(ran[i] == 1 && out[i].item == i);
    }
    CHECK(!zp_spread_active(NULL) && !zp_spread_active(&(zp_spread){.size = 1}));
    pthread_barrier_destroy(&gate);
    for (int r = 0; r < RANKS; r++) {
        zp_pool_free(pools[r]);
    }
    zp_model_free(m);
    return CHECK_DONE();
}
