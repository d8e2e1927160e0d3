/* A design study's rows as CSV (sweep.csv) and its checkpoint: the same lines, appended and
   flushed as points finish, read back by --resume to the same bits. */
#ifndef ZP_SWEEP_CSV_H
#define ZP_SWEEP_CSV_H

#include <stdio.h>

#include "grid.h"
#include "sweep.h"

/* The header line: point, the varied columns, then the result columns (F1..Fnp last but
   one, message last). */
void zp_sweep_csv_header(FILE *f, const zp_sweep *s, int np);
/* Point p's line. */
void zp_sweep_csv_row(FILE *f, const zp_sweep *s, int p, const zp_study_row *r);
/* Reads a line written by zp_sweep_csv_row (without its newline) into *p and r; -1 when it is
   not one of s's points with np parameters. */
int zp_sweep_csv_parse(const char *line, const zp_sweep *s, int np, int *p, zp_study_row *r);

/* The grid schedule's line ("grid,...", for the checkpoint; np parameters, bits for npoint
   points) and its reading back (-1 when it is not one). */
void zp_sweep_csv_grid(FILE *f, const zp_grid_result *g, int npoint);
int zp_sweep_csv_grid_parse(const char *line, int np, int npoint, zp_grid_result *g);

typedef struct zp_sweep_checkpoint {
    FILE *f;   /* owned, open for appending */
    int dirfd; /* owned (a duplicate): the output folder, where the file lives */
    char path[1100]; /* for messages */
} zp_sweep_checkpoint;

/* Opens checkpoint.csv in the output folder dirfd (named dir in messages), never through a
   link, for the study s of scene text base. With resume, the rows a
   checkpoint of the same study (same scene text, --vary and --run) holds go to rows[p] with
   done[p] = 1 (*ndone counts them), its grid schedule's line to *grid with *grid_done = 1, a
   torn last line (no newline, or not a row) is cut, and new rows follow; a checkpoint
   of another study is ZP_ERR_INPUT. Without resume (or with no checkpoint) it starts afresh.
   ZP_ERR_IO with why in err. */
zp_status zp_sweep_csv_checkpoint_open(zp_sweep_checkpoint *c, int dirfd, const char *dir,
                                   const zp_sweep *s, const char *base, int np, int resume,
                                   zp_study_row *rows, unsigned char *done, int *ndone,
                                   zp_grid_result *grid, int *grid_done, char *err, size_t errlen);
/* Appends point p's row and pushes it to the disk; 0, or -1 when it could not be written. */
int zp_sweep_csv_checkpoint_add(zp_sweep_checkpoint *c, const zp_sweep *s, int p,
                            const zp_study_row *r);
/* Appends the grid schedule's line and pushes it to the disk; 0 or -1. */
int zp_sweep_csv_checkpoint_add_grid(zp_sweep_checkpoint *c, const zp_sweep *s,
                                 const zp_grid_result *g);
/* Closes the file; remove = 1 also deletes it (the study's outputs hold every row). */
void zp_sweep_csv_checkpoint_close(zp_sweep_checkpoint *c, int remove_file);

#endif
