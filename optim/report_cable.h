/* The cable in the search's reports (docs/model.md "A cable that sags"): what the answer's ride
   asks of the line and where it runs lowest, and the highest anchor tension of the population.
   Writers only; each writes nothing without [cable]. */
#ifndef ZP_REPORT_CABLE_H
#define ZP_REPORT_CABLE_H

#include <stdio.h>

#include "answer.h"

/* a solved to ZP_ANSWER_REPORTED: the text summary's line, report.md's section, and
   summary.json's "cable" member (with its leading ",\n  "). */
void zp_report_cable_text(FILE *f, const zp_answer *a);
void zp_report_cable_md(FILE *f, const zp_answer *a);
void zp_report_cable_json(FILE *f, const zp_answer *a);

#endif
