/* The population keys on a case known in closed form: on a straight frictionless slope a chain
   started along the effective gravity moves rigidly with the trolley, which accelerates at
   a = F cos(alpha) / M - g sin(alpha) (M the whole mass), so it arrives at v = sqrt(2 a L).
   scale_links = 2 makes mass_range scale the rider's link 2 only (the lanyard, link 1, stays):
   each scenario's M, hence its arrival speed, follows by hand; min_arrival_speed between the
   light and the heavy rider's speeds is kept by the one and broken by the other, with the
   excess 1 - v / min. wind_range: the scenario at each end is the scene read with that wind.
   objective = slowest: the slowest held finish, by a brute-force loop (the heaviest rider's),
   and in closed form for a bare trolley on a straight slope (the heaviest trolley's time).
   Bad link numbers, envelope pairs, and a wind range without drag are refused at their line. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "robust.h"
#include "testutil.h"

#define G 9.81
#define SPEED_REL 1e-6 /* closed form at rtol 1e-10, as test_sim's K_RTOL allows */
#define KMH 3.6

static const char *const slope =
    "[course]\nx_start = 0\nsection = 200 : 100 - 0.2*x\n"
    "[trolley]\nmass = 5\n[body]\nlengths = 1, 2\nmasses = 1, 70\ndamping = 1\n"
    "[drive]\nforces = 50\n"
    "[limits]\nmin_arrival_speed = %.17g\n"
    "[robust]\nmass_range = 50, 150\nscale_links = 2\n";

/* arrival speed (m/s) of model m pushed by F from the effective-gravity start */
static double arrival(const zp_model *m, const zp_scene *sc, double F, zp_result *out) {
    double alpha = atan(-0.2), M = m->mtot;
    double theta = alpha - atan(F / (M * G));
    zp_chain start = {{0}, {0}};
    start.q[1] = 100;
    for (int i = 0; i < m->nlink; i++) {
        start.q[2 + i] = theta;
    }
    zp_sim_opts o = tu_opts(sc, 1e-10);
    zp_schedule sched = tu_sched(m, &F);
    zp_input in = {.sched = &sched, .start = &start};
    *out = *tu_run(m, &o, &in);
    CHECK(out->outcome == ZP_OUTCOME_FINISHED);
    double a = F * cos(alpha) / M - G * sin(alpha);
    return sqrt(2 * a * 200 / cos(alpha));
}

static void check_population(void) {
    char ini[1024];
    snprintf(ini, sizeof ini, slope, 1.0);
    zp_scene sc;
    zp_model *m = tu_model(ini, &sc);
    CHECK(m->scale_links == 2u);
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    double v[2];
    for (int k = 0; k < 2; k++) {
        double u = k ? 1 : -1; /* the lightest rider, then the heaviest */
        zp_scenario s;
        zp_box_scenario(&b, &u, &s);
        zp_model ms;
        zp_scenario_model(m, &s, &ms);
        CHECK(ms.mass[0] == m->mass[0]); /* the lanyard */
        CHECK_REL(ms.mass[1], m->mass[1] * (k ? 1.5 : 0.5), 1e-15);
        CHECK_REL(ms.mtot, 5 + 1 + 70 * (k ? 1.5 : 0.5), 1e-15);
        zp_result r;
        double want = arrival(&ms, &sc, 50, &r);
        CHECK_REL(r.v, want, SPEED_REL);
        v[k] = r.v;
    }
    CHECK(v[1] < v[0]); /* the heavy rider is the slow one under a horizontal push downhill */

    /* a floor between them: the light rider keeps it, the heavy one breaks it by 1 - v/min */
    double floor_kmh = 0.5 * (v[0] + v[1]) * KMH;
    snprintf(ini, sizeof ini, slope, floor_kmh);
    zp_scene sc2;
    zp_model *m2 = tu_model(ini, &sc2);
    zp_limits lim;
    zp_limits_from_scene(&sc2, &lim);
    CHECK(lim.max[ZP_LIMIT_MIN_ARRIVAL] == floor_kmh);
    zp_box_from_scene(&sc2, m2, &b);
    for (int k = 0; k < 2; k++) {
        double u = k ? 1 : -1;
        zp_scenario s;
        zp_box_scenario(&b, &u, &s);
        zp_model ms;
        zp_scenario_model(m2, &s, &ms);
        zp_result r;
        arrival(&ms, &sc2, 50, &r);
        int which;
        double ex = zp_limits_excess(&lim, &ms, &r, &which);
        CHECK(which == ZP_LIMIT_MIN_ARRIVAL);
        CHECK_NEAR(ex, 1 - v[k] * KMH / floor_kmh, 1e-6);
        CHECK((ex <= 0) == (k == 0));
    }
    zp_model_free(m2);
    zp_model_free(m);
}

/* wind_range: the scenario at each end of the range is the scene read with that [physics]
   wind (the same run, bit for bit), and a headwind arrives slower than a tailwind */
static void check_wind(void) {
    const char *fmt = "[course]\nx_start = 0\nsection = 200 : 100 - 0.2*x\n[trolley]\nmass = 5\n"
                      "[body]\nlengths = 1, 2\nmasses = 1, 70\ndamping = 1\n[drive]\nforces = 50\n"
                      "[physics]\ndrag_area = 0.05, 0.05, 0.6\nwind = %g\n"
                      "[robust]\nwind_range = -3, 3\n";
    char ini[1024];
    snprintf(ini, sizeof ini, fmt, 0.0);
    zp_scene sc;
    zp_model *m = tu_model(ini, &sc);
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    CHECK(b.d == 1 && b.wind_dim == 0);
    zp_sim_opts o = tu_opts(&sc, 1e-9);
    double f = 50, speed[2];
    zp_schedule sched = tu_sched(m, &f);
    for (int k = 0; k < 2; k++) {
        double u = k ? 1 : -1;
        zp_scenario s;
        zp_box_scenario(&b, &u, &s);
        zp_model ms;
        zp_scenario_model(m, &s, &ms);
        CHECK(ms.wind == (k ? 3 : -3));
        zp_input in = {.sched = &sched};
        zp_result a = *tu_run(&ms, &o, &in);
        snprintf(ini, sizeof ini, fmt, k ? 3.0 : -3.0);
        zp_scene sw;
        zp_model *mw = tu_model(ini, &sw);
        zp_result want = *tu_run(mw, &o, &in);
        CHECK(a.outcome == want.outcome && a.time == want.time && a.v == want.v);
        speed[k] = a.v;
        zp_model_free(mw);
    }
    CHECK(speed[0] < speed[1]);
    zp_model_free(m);
}

/* objective = slowest: a survivor's objective is the slowest finish over the nominal run and
   every held scenario (a brute-force loop over them), and under a horizontal push downhill
   that is the heaviest rider's; objective = nominal keeps the nominal finish */
static void check_slowest(void) {
    char ini[1024];
    snprintf(ini, sizeof ini, slope, 1.0);
    zp_scene sc;
    zp_model *m = tu_model(ini, &sc);
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    zp_scen_set set;
    CHECK(zp_scen_set_build(&set, &b, m, 6, 1) == ZP_OK);
    zp_sim_opts o = tu_opts(&sc, 1e-9);
    zp_objective ob = tu_objective(m, &sc, &o);
    ob.set = &set;
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    double f = 50;
    zp_eval nominal, slow;
    zp_objective_eval(&ob, s, &f, &nominal, &r);
    ob.slowest = 1;
    zp_objective_eval(&ob, s, &f, &slow, &r);
    CHECK(zp_objective_feasible(&slow) && nominal.obj == nominal.time);
    zp_schedule sched = tu_sched(m, &f);
    double want = nominal.time, heaviest = 0, t_heaviest = 0;
    for (int j = 0; j < set.n; j++) {
        zp_input in = {.sched = &sched, .force_scale = set.sc[j].force, .start = &set.start[j]};
        zp_eval e;
        zp_objective_eval_run(&ob, &set.m[j], s, &in, &e, &r);
        want = fmax(want, e.obj);
        if (set.m[j].mtot > heaviest) {
            heaviest = set.m[j].mtot;
            t_heaviest = e.obj;
        }
    }
    CHECK(slow.obj == want);
    CHECK(slow.obj == t_heaviest && slow.obj > nominal.obj);
    zp_sim_free(s);
    zp_scen_set_free(&set);
    zp_model_free(m);
}

/* objective = slowest in closed form: a trolley with a negligible chain (1 mg, 1 m links) on
   the straight slope y = 100 - 0.2 x, pushed horizontally by F: (1 + 0.04) x'' = F / m0 +
   0.2 g, so the run of x over 200 m takes T = sqrt(2 * 200 / x''); the heaviest trolley of
   trolley_mass_range is the slowest, and the slowest objective is its T */
static void check_slowest_closed_form(void) {
    const char *ini = "[course]\nx_start = 0\nsection = 200 : 100 - 0.2*x\n"
                      "[trolley]\nmass = 20\n[body]\nlengths = 1, 1\n"
                      "masses = 1e-6, 1e-6\ndamping = 1e-6\n[drive]\nforces = 30\n"
                      "[robust]\ntrolley_mass_range = 80, 150\n";
    zp_scene sc;
    zp_model *m = tu_model(ini, &sc);
    zp_box b;
    zp_box_from_scene(&sc, m, &b);
    zp_scen_set set;
    CHECK(zp_scen_set_build(&set, &b, m, 4, 1) == ZP_OK);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    zp_objective ob = tu_objective(m, &sc, &o);
    ob.set = &set;
    ob.slowest = 1;
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    double f = 30;
    zp_eval slow;
    zp_objective_eval(&ob, s, &f, &slow, &r);
    double acc = (f / (20 * 1.5) + 0.2 * G) / 1.04;
    double want = sqrt(2 * 200 / acc);
    CHECK(zp_objective_feasible(&slow));
    CHECK(fabs(slow.obj - want) <= 1e-6 * want);
    zp_sim_free(s);
    zp_scen_set_free(&set);
    zp_model_free(m);
}

/* g_links and scale_links take link numbers 1..nlink */
static void check_bad_links(void) {
    const char *bad[] = {"[limits]\ng_links = 3\n", "[robust]\nscale_links = 1.5\n",
                         "[limits]\ng_envelope = 6:1, 4\n", "[robust]\nwind_range = -3, 3\n"};
    const char *keys[] = {"g_links", "scale_links", "g_envelope", "wind_range"};
    for (int k = 0; k < 4; k++) {
        char ini[1024];
        snprintf(ini, sizeof ini,
                 "[course]\nx_start = 0\nsection = 200 : 100 - 0.2*x\n[trolley]\nmass = 5\n"
                 "[body]\nlengths = 1, 2\nmasses = 1, 70\n%s",
                 bad[k]);
        zp_scene sc;
        zp_diag d;
        zp_diag_init(&d);
        CHECK(zp_scene_load_string(ini, "bad.ini", &sc, &d) != ZP_OK);
        char msg[4096] = "";
        FILE *f = fmemopen(msg, sizeof msg, "w");
        zp_diag_print(&d, f);
        fclose(f);
        CHECK(strstr(msg, "bad.ini:") && strstr(msg, keys[k]));
    }
}

int main(void) {
    check_population();
    check_wind();
    check_slowest();
    check_slowest_closed_form();
    check_bad_links();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
