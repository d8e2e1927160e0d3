/* The work-precision study (docs/trade.md, `zipopt bench trade`): every method over a
   tolerance sweep on three cases of one scene, the error of what users read against a
   reference run by two methods that agree, against wall time and rhs evaluations. */
#ifndef ZP_TRADE_H
#define ZP_TRADE_H

#include "sim.h"

#define ZP_TRADE_NTOL 10         /* rtol 1e-3 .. 1e-12 */
#define ZP_TRADE_REF_RTOL 1e-13  /* the reference runs' tolerance: tighter than the sweep */
#define ZP_TRADE_ATOL_RATIO 1e-2 /* atol = rtol / 100, the scene default's ratio */
#define ZP_TRADE_MAX_IMPULSES 64 /* kink impulses compared per run */
#define ZP_TRADE_NCASE 3
#define ZP_TRADE_NTARGET 3

/* The scene at a surviving schedule, a dying one, and a stiff copy (heavy damping). */
typedef struct zp_trade_case {
    const char *name;
    double force;   /* N, every section */
    double damping; /* N m s/rad, every joint; < 0: the scene's */
    int ref_cvode;  /* the CVODE method of the reference pair, with gsl-rk8pd */
} zp_trade_case;

extern const zp_trade_case zp_trade_cases[ZP_TRADE_NCASE];
/* s, on the finish/death time: the errors the fastest configurations are found for */
extern const double zp_trade_targets[ZP_TRADE_NTARGET];

/* What a user reads from one run, plus its cost. */
typedef struct zp_trade_reading {
    int ok; /* 0: numerical failure */
    zp_outcome outcome;
    int died_link;
    double time, x, v;                     /* s, m, m/s */
    int nimp;                              /* kink crossings */
    double impulse[ZP_TRADE_MAX_IMPULSES]; /* N s */
    double angle[ZP_MAX_LINKS];            /* deg, largest |relative joint angle| */
    double wall;                           /* s, median over repeats */
    long evals, steps, rejected;
    int repeats;
} zp_trade_reading;

/* Errors against the reference; infinite when the outcome or the kinks crossed differ. */
typedef struct zp_trade_errors {
    double time, impulse, angle, x, v; /* s, N s, deg, m, m/s */
} zp_trade_errors;

/* The whole study: per case its reference, then every method at every tolerance. */
typedef struct zp_trade_study {
    double tols[ZP_TRADE_NTOL];
    zp_trade_reading ref[ZP_TRADE_NCASE];
    zp_trade_errors agree[ZP_TRADE_NCASE]; /* the second reference method against the first */
    zp_trade_reading runs[ZP_TRADE_NCASE][ZP_METHOD_COUNT][ZP_TRADE_NTOL];
    zp_trade_errors errs[ZP_TRADE_NCASE][ZP_METHOD_COUNT][ZP_TRADE_NTOL];
} zp_trade_study;

/* The study's tolerances, nothing run yet. */
void zp_trade_init(zp_trade_study *st);
/* Case c on scene base into st: its reference (then on_reference, may be NULL, is told), then
   every method at every tolerance, each run up to repeats times within a second. ZP_OK;
   ZP_ERR_INPUT with the case's scene problems in d; ZP_ERR_NUMERIC when the reference runs
   disagree on the outcome (st->ref[c] and st->agree[c] say how). */
zp_status zp_trade_run(const zp_scene *base, int c, int repeats, zp_trade_study *st,
                       void (*on_reference)(void *user, const zp_trade_study *st, int c),
                       void *user, zp_diag *d);
/* The fastest configuration (*bk method, *bt tolerance; total median wall returned) whose
   finish/death time error is within target on case c, or on all of them (c ==
   ZP_TRADE_NCASE); *bk < 0 when none is. */
double zp_trade_fastest(const zp_trade_study *st, double target, int c, int *bk, int *bt);

#endif
