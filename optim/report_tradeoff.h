/* What `zipopt tradeoff` writes (docs/commands.md "tradeoff"): tradeoff.csv, tradeoff.gp (its
   figure), report.md and the levels' JSON object. Writers only: every number is the levels'. */
#ifndef ZP_REPORT_TRADEOFF_H
#define ZP_REPORT_TRADEOFF_H

#include <stdio.h>

#include "tx.h"
#include "tradeoff.h"

/* tradeoff.csv, tradeoff.gp and report.md of T's finished levels into t (incomplete when a
   level was stopped); 0, or -1 with why in err. */
int zp_report_tradeoff_files(zp_tx *t, const zp_tradeoff *T, char *err, size_t errlen);
/* The finished levels as one JSON object, the CSV's columns by name. */
void zp_report_tradeoff_json(FILE *f, const zp_tradeoff *T);

#endif
