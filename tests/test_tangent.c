/* Rounded kinks (docs/model.md "Optional effects", kink_radius): f'' jumps where an arc meets its
   sections, so the simulator stops and restarts there (events.c tangent roots) and reads one
   piece of the course per integration (model.c zp_model_track_piece). Independent expectation:
   the converged finish time, where two method families (GSL's rk8pd and CVODE's BDF at rtol
   1e-13) agree; every method at rtol 1e-10 must meet it to 1e-8 s (before: 1.1e-6 s off with
   cvode-adams). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "testutil.h"

#define ARC_TOL 1e-8   /* s at rtol 1e-10: the bound */
#define REF_AGREE 1e-9 /* s: the two references must agree at least this well */

static const char *arc_ini(double radius) {
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "[course]\nx_start = 0\nsection = 60  : (x/10 - 3)^2 + 1\n"
             "section = 100 : -x/10 + 16\nsection = 140 : -(x/10 - 12)^2 + 10\n"
             "[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 1\n"
             "[physics]\nkink_radius = %g\n",
             radius);
    return buf;
}

static double finish(const zp_model *m, const zp_scene *sc, const char *method, double rtol,
                     double force) {
    zp_sim_opts o = tu_opts(sc, rtol);
    o.method = zp_method_find(method);
    double f[3] = {force, force, force};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_FINISHED);
    return r->time;
}

static void check_arcs(double radius, double force) {
    zp_scene sc;
    zp_model *m = tu_model(arc_ini(radius), &sc);
    double ref = finish(m, &sc, "gsl-rk8pd", 1e-13, force);
    CHECK_NEAR(finish(m, &sc, "cvode-bdf", 1e-13, force), ref, REF_AGREE);
    const char *methods[] = {"cvode-adams", "cvode-bdf", "gsl-rk8pd", "gsl-rk4imp"};
    for (int k = 0; k < 4; k++) {
        double t = finish(m, &sc, methods[k], 1e-10, force);
        printf("radius %g m, %g N, %-12s rtol 1e-10: %.12f s, %.2g s off\n", radius, force,
               methods[k], t, fabs(t - ref));
        CHECK_NEAR(t, ref, ARC_TOL);
    }
    zp_model_free(m);
}

int main(void) {
    check_arcs(3, 20);
    check_arcs(10, 20);
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
