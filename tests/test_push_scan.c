/* The best constant push's own scan (optim/push_scan.c) against a brute-force loop over every
   push 0.05 N apart, run one by one through the same objective: on the seed, whose survivable
   pushes are bands under 1 N wide (the search's own pushes kept 27.69 N, 15.03 s), and on a
   swing whose survival is monotone in the push (the optimum is the largest push that keeps the
   margin). The scan must be at least as fast as the brute force, survive when run again, and
   give the same bits on 1 and 2 threads. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "push_scan.h"
#include "testutil.h"

/* the fastest survivable push of the brute force, every step N over [lo, hi]; its push */
static double brute(const zp_objective *ob, const zp_sim_opts *o, double lo, double hi, double step,
                    double *push) {
    zp_sim *s = zp_sim_create(ob->m, o);
    CHECK(s != NULL);
    double best = INFINITY;
    int n = zp_objective_nparams(ob);
    for (int i = 0; lo + i * step <= hi + 1e-9; i++) {
        double f[ZP_SCHED_MAX_PARAMS];
        for (int k = 0; k < n; k++) {
            f[k] = lo + i * step;
        }
        zp_eval e;
        zp_result r;
        zp_objective_eval(ob, s, f, &e, &r);
        if (zp_objective_feasible(&e) && e.time < best) {
            best = e.time;
            *push = f[0];
        }
    }
    zp_sim_free(s);
    return best;
}

static void check_scene(zp_model *m, const zp_scene *sc, double hi, long budget) {
    zp_sim_opts o = tu_opts(sc, 1e-5);
    o.method = zp_method_find("gsl-rk8pd");
    zp_objective ob = tu_objective(m, sc, &o);
    double lo_b[ZP_MAX_SECTIONS], hi_b[ZP_MAX_SECTIONS];
    for (int k = 0; k < m->nsec; k++) {
        lo_b[k] = 0;
        hi_b[k] = hi;
    }
    zp_push_scan one, two;
    int npts = zp_push_scan_points(budget);
    CHECK(zp_push_scan_run(&ob, &o, lo_b, hi_b, npts, 1, &one) == ZP_OK);
    CHECK(zp_push_scan_run(&ob, &o, lo_b, hi_b, npts, 2, &two) == ZP_OK);
    CHECK(one.found && !memcmp(&one, &two, sizeof one));
    CHECK(one.evals >= npts && one.evals <= npts + ZP_PUSH_SCAN_ISLANDS * ZP_PUSH_SCAN_BISECT);
    double push = NAN, t = brute(&ob, &o, 0, hi, 0.05, &push);
    printf("push scan %.4f N %.6f s (%ld runs); brute force %.2f N %.6f s\n", one.p[0], one.e.time,
           one.evals, push, t);
    CHECK(one.e.time <= t + 1e-9);
    /* its push, run again alone, survives at the time stated */
    zp_sim *s = zp_sim_create(m, &o);
    zp_eval e;
    zp_result r;
    zp_objective_eval(&ob, s, one.p, &e, &r);
    CHECK(zp_objective_feasible(&e) && e.time == one.e.time);
    zp_sim_free(s);
}

int main(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    check_scene(m, &sc, 500, 5000);
    zp_model_free(m);
    m = tu_model(tu_swing, &sc);
    check_scene(m, &sc, 400, 400);
    zp_model_free(m);
    return CHECK_DONE();
}
