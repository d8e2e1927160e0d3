/* The search's budget study: for each scene, the best survivable finish time of the search
   alone (no verification) at budgets B, 2B, 4B, 8B, with the default budget and with 10x it;
   the first four must not increase, the default must be within 0.5 % of the 10x answer.
   Usage: search_budget B SCENE.ini...   (prints a markdown table; exit 1 if a check fails) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "search.h"
#include "setup.h"

#define MONO_TOL 1e-9 /* relative: a larger budget is never worse beyond this */
#define GOAL 0.005    /* relative: the default answer against 10x the budget */

static zp_search_result res;

/* the search as `zipopt SCENE.ini` runs it, at budget evals: its best time, INFINITY if none */
static double search_at(const zp_problem *st, long evals, long *spent, int *converged) {
    zp_objective ob = {
        .m = st->m, .limit = st->limit, .t_max = st->search.t_max, .shape = &st->sched};
    zp_search_opts o = {.max_evals = evals, .seed = st->seed};
    char err[256];
    if (zp_search_run(&ob, &st->search, st->sched.lo, st->sched.hi, &o, &res, err, sizeof err)) {
        fprintf(stderr, "search_budget: %s\n", err);
        exit(1);
    }
    *spent = res.evals;
    *converged = res.converged;
    return res.found ? res.best.time : INFINITY;
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fputs("usage: search_budget B SCENE.ini...\n", stderr);
        return 2;
    }
    long B = atol(argv[1]);
    int bad = 0;
    printf("| scene | sections | B | T(B) | T(2B) | T(4B) | T(8B) | monotone | default "
           "(sims) | T(default) | T(10x) (sims) | default vs 10x |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int a = 2; a < argc; a++) {
        static zp_problem st; /* large: kept off the stack */
        zp_overrides none = ZP_OVERRIDES_NONE;
        if (zp_setup_load("search_budget", argv[a], &none, &st)) {
            return 2;
        }
        double t[4];
        long spent;
        int conv, mono = 1;
        for (int i = 0; i < 4; i++) {
            t[i] = search_at(&st, B << i, &spent, &conv);
            mono &= i == 0 || t[i] <= t[i - 1] * (1 + MONO_TOL);
        }
        long def = st.max_evals, s_def, s_ten;
        int c_def, c_ten;
        double td = search_at(&st, def, &s_def, &c_def);
        double tt = search_at(&st, 10 * def, &s_ten, &c_ten);
        double gap = (td - tt) / tt;
        printf("| %s | %d | %ld | %.9g | %.9g | %.9g | %.9g | %s | %ld (%ld%s) | %.9g | %.9g "
               "(%ld%s) | %+.3g %% |\n",
               st.sc.name, st.m->nsec, B, t[0], t[1], t[2], t[3], mono ? "yes" : "**no**", def,
               s_def, c_def ? ", converged" : "", td, tt, s_ten, c_ten ? ", converged" : "",
               100 * gap);
        fflush(stdout);
        bad |= !mono || !(gap <= GOAL);
        zp_setup_free(&st);
    }
    return bad;
}
