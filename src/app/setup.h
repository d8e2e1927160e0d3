/* One setup step for the commands: a scene file and a command's overrides -> the scene's problem
   (optim/problem.h, through lib/prep.h), every problem printed at once. After zp_setup_load
   nothing edits the scene: commands read the fields of zp_problem. */
#ifndef ZP_SETUP_H
#define ZP_SETUP_H

#include "prep.h"

/* Loads path (NULL: the built-in seed scene) as zp_prep_load does; prints every problem to
   stderr for `zipopt <cmd>` with "nothing was written" and returns -1 (exit 2), or fills p
   and returns 0. Free with zp_setup_free. */
int zp_setup_load(const char *cmd, const char *path, const zp_overrides *ov, zp_problem *p);
void zp_setup_free(zp_problem *p);

#endif
