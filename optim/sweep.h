/* A design study's grid (docs/commands.md `zipopt sweep`): the --vary specs, the points, and each
   point's scene as text, so that the reader checks every point by every docs/scene-file.md rule. */
#ifndef ZP_SWEEP_H
#define ZP_SWEEP_H

#include <stddef.h>

#include "study.h"

#define ZP_SWEEP_MAX_VARY 4       /* --vary options in one study */
#define ZP_SWEEP_MAX_POINTS 10000 /* points in one study */

typedef enum {
    ZP_VARY_VALUE, /* the key's value itself */
    ZP_VARY_WHOLE, /* a whole number (max_evals, seed, samples) */
    ZP_VARY_SCALE, /* a list key: every item scaled by the value, a factor */
} zp_vary_kind;

typedef struct zp_sweep_vary {
    char section[16], key[32];
    zp_vary_kind kind;
    double a, b;    /* the range, a <= b (for a list key: factors) */
    int n;          /* values, a and b included (one value: a) */
    char text[128]; /* as typed after --vary, for messages and the checkpoint */
    char unit[16];  /* of the key's values ("kg", "km/h"), "" for a pure number */
    char base[96];  /* the scene's own value text (what a factor scales), "" when not given */
} zp_sweep_vary;

typedef struct zp_sweep {
    int nvary;
    zp_sweep_vary vary[ZP_SWEEP_MAX_VARY]; /* the first varies fastest along the points */
    int npoint;
    zp_study_kind kind;
} zp_sweep;

/* Parses "SECTION.KEY=A:B:N" into v: the key must be one docs/scene-file.md lists as numeric, A <=
   B finite, N >= 1 (and for a whole-number key every value whole). 0, or -1 with why. */
int zp_sweep_vary_parse(const char *text, zp_sweep_vary *v, char *why, size_t whylen);
/* Adds v to s (no key twice, at most ZP_SWEEP_MAX_VARY, at most ZP_SWEEP_MAX_POINTS points
   in all); 0, or -1 with why. */
int zp_sweep_add(zp_sweep *s, const zp_sweep_vary *v, char *why, size_t whylen);
/* The value of vary v at point p (an index over the whole grid). */
double zp_sweep_value(const zp_sweep *s, int v, int p);
/* The name of vary v's CSV column: SECTION.KEY, with "_factor" for a list key. */
void zp_sweep_column(const zp_sweep_vary *v, char *out, size_t cap);
/* "body.masses x0.9, trolley.mass 40": where point p lies, for messages and summaries. */
void zp_sweep_describe(const zp_sweep *s, int p, char *out, size_t cap);
/* x in the fewest digits that read back as x exactly (at most 17 significant). */
void zp_sweep_format(double x, char *out, size_t cap);
#define ZP_SWEEP_LINE_MAX 8192 /* bytes of one `key = value` line the study writes */
/* t with `key = value` in [sec]: the key's line replaced, else added to the section, else the
   section added at the end. A malloc'd text, or NULL (no memory, or a line over
   ZP_SWEEP_LINE_MAX). */
char *zp_sweep_set_text(const char *t, const char *sec, const char *key, const char *value);
/* Notes in each varied key of s the scene text base's own value of it (zp_sweep_vary.base). */
void zp_sweep_note_base(zp_sweep *s, const char *base);
/* Point p's scene: base with each varied key's line replaced (or added to its section, or the
   section added) with the point's value. Returns a malloc'd text, or NULL with why (a list key
   absent from base has nothing to scale; no memory). */
char *zp_sweep_point_text(const zp_sweep *s, const char *base, int p, char *why, size_t whylen);

/* Point p's scene read into sc from its text (zp_sweep_point_text of base), named path in
   messages; 0, or -1 with why in d. */
int zp_sweep_point_scene(const zp_sweep *s, const char *base, const char *path, int p,
                         zp_scene *sc, zp_diag *d);
/* Every point checked by every rule of the scene file before anything runs: its scene read
   (into sc, scratch), its model built and its [solver] judged. The first point with a problem,
   its problems in d (initialised here), or -1 when every point is valid. */
int zp_sweep_check_points(const zp_sweep *s, const char *base, const char *path, zp_scene *sc,
                          zp_diag *d);

#endif
