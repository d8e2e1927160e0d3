/* The queue over MPI (mpi_queue.h), compiled only with MPI: on rank 0 a dispatcher thread
   answers the other ranks while the main thread computes items like any rank. */
#include "mpi_queue.h"
#include "mpi_wait.h"

#include <mpi.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { TAG_ASK = 1, TAG_ITEM = 2 };
/* the dispatcher's nap between probes (1 ms): a rank waits at most this for its next item,
   and the dispatcher never spins a core that rank 0's threads compute on */
#define NAP_NS 1000000

typedef struct queue {
    const int *todo;
    int ntodo, next; /* items handed out so far */
    size_t size;
    zp_mpi_queue_work work;
    zp_mpi_queue_done done;
    void *user;
    pthread_mutex_t lock; /* next, and the calls to done */
} queue;

/* MPI is joined only under a launcher (mpirun, srun, hydra): a plain `zipopt sweep` neither
   pays for MPI_Init nor needs a launcher's environment. Set once, before any item runs. */
static int joined;

static int launched(void) {
    const char *vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"};
    for (int i = 0; i < 4; i++) {
        if (getenv(vars[i])) {
            return 1;
        }
    }
    return 0;
}

int zp_mpi_queue_start(char *err, size_t errlen) {
    if (!launched()) {
        return 0;
    }
    /* only one thread of a rank calls MPI at a time: rank 0's dispatcher, between init and
       finalize by the main thread */
    int provided;
    if (MPI_Init_thread(NULL, NULL, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS) {
        snprintf(err, errlen, "MPI_Init_thread failed");
        return -1;
    }
    joined = 1;
    if (provided < MPI_THREAD_SERIALIZED) {
        snprintf(err, errlen,
                 "this MPI library does not allow MPI calls from a second thread "
                 "(MPI_THREAD_SERIALIZED)");
        zp_mpi_queue_end();
        return -1;
    }
    return 0;
}

void zp_mpi_queue_end(void) {
    if (joined) {
        /* a rank that is done waits for the others asleep, not spinning in MPI_Finalize: where
           cores share their units (hyperthreads), a spinning rank slows those still at work */
        MPI_Request barrier;
        if (MPI_Ibarrier(MPI_COMM_WORLD, &barrier) == MPI_SUCCESS) {
            zp_mpi_queue_wait_napping(&barrier);
        }
        MPI_Finalize();
        joined = 0;
    }
}

int zp_mpi_queue_wait_napping(MPI_Request *req) {
    for (;;) {
        int flag = 0;
        if (MPI_Test(req, &flag, MPI_STATUS_IGNORE) != MPI_SUCCESS) {
            return -1;
        }
        if (flag) {
            return 0;
        }
        nanosleep(&(struct timespec){0, NAP_NS}, NULL);
    }
}

int zp_mpi_queue_rank(void) {
    int r = 0;
    if (joined) {
        MPI_Comm_rank(MPI_COMM_WORLD, &r);
    }
    return r;
}

int zp_mpi_queue_size(void) {
    int n = 1;
    if (joined) {
        MPI_Comm_size(MPI_COMM_WORLD, &n);
    }
    return n;
}

/* the next item to hand out, or -1 when none is left */
static int take(queue *q) {
    pthread_mutex_lock(&q->lock);
    int item = q->next < q->ntodo ? q->todo[q->next++] : -1;
    pthread_mutex_unlock(&q->lock);
    return item;
}

static void give(queue *q, int item, const void *result) {
    pthread_mutex_lock(&q->lock);
    q->done(q->user, item, result);
    pthread_mutex_unlock(&q->lock);
}

/* A message from a rank is its last item (-1 on its first request) and that item's result;
   the answer is the rank's next item, or -1: stop. */
static void *dispatch(void *arg) {
    queue *q = arg;
    char *buf = malloc(sizeof(int) + q->size);
    if (!buf) {
        fputs("zipopt: out of memory in the MPI dispatcher\n", stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    for (int active = zp_mpi_queue_size() - 1; active > 0;) {
        int flag;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, TAG_ASK, MPI_COMM_WORLD, &flag, &st);
        if (!flag) {
            nanosleep(&(struct timespec){0, NAP_NS}, NULL);
            continue;
        }
        int item, next;
        MPI_Recv(buf, (int)(sizeof(int) + q->size), MPI_BYTE, st.MPI_SOURCE, TAG_ASK,
                 MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        memcpy(&item, buf, sizeof item);
        if (item >= 0) {
            give(q, item, buf + sizeof item);
        }
        next = take(q);
        MPI_Send(&next, 1, MPI_INT, st.MPI_SOURCE, TAG_ITEM, MPI_COMM_WORLD);
        active -= next < 0;
    }
    free(buf);
    return NULL;
}

/* a rank other than 0: ask, compute, send the result with the next request, until told stop */
static void serve(queue *q) {
    char *buf = malloc(sizeof(int) + q->size);
    if (!buf) {
        fputs("zipopt: out of memory for the MPI work queue\n", stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    int item = -1;
    for (;;) {
        memcpy(buf, &item, sizeof item);
        MPI_Send(buf, (int)(sizeof item + (item < 0 ? 0 : q->size)), MPI_BYTE, 0, TAG_ASK,
                 MPI_COMM_WORLD);
        MPI_Recv(&item, 1, MPI_INT, 0, TAG_ITEM, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (item < 0) {
            break;
        }
        q->work(q->user, item, buf + sizeof item);
    }
    free(buf);
}

zp_status zp_mpi_queue_run(const int *todo, int ntodo, size_t size, zp_mpi_queue_work work,
                           zp_mpi_queue_done done, void *user, char *err, size_t errlen) {
    queue q = {todo, ntodo, 0, size, work, done, user, PTHREAD_MUTEX_INITIALIZER};
    if (zp_mpi_queue_rank() != 0) {
        serve(&q);
        return ZP_OK;
    }
    void *res = malloc(size);
    pthread_t th;
    int threaded = zp_mpi_queue_size() > 1;
    if (!res || (threaded && pthread_create(&th, NULL, dispatch, &q))) {
        /* the other ranks wait for an answer: they get their stop */
        q.next = q.ntodo;
        dispatch(&q);
        free(res);
        snprintf(err, errlen, "%s",
                 res ? "cannot start the MPI dispatcher thread" : "out of memory");
        return res ? ZP_ERR_IO : ZP_ERR_NOMEM;
    }
    for (int item; (item = take(&q)) >= 0;) {
        work(user, item, res);
        give(&q, item, res);
    }
    if (threaded) {
        pthread_join(th, NULL);
    }
    free(res);
    return ZP_OK;
}
