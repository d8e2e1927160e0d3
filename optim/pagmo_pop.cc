// pagmo2's sade and cmaes behind pagmo_pop.h: the population and the algorithm (whose adapted
// state, sade's F and CR or CMA-ES's mean, step size and covariance, and random engine carry
// over from one call to the next) live as long as the handle.
#include "pagmo_pop.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

namespace {

constexpr unsigned sade_variant = 6u; // best/1/bin (SciPy's best1bin)
constexpr unsigned adaptation = 1u;   // jDE
constexpr double ftol = 1e-6;         // s: a population this flat has collapsed ...
constexpr double xtol = 1e-3;         // N: ... when its members are this close too
constexpr unsigned long seed_step = 0x9e3779b97f4a7c15UL; // the next seed after a collapse

// what fitness calls, set before each evolution
struct context {
    zp_pagmo_pop_fitness fit = nullptr;
    void *user = nullptr;
};

// the box and the fitness as pagmo sees a problem; ctx outlives every copy pagmo makes
struct box_problem {
    const context *ctx = nullptr;
    pagmo::vector_double lo, hi;

    pagmo::vector_double fitness(const pagmo::vector_double &x) const {
        return {ctx->fit(ctx->user, x.data())};
    }
    std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const { return {lo, hi}; }
};

// every member within ftol of the first's value and xtol of it in each parameter: no
// difference left to evolve with
bool collapsed(const pagmo::population &pop) {
    const auto &f = pop.get_f();
    const auto &x = pop.get_x();
    for (std::size_t i = 1; i < f.size(); i++) {
        if (std::fabs(f[i][0] - f[0][0]) > ftol) {
            return false;
        }
        for (std::size_t k = 0; k < x[i].size(); k++) {
            if (std::fabs(x[i][k] - x[0][k]) > xtol) {
                return false;
            }
        }
    }
    return true;
}

unsigned seed32(unsigned long s) {
    return static_cast<unsigned>(s ^ (s >> 32));
}

constexpr double sigma_drawn = 0.5; // CMA-ES's first step over a drawn population: pagmo's

// one generation a call, with pagmo's own tolerances off: collapse is judged here after every
// generation; memory on: the adapted state carries over from one call to the next
pagmo::algorithm make_algorithm(zp_pagmo_algo kind, unsigned seed, double sigma0) {
    if (kind == ZP_PAGMO_CMAES) {
        // the first step sigma0 of the box and the learning rates pagmo derives from the
        // dimension (its defaults); bounds forced, as the simulator only knows the box. pagmo's
        // CMA-ES starts its mean at the best member
        return pagmo::algorithm(pagmo::cmaes(1u, -1, -1, -1, -1, sigma0, 0, 0, true, true, seed));
    }
    return pagmo::algorithm(pagmo::sade(1u, sade_variant, adaptation, 0, 0, true, seed));
}

} // namespace

struct zp_pagmo_pop {
    context ctx;
    box_problem prob;
    zp_pagmo_algo kind = ZP_PAGMO_SADE;
    int popsize = 0;
    unsigned long seed = 0;
    std::optional<pagmo::algorithm> algo;
    std::optional<pagmo::population> pop; // empty: to be drawn at the next evolution
    // the start of a population created at a point, until its first evolution
    bool at = false;
    pagmo::vector_double x0;
    double f0 = 0, sigma0 = sigma_drawn;
};

extern "C" zp_pagmo_pop *zp_pagmo_pop_create(zp_pagmo_algo algo, int n, const double *lo,
                                             const double *hi, int popsize, unsigned long seed) {
    try {
        auto d = std::make_unique<zp_pagmo_pop>();
        d->prob.ctx = &d->ctx;
        d->prob.lo.assign(lo, lo + n);
        d->prob.hi.assign(hi, hi + n);
        d->kind = algo;
        d->popsize = popsize;
        d->seed = seed;
        return d.release();
    } catch (...) {
        return nullptr;
    }
}

extern "C" zp_pagmo_pop *zp_pagmo_pop_create_at(int n, const double *lo, const double *hi,
                                                int popsize, unsigned long seed, const double *x0,
                                                double f0, double sigma0) {
    zp_pagmo_pop *d = zp_pagmo_pop_create(ZP_PAGMO_CMAES, n, lo, hi, popsize, seed);
    if (d) {
        try {
            d->x0.assign(x0, x0 + n);
        } catch (...) {
            delete d;
            return nullptr;
        }
        d->at = true;
        d->f0 = f0;
        d->sigma0 = sigma0;
    }
    return d;
}

extern "C" void zp_pagmo_pop_free(zp_pagmo_pop *d) {
    delete d;
}

extern "C" int zp_pagmo_pop_evolve(zp_pagmo_pop *d, int gens, zp_pagmo_pop_fitness fit,
                                   void *user) {
    d->ctx = context{fit, user};
    try {
        if (!d->pop) {
            d->algo.emplace(
                make_algorithm(d->kind, seed32(d->seed), d->at ? d->sigma0 : sigma_drawn));
            if (d->at) {
                d->pop.emplace(pagmo::problem(d->prob), 0u, seed32(d->seed >> 1));
                for (int i = 0; i < d->popsize; i++) {
                    d->pop->push_back(d->x0, pagmo::vector_double{d->f0});
                }
                d->at = false;
            } else {
                d->pop.emplace(pagmo::problem(d->prob),
                               static_cast<pagmo::population::size_type>(d->popsize),
                               seed32(d->seed >> 1));
            }
            d->seed += seed_step;
        }
        for (int g = 0; g < gens && d->pop; g++) {
            *d->pop = d->algo->evolve(*d->pop);
            if (collapsed(*d->pop)) {
                d->pop.reset(); // the next evolution draws a fresh one
            }
        }
    } catch (...) {
        d->ctx = context{};
        return -1;
    }
    d->ctx = context{};
    return 0;
}

extern "C" int zp_pagmo_pop_best(const zp_pagmo_pop *d, double *x, double *value) {
    if (!d->pop) {
        return -1;
    }
    try {
        const auto i = d->pop->best_idx();
        const auto &best = d->pop->get_x()[i];
        std::copy(best.begin(), best.end(), x);
        *value = d->pop->get_f()[i][0];
    } catch (...) {
        return -1;
    }
    return 0;
}
