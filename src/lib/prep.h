/* Scene file or text and a caller's overrides -> the scene's problem (optim/problem.h), every
   problem collected into one list and nothing printed: the commands (app/setup.h) print the
   list, the library (include/zipopt.h) returns it as text. */
#ifndef ZP_PREP_H
#define ZP_PREP_H

#include "problem.h"

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

/* Reads the scene (text when not NULL, named path in messages; else the file path; both NULL:
   the built-in seed scene) into p->sc, builds the problem (zp_problem_build: the model and
   every registry name judged) and lays the overrides over its schedule, seed and budget (cmd
   names the command in an override's message). 0 with p filled, or -1 with every problem in d
   and p freed. Free with zp_problem_free. */
int zp_prep_load(const char *cmd, const char *path, const char *text, const zp_overrides *ov,
                 zp_problem *p, zp_diag *d);

#endif
