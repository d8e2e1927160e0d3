/* `check`'s cable printout (cable_text.h): the loads of the riders from the scene's [robust]
   ranges, each rider's values from exact equilibria over the ride (cable_ride.h). */
#include "cable_text.h"

#include <math.h>

#include "cable_ride.h"
#include "out_json.h"

/* the load (N) of a rider whose trolley and rider's links are scaled by the percentages */
static double rider_load(const zp_model *m, double trolley_pct, double mass_pct) {
    double mass = m->m0 * trolley_pct / 100;
    for (int i = 0; i < m->nlink; i++) {
        mass += m->mass[i] * (m->scale_links >> i & 1 ? mass_pct / 100 : 1);
    }
    return m->g * mass;
}

static void print_rider(FILE *f, const zp_cable *c, const char *who, double load, double x_lo,
                        double x_hi) {
    zp_cable_ride r;
    char why[256];
    if (zp_cable_ride_over(c, load, x_lo, x_hi, &r, why, sizeof why) != ZP_OK) {
        fprintf(f, "  %-9s %8.1f N: no equilibrium: %s\n", who, load, why);
        return;
    }
    fprintf(f,
            "  %-9s %8.1f N: sag %.3f m at mid-span, %.3f m at most (x = %.1f m); lowest "
            "(%.2f, %.3f) m; end slope %.4f\n"
            "  %-9s             tension max: trolley %.0f N, anchor A %.0f N, anchor B %.0f N\n",
            who, load, r.sag_mid, r.sag_max, r.x_sag_max, r.x_low, r.y_low, r.slope_end, "",
            r.trolley_max, r.ta_max, r.tb_max);
}

/* the riders check shows: the nominal one, and with [robust] mass ranges the lightest and
   heaviest; returns how many */
static int riders(const zp_model *m, const zp_scene *sc, zp_cable_text_rider out[3]) {
    out[0] = (zp_cable_text_rider){"nominal", m->g * m->mtot};
    int varied = sc->robust && (sc->mass_range[0] != sc->mass_range[1] ||
                                sc->trolley_mass_range[0] != sc->trolley_mass_range[1]);
    if (!varied) {
        return 1;
    }
    out[1] = (zp_cable_text_rider){"lightest",
                                   rider_load(m, sc->trolley_mass_range[0], sc->mass_range[0])};
    out[2] = (zp_cable_text_rider){"heaviest",
                                   rider_load(m, sc->trolley_mass_range[1], sc->mass_range[1])};
    return 3;
}

int zp_cable_text_riders(const zp_model *m, const zp_scene *sc, zp_cable_text_rider out[3]) {
    return m->cable_paths ? riders(m, sc, out) : 0;
}

void zp_cable_text_print(FILE *f, const zp_model *m, const zp_scene *sc) {
    if (!m->cable_paths) {
        return;
    }
    const zp_cable *c = zp_cable_paths_cable(m->cable_paths);
    fprintf(f, "cable: A (%g, %g) m to B (%g, %g) m, unstretched length %.6g m, %g N/m, EA %g N\n",
            c->xa, c->ya, c->xb, c->yb, c->length, c->weight, c->ea);
    zp_cable_unloaded u;
    char why[256];
    if (zp_cable_hang(c, &u, why, sizeof why) == ZP_OK) {
        fprintf(f,
                "  unloaded: horizontal tension %.0f N; tension at A %.0f N, at B %.0f N; sag "
                "%.3f m at mid-span; lowest (%.2f, %.3f) m\n",
                u.h, u.ta, u.tb, u.sag_mid, u.x_low, u.y_low);
    } else {
        fprintf(f, "  unloaded: %s\n", why);
    }
    double x_lo = m->xb[0], x_hi = m->xb[m->nsec];
    fprintf(f, "  loaded, over the ride x in [%g, %g] m (sag: below the chord):\n", x_lo, x_hi);
    zp_cable_text_rider r[3];
    int n = riders(m, sc, r);
    for (int i = 0; i < n; i++) {
        print_rider(f, c, r[i].who, r[i].load, x_lo, x_hi);
    }
}

/* one rider's object of check --json's cable.riders (null values where no equilibrium) */
static void json_rider(FILE *f, const zp_cable *c, const zp_cable_text_rider *who, double x_lo,
                       double x_hi) {
    zp_cable_ride r;
    char why[256];
    int ok = zp_cable_ride_over(c, who->load, x_lo, x_hi, &r, why, sizeof why) == ZP_OK;
    fputs("{", f);
    zp_out_json_key_string(f, "rider", who->who, ", ");
    zp_out_json_key(f, "load", who->load, ", ");
    zp_out_json_key(f, "sag_mid", ok ? r.sag_mid : NAN, ", ");
    zp_out_json_key(f, "sag_max", ok ? r.sag_max : NAN, ", ");
    zp_out_json_key(f, "x_sag_max", ok ? r.x_sag_max : NAN, ", ");
    zp_out_json_key(f, "lowest_x", ok ? r.x_low : NAN, ", ");
    zp_out_json_key(f, "lowest_y", ok ? r.y_low : NAN, ", ");
    zp_out_json_key(f, "slope_end", ok ? r.slope_end : NAN, ", ");
    zp_out_json_key(f, "trolley_tension_max", ok ? r.trolley_max : NAN, ", ");
    zp_out_json_key(f, "anchor_a_tension_max", ok ? r.ta_max : NAN, ", ");
    zp_out_json_key(f, "anchor_b_tension_max", ok ? r.tb_max : NAN, "}");
}

void zp_cable_text_json(FILE *f, const zp_model *m, const zp_scene *sc, int n) {
    if (!m->cable_paths) {
        return;
    }
    const zp_cable *c = zp_cable_paths_cable(m->cable_paths);
    fputs(n ? ", " : "", f);
    zp_out_json_key(f, "unstretched_length", c->length, ", \"unloaded\": ");
    zp_cable_unloaded u;
    char why[256];
    if (zp_cable_hang(c, &u, why, sizeof why) == ZP_OK) {
        fputs("{", f);
        zp_out_json_key(f, "horizontal_tension", u.h, ", ");
        zp_out_json_key(f, "anchor_a_tension", u.ta, ", ");
        zp_out_json_key(f, "anchor_b_tension", u.tb, ", ");
        zp_out_json_key(f, "sag_mid", u.sag_mid, ", ");
        zp_out_json_key(f, "lowest_x", u.x_low, ", ");
        zp_out_json_key(f, "lowest_y", u.y_low, "}, ");
    } else {
        fputs("null, ", f); /* a weightless rope has no shape of its own */
    }
    double x_lo = m->xb[0], x_hi = m->xb[m->nsec];
    zp_out_json_key(f, "ride_from", x_lo, ", ");
    zp_out_json_key(f, "ride_to", x_hi, ", \"riders\": [");
    zp_cable_text_rider r[3];
    int nr = riders(m, sc, r);
    for (int i = 0; i < nr; i++) {
        fputs(i ? ", " : "", f);
        json_rider(f, c, &r[i], x_lo, x_hi);
    }
    fputs("]", f);
}
