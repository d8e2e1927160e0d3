/* What `zipopt bench trade` writes (docs/trade.md): trade.csv, trade.gp (its work-precision
   plot), the tables as text and the study as one JSON object. Writers only. */
#ifndef ZP_OUT_TRADE_H
#define ZP_OUT_TRADE_H

#include <stdio.h>

#include "trade.h"

/* trade.csv: a line per case, method and tolerance. */
void zp_out_trade_csv(FILE *f, const zp_trade_study *st);
/* trade.gp: error of the finish/death time against wall time, a panel per case, a line per
   method, read straight from trade.csv. */
void zp_out_trade_gnuplot(FILE *f);
/* Per case the time error and cost of every configuration; then the fastest configuration
   reaching each target, per case and over all three. */
void zp_out_trade_text(FILE *f, const zp_trade_study *st);
/* The study of scene (its name), each run repeated up to repeats times, as one JSON object. */
void zp_out_trade_json(FILE *f, const zp_trade_study *st, const char *scene, int repeats);

#endif
