/* Headroom by bisection along rays from the nominal: a scenario is the nominal plus s times a
   deviation (force shares, factor - 1 of masses, lengths, trolley and damping, start angles),
   the ray scaled so that s = 1 meets the stated box's face. */
#include "headroom.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "state.h"

#define GROW_CAP 4.0   /* factors past this are not searched: "holds beyond 4x" */
#define BISECT_ITER 14 /* a share of 1e-4 of the bracket */

/* the lines: the force, the four factors (mass, length, trolley, damping), the start angles,
   the wind, then the whole box */
enum { LINE_FORCE = 0, LINE_THETA = 5, LINE_WIND = 6, LINE_BOX = 7 };

static const char *const range_names[ZP_HEADROOM_LINES] = {
    "force error",   "rider mass",  "rider size", "trolley mass",
    "joint damping", "start angle", "wind",       "the whole box"};

const char *zp_headroom_range_name(int range) {
    return range >= 0 && range < ZP_HEADROOM_LINES ? range_names[range] : "";
}

const zp_headroom_line *zp_headroom_inside(const zp_headroom *h) {
    const zp_headroom_line *L = &h->line[ZP_HEADROOM_LINES - 1];
    return L->range >= 0 && L->breaks < 1 ? L : NULL;
}

/* a deviation from the nominal: coordinate k of the force, 4 factors - 1, nlink angles (rad),
   the wind (m/s) */
typedef struct dev {
    double force[ZP_MAX_SECTIONS];
    double fac[4];
    double theta[ZP_MAX_LINKS];
    double wind;
} dev;

/* whether a box varies the range of line l (not the whole box's) */
static int varied(const zp_box *b, int l) {
    return l == LINE_FORCE   ? b->nforce > 0
           : l == LINE_THETA ? b->theta0 >= 0
           : l == LINE_WIND  ? b->wind_dim >= 0
                             : b->dim[l - 1] >= 0;
}

/* the deviation d restricted to line l's range, or whole for the box's line */
static dev restrict_to(const dev *d, int l) {
    dev r;
    memset(&r, 0, sizeof r);
    if (l == LINE_FORCE || l == LINE_BOX) {
        memcpy(r.force, d->force, sizeof r.force);
    }
    for (int q = 0; q < 4; q++) {
        if (l == q + 1 || l == LINE_BOX) {
            r.fac[q] = d->fac[q];
        }
    }
    if (l == LINE_THETA || l == LINE_BOX) {
        memcpy(r.theta, d->theta, sizeof r.theta);
    }
    if (l == LINE_WIND || l == LINE_BOX) {
        r.wind = d->wind;
    }
    return r;
}

/* the largest s with s d inside the stated box (INFINITY: d is zero) */
static double face(const zp_box *b, const dev *d) {
    double s = INFINITY;
    for (int k = 0; k < b->nforce; k++) {
        if (d->force[k] != 0) {
            s = fmin(s, b->force_error / fabs(d->force[k]));
        }
    }
    for (int q = 0; q < 4; q++) {
        double bound = d->fac[q] > 0 ? b->range[q][1] - 1 : b->range[q][0] - 1;
        if (b->dim[q] >= 0 && d->fac[q] != 0 && bound / d->fac[q] > 0) {
            s = fmin(s, bound / d->fac[q]);
        }
    }
    for (int i = 0; b->theta0 >= 0 && i < b->nlink; i++) {
        if (d->theta[i] != 0) {
            s = fmin(s, b->theta_max / fabs(d->theta[i]));
        }
    }
    double wb = d->wind > 0 ? b->wind[1] - b->wind0 : b->wind[0] - b->wind0;
    if (b->wind_dim >= 0 && d->wind != 0 && wb / d->wind > 0) {
        s = fmin(s, wb / d->wind);
    }
    return s;
}

typedef struct ray {
    const zp_objective *ob;
    zp_sim *s;
    zp_result *r;
    zp_schedule sched;
    zp_chain c0;
    dev d;          /* the direction, scaled to meet the stated box's face at factor 1 */
    int alive_only; /* 1: "holds" is finishing alive, whatever the margin and limits */
} ray;

/* whether the answer holds at factor f along the ray; what broke in why */
static int holds_at(ray *ry, double f, char *why, size_t n) {
    const zp_model *nom = ry->ob->m;
    zp_scenario sc;
    zp_scenario_nominal(&sc);
    for (int k = 0; k < nom->nsec; k++) {
        sc.force[k] = 1 + f * ry->d.force[k];
    }
    double *fac[4] = {&sc.mass, &sc.length, &sc.trolley, &sc.damping};
    int physical = 1;
    for (int q = 0; q < 4; q++) {
        *fac[q] = 1 + f * ry->d.fac[q];
        physical &= *fac[q] > 0;
    }
    for (int i = 0; i < nom->nlink; i++) {
        sc.theta[i] = f * ry->d.theta[i];
    }
    sc.wind_set = ry->d.wind != 0;
    sc.wind = nom->wind + f * ry->d.wind;
    if (!physical) {
        snprintf(why, n, "a range reaching 0 %%");
        return 0;
    }
    zp_model m;
    zp_chain start;
    zp_scenario_model(nom, &sc, &m);
    zp_scenario_start(&ry->c0, m.nlink, &sc, &start);
    zp_input in = {.sched = &ry->sched, .force_scale = sc.force, .start = &start};
    zp_eval e;
    zp_objective_eval_run(ry->ob, &m, ry->s, &in, &e, ry->r);
    if (e.failed || e.outcome != ZP_OUTCOME_FINISHED) {
        snprintf(why, n, "%s", e.failed ? "numerical failure" : zp_sim_outcome_name(e.outcome));
        return 0;
    }
    if (ry->alive_only) {
        return 1;
    }
    if (e.angle > ry->ob->limit) {
        snprintf(why, n, "margin");
        return 0;
    }
    int which;
    if (zp_limits_any(&ry->ob->lim) && zp_limits_excess(&ry->ob->lim, &m, ry->r, &which) > 0) {
        snprintf(why, n, "%s", zp_limits_name(which));
        return 0;
    }
    return 1;
}

/* the factor up to which the answer holds along the ray: grown from 1 until it breaks (or the
   cap), or shrunk toward the nominal if it breaks inside the box, then bisected; *holds, the
   first factor found breaking (*breaks, INFINITY: none) and what broke there */
static void search_ray(ray *ry, double *holds, double *breaks, char *what, size_t n) {
    static const double grow[] = {1, 1.25, 1.5, 2, 3, GROW_CAP};
    double lo = 0, hi = INFINITY;
    char why[32] = "", last[32] = "";
    for (size_t g = 0; g < sizeof grow / sizeof *grow; g++) {
        if (!holds_at(ry, grow[g], why, sizeof why)) {
            hi = grow[g];
            memcpy(last, why, sizeof last);
            break;
        }
        lo = grow[g];
    }
    for (int it = 0; isfinite(hi) && it < BISECT_ITER; it++) {
        double mid = 0.5 * (lo + hi);
        if (holds_at(ry, mid, why, sizeof why)) {
            lo = mid;
        } else {
            hi = mid;
            memcpy(last, why, sizeof last);
        }
    }
    *holds = lo;
    *breaks = hi;
    snprintf(what, n, "%s", isfinite(hi) ? last : "");
}

void zp_headroom_find(const zp_objective *ob, const zp_box *b, const zp_box *hold, const double *wu,
                      const zp_sim_opts *so, const double *p, zp_headroom *h) {
    double keep = h->safety_factor;
    memset(h, 0, sizeof *h);
    h->safety_factor = keep;
    for (int l = 0; l < ZP_HEADROOM_LINES; l++) {
        h->line[l].range = -1;
    }
    zp_sim *s = zp_sim_create(ob->m, so);
    static _Thread_local zp_result r;
    if (!s) {
        return;
    }
    /* the worst direction found: the deviation of the held box's point wu */
    dev worst;
    memset(&worst, 0, sizeof worst);
    zp_scenario ws;
    double up[ZP_BOX_MAX];
    for (int c = 0; c < hold->d; c++) {
        up[c] = wu ? wu[c] : 1;
    }
    zp_box_scenario(hold, up, &ws);
    for (int k = 0; k < hold->nforce; k++) {
        worst.force[k] = ws.force[k] - 1;
    }
    double fac[4] = {ws.mass, ws.length, ws.trolley, ws.damping};
    for (int q = 0; q < 4; q++) {
        worst.fac[q] = fac[q] - 1;
    }
    for (int i = 0; hold->theta0 >= 0 && i < hold->nlink; i++) {
        worst.theta[i] = ws.theta[i];
    }
    worst.wind = ws.wind_set ? ws.wind - hold->wind0 : 0;
    ray ry = {ob, s, &r, zp_objective_schedule(ob, p), {{0}, {0}}, worst, 0};
    zp_state_start(ob->m, ob->m->course, &ry.c0);
    for (int l = 0; l < ZP_HEADROOM_LINES; l++) {
        if (l != LINE_BOX && !varied(b, l)) {
            continue;
        }
        dev d = restrict_to(&worst, l);
        double sf = face(b, &d);
        if (!isfinite(sf)) {
            continue; /* the worst point has no deviation in this range */
        }
        for (int k = 0; k < ZP_MAX_SECTIONS; k++) {
            d.force[k] *= sf;
        }
        for (int q = 0; q < 4; q++) {
            d.fac[q] *= sf;
        }
        for (int i = 0; i < ZP_MAX_LINKS; i++) {
            d.theta[i] *= sf;
        }
        d.wind *= sf;
        ry.d = d;
        h->line[l].range = l;
        zp_headroom_line *L = &h->line[l];
        ry.alive_only = 0;
        search_ray(&ry, &L->holds, &L->breaks, L->limited_by, sizeof L->limited_by);
        /* and how much further the rider at least finishes alive */
        ry.alive_only = 1;
        search_ray(&ry, &L->alive, &L->dies, L->ends_by, sizeof L->ends_by);
    }
    zp_sim_free(s);
}
