/* The [limits] judged on a run's result (limit.h). */
#include "limit.h"

#include <math.h>

#include "cable_path.h"
#include "cable_ride.h"

#define KMH (3.6) /* km/h per m/s */

static const char *const limit_names[ZP_LIMIT_COUNT] = {
    "max_g", "max_joint_force", "max_arrival_speed", "max_kink_dv", "g_envelope",
    "min_arrival_speed", "max_drive_power", "max_cable_tension"};
static const char *const limit_units[ZP_LIMIT_COUNT] = {
    "g", "N", "km/h", "m/s", "x its allowance", "km/h", "W", "N"};

const char *zp_limits_name(int i) { return limit_names[i]; }
const char *zp_limits_unit(int i) { return limit_units[i]; }

void zp_limits_from_scene(const zp_scene *sc, zp_limits *l) {
    l->max[ZP_LIMIT_G] = sc->max_g;
    l->max[ZP_LIMIT_JOINT] = sc->max_joint_force;
    l->max[ZP_LIMIT_ARRIVAL] = sc->max_arrival_speed;
    l->max[ZP_LIMIT_KINK_DV] = sc->max_kink_dv;
    l->max[ZP_LIMIT_G_ENVELOPE] = sc->nenv > 0 ? 1 : 0;
    l->max[ZP_LIMIT_MIN_ARRIVAL] = sc->min_arrival_speed;
    l->max[ZP_LIMIT_DRIVE_POWER] = sc->max_drive_power;
    l->max[ZP_LIMIT_CABLE_TENSION] = sc->max_cable_tension;
}

int zp_limits_kept(int i, double v, double max) {
    return i == ZP_LIMIT_MIN_ARRIVAL ? v >= max : v <= max;
}

int zp_limits_any(const zp_limits *l) {
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (l->max[i] > 0) {
            return 1;
        }
    }
    return 0;
}

int zp_limits_need_peaks(const zp_limits *l) {
    return l->max[ZP_LIMIT_G] > 0 || l->max[ZP_LIMIT_JOINT] > 0 ||
           l->max[ZP_LIMIT_G_ENVELOPE] > 0;
}

int zp_limits_reached_in(const zp_result *r, int i) {
    return i != ZP_LIMIT_ARRIVAL || r->outcome == ZP_OUTCOME_FINISHED;
}

/* within this of max_cable_tension, the exact equilibria decide whether it is kept (the
   path's fitted tensions agree with them to about 1e-13) */
#define CABLE_EXACT_BAND 1e-9

/* the largest anchor tension over the x run r visited: from exact equilibria when exact (NaN
   when one fails), else from the path's fitted series (a hundredth of the cost) */
static double anchor_tension(const zp_model *m, const zp_result *r, int exact) {
    if (!exact) {
        return zp_cable_path_anchor_max(m->cable_path, r->x_min, r->x_max);
    }
    double t;
    char why[256];
    zp_cable_ride_anchor_max(zp_cable_paths_cable(m->cable_paths), m->g * m->mtot, r->x_min,
                             r->x_max, &t, why, sizeof why);
    return t;
}

double zp_limits_anchor_tension(const zp_model *m, const zp_result *r) {
    return m->cable_paths ? anchor_tension(m, r, 0) : 0;
}

double zp_limits_cable_floor(const zp_model *m) {
    if (!m->cable_paths) {
        return 0;
    }
    zp_result ride = {.x_min = m->xb[0], .x_max = m->xb[m->nsec]}; /* what every finish visits */
    return anchor_tension(m, &ride, 1);
}

/* zp_limits_reached, the anchor tension only when cable is set (exact) */
static void reached(const zp_model *m, const zp_result *r, int cable, double v[ZP_LIMIT_COUNT]) {
    v[ZP_LIMIT_G] = v[ZP_LIMIT_JOINT] = 0;
    for (int i = 0; i < m->nlink; i++) {
        if (m->g_links >> i & 1) {
            v[ZP_LIMIT_G] = fmax(v[ZP_LIMIT_G], r->peaks.acc_g[i]);
        }
        v[ZP_LIMIT_JOINT] = fmax(v[ZP_LIMIT_JOINT], r->peaks.joint[i]);
    }
    v[ZP_LIMIT_ARRIVAL] = r->outcome == ZP_OUTCOME_FINISHED ? r->v * KMH : 0;
    v[ZP_LIMIT_MIN_ARRIVAL] = v[ZP_LIMIT_ARRIVAL];
    v[ZP_LIMIT_KINK_DV] = r->peaks.kink_dv;
    v[ZP_LIMIT_DRIVE_POWER] = r->drive_peak_power;
    v[ZP_LIMIT_CABLE_TENSION] = cable && m->cable_paths ? anchor_tension(m, r, 1) : 0;
    int w = zp_limits_envelope_worst(m, r);
    v[ZP_LIMIT_G_ENVELOPE] = w < 0 ? 0 : r->env_longest[w] / m->env_s[w];
}

void zp_limits_reached(const zp_model *m, const zp_result *r, double v[ZP_LIMIT_COUNT]) {
    reached(m, r, 1, v);
}

int zp_limits_envelope_worst(const zp_model *m, const zp_result *r) {
    int w = -1;
    for (int l = 0; l < m->nenv; l++) {
        if (w < 0 || r->env_longest[l] / m->env_s[l] > r->env_longest[w] / m->env_s[w]) {
            w = l;
        }
    }
    return w;
}

void zp_limits_judged(const zp_limits *l, const zp_model *m, const zp_result *r,
                      double v[ZP_LIMIT_COUNT]) {
    double cable = l->max[ZP_LIMIT_CABLE_TENSION];
    reached(m, r, 0, v);
    if (cable > 0 && m->cable_paths) {
        /* every run of a search is judged: the fitted tensions, exact near the limit */
        v[ZP_LIMIT_CABLE_TENSION] = anchor_tension(m, r, 0);
        if (!(fabs(v[ZP_LIMIT_CABLE_TENSION] / cable - 1) > CABLE_EXACT_BAND)) {
            v[ZP_LIMIT_CABLE_TENSION] = anchor_tension(m, r, 1);
        }
    }
}

double zp_limits_excess(const zp_limits *l, const zp_model *m, const zp_result *r, int *which) {
    double v[ZP_LIMIT_COUNT];
    zp_limits_judged(l, m, r, v);
    return zp_limits_excess_of(l, v, which);
}

zp_breaks zp_limits_broken(const zp_model *m, const zp_limits *lim, double limit,
                           const zp_result *r, int *which) {
    *which = -1;
    if (r->outcome != ZP_OUTCOME_FINISHED) {
        return r->outcome == ZP_OUTCOME_DIED ? ZP_BREAKS_DEATH : ZP_BREAKS_STALL;
    }
    if (zp_model_angle_used(m, r->max_rel_angle) > limit) {
        return ZP_BREAKS_MARGIN;
    }
    double excess = lim ? zp_limits_excess(lim, m, r, which) : -1;
    return *which >= 0 && excess > 0 ? ZP_BREAKS_LIMIT : ZP_BREAKS_NOTHING;
}

double zp_limits_excess_of(const zp_limits *l, const double v[ZP_LIMIT_COUNT], int *which) {
    double worst = -1;
    *which = -1;
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        /* relative excess past the limit: over a ceiling, under the floor */
        double ex = i == ZP_LIMIT_MIN_ARRIVAL ? 1 - v[i] / l->max[i] : v[i] / l->max[i] - 1;
        if (l->max[i] > 0 && (*which < 0 || ex > worst)) {
            worst = ex;
            *which = i;
        }
    }
    /* a non-finite peak (a broken run) breaks every limit */
    return isfinite(worst) ? worst : 1;
}
