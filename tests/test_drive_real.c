/* A real drive (docs/model.md "A real drive"): a profile is linear in x between evenly spaced
   knots and with one knot per section is the constant kind bit for bit, in the force and in a
   whole run; a power P caps the applied force at P / |v|, so a bare trolley on a straight
   incline follows the closed form of m v dv/ds = P / v - m g sin(a) once capped, every row's
   F_applied v stays at or below P, and the energy balance holds with the applied force's work;
   bad [drive] kind, knots, power, response and forces exit 2 naming the file, the line and
   the key. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "testutil.h"

/* the force at the knots, linear between them, the end knots' force a hair past the ends */
static void test_profile_force(void) {
    const double x_end[2] = {10, 30}, f[6] = {0, 100, 40, -20, 20, 60};
    zp_schedule s = zp_drive_profile(2, 3, 0, x_end, f, -100, 200);
    CHECK(s.kind == ZP_SCHED_PROFILE && s.np == 6 && s.knots == 3);
    CHECK(zp_drive_param_section(&s, 2) == 0 && zp_drive_param_section(&s, 3) == 1);
    double from, to;
    zp_drive_param_span(&s, 4, s.xb, &from, &to);
    CHECK(from == 20 && to == 20);
    const struct {
        double x;
        int sec;
        double F;
    } at[] = {{0, 0, 0},   {5, 0, 100},  {2.5, 0, 50}, {7.5, 0, 70},  {10, 0, 40}, {-1, 0, 0},
              {10.5, 0, 40}, {10, 1, -20}, {20, 1, 20}, {25, 1, 40}, {30, 1, 60}, {31, 1, 60}};
    for (size_t i = 0; i < sizeof at / sizeof *at; i++) {
        CHECK_NEAR(zp_drive_force(&s, &(zp_drive_state){1, at[i].x, 3, at[i].sec}), at[i].F,
                   1e-12);
    }
    char why[128];
    zp_schedule r;
    CHECK(zp_drive_parse(&s, "1, 2, 3", &r, why, sizeof why) == -2);
    CHECK(strstr(why, "expected 6 (2 sections x 3 knots)") != NULL);
    CHECK(zp_drive_parse(&s, "1, 2, 3, 4, 5, 6", &r, why, sizeof why) == 0 && r.p[5] == 6);
    CHECK(zp_drive_kind_find("profile") == ZP_SCHED_PROFILE &&
          zp_drive_kind_find("constant") == ZP_SCHED_SECTIONS && zp_drive_kind_find("x") < 0);
}

/* |F| <= P / |v| pushing and braking; no cap at rest or below it */
static void test_cap(void) {
    const double f[2] = {400, -400};
    zp_schedule s = zp_drive_sections(2, f, -500, 500);
    s.power = 2000;
    CHECK(zp_drive_force(&s, &(zp_drive_state){0, 0, 0, 0}) == 400);
    CHECK(zp_drive_force(&s, &(zp_drive_state){0, 0, 4, 0}) == 400);
    CHECK(!zp_drive_capped(&s, &(zp_drive_state){0, 0, 4, 0}));
    CHECK(zp_drive_force(&s, &(zp_drive_state){0, 0, 10, 0}) == 200);
    CHECK(zp_drive_capped(&s, &(zp_drive_state){0, 0, 10, 0}));
    CHECK(zp_drive_force(&s, &(zp_drive_state){0, 0, -10, 0}) == 200);
    CHECK(zp_drive_force(&s, &(zp_drive_state){0, 0, 10, 1}) == -200);
    CHECK(zp_drive_force(&s, &(zp_drive_state){0, 0, -8, 1}) == -250);
}

static const char *const seed_drive = "[drive]\nforces = 59.6, 500, 480\n";
static const char *const seed_drive_k1 = "[drive]\nkind = profile\nknots = 1\n"
                                         "forces = 59.6, 500, 480\n";

/* the seed's course and body with the [drive] given */
static zp_model *seed_with(const char *drive, zp_scene *sc) {
    char ini[2048];
    snprintf(ini, sizeof ini,
             "[course]\nx_start = 0\nsection = 60 : (x/10 - 3)^2 + 1\n"
             "section = 100 : -x/10 + 16\nsection = 140 : -(x/10 - 12)^2 + 10\n"
             "[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\n"
             "damping = 1\n%s",
             drive);
    return tu_model(ini, sc);
}

/* a profile of one knot per section runs as the constant kind, bit for bit */
static void test_one_knot(void) {
    zp_scene sa, sb;
    zp_model *ma = seed_with(seed_drive, &sa), *mb = seed_with(seed_drive_k1, &sb);
    zp_schedule a = zp_drive_of_scene(&sa), b = zp_drive_of_scene(&sb);
    CHECK(a.kind == ZP_SCHED_SECTIONS && b.kind == ZP_SCHED_PROFILE && a.np == 3 && b.np == 3);
    zp_sim_opts o = tu_opts(&sa, 1e-9);
    zp_result ra = *tu_run(ma, &o, &(zp_input){.sched = &a});
    zp_result rb = *tu_run(mb, &o, &(zp_input){.sched = &b});
    CHECK(ra.outcome == rb.outcome && ra.time == rb.time && ra.x == rb.x && ra.v == rb.v);
    CHECK(ra.w_drive == rb.w_drive && ra.e_final == rb.e_final && ra.steps == rb.steps);
    for (int i = 0; i < 3; i++) {
        CHECK(ra.max_rel_angle[i] == rb.max_rel_angle[i]);
    }
    zp_model_free(ma);
    zp_model_free(mb);
}

/* x (m along the course) gained from speed v0 to v under the cap: the integral of
   m v^2 / (P - c v) dv, c = m g sin(a) */
static double capped_distance(double m, double P, double c, double v0, double v) {
    double g0 = -v0 * v0 / (2 * c) - P * v0 / (c * c) - P * P / (c * c * c) * log(P - c * v0);
    double g1 = -v * v / (2 * c) - P * v / (c * c) - P * P / (c * c * c) * log(P - c * v);
    return m * (g1 - g0);
}

/* a bare trolley (its one link of negligible mass) pushed along a straight incline under a power
   cap: once capped its speed follows the closed form; every row keeps F_applied v <= P; the drive
   work balances the energy */
static void test_power_incline(void) {
    const double P = 5000, slope = 0.1, link = 1e-6;
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 300 : x/10\n"
                           "[trolley]\nmass = 30\n[body]\nlengths = 1\nmasses = 1e-6\n"
                           "[drive]\ndirection = tangent\nforces = 2000\nmax = 5000\n"
                           "power = 5000\n[solver]\noutput_dt = 0.05\n",
                           &sc);
    zp_schedule s = zp_drive_of_scene(&sc);
    CHECK(s.power == P);
    zp_sim_opts o = tu_opts(&sc, 1e-11);
    o.output_dt = 0.05;
    zp_sim *sim = zp_sim_create(m, &o);
    zp_result r;
    CHECK(sim && zp_sim_run(m, sim, &(zp_input){.sched = &s}, &r) == ZP_OK);
    CHECK(r.outcome == ZP_OUTCOME_FINISHED);
    const zp_row_store *rows = zp_sim_rows(sim);
    double mass = 30 + link, norm = sqrt(1 + slope * slope);
    double c = mass * sc.gravity * slope / norm;
    double s0 = NAN, v0 = NAN, worst = 0;
    int checked = 0;
    for (int k = 0; k < rows->n; k++) {
        zp_row row;
        zp_row_store_get(rows, k, &row);
        double v = row.c.v[0] * norm, along = row.c.q[0] * norm;
        double F = zp_drive_force(&s, &(zp_drive_state){row.t, row.c.q[0], v, 0});
        CHECK(F * v <= P * (1 + 1e-9));
        if (v < 2 * P / 2000) {
            continue; /* not yet capped (the cap binds past 2.5 m/s) */
        }
        if (isnan(s0)) {
            s0 = along;
            v0 = v;
            continue;
        }
        double want = s0 + capped_distance(mass, P, c, v0, v);
        worst = fmax(worst, fabs(along - want) / along);
        checked++;
    }
    CHECK(checked > 20);
    CHECK_NEAR(worst, 0, 1e-6);
    CHECK_NEAR(r.drive_peak_power / P, 1, 1e-9);
    CHECK(r.drive_time_at_cap > 0.9 * r.time && r.drive_time_at_cap < r.time);
    double residual = r.e_final - r.e_initial - r.w_drive + r.w_damp + r.e_impulse;
    CHECK_NEAR(residual / r.w_drive, 0, 1e-6);
    zp_sim_free(sim);
    zp_model_free(m);
}

/* a profile under a cap on the seed: the energy balance holds with the applied force's work */
static void test_profile_energy(void) {
    zp_scene sc;
    zp_model *m = seed_with("[drive]\nkind = profile\nknots = 3\npower = 4000\n"
                            "forces = 50, 120, 300, 500, 400, 500, 500, 250, 0\n",
                            &sc);
    zp_schedule s = zp_drive_of_scene(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    const zp_result *r = tu_run(m, &o, &(zp_input){.sched = &s});
    CHECK(r->drive_peak_power <= 4000 * (1 + 1e-9) && r->drive_time_at_cap > 0);
    double residual = r->e_final - r->e_initial - r->w_drive + r->w_damp + r->e_impulse;
    CHECK_NEAR(residual / r->w_drive, 0, 1e-6);
    zp_model_free(m);
}

/* bad [drive] input exits 2 naming file, line and key */
static void test_bad_input(void) {
    static const struct {
        const char *drive, *want;
    } cases[] = {
        {"kind = profile\nknots = 0", ":11: [drive] knots:"},
        {"kind = profile\nknots = 33", ":11: [drive] knots:"},
        {"kind = wavy", ":10: [drive] kind:"},
        {"knots = 3", ":10: [drive] knots:"},
        {"power = 0", ":10: [drive] power:"},
        {"power = -100", ":10: [drive] power:"},
        {"kind = profile\nknots = 2\nforces = 1, 2, 3", ":12: [drive] forces:"},
        {"kind = profile\nforces = 1, 2", ":11: [drive] forces:"},
        {"response = -0.1", ":10: [drive] response:"},
        {"response = fast", ":10: [drive] response:"},
    };
    char dir[] = "/tmp/zp_drive_real_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char path[256], cmd[1024], out[8192];
        snprintf(path, sizeof path, "%s/bad%zu.ini", dir, i);
        FILE *f = fopen(path, "w");
        CHECK(f != NULL);
        if (!f) {
            continue;
        }
        fprintf(f, "[course]\nx_start = 0\nsection = 10 : x/5\n[trolley]\nmass = 10\n"
                   "[body]\nlengths = 1\nmasses = 2\n[drive]\n%s\n",
                cases[i].drive);
        fclose(f);
        snprintf(cmd, sizeof cmd, "'%s' check '%s' 2>&1 >/dev/null", ZP_EXE, path);
        CHECK(tu_sh(cmd, out, sizeof out) == 2);
        char want[512];
        snprintf(want, sizeof want, "%s%s", path, cases[i].want);
        if (!strstr(out, want)) {
            fprintf(stderr, "case %zu: want `%s` in:\n%s", i, want, out);
        }
        CHECK(strstr(out, want) != NULL);
        remove(path);
    }
    rmdir(dir);
}

int main(void) {
    test_profile_force();
    test_cap();
    test_one_knot();
    test_power_incline();
    test_profile_energy();
    test_bad_input();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
