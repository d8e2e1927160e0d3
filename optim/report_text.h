/* The search's text summary on stdout (docs/commands.md "the search"): the schedule, its
   outcome and verification, the best constant push, the search's cost, the robustness and
   headroom, the convergence. Writer only; summary.json says the same as JSON (report.h). */
#ifndef ZP_REPORT_TEXT_H
#define ZP_REPORT_TEXT_H

#include <stdio.h>

#include "answer.h"

/* a solved to ZP_ANSWER_REPORTED. */
void zp_report_text_write(FILE *f, const zp_answer *a);

#endif
