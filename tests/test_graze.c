/* A grazing death (src/core/graze.c): a joint that passes the death angle and comes back inside
   one integrator step is a death by every method, at the time it first reached the angle.
   Independent expectations: the same run with the death angle out of reach takes the same steps
   up to there, so its dense output at the reported time must show the joint exactly at the
   death angle, and every earlier trajectory row inside it; and the seed at a constant 12.0869 N,
   whose toe joint grazes 180 deg, dies by every method. Death angles per joint: each joint
   dies at its own, and the margin judged is the smallest of each joint's. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "testutil.h"

#define DEG (180.0 / M_PI)
/* deg the death angle is set below a finishing run's largest angle: a peak this shallow stays
   past the angle for far less than one step at rtol 1e-6 */
#define GRAZE_DEPTH_DEG 1e-4
/* rad: the reported time is bisected on the dense output to the last bit of t; the angle there
   moves by its rate (~1 rad/s) times that */
#define AT_ANGLE_TOL 1e-9

static const char *const methods[] = {"cvode-adams", "cvode-bdf", "gsl-rk8pd", "gsl-rk4imp"};

static const char *seed_ini_text(const char *death) {
    static char buf[1024];
    snprintf(buf, sizeof buf,
             "[course]\nx_start = 0\nsection = 60  : (x/10 - 3)^2 + 1\n"
             "section = 100 : -x/10 + 16\nsection = 140 : -(x/10 - 12)^2 + 10\n"
             "[trolley]\nmass = 30\n[body]\nlengths = 5, 5, 5\nmasses = 15, 5, 2\ndamping = 1\n"
             "death_angle = %s\n",
             death);
    return buf;
}

static const char *seed_ini(double death_deg) {
    char v[64];
    snprintf(v, sizeof v, "%.17g", death_deg);
    return seed_ini_text(v);
}

/* the trajectory rows of s's last run, copied out of its packed store (the caller frees) */
static zp_row *rows_copy(const zp_sim *s, int *n) {
    const zp_row_store *st = zp_sim_rows(s);
    zp_row *v = malloc(sizeof *v * (size_t)(st->n > 0 ? st->n : 1));
    for (int k = 0; v && k < st->n; k++) {
        zp_row_store_get(st, k, &v[k]);
    }
    *n = v ? st->n : 0;
    return v;
}

static void check_graze(const char *method, double rtol) {
    zp_scene sc;
    zp_model *m = tu_model(seed_ini(180), &sc);
    zp_sim_opts o = tu_opts(&sc, rtol);
    o.method = zp_method_find(method);
    double f[3] = {10, 10, 10};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    zp_result alive = *tu_run(m, &o, &in);
    CHECK(alive.outcome == ZP_OUTCOME_FINISHED);
    int k = 0;
    for (int i = 1; i < m->nlink; i++) {
        k = alive.max_rel_angle[i] > alive.max_rel_angle[k] ? i : k;
    }

    /* the death angle just under the largest angle of the run */
    zp_scene sc2;
    double death = alive.max_rel_angle[k] * DEG - GRAZE_DEPTH_DEG;
    zp_model *m2 = tu_model(seed_ini(death), &sc2);
    zp_result died = *tu_run(m2, &o, &in);
    CHECK(died.outcome == ZP_OUTCOME_DIED);
    CHECK(died.died_link == k + 1);
    CHECK(died.time < alive.time);

    /* the first crossing of the death angle, seen on the run that survives it */
    o.output_dt = 1e-3;
    in.sample_t = &died.time;
    in.nsample = 1;
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(s && zp_sim_run(m, s, &in, &r) == ZP_OK);
    int n;
    const zp_row *smp = zp_sim_samples(s, &n);
    CHECK(n == 1);
    double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
    if (n == 1) {
        zp_state_relative(m, &smp[0].c, phi, w);
        CHECK_NEAR(fabs(phi[k]), m2->phi_max, AT_ANGLE_TOL);
    }
    zp_row *rows = rows_copy(s, &n);
    int before = 0;
    for (int j = 0; j < n && rows[j].t < died.time; j++) {
        zp_state_relative(m, &rows[j].c, phi, w);
        before += fabs(phi[k]) >= m2->phi_max;
    }
    CHECK(before == 0);
    free(rows);
    printf("%-12s rtol %.0e: link %d dies at %.9f s (largest angle %.6f deg)\n", method, rtol,
           died.died_link, died.time, alive.max_rel_angle[k] * DEG);
    zp_sim_free(s);
    zp_model_free(m2);
    zp_model_free(m);
}

/* the seed at a constant 12.0869 N: the toe joint reaches 180 deg at about 14.73 s */
static void check_seed_graze(const char *method) {
    zp_scene sc;
    zp_model *m = tu_model(seed_ini(180), &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    o.method = zp_method_find(method);
    double f[3] = {12.0869, 12.0869, 12.0869};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    const zp_result *r = tu_run(m, &o, &in);
    CHECK(r->outcome == ZP_OUTCOME_DIED);
    CHECK(r->died_link == 3);
    CHECK(r->max_rel_angle[2] <= m->phi_max * (1 + 1e-12));
    printf("%-12s seed at 12.0869 N: %s at %.9f s\n", method, zp_sim_outcome_name(r->outcome),
           r->time);
    zp_model_free(m);
}

/* a death angle per joint: joint 3 at 130 deg (below the 132.2 deg it reaches at 10 N) dies
   where the run with 180 everywhere first crosses 130 on joint 3, while 130 on joint 1 (which
   never passes 48 deg) changes nothing; the margin the search reads is the smallest of each
   joint's own; one value per joint must match the links, and the margin stay below each */
static void check_per_joint(void) {
    zp_scene sc;
    zp_model *m = tu_model(seed_ini(180), &sc);
    zp_sim_opts o = tu_opts(&sc, 1e-9);
    o.output_dt = 1e-3;
    double f[3] = {10, 10, 10};
    zp_schedule sched = tu_sched(m, f);
    zp_input in = {.sched = &sched};
    zp_result alive = *tu_run(m, &o, &in);
    CHECK(alive.outcome == ZP_OUTCOME_FINISHED && alive.max_rel_angle[2] * DEG > 130);
    /* the first row of the survivor past 130 deg on joint 3 bounds the death from above */
    int n;
    zp_row *rows = rows_copy(*tu_last_sim(), &n);
    double t_past = INFINITY, t_before = 0;
    for (int j = 0; j < n && !isfinite(t_past); j++) {
        double phi[ZP_MAX_LINKS], w[ZP_MAX_LINKS];
        zp_state_relative(m, &rows[j].c, phi, w);
        if (fabs(phi[2]) * DEG >= 130) {
            t_past = rows[j].t;
        } else {
            t_before = rows[j].t;
        }
    }
    free(rows);
    zp_scene s3, s1;
    zp_model *m3 = tu_model(seed_ini_text("180, 180, 130"), &s3);
    zp_model *m1 = tu_model(seed_ini_text("130, 180, 180"), &s1);
    CHECK(s3.ndeath == 3 && s3.death_angle == 180 && m3->phi_max_j[2] == 130 / DEG);
    o.output_dt = 0;
    zp_result r3 = *tu_run(m3, &o, &in);
    CHECK(r3.outcome == ZP_OUTCOME_DIED && r3.died_link == 3);
    CHECK(r3.time > t_before && r3.time <= t_past);
    zp_result r1 = *tu_run(m1, &o, &in);
    CHECK(r1.outcome == ZP_OUTCOME_FINISHED && r1.time == alive.time);
    /* the margin the search judges: the smallest of 130 - a1 and 180 - a2, 180 - a3 */
    double want = fmin(130 / DEG - r1.max_rel_angle[0],
                       fmin(M_PI - r1.max_rel_angle[1], M_PI - r1.max_rel_angle[2]));
    CHECK_NEAR(m1->phi_max - zp_model_angle_used(m1, r1.max_rel_angle), want, 1e-15);
    zp_model_free(m1);
    zp_model_free(m3);
    zp_model_free(m);

    const char *bad[] = {"180, 170", "180, 180, 5\n[optimize]\nmargin = 10"};
    for (int k = 0; k < 2; k++) {
        zp_scene sb;
        zp_diag d;
        zp_diag_init(&d);
        CHECK(zp_scene_load_string(seed_ini_text(bad[k]), "bad.ini", &sb, &d) != ZP_OK);
        char msg[4096] = "";
        FILE *fm = fmemopen(msg, sizeof msg, "w");
        zp_diag_print(&d, fm);
        fclose(fm);
        CHECK(strstr(msg, "bad.ini:") && (strstr(msg, "death_angle") || strstr(msg, "margin")));
    }
}

int main(void) {
    check_per_joint();
    for (size_t i = 0; i < sizeof methods / sizeof *methods; i++) {
        check_graze(methods[i], 1e-6);
        check_graze(methods[i], 1e-9);
        check_seed_graze(methods[i]);
    }
    zp_sim_free(*tu_last_sim());
    return CHECK_DONE();
}
