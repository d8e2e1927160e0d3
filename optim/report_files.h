/* The search's files (docs/commands.md "Files"): report.md, report.html, schedule.ini,
   summary.json and trajectory.csv of one answer, into the command's transaction. */
#ifndef ZP_REPORT_FILES_H
#define ZP_REPORT_FILES_H

#include "tx.h"
#include "report.h"

/* a's files (a solved to ZP_ANSWER_REPORTED, its files at w) into t; 0, or -1 with why in err. */
int zp_report_files_write(zp_tx *t, const zp_answer *a, const zp_report_place *w, char *err,
                          size_t errlen);

#endif
