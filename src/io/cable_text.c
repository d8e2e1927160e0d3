/* `check`'s cable printout (cable_text.h): the loads of the riders from the scene's [robust]
   ranges, each rider's values from exact equilibria over the ride (cable_ride.h). */
#include "cable_text.h"

#include <math.h>

#include "cable_ride.h"

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
    print_rider(f, c, "nominal", m->g * m->mtot, x_lo, x_hi);
    int varied = sc->robust && (sc->mass_range[0] != sc->mass_range[1] ||
                                sc->trolley_mass_range[0] != sc->trolley_mass_range[1]);
    if (varied) {
        print_rider(f, c, "lightest", rider_load(m, sc->trolley_mass_range[0], sc->mass_range[0]),
                    x_lo, x_hi);
        print_rider(f, c, "heaviest", rider_load(m, sc->trolley_mass_range[1], sc->mass_range[1]),
                    x_lo, x_hi);
    }
}
