/* The search's verification: the robustness tallies of the one parallel batch against a serial
   brute-force loop and across thread counts, and [solver] accuracy met by rerunning the answer,
   against a reference run at rtol 1e-12. */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "method.h"
#include "testutil.h"
#include "verify.h"

#define NROBUST 20

static const double levels[ZP_VERIFY_LEVELS] = {0.02, 0.05}; /* verify.h: +/-2 % and +/-5 % */

/* the seed's search answer, a schedule on the edge of death */
static const double answer[3] = {59.58914569124449, 500, 500};

/* the perturbed runs one by one, as verify.h describes them: survivors per level */
static void brute_force(const zp_objective *ob, const zp_sim_opts *o, unsigned long seed,
                        int survived[ZP_VERIFY_LEVELS], int kept[ZP_VERIFY_LEVELS]) {
    zp_sim_opts fast = *o;
    fast.output_dt = 0;
    fast.track_loads = 0;
    zp_sim *s = zp_sim_create(ob->m, &fast);
    static zp_result r;
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, seed);
    for (int i = 0; i < ZP_VERIFY_LEVELS * NROBUST; i++) {
        double f[3];
        for (int k = 0; k < 3; k++) {
            f[k] = answer[k] * (1 + levels[i / NROBUST] * (2 * gsl_rng_uniform(g) - 1));
        }
        zp_eval e;
        zp_objective_eval(ob, s, f, &e, &r);
        survived[i / NROBUST] += e.outcome == ZP_OUTCOME_FINISHED && !e.failed;
        kept[i / NROBUST] += zp_objective_feasible(&e);
    }
    gsl_rng_free(g);
    zp_sim_free(s);
}

static void test_batch(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_objective ob = tu_objective(m, &sc, &o);
    int survived[ZP_VERIFY_LEVELS] = {0}, kept[ZP_VERIFY_LEVELS] = {0};
    brute_force(&ob, &o, 7, survived, kept);
    zp_verify v[2];
    for (int t = 0; t < 2; t++) {
        zp_sim *s = NULL;
        char err[512];
        CHECK(zp_verify_run(&ob, &o, answer, 7, NROBUST, t + 1, &s, &v[t], NULL, NULL, err,
                            sizeof err) == ZP_OK);
        CHECK(v[t].robust_done);
        for (int l = 0; l < ZP_VERIFY_LEVELS; l++) {
            CHECK(v[t].rob[l].n == NROBUST);
            CHECK(v[t].rob[l].survived == survived[l]);
            CHECK(v[t].rob[l].kept == kept[l]);
        }
        /* the tighter run is the same schedule at rtol / 100 */
        zp_sim_opts to = o;
        to.rtol /= 100;
        to.atol /= 100;
        zp_schedule sched = tu_sched(m, answer);
        zp_input in = {.sched = &sched};
        CHECK(tu_run(m, &to, &in)->time == v[t].tight->time);
        zp_sim_free(s);
    }
    /* one thread or two: the same answer to the bit */
    CHECK(v[0].run->time == v[1].run->time && v[0].tight->time == v[1].tight->time);
    CHECK(v[0].kill_found == v[1].kill_found && v[0].kill == v[1].kill &&
          v[0].kill_param == v[1].kill_param && v[0].agree == v[1].agree);
    /* a smallest kill of one force does kill, changed that much one way or the other */
    if (v[0].kill_found && v[0].kill_param) {
        int k = v[0].kill_param - 1, deadly = 0;
        for (int sign = -1; sign <= 1; sign += 2) {
            double f[3] = {answer[0], answer[1], answer[2]};
            f[k] *= 1 + sign * v[0].kill;
            zp_schedule sched = tu_sched(m, f);
            zp_input in = {.sched = &sched};
            const zp_result *r = tu_run(m, &o, &in);
            deadly |= r->outcome == ZP_OUTCOME_DIED;
        }
        CHECK(deadly);
    }
    for (int t = 0; t < 2; t++) {
        zp_verify_free(&v[t]);
    }
    zp_model_free(m);
}

/* [solver] accuracy the first pick misses (a coarse rtol): the answer is rerun until it meets
   the request, checked against a reference run at rtol 1e-12 */
static void test_accuracy(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-3);
    o.method = ZP_METHOD_CVODE_ADAMS;
    o.output_dt = 0.02;
    zp_objective ob = tu_objective(m, &sc, &o);
    zp_sim_opts ref = tu_opts(&sc, 1e-12);
    ref.method = ZP_METHOD_GSL_RK8PD;
    zp_schedule sched = tu_sched(m, answer);
    zp_input in = {.sched = &sched};
    double t_ref = tu_run(m, &ref, &in)->time;
    const double requests[] = {1e-6, 1e-1};
    for (int i = 0; i < 2; i++) {
        double acc = requests[i];
        zp_verify v;
        zp_sim *s = NULL;
        char err[512];
        CHECK(zp_verify_run(&ob, &o, answer, 1, 0, 0, &s, &v, NULL, NULL, err, sizeof err) ==
              ZP_OK);
        double first = fabs(v.run->time - v.tight->time);
        zp_sim_opts got;
        zp_accuracy a;
        CHECK(zp_verify_accuracy(&ob, &o, answer, acc, &s, &v, &got, &a, err, sizeof err) == ZP_OK);
        CHECK(a.ok && a.met <= acc && a.requested == acc && a.method == o.method);
        CHECK(fabs(v.run->time - t_ref) <= acc);
        CHECK(got.rtol == a.rtol && got.output_dt == o.output_dt);
        /* the verification now states the answer's own estimate */
        CHECK(fabs(v.run->time - v.tight->time) == a.met);
        CHECK(v.agree == (a.met <= ZP_VERIFY_DT));
        const zp_row_store *rows = zp_sim_rows(s);
        CHECK(rows->n > 1 && zp_row_store_t(rows, rows->n - 1) <= v.run->time);
        if (i == 0) { /* the first pick missed: it took reruns at a tighter rtol */
            CHECK(first > acc && a.reruns >= 1 && a.rtol < o.rtol);
        } else { /* met at once: nothing rerun */
            CHECK(first <= acc && a.reruns == 0 && a.rtol == o.rtol);
        }
        zp_sim_free(s);
        zp_verify_free(&v);
    }
    zp_model_free(m);
}

int main(void) {
    test_batch();
    test_accuracy();
    return CHECK_DONE();
}
