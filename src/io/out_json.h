/* JSON: the pieces every writer builds with (numbers that round-trip, escaped strings), and the
   object of one simulation (docs/commands.md "simulate --json"). Writers only, no decisions. */
#ifndef ZP_OUT_JSON_H
#define ZP_OUT_JSON_H

#include <stdio.h>

#include "accuracy.h"
#include "estimate.h"
#include "scenario.h"
#include "sens.h"
#include "sim.h"

/* What the run was, echoed so a JSON file stands on its own. */
typedef struct zp_run_meta {
    const char *scene;       /* scene name */
    const char *method;      /* integrator name */
    const char *formulation; /* formulation name */
    double rtol, atol;
    const zp_schedule *sched; /* borrowed: the drive schedule that ran */
    const zp_estimate *estimate; /* borrowed; NULL: no error estimate was made */
    const double *unreached;     /* s: asked sample times after the end of the run */
    int nunreached;
    const zp_limits *lim;        /* borrowed; NULL: no [limits] (each reached value still shown) */
    const zp_accuracy *accuracy; /* borrowed; NULL: no accuracy was requested */
    const zp_sens_result *gradient; /* borrowed; NULL: no gradient was asked for */
} zp_run_meta;

/* A number that round-trips, or null if it is not finite. */
void zp_out_json_number(FILE *f, double v);
/* A string with JSON escapes. */
void zp_out_json_string(FILE *f, const char *s);
/* "key": v (a number as zp_out_json_number, or the string s), then sep. */
void zp_out_json_key(FILE *f, const char *key, double v, const char *sep);
void zp_out_json_key_string(FILE *f, const char *key, const char *s, const char *sep);
/* [v[0] * scale, ..] of n numbers. */
void zp_out_json_list(FILE *f, const double *v, int n, double scale);
/* The [limits] object: for each limit, what r reached and the limit (null when off, lim may
   be NULL), and whether it was kept. */
void zp_out_json_limits(FILE *f, const zp_model *m, const zp_result *r, const zp_limits *lim);
/* The whole object of r, the last run of workspace s (its samples and kink crossings). */
void zp_out_json_result(FILE *f, const zp_model *m, const zp_result *r, const zp_sim *s,
                        const zp_run_meta *meta);

#endif
