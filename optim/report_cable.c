/* The cable in the search's reports (report_cable.h): the answer's ride over the x it visited,
   from exact equilibria under the nominal rider's load (cable_ride.h, the values simulate
   --json's `cable` gives), and the fresh scenario whose ride loaded the anchors most. */
#include "report_cable.h"

#include <math.h>

#include "cable_ride.h"
#include "out_json.h"

/* the answer's ride into cr: 1, or 0 when an equilibrium failed (why filled) */
static int answer_ride(const zp_answer *a, zp_cable_ride *cr, char *why, size_t whylen) {
    const zp_model *m = a->pb->m;
    const zp_result *r = a->v.run;
    return zp_cable_ride_over(zp_cable_paths_cable(m->cable_paths), m->g * m->mtot, r->x_min,
                              r->x_max, cr, why, whylen) == ZP_OK;
}

/* the fresh scenario with the highest anchor tension, NULL when none was checked */
static const zp_spread_end *population_worst(const zp_answer *a) {
    const zp_robust_check *c = &a->rp.check;
    return a->rp.robust && c->samples > 0 && c->tension_high.sample >= 0 ? &c->tension_high : NULL;
}

void zp_report_cable_text(FILE *f, const zp_answer *a) {
    if (!a->pb->m->cable_paths) {
        return;
    }
    zp_cable_ride cr;
    char why[256];
    if (!answer_ride(a, &cr, why, sizeof why)) {
        fprintf(f, "cable: no equilibrium along the ride: %s\n", why);
        return;
    }
    fprintf(f, "cable: anchor tension at most %.0f N (A %.0f N, B %.0f N)",
            fmax(cr.ta_max, cr.tb_max), cr.ta_max, cr.tb_max);
    const zp_spread_end *w = population_worst(a);
    if (w) {
        fprintf(f, ", the population's worst %.0f N", w->value);
    }
    fprintf(f, "; lowest point %.3f m at x = %.2f m; sag %.3f m at mid-span\n", cr.y_low, cr.x_low,
            cr.sag_mid);
}

void zp_report_cable_md(FILE *f, const zp_answer *a) {
    if (!a->pb->m->cable_paths) {
        return;
    }
    const zp_model *m = a->pb->m;
    const zp_result *r = a->v.run;
    zp_cable_ride cr;
    char why[256];
    fputs("\n## The cable\n\n", f);
    if (!answer_ride(a, &cr, why, sizeof why)) {
        fprintf(f, "No equilibrium of the loaded cable along the ride: %s.\n", why);
        return;
    }
    fprintf(f,
            "The nominal rider (%.1f N with the trolley) over x from %.2f to %.2f m, from the "
            "cable's exact equilibria (it is quasi-static: each value is a function of the "
            "trolley's x):\n\n"
            "| | |\n|---|---|\n"
            "| largest tension at anchor A | %.0f N |\n"
            "| largest tension at anchor B | %.0f N |\n"
            "| largest tension at the trolley | %.0f N |\n"
            "| lowest point | %.3f m at x = %.2f m |\n"
            "| sag below the chord | %.3f m at mid-span, %.3f m at most (x = %.2f m) |\n",
            m->g * m->mtot, r->x_min, r->x_max, cr.ta_max, cr.tb_max, cr.trolley_max, cr.y_low,
            cr.x_low, cr.sag_mid, cr.sag_max, cr.x_sag_max);
    const zp_spread_end *w = population_worst(a);
    if (w) {
        fprintf(f,
                "\nOver the %d fresh scenarios that finished, each rider on their own path: the "
                "highest anchor tension is %.0f N (fresh scenario %d).\n",
                a->rp.check.survived, w->value, w->sample + 1);
    }
}

void zp_report_cable_json(FILE *f, const zp_answer *a) {
    if (!a->pb->m->cable_paths) {
        return;
    }
    zp_cable_ride cr;
    char why[256];
    int ok = answer_ride(a, &cr, why, sizeof why);
    fputs(",\n  \"cable\": {", f);
    zp_out_json_key(f, "anchor_tension_max", ok ? fmax(cr.ta_max, cr.tb_max) : NAN, ", ");
    zp_out_json_key(f, "anchor_a_tension_max", ok ? cr.ta_max : NAN, ", ");
    zp_out_json_key(f, "anchor_b_tension_max", ok ? cr.tb_max : NAN, ", ");
    zp_out_json_key(f, "trolley_tension_max", ok ? cr.trolley_max : NAN, ", ");
    zp_out_json_key(f, "lowest_x", ok ? cr.x_low : NAN, ", ");
    zp_out_json_key(f, "lowest_y", ok ? cr.y_low : NAN, ", ");
    zp_out_json_key(f, "sag_mid", ok ? cr.sag_mid : NAN, ", ");
    /* the fresh scenario that loaded the anchors most: its tension and index (0-based) */
    const zp_spread_end *w = population_worst(a);
    if (w) {
        fputs("\"population_anchor_tension_max\": {", f);
        zp_out_json_key(f, "value", w->value, ", ");
        fprintf(f, "\"sample\": %d}}", w->sample);
    } else {
        fputs("\"population_anchor_tension_max\": null}", f);
    }
}
