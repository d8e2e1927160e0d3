/* What `zipopt check` prints of a scene (docs/commands.md "check"): the text that describes it
   and its JSON object. Writers only: the model decides what is a kink, the setup what runs. */
#ifndef ZP_OUT_CHECK_H
#define ZP_OUT_CHECK_H

#include <stdio.h>

#include "sim.h"

/* The scene as every command would run it. */
typedef struct zp_out_check {
    const zp_scene *sc;       /* borrowed: as read, names and settings */
    const zp_model *m;        /* borrowed: built from sc */
    const zp_schedule *sched; /* borrowed: [drive] forces with their bounds */
    const zp_sim_opts *sim;   /* borrowed: [solver], with accuracy's pick made */
    long max_evals;           /* the search's budget: the scene's, or the default */
} zp_out_check;

/* The course (sections with f, f', f'' at their ends, boundaries, arcs), body, drive, solver,
   search, optional sections, physics and every key added. */
void zp_out_check_text(FILE *f, const zp_out_check *c);
/* The same as one JSON object on one line. */
void zp_out_check_json(FILE *f, const zp_out_check *c);

#endif
