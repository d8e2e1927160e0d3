/* The polish alone, derivative-free (COBYLA) against the gradient polish (SLSQP with the
   sensitivities), from the same starts: the best constant push of the default search's scan,
   and the default search's answer with its pushes 5 % less. For each, the simulations
   (sensitivity runs charged as the search charges them) to reach the better survivable end of
   the two within 1e-6 relative, where each ended and its wall time; and what a sensitivity run
   costs in plain runs' wall time, measured at the start.
   Usage: polish_compare SCENE.ini...   (prints a markdown table) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "leg.h"
#include "search.h"
#include "sens.h"
#include "setup.h"
#include "sim.h"
#include "strategy.h"

#define CAP 20000 /* simulations a polish may spend: enough to stop on its own tolerances */
#define SAME 1e-6  /* relative: the same answer */
#define STEP 0.02  /* the first steps, share of the box (the search's) */
#define NEAR 0.95  /* the near start: the answer's pushes above their least, times this */
#define TIMED 50   /* runs timed for the cost of a sensitivity run */

static zp_search_result res;

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

typedef struct polished {
    zp_leg_rec rec;
    double wall;
    int nhist;
    zp_search_hist hist[ZP_SEARCH_HIST];
} polished;

/* one polish of `how` from x0 on one thread, alone in a fresh search state */
static void polish_alone(const zp_problem *st, const zp_objective *ob, const zp_strategy *how,
                         const double *x0, polished *out) {
    zp_search_opts o = {.max_evals = CAP, .seed = st->seed, .nthreads = 1};
    zp_search_state S;
    char err[256];
    zp_search_state_begin(&S, ob, st->sched.lo, st->sched.hi, &o, &res);
    double step[ZP_SCHED_MAX_PARAMS];
    for (int k = 0; k < S.n; k++) {
        step[k] = STEP * (st->sched.hi[k] - st->sched.lo[k]);
    }
    zp_leg_job job = {.x0 = x0, .step = step, .cap = CAP, .out = &out->rec};
    double t0 = now();
    if (zp_search_state_start(&S, &st->search, err, sizeof err) ||
        zp_leg_batch(&S, how->polish, how, &job, 1, err, sizeof err)) {
        fprintf(stderr, "polish_compare: %s\n", err);
        exit(1);
    }
    out->wall = now() - t0;
    out->nhist = res.nhist;
    memcpy(out->hist, res.hist, sizeof res.hist);
    zp_search_state_end(&S);
}

/* simulations until the history reached t (within SAME), -1: never */
static long reached(const polished *p, double t) {
    for (int i = 0; i < p->nhist; i++) {
        if (p->hist[i].time <= t * (1 + SAME)) {
            return p->hist[i].evals;
        }
    }
    return -1;
}

/* wall time of a sensitivity run over a plain run's, at parameters f */
static double sens_cost(const zp_problem *st, const zp_objective *ob, const double *f) {
    zp_schedule sched = zp_objective_schedule(ob, f);
    zp_sim *s = zp_sim_create(st->m, &st->search);
    zp_result *r = calloc(1, sizeof *r);
    zp_sens_result *sr = malloc(sizeof *sr);
    zp_eval e;
    double t0 = now();
    for (int i = 0; s && r && i < TIMED; i++) {
        zp_objective_eval(ob, s, f, &e, r);
    }
    double t1 = now();
    for (int i = 0; sr && i < TIMED; i++) {
        zp_sens_run(st->m, &st->search, &sched, NULL, sr);
    }
    double t2 = now();
    free(sr);
    free(r);
    zp_sim_free(s);
    return (t2 - t1) / (t1 - t0);
}

/* the polish's end time when survivable, else INFINITY */
static double end_time(const polished *p) {
    return zp_objective_feasible(&p->rec.e) ? p->rec.e.time : INFINITY;
}

/* both polishes from x0: a row of the table */
static void compare(const zp_problem *st, const zp_objective *ob, const double *x0,
                    const char *start) {
    static polished dfree, grad;
    polish_alone(st, ob, &zp_strategy_nlopt_cobyla, x0, &dfree);
    polish_alone(st, ob, &zp_strategy_slsqp, x0, &grad);
    double best = fmin(end_time(&dfree), end_time(&grad));
    long nd = reached(&dfree, best), ng = reached(&grad, best);
    double cost = sens_cost(st, ob, x0);
    printf("| %s | %d | %s | %.9g | %ld | %.9g (%ld, %.3g s) | %ld | %.9g (%ld, %.3g s) | %.2g | "
           "%s%.3g |\n",
           st->sc.name, st->sched.np, start, best, nd, dfree.rec.e.time, dfree.rec.n, dfree.wall,
           ng, grad.rec.e.time, grad.rec.n, grad.wall, cost, nd > 0 && ng > 0 ? "" : "n/a ",
           nd > 0 && ng > 0 ? (double)nd / ng : 0.0);
    fflush(stdout);
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fputs("usage: polish_compare SCENE.ini...\n", stderr);
        return 2;
    }
    printf("| scene | parameters | start | answer (s) | COBYLA: sims to it | COBYLA "
           "ended (sims, wall) | SLSQP: sims to it | SLSQP ended (sims, wall) | sensitivity run "
           "(plain runs) | sims ratio |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (int a = 1; a < argc; a++) {
        static zp_problem st; /* large: kept off the stack */
        zp_overrides none = ZP_OVERRIDES_NONE;
        if (zp_setup_load("polish_compare", argv[a], &none, &st)) {
            return 2;
        }
        zp_objective ob = {
            .m = st.m, .limit = st.limit, .t_max = st.search.t_max, .shape = &st.sched};
        zp_search_opts o = {.max_evals = st.max_evals, .seed = st.seed};
        char err[256];
        if (zp_search_run(&ob, &st.search, st.sched.lo, st.sched.hi, &o, &res, err, sizeof err) ||
            !res.base_found) {
            fprintf(stderr, "polish_compare: %s: no survivable constant push\n", argv[a]);
            return 1;
        }
        /* the scan's best constant push, far from the answer; and the search's answer with
           every push 5 % less (above its least), in its basin */
        double x0[2][ZP_SCHED_MAX_PARAMS];
        memcpy(x0[0], res.base_p, sizeof x0[0]);
        for (int k = 0; k < st.sched.np; k++) {
            x0[1][k] = st.sched.lo[k] + NEAR * (res.force[k] - st.sched.lo[k]);
        }
        for (int i = 0; i < 2; i++) {
            compare(&st, &ob, x0[i], i ? "near the answer" : "constant push");
        }
        zp_setup_free(&st);
    }
    return 0;
}
