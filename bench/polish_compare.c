/* The polish alone, derivative-free (COBYLA) against the gradient polish (SLSQP with the
   sensitivities), from the same starts: the best constant push of the default search's scan,
   and the default search's answer with its pushes 5 % less. For each, where each ended (its
   simulations, sensitivity runs charged as the search charges them, and wall time), the
   simulations each took to the answer both reach (the worse survivable end, within 1e-6
   relative) and their ratio; and what a sensitivity run is charged and costs in plain runs'
   wall time, measured at the start.
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

/* one polish of `how` from x0 on one thread, alone in a fresh search state, of at most cap
   simulations */
static void polish_alone(const zp_problem *st, const zp_objective *ob, const zp_strategy *how,
                         const double *x0, long cap, polished *out) {
    zp_search_opts o = {.max_evals = cap, .seed = st->seed, .nthreads = 1};
    zp_search_state S;
    char err[256];
    zp_search_state_begin(&S, ob, st->sched.lo, st->sched.hi, &o, &res);
    double step[ZP_SCHED_MAX_PARAMS];
    for (int k = 0; k < S.n; k++) {
        step[k] = STEP * (st->sched.hi[k] - st->sched.lo[k]);
    }
    zp_leg_job job = {.x0 = x0, .step = step, .cap = cap, .out = &out->rec};
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

/* the polish's end time when survivable, else INFINITY */
static double end_time(const polished *p) {
    return zp_objective_feasible(&p->rec.e) ? p->rec.e.time : INFINITY;
}

/* simulations until polish p (of how from x0) reached t (within SAME), -1: never. From its
   history of improvements; where that was cut short (a leg keeps its first
   ZP_LEG_IMPROVEMENTS) by bisection on the budget, since a polish with a smaller budget runs
   what a larger one does first */
static long reached(const zp_problem *st, const zp_objective *ob, const zp_strategy *how,
                    const double *x0, const polished *p, double t) {
    for (int i = 0; i < p->nhist; i++) {
        if (p->hist[i].time <= t * (1 + SAME)) {
            return p->hist[i].evals;
        }
    }
    if (!(end_time(p) <= t * (1 + SAME))) {
        return -1;
    }
    static polished q;
    /* not yet there at lo simulations, there at hi */
    long lo = p->nhist > 0 ? p->hist[p->nhist - 1].evals : 0, hi = p->rec.n;
    while (hi - lo > 1) {
        long mid = lo + (hi - lo) / 2;
        polish_alone(st, ob, how, x0, mid, &q);
        *(end_time(&q) <= t * (1 + SAME) ? &hi : &lo) = mid;
    }
    return hi;
}

/* what a sensitivity run costs at parameters f */
typedef struct sens_price {
    long charged;     /* plain runs, as the gradient polish charges it */
    double evals;     /* its integrator's evaluations over the plain run's */
    double per_eval;  /* plain rate evaluations per evaluation of its own (the stencils) */
    double wall;      /* its wall time over a plain run's */
} sens_price;

static sens_price sens_cost(const zp_problem *st, const zp_objective *ob, const double *f) {
    sens_price p = {-1, NAN, NAN, NAN};
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
    if (sr && r && r->rhs_evals > 0 && sr->rhs_evals > 0) {
        p.charged = 1 + (sr->rates - 1) / r->rhs_evals;
        p.evals = (double)sr->rhs_evals / r->rhs_evals;
        p.per_eval = (double)sr->rates / sr->rhs_evals;
        p.wall = (t2 - t1) / (t1 - t0);
    }
    free(sr);
    free(r);
    zp_sim_free(s);
    return p;
}

/* both polishes from x0: a row of the table. The answer both reach is the worse of their
   survivable ends (one that ends unsurvivable reaches none); the goal is fewer simulations to
   it, within SAME */
static void compare(const zp_problem *st, const zp_objective *ob, const double *x0,
                    const char *start) {
    static polished dfree, grad;
    polish_alone(st, ob, &zp_strategy_nlopt_cobyla, x0, CAP, &dfree);
    polish_alone(st, ob, &zp_strategy_slsqp, x0, CAP, &grad);
    double both = fmax(end_time(&dfree), end_time(&grad));
    long nd = isfinite(both) ? reached(st, ob, &zp_strategy_nlopt_cobyla, x0, &dfree, both) : -1;
    long ng = isfinite(both) ? reached(st, ob, &zp_strategy_slsqp, x0, &grad, both) : -1;
    sens_price c = sens_cost(st, ob, x0);
    printf("| %s | %d | %s | %.9g%s (%ld, %.3g s) | %.9g%s (%ld, %.3g s) | %.9g | %ld | %ld | "
           "%s%.3g | %ld = %.2g x %.3g, %.2g |\n",
           st->sc.name, st->sched.np, start, dfree.rec.e.time,
           zp_objective_feasible(&dfree.rec.e) ? "" : " (not survivable)", dfree.rec.n,
           dfree.wall, grad.rec.e.time,
           zp_objective_feasible(&grad.rec.e) ? "" : " (not survivable)", grad.rec.n, grad.wall,
           both, nd, ng, nd > 0 && ng > 0 ? "" : "n/a ", nd > 0 && ng > 0 ? (double)nd / ng : 0.0,
           c.charged, c.evals, c.per_eval, c.wall);
    fflush(stdout);
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fputs("usage: polish_compare SCENE.ini...\n", stderr);
        return 2;
    }
    printf("| scene | parameters | start | COBYLA ended (sims, wall) | SLSQP ended (sims, wall) "
           "| answer both reach (s) | COBYLA: sims to it | SLSQP: sims to it | ratio | "
           "sensitivity run (plain runs charged = evaluations x rates per evaluation, wall) |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n");
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
