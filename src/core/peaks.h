/* Exact load peaks (docs/model.md forces; docs/scene-file.md [limits]): every local maximum of each
   load history (a link's felt acceleration, a joint's force) that can exceed that history's peak so
   far, wherever it lies in an integrator step, located by Brent's method on the dense output. */
#ifndef ZP_PEAKS_H
#define ZP_PEAKS_H

#include <gsl/gsl_min.h>

#include "model.h"

#define ZP_PEAKS_MAX (2 * ZP_MAX_LINKS) /* histories: felt g per link, then force per joint */

/* Every history's value at time t inside the current interval into v: from the dense output,
   or with exact set at a located maximum from a state as accurate as the integrator's steps.
   0 on success. The caller's peaks take in what it evaluates. */
typedef int (*zp_peaks_fn)(double t, int exact, double *v, void *user);

typedef struct zp_peaks {
    int nq;                     /* histories */
    double t;                   /* s, where the last interval ended */
    double v[ZP_PEAKS_MAX];     /* their values there */
    double slope[ZP_PEAKS_MAX]; /* their rates there (per s); NAN: unknown (a restart) */
    double best[ZP_PEAKS_MAX];  /* the largest value seen in this run */
    double best_t[ZP_PEAKS_MAX]; /* s, where it was seen (the first time, on a tie) */
    double gap[ZP_PEAKS_MAX];   /* the largest |exact - dense output| met at a maximum */
    double vtmp[ZP_PEAKS_MAX];  /* scratch */
    int q;                      /* the history Brent's method works on */
    zp_peaks_fn f;              /* borrowed, with user, during an interval */
    void *user;
    gsl_min_fminimizer *brent; /* owned */
} zp_peaks;

/* A workspace for nq histories; NULL when out of memory. zp_peaks_free(NULL) is a no-op. */
zp_peaks *zp_peaks_create(int nq);
void zp_peaks_free(zp_peaks *p);
/* A new run: no value seen yet. */
void zp_peaks_reset(zp_peaks *p);
/* The integrator (re)starts at t with values v: the rates there are unknown. */
void zp_peaks_restart(zp_peaks *p, double t, const double *v);
/* The interval from the last end to b (values vb there) just integrated: its maxima located
   through f, which must read the dense output of the interval. */
void zp_peaks_interval(zp_peaks *p, double b, const double *vb, zp_peaks_fn f, void *user);

#endif
