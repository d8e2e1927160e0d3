/* A command run on every rank of an MPI job, rank 0 speaking for it (mpi_spread.h). */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "mpi_queue.h"
#include "mpi_spread.h"

/* the arguments whose files the ranks compare (a command line has a handful) */
#define AGREE_ARGS 32

/* what one rank sees of the command line: per argument whether it names a regular file here
   and the file's digest, and its first problem in words */
typedef struct agree_rec {
    uint64_t digest[AGREE_ARGS];
    signed char is_file[AGREE_ARGS]; /* 1: a regular file read here, -1: one that cannot be */
    char problem[240];
} agree_rec;

/* FNV-1a over the bytes of the file the argument names: 1 with the digest, 0 when it names no
   regular file here, -1 with why when it names one that cannot be read */
static int digest_arg(const char *arg, uint64_t *h, char *why, size_t n) {
    *h = 1469598103934665603u;
    struct stat st;
    if (stat(arg, &st) || !S_ISREG(st.st_mode)) {
        snprintf(why, n, "%s: %s", arg, errno ? strerror(errno) : "not a regular file");
        return 0;
    }
    FILE *f = fopen(arg, "rb");
    if (!f) {
        snprintf(why, n, "%s: %s", arg, strerror(errno));
        return -1;
    }
    int c;
    while ((c = getc(f)) != EOF) {
        *h = (*h ^ (unsigned char)c) * 1099511628211u;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad) {
        snprintf(why, n, "%s: read error", arg);
    }
    return bad ? -1 : 1;
}

/* every rank reads the same command line and the same bytes in every file it names (a scene,
   a schedule) before any rank does anything else: a file missing on one rank, or different
   there, stops every rank alike (exit 2) with that rank's reason said by rank 0, instead of
   one rank failing alone while the others wait for it in an exchange, or ranks mixing the
   rows of different scenes */
static int inputs_agree(const char *name, int argc, char **argv, const zp_spread *sp) {
    agree_rec *all = calloc((size_t)sp->size, sizeof *all);
    int *count = malloc(sizeof *count * (size_t)sp->size);
    if (!all || !count) {
        free(count);
        sp->allgather(sp->user, NULL, NULL, 0); /* ends the job: out of memory */
        return ZP_EXIT_FAIL;
    }
    agree_rec *mine = &all[sp->rank];
    char why[AGREE_ARGS][200];
    for (int i = 1; i < argc && i <= AGREE_ARGS; i++) {
        errno = 0;
        mine->is_file[i - 1] =
            (signed char)digest_arg(argv[i], &mine->digest[i - 1], why[i - 1], sizeof why[i - 1]);
    }
    for (int r = 0; r < sp->size; r++) {
        count[r] = 1;
    }
    int status = sp->allgather(sp->user, all, count, sizeof *all) ? ZP_EXIT_FAIL : ZP_EXIT_OK;
    /* each rank judges its own copy against rank 0's and every other rank's, all alike */
    for (int i = 0; status == ZP_EXIT_OK && i + 1 < argc && i < AGREE_ARGS; i++) {
        int anywhere = 0;
        for (int r = 0; r < sp->size; r++) {
            anywhere |= all[r].is_file[i] != 0;
        }
        for (int r = 0; anywhere && r < sp->size && !all[sp->rank].problem[0]; r++) {
            if (mine->is_file[i] != 1) {
                snprintf(mine->problem, sizeof mine->problem, "rank %d: %.200s", sp->rank, why[i]);
            } else if (all[r].is_file[i] == 1 && all[r].digest[i] != mine->digest[i]) {
                snprintf(mine->problem, sizeof mine->problem,
                         "rank %d: %.160s differs from rank %d's (same name, other contents)",
                         sp->rank, argv[i + 1], r);
            }
        }
    }
    /* and the verdicts go round once more, so that rank 0 can say every rank's */
    if (status == ZP_EXIT_OK && sp->allgather(sp->user, all, count, sizeof *all)) {
        status = ZP_EXIT_FAIL;
    }
    for (int r = 0; status == ZP_EXIT_OK && r < sp->size; r++) {
        if (all[r].problem[0]) {
            status = ZP_EXIT_USAGE;
        }
    }
    if (status == ZP_EXIT_USAGE && sp->rank == 0) {
        fprintf(stderr, "zipopt %s: the MPI ranks must read the same input:", name);
        for (int r = 0; r < sp->size; r++) {
            if (all[r].problem[0]) {
                fprintf(stderr, " %s;", all[r].problem);
            }
        }
        fputs(" nothing was written\n", stderr);
    }
    free(count);
    free(all);
    return status;
}

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
    int status = sp.size > 1 ? inputs_agree(name, argc, argv, &sp) : ZP_EXIT_OK;
    if (status == ZP_EXIT_OK) {
        status = body(argc, argv, &sp);
    }
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
