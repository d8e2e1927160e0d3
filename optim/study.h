/* One point of a design study: the search (or one simulation) on a scene, reduced to a row of
   plain numbers that can be sent between processes and written as one CSV line. */
#ifndef ZP_STUDY_H
#define ZP_STUDY_H

#include "drive.h"
#include "scenario.h"
#include "sim.h"

typedef enum { ZP_STUDY_SEARCH, ZP_STUDY_SIMULATE, ZP_STUDY_KIND_COUNT } zp_study_kind;

/* What one point came to. Plain data (no pointers): copied as bytes between ranks. */
typedef struct zp_study_row {
    int failed;         /* 1: the search or simulation could not be done; message says why */
    int found;          /* a schedule (search) or the scene's schedule (simulate) finishes with
                           the margin kept */
    zp_outcome outcome; /* of the answer's run at the scene's tolerance */
    double time;        /* s: finish, death or stall of that run */
    double margin;      /* deg: death_angle minus the largest |relative joint angle| */
    char limit[64];     /* found: the limits active at the answer ("margin", "drive.max", a
                           [limits] key reached within 0.1 %, joined by '+', or "none"); else
                           the first one broken ("death", "t_max", "margin", or the [limits]
                           key exceeded most) */
    double reached[ZP_LIMIT_COUNT]; /* what the answer's run reached of each [limits] quantity
                                       (g, N, km/h, m/s), peaks located exactly, set or not */
    int verified;       /* search: the answer agrees at a 100x tighter tolerance; simulate: 0 */
    long evals;         /* simulations the point spent */
    int np;                            /* the parameters of the scene's kind of schedule */
    double force[ZP_SCHED_MAX_PARAMS]; /* the answer's (or closest candidate's) parameters:
                                          N per section for per-section forces */
    char message[200];             /* why it failed, for the row */
} zp_study_row;

/* Name of a kind as typed after --run ("search", "simulate"); find returns -1 if unknown. */
const char *zp_study_kind_name(zp_study_kind k);
int zp_study_kind_find(const char *name);

/* Runs the point: builds sc's model, then the search over the scene's schedule (its [drive]
   kind and bounds; the [optimize] budget and seed; OpenMP threads inside) with its answer
   re-run at the scene's tolerance and checked 100x tighter, or one simulation of sc's [drive]
   forces. max_time > 0 stops the search after that many seconds of wall time (the row then
   depends on the machine's speed); with 0 the row depends only on sc, never on the
   process or the thread count. A failure (bad model, integrator breakdown, no memory) is a row
   with failed = 1, not an error of the study. */
void zp_study_run(const zp_scene *sc, zp_study_kind kind, double max_time, zp_study_row *row);

#endif
