/* The brake zone ([brake], docs/model.md "A brake zone") in both formulations against closed
   forms: a trolley with a negligible link coasting on a flat course into an eddy brake keeps
   its speed to the zone and then slows as v = v0 - (c/m) s, s the distance braked (m dv/ds =
   -c), the brake's work 1/2 m (v0^2 - v^2) and the energy audit closed; a friction brake F
   stops it at a constant deceleration F/m and holds it there on the flat, never driving it
   back; sent up a slope inside the zone it stops where g sin(a) + F/m has taken its speed
   and stays there iff F >= m g sin(a), else slides back at g sin(a) - F/m (the stick rule
   of rolling resistance); the finish time's gradient through the zone's ends against
   differences of whole runs; a scene whose zone or forces do not fit is refused naming the file,
   the line and the key. */
#include <string.h>

#include "check.h"
#include "estimate.h"
#include "sens.h"
#include "testutil.h"

#define MASS 30.0
#define V0 10.0
#define EDDY 6.0
#define ZONE 20.0
/* the link's 1e-6 kg against the trolley's 30 kg */
#define NEGLIGIBLE_REL 1e-6
#define G 9.81

static const char *const forms[] = {"lagrange", "newton-euler"};

/* s braked at time t, the trolley entering the zone at ZONE / V0 */
static double braked(double t) {
    double t_in = ZONE / V0;
    return t <= t_in ? 0 : MASS * V0 / EDDY * (1 - exp(-EDDY * (t - t_in) / MASS));
}

static void check_eddy(int formulation) {
    char ini[512];
    snprintf(ini, sizeof ini,
             "[course]\nx_start = 0\nsection = 200 : 5\n[trolley]\nmass = %g\n[body]\n"
             "lengths = 1\nmasses = 1e-6\n[solver]\nt_max = 12\n[brake]\nstart = %g\neddy = %g\n",
             MASS, ZONE, EDDY);
    zp_scene sc;
    zp_model *m = tu_model(ini, &sc);
    CHECK(m->physics == ZP_PHYS_BRAKE && m->nwork == ZP_W_MAX && m->brake_zone[1] == 200);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    o.formulation = formulation;
    zp_chain start;
    zp_state_start(m, m->course, &start);
    start.v[0] = V0;
    double f[1] = {0}, times[] = {1, 3, 6, 11};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched, .start = &start, .sample_t = times, .nsample = 4};
    const zp_result *r = tu_run(m, &o, &in);
    int n;
    const zp_row *smp = zp_sim_samples(*tu_last_sim(), &n);
    CHECK(n == 4 && r->outcome == ZP_OUTCOME_STALLED);
    CHECK_REL(r->brake_speed_in, V0, NEGLIGIBLE_REL); /* it coasts to the zone */
    const zp_arc_peaks *zone = zp_sim_zone_peaks(*tu_last_sim());
    CHECK(zone->visited && zone->acc_g >= r->brake_g_in && r->brake_g_in > 0);
    for (int k = 0; k < n; k++) {
        double s = braked(times[k]), v = V0 - EDDY / MASS * s;
        double x = times[k] <= ZONE / V0 ? V0 * times[k] : ZONE + s;
        CHECK_REL(smp[k].c.q[0], x, NEGLIGIBLE_REL);
        CHECK_REL(smp[k].c.v[0], v, NEGLIGIBLE_REL);
        double work = 0.5 * MASS * (V0 * V0 - v * v);
        CHECK_NEAR(smp[k].w_effect[ZP_EFFECT_W_BRAKE], work, NEGLIGIBLE_REL * MASS * V0 * V0);
    }
    CHECK(fabs(zp_estimate_energy_residual(r)) < 1e-6 * MASS * V0 * V0);
    zp_model_free(m);
}

/* a trolley sent at V0 up the course height(x) (a slope of angle al) through a friction brake
   of grip F from x = 0 */
static const zp_result *run_friction(const char *height, double al, double F, int formulation,
                                     const double *times, int ntimes) {
    char ini[512];
    snprintf(ini, sizeof ini,
             "[course]\nx_start = 0\nsection = 200 : %s\n[trolley]\nmass = %g\n[body]\n"
             "lengths = 1\nmasses = 1e-6\n[solver]\nt_max = 12\n[brake]\nstart = 0\n"
             "friction = %g\n",
             height, MASS, F);
    static zp_scene sc;
    static zp_model *m;
    zp_model_free(m);
    m = tu_model(ini, &sc);
    CHECK(m->stick && m->physics == ZP_PHYS_BRAKE);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    o.formulation = formulation;
    zp_chain start;
    zp_state_start(m, m->course, &start);
    start.v[0] = V0 * cos(al);
    start.v[1] = V0 * sin(al);
    double f[1] = {0};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched, .start = &start, .sample_t = times, .nsample = ntimes};
    return tu_run(m, &o, &in);
}

static void check_friction(int formulation) {
    /* on the flat: a = F/m until it stops at V0^2 m / (2 F), held there */
    const double F = 150, a = F / MASS, times[] = {1};
    const zp_result *r = run_friction("5", 0, F, formulation, times, 1);
    int n;
    const zp_row *smp = zp_sim_samples(*tu_last_sim(), &n);
    CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_HELD_BY_FRICTION);
    CHECK_REL(r->x, V0 * V0 / (2 * a), NEGLIGIBLE_REL);
    CHECK_REL(r->time, V0 / a, NEGLIGIBLE_REL);
    CHECK(n == 1);
    CHECK_REL(smp[0].c.v[0], V0 - a, NEGLIGIBLE_REL);
    CHECK_REL(r->w_effect[ZP_EFFECT_W_BRAKE], 0.5 * MASS * V0 * V0, NEGLIGIBLE_REL);
    CHECK(fabs(zp_estimate_energy_residual(r)) < 1e-6 * MASS * V0 * V0);
    /* uphill: stopped by gravity and the brake together, then held or let slide back */
    const double al = atan(0.2), pull = MASS * G * sin(al);
    for (double grip = 0.5 * pull; grip < 2 * pull; grip += pull) {
        double stop = V0 * V0 / (2 * (G * sin(al) + grip / MASS)),
               t_stop = V0 / (G * sin(al) + grip / MASS);
        double back = G * sin(al) - grip / MASS, later[] = {t_stop + 1};
        r = run_friction("0.2*x", al, grip, formulation, later, 1);
        smp = zp_sim_samples(*tu_last_sim(), &n);
        if (grip >= pull) {
            CHECK(r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_HELD_BY_FRICTION);
            CHECK_REL(r->x, stop * cos(al), NEGLIGIBLE_REL);
        } else {
            CHECK(n == 1);
            CHECK_REL(smp[0].c.q[0], (stop - 0.5 * back) * cos(al), NEGLIGIBLE_REL);
        }
    }
}

/* the finish time of sched on m at options o */
static double finish_time(const zp_model *m, const zp_sim_opts *o, const zp_schedule *sched) {
    const zp_result *r = tu_run(m, o, &(zp_input){.sched = sched});
    CHECK(r->outcome == ZP_OUTCOME_FINISHED);
    return r->time;
}

/* the finish time's gradient (sens.c) through an eddy brake zone: its ends' events carry the
   jump of the rates, against four-point differences of whole runs (h = 1e-3 of the force) */
static void check_gradient(int formulation) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 20 : 10 - x/5\nsection = 60 : 6\n"
                           "[trolley]\nmass = 30\n[body]\nlengths = 1\nmasses = 20\n"
                           "[drive]\nforces = 50, 80\n[brake]\nstart = 30\nend = 50\n"
                           "eddy = 25\n",
                           &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-11);
    o.atol = 1e-13;
    o.formulation = formulation;
    zp_schedule sh = zp_drive_of_scene(&sc);
    zp_sens_result g;
    CHECK(zp_sens_run(m, &o, &sh, NULL, &g) == ZP_OK && g.smooth);
    CHECK_REL(g.time, finish_time(m, &o, &sh), 1e-8);
    for (int k = 0; k < sh.np; k++) {
        double h = 1e-3 * sh.p[k], T[4];
        static const double at[4] = {2, 1, -1, -2};
        for (int j = 0; j < 4; j++) {
            zp_schedule q = sh;
            q.p[k] += at[j] * h;
            T[j] = finish_time(m, &o, &q);
        }
        double dT = (-T[0] + 8 * T[1] - 8 * T[2] + T[3]) / (12 * h);
        CHECK_REL(g.dtime[k], dT, 1e-5);
    }
    zp_model_free(m);
}

/* the scene's text with [brake] keys as given: refused with a message
   naming test.ini, line and key */
static void check_refused(const char *keys, const char *section, int line, const char *key) {
    char ini[512], want[128];
    snprintf(ini, sizeof ini,
             "[course]\nx_start = 0\nsection = 200 : 5\n[trolley]\nmass = 30\n[body]\n"
             "lengths = 1\nmasses = 1\n%s",
             keys);
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(ini, "test.ini", &sc, &d) == ZP_ERR_INPUT);
    snprintf(want, sizeof want, "test.ini:%d: [%s] %s:", line, section, key);
    CHECK(d.n >= 1 && strstr(d.text[0], want) != NULL);
    if (d.n < 1 || !strstr(d.text[0], want)) {
        fprintf(stderr, "want %s, got %s\n", want, d.n ? d.text[0] : "nothing");
    }
}

static void test_refused(void) {
    check_refused("[brake]\nstart = 250\neddy = 10\n", "brake", 10, "start");
    check_refused("[brake]\nstart = -1\neddy = 10\n", "brake", 10, "start");
    check_refused("[brake]\nstart = 150\nend = 210\neddy = 10\n", "brake", 11, "end");
    check_refused("[brake]\nstart = 150\nend = 100\neddy = 10\n", "brake", 11, "end");
    check_refused("[brake]\nstart = 150\neddy = -10\n", "brake", 11, "eddy");
    check_refused("[brake]\nstart = 150\nfriction = -1\n", "brake", 11, "friction");
    check_refused("[brake]\neddy = 10\n", "brake", 9, "start");
    check_refused("[brake]\nstart = 150\nend = 150\neddy = 10\n", "brake", 11, "end");
    check_refused("[brake]\nstart = 200\neddy = 10\n", "brake", 10, "start");
    check_refused("[brake]\nstart = 150\neddy = ten\n", "brake", 11, "eddy");
}

/* a [brake] whose forces are both 0 is off: no work slot, the plain scene's layout */
static void test_off(void) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 200 : 5\n[trolley]\nmass = 30\n"
                           "[body]\nlengths = 1\nmasses = 1\n[brake]\nstart = 150\n",
                           &sc);
    CHECK(sc.brake && m->physics == 0 && m->nwork == ZP_W_EFFECTS && !m->stick);
    zp_model_free(m);
}

int main(void) {
    for (int f = 0; f < 2; f++) {
        check_eddy(zp_formulation_find(forms[f]));
        check_friction(zp_formulation_find(forms[f]));
        check_gradient(zp_formulation_find(forms[f]));
    }
    test_refused();
    test_off();
    return CHECK_DONE();
}
