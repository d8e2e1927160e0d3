/* The failures of an answer on fresh scenarios, tabulated (diagnose.h). */
#include "diagnose.h"

#include <math.h>
#include <string.h>

#define DEG (180 / M_PI)

const char *zp_diagnose_kind_name(int k) {
    static const char *const fixed[ZP_FAIL_LIMIT] = {"died", "stalled", "margin"};
    return k < ZP_FAIL_LIMIT ? fixed[k] : zp_limits_name(k - ZP_FAIL_LIMIT);
}

const char *zp_diagnose_range_name(int r) {
    static const char *const names[ZP_DIAG_RANGES] = {"force error",  "rider mass", "rider size",
                                                      "trolley mass", "damping",    "start angle"};
    return names[r];
}

/* the mean of u over coordinates [first, first + n): where the scenario lies in that range */
static double mean(const double *u, int first, int n) {
    double s = 0;
    for (int i = 0; i < n; i++) {
        s += u[first + i];
    }
    return s / n;
}

/* which kind broke w, or -1 when the answer keeps everything there */
static int kind_of(const zp_robust_worst *w, double margin_deg) {
    if (w->outcome != ZP_OUTCOME_FINISHED) {
        return w->outcome == ZP_OUTCOME_DIED ? ZP_FAIL_DIED : ZP_FAIL_STALLED;
    }
    if (w->margin_deg < margin_deg) {
        return ZP_FAIL_MARGIN;
    }
    return w->limit >= 0 && w->excess > 0 ? ZP_FAIL_LIMIT + w->limit : -1;
}

void zp_diagnose(const zp_box *b, const zp_objective *ob, const zp_robust_worst *each, int n,
                 zp_diagnosis *d) {
    memset(d, 0, sizeof *d);
    d->samples = n;
    d->margin_deg = INFINITY;
    double margin = (ob->m->phi_max - ob->limit) * DEG;
    /* each range's coordinates in the box: [first, first + count) */
    int first[ZP_DIAG_RANGES] = {0, b->dim[0], b->dim[1], b->dim[2], b->dim[3], b->theta0};
    int count[ZP_DIAG_RANGES] = {b->nforce, 1, 1, 1, 1, b->nlink};
    for (int r = 0; r < ZP_DIAG_RANGES; r++) {
        zp_diag_range *g = &d->range[r];
        g->varied = first[r] >= 0 && count[r] > 0;
        double lo = r == 0 ? -100 * b->force_error : r == 5 ? -b->theta_max * DEG : 0, hi = -lo;
        if (r >= 1 && r <= 4) {
            lo = 100 * b->range[r - 1][0];
            hi = 100 * b->range[r - 1][1];
        }
        g->edge[0] = lo;
        g->edge[1] = (lo + hi) / 2;
        g->edge[2] = hi;
    }
    for (int i = 0; i < n; i++) {
        const zp_robust_worst *w = &each[i];
        int k = kind_of(w, margin);
        if (k >= 0) {
            d->broken++;
            d->by[k]++;
        }
        if (k == ZP_FAIL_MARGIN) {
            d->margin_deg = fmin(d->margin_deg, w->margin_deg);
        } else if (k >= ZP_FAIL_LIMIT) {
            int l = k - ZP_FAIL_LIMIT;
            d->needed[l] = fmax(d->needed[l], (1 + w->excess) * ob->lim.max[l]);
        }
        for (int r = 0; r < ZP_DIAG_RANGES; r++) {
            if (d->range[r].varied) {
                int side = mean(w->u, first[r], count[r]) >= 0;
                d->range[r].n[side]++;
                d->range[r].bad[side] += k >= 0;
            }
        }
    }
}
