/* The survival constraint in parts (cons_parts.h). */
#include "cons_parts.h"

int zp_cons_parts_count(const zp_objective *ob) {
    int n = 1;
    for (int i = 0; !ob->set && i < ZP_LIMIT_COUNT; i++) {
        n += ob->lim.max[i] > 0;
    }
    return n;
}

void zp_cons_parts_eval(const zp_objective *ob, const zp_eval *e, const zp_result *r, double *c) {
    int n = zp_cons_parts_count(ob);
    if (n == 1 || e->failed || e->outcome != ZP_OUTCOME_FINISHED) {
        for (int k = 0; k < n; k++) {
            c[k] = e->cons;
        }
        return;
    }
    double v[ZP_LIMIT_COUNT];
    zp_limits_reached(ob->m, r, v);
    /* the fitted tension the objective judges by, not the exact one (100x its cost) */
    v[ZP_LIMIT_CABLE_TENSION] = zp_limits_anchor_tension(ob->m, r);
    c[0] = zp_objective_margin_cons(ob, e);
    for (int i = 0, k = 1; i < ZP_LIMIT_COUNT; i++) {
        double per_unit;
        if (ob->lim.max[i] > 0) {
            c[k++] = zp_objective_limit_cons(ob, i, v[i], &per_unit);
        }
    }
}
