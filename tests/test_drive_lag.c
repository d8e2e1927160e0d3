/* A drive with a response time (docs/model.md "A real drive"): the applied force is a state of
   the simulator that follows the capped schedule, F_a' = (F_s - F_a) / tau, from F_a = 0.
   Independent expectations: a step schedule on a bare trolley gives F_a = F (1 - exp(-t/tau))
   and x = (F/m) (t^2/2 - tau t + tau^2 (1 - exp(-t/tau))) while the section does not change
   (both formulations, every method); under a power cap the trolley's speed and F_a follow the
   three-state ODE of the bare trolley written here and integrated by GSL; the energy balance
   holds with the applied force's work; response = 0 runs bit for bit as no key; the gradients
   of the finish time agree with central differences of whole runs (with and without rolling
   resistance); a trolley held by rolling resistance at the start is released once the drive's
   force has grown (a bad response is refused in test_drive_real's table of bad [drive] lines). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "sens.h"
#include "testutil.h"

/* a bare trolley (one link of negligible mass) on a 300 m course f, the drive as given */
static zp_model *bare(const char *f, const char *drive, zp_scene *sc) {
    char ini[1024];
    snprintf(ini, sizeof ini,
             "[course]\nx_start = 0\nsection = 300 : %s\n[trolley]\nmass = 30\n"
             "[body]\nlengths = 1\nmasses = 1e-6\n[drive]\n%s\n[solver]\noutput_dt = 0.05\n",
             f, drive);
    return tu_model(ini, sc);
}

/* the rows of one run of m under the scene's schedule (the workspace tu_last_sim keeps) */
static const zp_row_store *rows_of(const zp_model *m, const zp_sim_opts *o, const zp_scene *sc,
                                   const zp_result **r) {
    static zp_schedule s;
    s = zp_drive_of_scene(sc);
    *r = tu_run(m, o, &(zp_input){.sched = &s});
    return zp_sim_rows(*tu_last_sim());
}

/* a step of F through the lag on a flat course: F_a and x in closed form, every formulation
   and method */
static void test_step(void) {
    const double F = 200, tau = 0.4, mass = 30 + 1e-6;
    zp_scene sc;
    zp_model *m = bare("0", "forces = 200\nresponse = 0.4", &sc);
    CHECK(m->ndrive == 1 && m->drive_response == tau);
    for (int form = 0; form < ZP_FORM_COUNT; form++) {
        for (int meth = 0; meth < ZP_METHOD_COUNT; meth++) {
            zp_sim_opts o = tu_opts(&sc, 1e-11);
            o.output_dt = 0.05;
            o.formulation = form;
            o.method = meth;
            const zp_result *r;
            const zp_row_store *rows = rows_of(m, &o, &sc, &r);
            CHECK(r->outcome == ZP_OUTCOME_FINISHED && rows->n > 100);
            double worst_f = 0, worst_x = 0, end_f = 0;
            for (int k = 1; k < rows->n; k++) {
                zp_row row;
                zp_row_store_get(rows, k, &row);
                double t = row.t, e = -expm1(-t / tau);
                double x = F / mass * (t * t / 2 - tau * t + tau * tau * e);
                worst_f = fmax(worst_f, fabs(row.f_applied - F * e) / (F * e));
                worst_x = fmax(worst_x, fabs(row.c.q[0] - x) / x);
                end_f = fabs(row.f_applied - F * e) / (F * e); /* the last: the end state */
            }
            printf("step, %s, %s: F_a within %.1e (%.1e at the end), x within %.1e "
                   "(relative)\n",
                   zp_formulation_get(form)->name, zp_method_get(meth)->name, worst_f, end_f,
                   worst_x);
            /* rows between steps are the method's dense output: gsl-rk8pd's steps are long and
               its interpolant cubic in the entries that are not positions (method_gsl.c) */
            CHECK(end_f <= 1e-8);
            CHECK(worst_f <= (meth == ZP_METHOD_GSL_RK8PD ? 1e-6 : 1e-8));
            CHECK(worst_x <= 1e-6); /* the link's 1e-6 kg swings against 30 kg */
        }
    }
    zp_model_free(m);
}

/* the bare trolley down a straight incline of slope -a: along the course s' = v,
   v' = F_a / m + g sin(a), F_a' = (F_s - F_a) / tau, F_s = F capped at P / |v| */
typedef struct incline {
    double mass, g, sin_a, F, P, tau;
} incline;

static int incline_rates(double t, const double y[], double f[], void *params) {
    const incline *c = params;
    (void)t;
    double Fs = fabs(c->F * y[1]) > c->P ? c->P / fabs(y[1]) : c->F;
    f[0] = y[1];
    f[1] = y[2] / c->mass + c->g * c->sin_a;
    f[2] = (Fs - y[2]) / c->tau;
    return GSL_SUCCESS;
}

/* the power cap, then the lag: the run against the ODE above integrated by GSL; the lagging
   force overshoots the cap while the speed grows, and the figures say so */
static void test_cap_then_lag(void) {
    const double slope = 0.1, P = 5000;
    zp_scene sc;
    zp_model *m = bare("-x/10", "direction = tangent\nforces = 2000\nmax = 5000\npower = 5000\n"
                                "response = 0.5",
                       &sc);
    double norm = sqrt(1 + slope * slope);
    incline c = {30 + 1e-6, sc.gravity, slope / norm, 2000, P, 0.5};
    for (int form = 0; form < ZP_FORM_COUNT; form++) {
        zp_sim_opts o = tu_opts(&sc, 1e-11);
        o.output_dt = 0.05;
        o.formulation = form;
        const zp_result *r;
        const zp_row_store *rows = rows_of(m, &o, &sc, &r);
        CHECK(r->outcome == ZP_OUTCOME_FINISHED && rows->n > 50);
        gsl_odeiv2_system sys = {incline_rates, NULL, 3, &c};
        gsl_odeiv2_driver *d =
            gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6, 1e-13, 1e-13);
        double y[3] = {0, 0, 0}, t = 0, worst_v = 0, worst_f = 0, worst_s = 0, over = 0;
        for (int k = 1; k < rows->n; k++) {
            zp_row row;
            zp_row_store_get(rows, k, &row);
            CHECK(gsl_odeiv2_driver_apply(d, &t, row.t, y) == GSL_SUCCESS);
            worst_s = fmax(worst_s, fabs(row.c.q[0] * norm - y[0]) / y[0]);
            worst_v = fmax(worst_v, fabs(row.c.v[0] * norm - y[1]) / y[1]);
            worst_f = fmax(worst_f, fabs(row.f_applied - y[2]) / y[2]);
            over = fmax(over, row.f_applied * row.c.v[0] * norm / P);
        }
        gsl_odeiv2_driver_free(d);
        printf("cap then lag, %s: s within %.1e, v within %.1e, F_a within %.1e; F_a v up to "
               "%.4f P, peak %.4f P, %.2f s of %.2f s at the cap\n",
               zp_formulation_get(form)->name, worst_s, worst_v, worst_f, over,
               r->drive_peak_power / P, r->drive_time_at_cap, r->time);
        CHECK(worst_s <= 1e-7 && worst_v <= 1e-7 && worst_f <= 1e-7);
        CHECK(over > 1.01 && r->drive_peak_power >= over * P * (1 - 1e-9));
        CHECK(r->drive_time_at_cap > 0.5 * r->time && r->drive_time_at_cap < r->time);
        double residual = r->e_final - r->e_initial - r->w_drive + r->w_damp + r->e_impulse;
        CHECK_NEAR(residual / r->w_drive, 0, 1e-7);
    }
    zp_model_free(m);
}

static const char *const seed_course =
    "[course]\nx_start = 0\nsection = 60 : (x/10 - 3)^2 + 1\n"
    "section = 100 : -x/10 + 16\nsection = 140 : -(x/10 - 12)^2 + 10\n"
    "[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 1\n";

static zp_model *seed_with(const char *drive, zp_scene *sc) {
    char ini[2048];
    snprintf(ini, sizeof ini, "%s[drive]\n%s\n", seed_course, drive);
    return tu_model(ini, sc);
}

/* the seed through two kinks with a lag (and a cap): the energy balance holds with the
   applied force's work, in both formulations */
static void test_energy(void) {
    static const char *const drives[] = {
        "forces = 59.6, 500, 480\nresponse = 0.3",
        "forces = 59.6, 500, 480\nresponse = 1.5\npower = 4000",
    };
    for (size_t i = 0; i < sizeof drives / sizeof *drives; i++) {
        zp_scene sc;
        zp_model *m = seed_with(drives[i], &sc);
        zp_schedule s = zp_drive_of_scene(&sc);
        for (int form = 0; form < ZP_FORM_COUNT; form++) {
            zp_sim_opts o = tu_opts(&sc, 1e-10);
            o.formulation = form;
            const zp_result *r = tu_run(m, &o, &(zp_input){.sched = &s});
            double residual = r->e_final - r->e_initial - r->w_drive + r->w_damp + r->e_impulse;
            printf("energy, drive %zu, %s: %s at %.4f s after %d kinks, residual %.1e of the "
                   "drive's %.0f J\n",
                   i + 1, zp_formulation_get(form)->name, zp_sim_outcome_name(r->outcome),
                   r->time, r->ncross, residual / r->w_drive, r->w_drive);
            CHECK(r->ncross == 2);
            CHECK_NEAR(residual / r->w_drive, 0, 1e-6);
        }
        zp_model_free(m);
    }
}

/* response = 0 is no key, bit for bit: the same state, steps and answers */
static void test_zero(void) {
    zp_scene sa, sb;
    zp_model *ma = seed_with("forces = 59.6, 500, 480", &sa);
    zp_model *mb = seed_with("forces = 59.6, 500, 480\nresponse = 0", &sb);
    CHECK(ma->ndrive == 0 && mb->ndrive == 0);
    zp_schedule a = zp_drive_of_scene(&sa), b = zp_drive_of_scene(&sb);
    zp_sim_opts o = tu_opts(&sa, 1e-9);
    zp_result ra = *tu_run(ma, &o, &(zp_input){.sched = &a});
    zp_result rb = *tu_run(mb, &o, &(zp_input){.sched = &b});
    CHECK(ra.outcome == rb.outcome && ra.time == rb.time && ra.x == rb.x && ra.v == rb.v);
    CHECK(ra.w_drive == rb.w_drive && ra.e_final == rb.e_final && ra.steps == rb.steps &&
          ra.rhs_evals == rb.rhs_evals && ra.drive_peak_power == rb.drive_peak_power);
    for (int i = 0; i < 3; i++) {
        CHECK(ra.max_rel_angle[i] == rb.max_rel_angle[i]);
    }
    zp_model_free(ma);
    zp_model_free(mb);
}

/* d time / d p_k through a kink (its impulse, the lag's rate jumping there), without and with
   rolling resistance, against the four-point difference of whole runs at rtol 1e-11 */
static void test_gradient(void) {
    static const char *const physics[] = {"", "[physics]\nrolling = 0.01\n"};
    for (size_t ph = 0; ph < sizeof physics / sizeof *physics; ph++) {
        char ini[1024];
        snprintf(ini, sizeof ini,
                 "[course]\nx_start = 0\nsection = 50 : -x/10 + 10\n"
                 "section = 100 : -x/20 + 7.5\n[trolley]\nmass = 30\n"
                 "[body]\nlengths = 2\nmasses = 10\ndamping = 1\n"
                 "[drive]\nforces = 100, 50\nresponse = 0.5\n%s",
                 physics[ph]);
        zp_scene sc;
        zp_model *m = tu_model(ini, &sc);
        zp_schedule s = zp_drive_of_scene(&sc);
        for (int form = 0; form < ZP_FORM_COUNT; form++) {
            zp_sim_opts o = tu_opts(&sc, 1e-11);
            o.formulation = form;
            zp_sens_result g;
            CHECK(zp_sens_run(m, &o, &s, NULL, &g) == ZP_OK && g.smooth &&
                  g.outcome == ZP_OUTCOME_FINISHED && g.ncross == 1);
            for (int k = 0; k < s.np; k++) {
                double h = 1e-3 * fabs(s.p[k]), T[4];
                static const double at[4] = {2, 1, -1, -2};
                for (int j = 0; j < 4; j++) {
                    zp_schedule q = s;
                    q.p[k] += at[j] * h;
                    const zp_result *r = tu_run(m, &o, &(zp_input){.sched = &q});
                    CHECK(r->outcome == ZP_OUTCOME_FINISHED && r->ncross == 1);
                    T[j] = r->time;
                }
                double dT = (-T[0] + 8 * T[1] - 8 * T[2] + T[3]) / (12 * h);
                double noise = 10 * 1e-11 * (g.time + 1) / h;
                printf("gradient%s, %s, p%d: dT/dp %.10e, differences %.10e (rel %.1e)\n",
                       ph ? " with rolling resistance" : "", zp_formulation_get(form)->name,
                       k + 1, g.dtime[k], dT, fabs(g.dtime[k] - dT) / fabs(dT));
                CHECK(fabs(g.dtime[k] - dT) <= 1e-6 * fabs(dT) + noise);
            }
        }
        zp_model_free(m);
    }
}

/* held by rolling resistance at the start (F_a = 0), the trolley is released as the drive's
   force grows: the hold does not end the run while the force still lags the schedule */
static void test_held_then_released(void) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 100 : 0\n[trolley]\nmass = 30\n"
                           "[body]\nlengths = 1\nmasses = 5\ndamping = 1\n"
                           "[drive]\nforces = 100\nresponse = 2\n[physics]\nrolling = 0.1\n",
                           &sc);
    zp_schedule s = zp_drive_of_scene(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-10);
    const zp_result *r = tu_run(m, &o, &(zp_input){.sched = &s});
    /* released where F_a = mu m g: t = -tau ln(1 - mu m g / F) */
    double release = -2 * log(1 - 0.1 * 35 * sc.gravity / 100);
    printf("held then released: %s at %.4f s (released near %.4f s)\n",
           zp_sim_outcome_name(r->outcome), r->time, release);
    CHECK(r->outcome == ZP_OUTCOME_FINISHED && r->time > release && r->x_min == 0);
    zp_model_free(m);
}

int main(void) {
    test_step();
    test_cap_then_lag();
    test_energy();
    test_zero();
    test_gradient();
    test_held_then_released();
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
