/* One setup step: a scene file and a command's overrides -> everything a command runs with
   (model, simulator and search options, schedule), every problem reported at once. After
   zp_setup_load nothing edits the scene: commands read the fields below. */
#ifndef ZP_SETUP_H
#define ZP_SETUP_H

#include "sim.h"

/* What a command line may lay over the scene. */
typedef struct zp_overrides {
    const char *schedule; /* --schedule FILE ([drive] forces), or NULL */
    const char *force;    /* --force F1,.. (N per section), or NULL; after the file */
    int has_seed;         /* --seed given: seed replaces the scene's */
    unsigned long seed;   /* --seed, 0 to ULONG_MAX as [optimize] seed */
    long max_evals;       /* --max-evals, <= 0: the scene's */
} zp_overrides;

#define ZP_OVERRIDES_NONE ((zp_overrides){NULL, NULL, 0, 0, 0})

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

/* Loads path (NULL: the built-in seed scene), builds the model, judges every registry name
   ([solver] method and formulation, [optimize] method) and lays the overrides over the
   schedule, collecting every problem; prints them to stderr for `zipopt <cmd>` with "nothing
   was written" and returns -1 (exit 2), or fills st and returns 0. Free with zp_setup_free. */
int zp_setup_load(const char *cmd, const char *path, const zp_overrides *ov, zp_setup *st);
void zp_setup_free(zp_setup *st);

#endif
