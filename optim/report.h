/* The search's outputs: report.md (report.c), summary.json (summary.c), schedule.ini and
   checkpoint.ini (checkpoint.c). Writers only: every number comes in through zp_report. */
#ifndef ZP_REPORT_H
#define ZP_REPORT_H

#include <stdio.h>

#include "diagnose.h"
#include "robust.h"
#include "search.h"
#include "verify.h"

typedef struct zp_report {
    const zp_scene *sc;            /* borrowed */
    const zp_model *m;             /* borrowed */
    const zp_search_result *res;   /* borrowed */
    const zp_verify *v;            /* borrowed: v->run is the best run at the scene's tolerance */
    const zp_sim *best;            /* borrowed: the workspace of v->run (its kink crossings) */
    const zp_result *study;        /* borrowed, NULL: the scene gives no [drive] forces; else
                                      their run, at the search's options */
    const char *algo;              /* strategy name */
    const char *method;            /* integrator name */
    const char *scene_arg;         /* the scene file as given, NULL: the built-in seed */
    const char *out_dir;
    int figures;                   /* 1: course, energy, angles, loads .png beside the report */
    const zp_sim_opts *search;     /* borrowed: the options the search's runs used */
    const zp_sim_opts *solver;     /* borrowed: those of the best run (v->run) */
    const zp_schedule *shape;      /* borrowed: the kind and bounds res->force fills */
    unsigned long seed;            /* the search's seed and budget, as they ran */
    long max_evals;
    const zp_limits *lim;          /* borrowed: [limits], NULL or all 0: none */
    const zp_box *box;             /* borrowed, NULL: no [robust] */
    const zp_scen_set *set;        /* borrowed with box: the scenarios the answer is held to */
    const zp_robust_info *rinfo;   /* borrowed with box */
    const zp_robust_check *check;  /* borrowed with box: the verification on fresh scenarios */
    const zp_accuracy *acc;        /* borrowed, NULL: no [solver] accuracy; else what the
                                      answer's run (at *solver) met */
    const zp_diagnosis *diag;      /* borrowed, NULL: the answer keeps every fresh scenario */
} zp_report;

/* A schedule file: only [drive] forces (docs/scene-file.md), with comments saying what it is. */
void zp_report_write_schedule(FILE *f, const zp_scene *sc, const zp_schedule *sched,
                              const char *comment);
void zp_report_write_json(FILE *f, const zp_report *r);
/* robust.headroom (docs/commands.md) as one JSON object: factor and limited_by for the whole box
   (null and "" when not searched), breaks_at, safety_factor, and ranges: per varied range. */
void zp_summary_headroom_json(FILE *f, const zp_headroom *h);
/* The plain sentence on convergence: how many polishes reached the best, and whether a larger
   budget is likely to help. */
void zp_report_convergence(char *buf, size_t n, const zp_search_result *s);
void zp_report_write_md(FILE *f, const zp_report *r);
/* What run (of r's scene) breaks first: "death", "a stall", "the margin", a [limits] key, or
   "" when it keeps them all. */
void zp_report_breaks(const zp_report *r, const zp_result *run, char *out, size_t cap);
/* The scenarios the answer fails (report_diag.c): a report.md section, summary.json's value. */
void zp_report_diagnosis_md(FILE *f, const zp_diagnosis *d);
void zp_report_diagnosis_json(FILE *f, const zp_diagnosis *d);

#endif
