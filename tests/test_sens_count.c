/* The sensitivity run counts the work its integrator really did: every evaluation of the
   augmented rates is counted here through a link-time wrapper (-Wl,--wrap=zp_sens_rhs) and
   must equal the run's rhs_evals, and its step count must be what its step budget sees (the
   run passes with max_steps = its steps and fails with one fewer). The seed meets joint-angle
   extremum roots, which do not restart the integrator. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "sens.h"
#include "testutil.h"

int __real_zp_sens_rhs(double t, const double *ya, double *yd, void *user);
int __wrap_zp_sens_rhs(double t, const double *ya, double *yd, void *user);

static long calls;

int __wrap_zp_sens_rhs(double t, const double *ya, double *yd, void *user) {
    calls++;
    return __real_zp_sens_rhs(t, ya, yd, user);
}

static void scene(const char *name) {
    char path[512];
    snprintf(path, sizeof path, "%s/config/%s", ZP_SOURCE_DIR, name);
    zp_scene sc;
    zp_model *m = tu_model_file(path, &sc);
    CHECK(m != NULL);
    if (!m) {
        return;
    }
    zp_sim_opts o = tu_opts(&sc, 1e-9);
    zp_limits lim;
    zp_limits_from_scene(&sc, &lim);
    zp_schedule sh = zp_drive_of_scene(&sc);
    zp_sens_result r, again;
    calls = 0;
    CHECK(zp_sens_run(m, &o, &sh, &lim, &r) == ZP_OK);
    printf("%s: %ld steps, %ld augmented rate evaluations counted, %ld made, %ld plain rates\n",
           name, r.steps, r.rhs_evals, calls, r.rates);
    CHECK(r.rhs_evals == calls);
    CHECK(r.steps > 0 && r.rates >= r.rhs_evals);
    o.max_steps = r.steps;
    CHECK(zp_sens_run(m, &o, &sh, &lim, &again) == ZP_OK);
    CHECK(again.steps == r.steps && again.time == r.time);
    o.max_steps = r.steps - 1;
    CHECK(zp_sens_run(m, &o, &sh, &lim, &again) == ZP_ERR_NUMERIC);
    zp_model_free(m);
}

int main(void) {
    scene("seed.ini");
    scene("seed_profile.ini");
    scene("multi4.ini");
    return CHECK_DONE();
}
