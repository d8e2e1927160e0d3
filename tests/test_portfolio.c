/* The portfolio (optim/strategy_portfolio.c: the scan beside pagmo's seeded populations, the one
   population's windows, the bang-bang searches): a larger budget runs everything a smaller one
   does, and the same seed gives the same bits on 1 and 2 threads.
   Independent expectations: the smaller budget's own history, and the other thread count's. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "search.h"
#include "searchutil.h"
#include "testutil.h"

static zp_search_result res, res2;

/* the portfolio at budgets lo, 2 lo, .. hi on 2 threads: each runs everything the smaller one
   did (its history a prefix), never slower; then hi on 1 thread: the same bits */
static void budgets(const zp_model *m, zp_scene *sc, long lo, long hi) {
    zp_sim_opts o = tu_opts(sc, 1e-5);
    zp_objective ob = tu_objective(m, sc, &o);
    int a = zp_search_algo_find("portfolio-cobyla");
    CHECK(a >= 0);
    double prev = INFINITY;
    for (long b = lo; b <= hi; b *= 2) {
        sc->max_evals = b;
        tu_search_with(&ob, &o, sc, a, 2, &res);
        CHECK(res.evals <= b);
        double t = res.found ? res.best.time : INFINITY;
        CHECK(t <= prev * (1 + 1e-9));
        prev = t;
        if (b > lo) {
            tu_history_extends(&res, &res2);
        }
        res2 = res;
    }
    tu_search_with(&ob, &o, sc, a, 1, &res2);
    CHECK(!memcmp(res.force, res2.force, sizeof res.force));
    CHECK(res.evals == res2.evals && res.best.time == res2.best.time && res.nhist == res2.nhist);
}

/* budgets that cut the populations' legs in the first round and in later ones; the seed: four
   CMA-ES populations */
static void seed(zp_scene *sc) {
    zp_model *m = tu_seed_model(sc);
    budgets(m, sc, 400, 3200);
    zp_model_free(m);
}

/* 8 parameters: one population of differential evolution, its leg cut in its third round at
   9000, and the bang-bang searches from the map's best */
static void multi8(zp_scene *sc) {
    zp_model *m = tu_model_file(ZP_SOURCE_DIR "/config/multi8.ini", sc);
    CHECK(m != NULL && sc->nsec >= 8);
    if (m) {
        budgets(m, sc, 2250, 9000);
        CHECK(res.npinned >= 1 && res2.npinned == res.npinned); /* bang-bang searches too */
    }
    zp_model_free(m);
}

/* a 9-section copy of multi8, where the one population's leg also searches windows of its best
   schedule, the rest held: 16000 begins the first one, after three bang-bang searches */
static void multi9(zp_scene *sc) {
    zp_model *m = tu_model_file(ZP_SOURCE_DIR "/tests/scenes/multi9.ini", sc);
    CHECK(m != NULL && sc->nsec == 9);
    if (m) {
        budgets(m, sc, 8000, 16000);
        CHECK(res.nwindows >= 1 && res2.nwindows == res.nwindows);
    }
    zp_model_free(m);
}

/* usage: test_portfolio [seed] [multi8] [multi9]: the parts named, all without a name */
int main(int argc, char **argv) {
    static const struct {
        const char *name;
        void (*run)(zp_scene *);
    } parts[] = {{"seed", seed}, {"multi8", multi8}, {"multi9", multi9}};
    const int nparts = (int)(sizeof parts / sizeof parts[0]);
    zp_scene sc;
    for (int k = 0; argc == 1 && k < nparts; k++) {
        parts[k].run(&sc);
    }
    for (int i = 1; i < argc; i++) {
        int k = 0;
        while (k < nparts && strcmp(argv[i], parts[k].name)) {
            k++;
        }
        CHECK(k < nparts); /* a misspelt part would otherwise pass by running nothing */
        if (k < nparts) {
            parts[k].run(&sc);
        }
    }
    return CHECK_DONE();
}
