/* A g-duration envelope (docs/scene-file.md [limits] g_envelope): how long at a time felt g stays
   above each level, from a run's felt-g history with every crossing of a level located. */
#ifndef ZP_ENVELOPE_H
#define ZP_ENVELOPE_H

#define ZP_ENV_MAX 8 /* levels at most */

/* felt g at time t inside the current interval (the dense output) into *g; 0 on success */
typedef int (*zp_envelope_fn)(double t, double *g, void *user);

typedef struct zp_envelope {
    int n;                      /* levels */
    double level[ZP_ENV_MAX];   /* g */
    double t;                   /* s, where the history was last seen */
    double g;                   /* g there */
    double since[ZP_ENV_MAX];   /* s, start of the excursion above level l under way; NAN: below */
    double longest[ZP_ENV_MAX]; /* s, the longest excursion above each level so far */
} zp_envelope;

/* A new run at (t, g) with n levels (n <= ZP_ENV_MAX). */
void zp_envelope_start(zp_envelope *e, int n, const double *level, double t, double g);
/* The history jumps to g at t (an impulse or restart): a level it jumps across is crossed at t. */
void zp_envelope_jump(zp_envelope *e, double t, double g);
/* The interval from the last time seen to b (g = gb there) just integrated: its midpoint read
   through f, every crossing of a level between the three located by bisection through f. */
void zp_envelope_interval(zp_envelope *e, double b, double gb, zp_envelope_fn f, void *user);
/* The run ends at t: excursions under way end there. */
void zp_envelope_end(zp_envelope *e, double t);

#endif
