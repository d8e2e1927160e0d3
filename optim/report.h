/* The search's outputs: report.md (report.c), summary.json (summary.c), schedule.ini and
   checkpoint.ini (checkpoint.c). Writers only: every number comes from the answer (answer.h). */
#ifndef ZP_REPORT_H
#define ZP_REPORT_H

#include <stdio.h>

#include "answer.h"

/* Where the search's files go: what only the command knows. */
typedef struct zp_report_place {
    const char *scene_arg; /* the scene file as given, NULL: the built-in seed */
    const char *out_dir;
    int figures;           /* 1: course, energy, angles, loads .png beside the report */
} zp_report_place;

/* A schedule file: only [drive] forces (docs/scene-file.md), with comments saying what it is. */
void zp_checkpoint_write_schedule(FILE *f, const zp_scene *sc, const zp_schedule *sched,
                              const char *comment);
/* summary.json's object: a solved to ZP_ANSWER_REPORTED. */
void zp_summary_write_json(FILE *f, const zp_answer *a);
/* robust.headroom (docs/commands.md) as one JSON object: factor and limited_by for the whole box
   (null and "" when not searched), breaks_at, safety_factor, and ranges: per varied range. */
void zp_summary_headroom_json(FILE *f, const zp_headroom *h);
/* The plain sentence on convergence: how many polishes reached the best, and whether a larger
   budget is likely to help. */
void zp_report_convergence(char *buf, size_t n, const zp_answer *a);
/* The sentence on a fallback taken (a->fallback.taken): which ranked schedule failed its
   rerun, why, and what the answer is instead; report.md and the text summary both say it. */
void zp_report_fallback(char *buf, size_t n, const zp_answer *a);
/* report.md: a solved to ZP_ANSWER_REPORTED, its files at w. */
void zp_report_write_md(FILE *f, const zp_answer *a, const zp_report_place *w);
/* What run (of p's model) breaks first: "death", "a stall", "the margin", a [limits] key, or
   "" when it keeps them all. */
void zp_report_breaks(const zp_problem *p, const zp_result *run, char *out, size_t cap);
/* The scenarios the answer fails (report_diag.c): a report.md section, summary.json's value. */
void zp_report_diagnosis_md(FILE *f, const zp_diagnosis *d);
void zp_report_diagnosis_json(FILE *f, const zp_diagnosis *d);

#endif
