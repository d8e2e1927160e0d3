/* report.md's and summary.json's account of the scenarios an answer fails (diagnose.h): what
   breaks, in which part of each range, and what each broken limit would have to allow. */
#include <math.h>

#include "report.h"

static const char *const below[ZP_DIAG_RANGES] = {"weaker drive",   "lighter riders",
                                                  "smaller riders", "lighter trolley",
                                                  "less damping",   "swung back"};
static const char *const above[ZP_DIAG_RANGES] = {"stronger drive", "heavier riders",
                                                  "larger riders",  "heavier trolley",
                                                  "more damping",   "swung forward"};
static const char *const unit[ZP_DIAG_RANGES] = {" %", " %", " %", " %", " %", " deg"};

void zp_report_diagnosis_md(FILE *f, const zp_diagnosis *d) {
    fprintf(f,
            "\n### Where it fails\n\nThe answer breaks %d of the %d fresh scenarios. What "
            "breaks first in each:\n\n| what breaks | scenarios |\n|---|---|\n",
            d->broken, d->samples);
    for (int k = 0; k < ZP_FAIL_KINDS; k++) {
        if (d->by[k]) {
            fprintf(f, "| %s | %d |\n", zp_diagnose_kind_name(k), d->by[k]);
        }
    }
    fputs("\nBy range, each split at its middle (broken / scenarios; the force error is each "
          "scenario's mean over the sections, the start angle its mean over the links):\n\n"
          "| range | lower half | upper half |\n|---|---|---|\n",
          f);
    for (int r = 0; r < ZP_DIAG_RANGES; r++) {
        const zp_diag_range *g = &d->range[r];
        if (g->varied) {
            fprintf(f, "| %s | %d / %d (%s: %.4g to %.4g%s) | %d / %d (%s: %.4g to %.4g%s) |\n",
                    zp_diagnose_range_name(r), g->bad[0], g->n[0], below[r], g->edge[0], g->edge[1],
                    unit[r], g->bad[1], g->n[1], above[r], g->edge[1], g->edge[2], unit[r]);
        }
    }
    fputs("\nWhat this answer would need to hold them:", f);
    if (d->by[ZP_FAIL_DIED] + d->by[ZP_FAIL_STALLED]) {
        fputs(" another schedule (it dies or stalls in some; no limit can change that);", f);
    }
    if (d->by[ZP_FAIL_MARGIN]) {
        fprintf(f, " a margin of at most %.2f deg;", d->margin_deg);
    }
    for (int l = 0; l < ZP_LIMIT_COUNT; l++) {
        if (d->needed[l] > 0) {
            fprintf(f, " %s of at least %.4g %s;", zp_limits_name(l), d->needed[l],
                    zp_limits_unit(l));
        }
    }
    fputs(" or narrower ranges where the table shows the failures.\n", f);
}

void zp_report_diagnosis_json(FILE *f, const zp_diagnosis *d) {
    fprintf(f, "{\"samples\": %d, \"broken\": %d, \"by\": {", d->samples, d->broken);
    for (int k = 0, n = 0; k < ZP_FAIL_KINDS; k++) {
        if (d->by[k]) {
            fprintf(f, "%s\"%s\": %d", n++ ? ", " : "", zp_diagnose_kind_name(k), d->by[k]);
        }
    }
    fputs("}, \"ranges\": [", f);
    for (int r = 0, n = 0; r < ZP_DIAG_RANGES; r++) {
        const zp_diag_range *g = &d->range[r];
        if (g->varied) {
            fprintf(f,
                    "%s{\"range\": \"%s\", \"edges\": [%.17g, %.17g, %.17g], \"lower\": "
                    "{\"broken\": %d, \"scenarios\": %d}, \"upper\": {\"broken\": %d, "
                    "\"scenarios\": %d}}",
                    n++ ? ", " : "", zp_diagnose_range_name(r), g->edge[0], g->edge[1], g->edge[2],
                    g->bad[0], g->n[0], g->bad[1], g->n[1]);
        }
    }
    fputs("], \"needed\": {", f);
    int n = 0;
    if (d->by[ZP_FAIL_MARGIN]) {
        fprintf(f, "\"margin\": %.17g", d->margin_deg);
        n++;
    }
    for (int l = 0; l < ZP_LIMIT_COUNT; l++) {
        if (d->needed[l] > 0) {
            fprintf(f, "%s\"%s\": %.17g", n++ ? ", " : "", zp_limits_name(l), d->needed[l]);
        }
    }
    fputs("}}", f);
}
