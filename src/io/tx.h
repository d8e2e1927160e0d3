/* One write-aside transaction per command (docs/commands.md "Files"): every file of the run is made
   in a private hidden folder inside the output folder and moved into place as a set, under a lock
   on the output folder; on a failure or a signal nothing of the run remains. */
#ifndef ZP_OUT_FILE_H
#define ZP_OUT_FILE_H

#include <signal.h>
#include <stdio.h>
#include <sys/types.h>

#include "diag.h"

#define ZP_TX_MAX_OPEN 32  /* files open at once */
#define ZP_TX_MAX_DIRS 32  /* folders one transaction may create */
#define ZP_TX_MAX_CHILD 16 /* helper processes (gnuplot) at once */

typedef struct zp_tx {
    char dir[1024];    /* the output folder, for messages */
    char tmp_name[32]; /* the private folder's name inside it */
    int dirfd, tmpfd;  /* -1 when closed */
    int ndir;          /* folders this transaction created, outermost first */
    int dir_parent[ZP_TX_MAX_DIRS];
    char dir_name[ZP_TX_MAX_DIRS][256];
    int nopen;
    FILE *f[ZP_TX_MAX_OPEN];
    char fname[ZP_TX_MAX_OPEN][256];
    volatile pid_t child[ZP_TX_MAX_CHILD]; /* 0: free slot */
    volatile sig_atomic_t *soft_stop;      /* set by the first SIGINT instead of ending the run */
    char ck_name[64]; /* the checkpoint this run put in place, if ck_ino != 0 */
    dev_t ck_dev;
    ino_t ck_ino;
    char written[4096]; /* after a commit: the names moved into place, comma-separated */
} zp_tx;

/* Blocks SIGINT, SIGTERM, SIGHUP and SIGQUIT in the calling thread (so in every thread it
   or its threads start later) and starts the one thread that takes them: with a transaction
   begun, it cleans up under the transaction lock, then the process dies of the signal. Call
   it first in main, before any thread exists (zp_tx_begin calls it too; threads started
   before then keep the default actions). Once per process; later calls do nothing. */
void zp_tx_signals_start(void);
/* Opens (creating it like mkdir -p) base, following links as the user named it, then the
   plain folder names of sub ("a/b", may be NULL) below it, never following a link there;
   makes the private folder and hands the transaction to the signal thread (see
   zp_tx_signals_start). ZP_ERR_IO with why in err, nothing left behind. */
zp_status zp_tx_begin(zp_tx *t, const char *base, const char *sub, char *err, size_t errlen);
/* With stop set, the first SIGINT only sets *stop (the command then finishes and commits);
   the next one ends the run like SIGTERM. */
void zp_tx_soft_interrupt(zp_tx *t, volatile sig_atomic_t *stop);
/* Creates name (a plain file name) in the private folder, exclusively; NULL with why. For
   tests, ZIPOPT_TEST_FULL=N makes the Nth file opened in the process go to /dev/full, so its
   writes fail as on a full disk. */
FILE *zp_tx_open(zp_tx *t, const char *name, char *err, size_t errlen);
/* Opens the n files names[] in order (zp_tx_open) into f[]; 0, or -1 with why at the first that
   fails. */
int zp_tx_open_set(zp_tx *t, const char *const *names, FILE **f, int n, char *err,
                   size_t errlen);
/* Closes every open file, checking each was written whole; 0, or -1 with why. */
int zp_tx_flush(zp_tx *t, char *err, size_t errlen);
/* The private folder's descriptor, where helper processes work. */
int zp_tx_workdir(const zp_tx *t);
/* Registers a running helper process (killed if the run is ended by a signal); 0 when full. */
int zp_tx_add_child(zp_tx *t, pid_t pid);
void zp_tx_drop_child(zp_tx *t, pid_t pid);
/* Holds off the signal thread's cleanup (a process-wide lock, not recursive) while a step
   must finish whole, such as starting a helper and registering it; any thread may hold it. */
void zp_tx_lock(void);
void zp_tx_unlock(void);
/* In a forked child before exec: the handled signals unblocked, at their default actions. */
void zp_tx_child_signals(void);
/* Writes a file straight into the output folder (made aside, renamed under the lock), for a
   checkpoint kept while the run goes on; removed by the commit or the abort when it is still
   the one this run wrote. 0, or -1 with why. */
int zp_tx_checkpoint(zp_tx *t, const char *name, void (*write)(FILE *f, void *user), void *user,
                     char *err, size_t errlen);
/* Moves every visible regular file of the private folder into the output folder, as a set:
   when one move fails the earlier ones are undone. Then removes the private folder and
   disarms the handler. ZP_OK with t->written set, or ZP_ERR_IO with why; either way the
   transaction is over. */
zp_status zp_tx_commit(zp_tx *t, char *err, size_t errlen);
/* Ends the transaction leaving nothing of it: the private folder, the checkpoint, and the
   folders it created when they are empty. Safe to call when it has ended already. */
void zp_tx_abort(zp_tx *t);

#endif
