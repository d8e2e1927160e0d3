/* The scene description (CONFIG.md): plain data in the file's units, with the line of each key.
   The reader (io/scene_read.h) fills it; the model is built from it. */
#ifndef ZP_SCENE_H
#define ZP_SCENE_H

#include <stddef.h>

#include "diag.h"

#define ZP_MAX_LINKS 8
#define ZP_MAX_SECTIONS 64
#define ZP_EXPR_MAX 256
#define ZP_NAME_MAX 128

typedef struct zp_scene {
    char path[1024];           /* the file this came from, for messages */
    char name[ZP_NAME_MAX];    /* [scene] name, default: the file's stem */
    double gravity;            /* m/s^2 */

    double x_start;                          /* m */
    int nsec;                                /* [course] section lines */
    double x_end[ZP_MAX_SECTIONS];           /* m, right end of each section */
    char expr[ZP_MAX_SECTIONS][ZP_EXPR_MAX]; /* f(x) text of each section */
    int sec_line[ZP_MAX_SECTIONS];           /* line of each section key */

    double trolley_mass; /* kg */

    int nlink;
    double lengths[ZP_MAX_LINKS]; /* m, from the trolley down */
    double masses[ZP_MAX_LINKS];  /* kg */
    int ndamping;                 /* 1 (all joints) or nlink */
    double damping[ZP_MAX_LINKS]; /* N m s/rad */
    double death_angle;           /* deg */

    char direction[16];                /* horizontal | tangent */
    int nforce;                        /* 0 when absent: all forces 0 */
    double forces[ZP_MAX_SECTIONS];    /* N, per section */
    double force_min, force_max;       /* N, search bounds */

    char method[32];      /* integrator name (method registry) */
    char formulation[32]; /* formulation name (formulation registry) */
    double rtol, atol;
    double t_max;     /* s */
    double output_dt; /* s */

    double margin;  /* deg */
    long max_evals; /* simulations the search may spend */
    unsigned long seed;
    char search_method[32]; /* integrator of the search's runs (the answer is rerun with [solver]) */
    double search_rtol;     /* their rtol; atol = rtol / 100 */

    /* lines of keys that later stages judge (0 if absent), for their messages */
    int line_forces, line_method, line_formulation, line_search_method;
} zp_scene;

#endif
