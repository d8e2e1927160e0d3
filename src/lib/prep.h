/* Scene file or text and a caller's overrides -> everything a run needs (model, simulator and
   search options, schedule), every problem collected into one list and nothing printed: the
   commands (app/setup.h) print the list, the library (include/zipopt.h) returns it as text. */
#ifndef ZP_PREP_H
#define ZP_PREP_H

#include "sim.h"

/* What a command line may lay over the scene. */
typedef struct zp_overrides {
    const char *schedule; /* --schedule FILE ([drive] forces), or NULL */
    const char *force;    /* --force F1,.. (N per section), or NULL; after the file */
    int has_seed;         /* --seed given: seed replaces the scene's */
    unsigned long seed;   /* --seed, 0 to ULONG_MAX as [optimize] seed */
    long max_evals;       /* --max-evals, <= 0: the scene's */
    int unnamed_ok;       /* the library: the scene need not name a folder (nothing is written) */
} zp_overrides;

#define ZP_OVERRIDES_NONE ((zp_overrides){NULL, NULL, 0, 0, 0, 0})

typedef struct zp_setup {
    zp_scene sc;        /* the scene as read: names, lines and settings for messages */
    zp_model *m;        /* owned */
    zp_sim_opts sim;    /* [solver]: the runs a command shows */
    zp_sim_opts search; /* the search's runs: [optimize] method and rtol (atol = rtol / 100),
                           no trajectory, no load peaks */
    zp_schedule sched;  /* [drive] forces with [drive] min, max as bounds, or the overrides */
    double limit;       /* rad, largest relative joint angle the search allows: death - margin */
    long max_evals;     /* simulations the search may spend */
    unsigned long seed;
} zp_setup;

/* Reads the scene (text when not NULL, named path in messages; else the file path; both NULL:
   the built-in seed scene), builds the model, judges every registry name ([solver] method and
   formulation, [optimize] method) and lays the overrides over the schedule (cmd names the
   command in an override's message). 0 with st filled, or -1 with every problem in d and st
   freed. Free with zp_prep_free. */
int zp_prep_load(const char *cmd, const char *path, const char *text, const zp_overrides *ov,
                 zp_setup *st, zp_diag *d);
void zp_prep_free(zp_setup *st);

#endif
