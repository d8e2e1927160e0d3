/* Why an answer fails its population: the fresh scenarios it breaks, counted by what breaks
   (death, a stall, the margin, each [limits] key) and by where they lie in each [robust] range,
   and what each limit would have to allow for the answer to keep it there. */
#ifndef ZP_DIAGNOSE_H
#define ZP_DIAGNOSE_H

#include "robust.h"

enum { ZP_FAIL_DIED, ZP_FAIL_STALLED, ZP_FAIL_MARGIN, ZP_FAIL_LIMIT }; /* then one per limit */
#define ZP_FAIL_KINDS (ZP_FAIL_LIMIT + ZP_LIMIT_COUNT)
#define ZP_DIAG_RANGES 6 /* force error, rider mass, rider height, trolley mass, damping, start */

/* One [robust] range split at its middle: the scenarios in its lower half (lighter, smaller,
   a weaker drive, less damping, swung back) and its upper half, and how many of each the
   answer breaks. */
typedef struct zp_diag_range {
    int varied;       /* the box varies it */
    int n[2], bad[2]; /* scenarios in the lower and the upper half; broken among them */
    double edge[3];   /* the range's low end, middle and high end: % of the nominal (the force
                         error: % off the schedule, averaged over the sections), or deg */
} zp_diag_range;

typedef struct zp_diagnosis {
    int samples, broken;
    int by[ZP_FAIL_KINDS];         /* broken scenarios by what breaks first */
    double needed[ZP_LIMIT_COUNT]; /* the largest value reached where that limit broke most:
                                      what it would have to allow (its unit); 0: none broke */
    double margin_deg;             /* the smallest margin left where the margin broke, deg */
    zp_diag_range range[ZP_DIAG_RANGES];
} zp_diagnosis;

/* The name of failure kind k ("died", "margin", "max_g", ..) and of range r ("force error",
   ..), for reports. */
const char *zp_diagnose_kind_name(int k);
const char *zp_diagnose_range_name(int r);

/* Tabulates each[n] (zp_robust_verify_each's verdicts of the answer on the box b, judged by
   ob's margin and limits) into d. */
void zp_diagnose(const zp_box *b, const zp_objective *ob, const zp_robust_worst *each, int n,
                 zp_diagnosis *d);

#endif
