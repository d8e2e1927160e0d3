/* A scene file (CONFIG.md) as parsed text: values in the file's units, with the line of each key. */
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

/* Reads and validates a scene file (every CONFIG.md rule). On error fills d and returns
   ZP_ERR_INPUT; sc then holds defaults plus whatever parsed. */
zp_status zp_scene_load(const char *path, zp_scene *sc, zp_diag *d);
/* The same from text in memory; path only names it in messages. */
zp_status zp_scene_load_string(const char *text, const char *path, zp_scene *sc, zp_diag *d);
/* The built-in seed scene (CONFIG.md's example). */
void zp_scene_seed(zp_scene *sc);
/* Lays a schedule file (only [drive] forces) over sc. */
zp_status zp_scene_overlay_schedule(const char *path, zp_scene *sc, zp_diag *d);
/* Parses "a, b, c" (finite decimal numbers, CONFIG.md lists) into at most max doubles;
   returns the count, or -1 with why on an empty or bad item or more than max items. */
int zp_scene_parse_list(const char *text, double *out, int max, char *why, size_t whylen);

#endif
