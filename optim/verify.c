/* Verification of the best schedule: the same run at a 100x tighter tolerance, seeded random
   perturbations of every parameter and, parameter by parameter, the smallest change that kills,
   in one parallel batch (the tighter run in it, or first alone when the caller judges by it);
   and the answer rerun tighter when [solver] accuracy asks for more. */
#include "verify.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "problem.h"

#define KILL_TOL 1e-4 /* relative precision of the smallest deadly change, per parameter */

/* the perturbation levels when the caller sets none */
static const double default_levels[ZP_VERIFY_LEVELS] = {0.02, 0.05};

static int died(const zp_eval *e) {
    return e->failed || e->outcome == ZP_OUTCOME_DIED;
}

/* one parameter changed by the relative amount s: does the spy die? */
static int kills(const zp_objective *ob, zp_sim *s, zp_result *r, const double *force, int k,
                 double rel) {
    double f[ZP_SCHED_MAX_PARAMS];
    memcpy(f, force, sizeof *f * zp_objective_nparams(ob));
    f[k] *= 1 + rel;
    zp_eval e;
    zp_objective_eval(ob, s, f, &e, r);
    return died(&e);
}

/* the smallest change of parameter k, either way, that kills (bisection), or 0 when none within
   the largest level */
static double kill_of(const zp_objective *ob, zp_sim *s, zp_result *r, const double *force, int k,
                      double top) {
    double best = 0;
    for (int sign = -1; sign <= 1; sign += 2) {
        if (force[k] == 0 || !kills(ob, s, r, force, k, sign * top)) {
            continue;
        }
        double lo = 0, hi = top;
        while (hi - lo > KILL_TOL) {
            double mid = 0.5 * (lo + hi);
            if (kills(ob, s, r, force, k, sign * mid)) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        best = best == 0 ? hi : fmin(best, hi);
    }
    return best;
}

/* The checks of one batch, longest first so no long job is left to run alone at the end: the
   bisections (chains of runs), the tighter run (with_tight), then the perturbed schedules. */
typedef struct check_batch {
    const zp_objective *ob;
    const double *force;
    int nkill, ntot;   /* bisections (0 without robustness) and perturbed runs */
    int with_tight;    /* 1: job nkill is the tighter run */
    zp_sim *tight_sim; /* owned: the tighter run's workspace, NULL without it */
    const zp_input *in;
    zp_verify *v;
    zp_status tight_st;
    double *pf;   /* owned, ntot x np: the perturbed parameters */
    zp_eval *pe;  /* owned, ntot */
    double *kill; /* owned, nkill */
} check_batch;

static void check_job(void *user, int i, zp_sim *s, zp_result *r) {
    check_batch *b = user;
    int np = zp_objective_nparams(b->ob);
    if (i < b->nkill) {
        b->kill[i] = kill_of(b->ob, s, r, b->force, i, b->v->level[ZP_VERIFY_LEVELS - 1]);
    } else if (b->with_tight && i == b->nkill) {
        b->tight_st = zp_sim_run(b->ob->m, b->tight_sim, b->in, b->v->tight);
    } else {
        int k = i - b->nkill - b->with_tight;
        zp_objective_eval(b->ob, s, b->pf + (size_t)k * np, &b->pe[k], r);
    }
}

/* the tally of the robustness runs, in order: survivors per level and the smallest kill */
static void tally(zp_verify *v, const check_batch *b, int nrobust) {
    int np = zp_objective_nparams(b->ob);
    const double *force = b->force;
    for (int i = 0; i < b->ntot; i++) {
        const zp_eval *e = &b->pe[i];
        zp_robust *rb = &v->rob[i / nrobust];
        rb->level = v->level[i / nrobust];
        rb->n++;
        rb->survived += e->outcome == ZP_OUTCOME_FINISHED && !e->failed;
        rb->kept += zp_objective_feasible(e);
        if (died(e)) {
            /* the size of this mixed change: its largest relative part */
            double size = 0;
            for (int k = 0; k < np; k++) {
                if (force[k] != 0) {
                    size = fmax(size, fabs(b->pf[(size_t)i * np + k] / force[k] - 1));
                }
            }
            if (!v->kill_found || size < v->kill) {
                v->kill_found = 1;
                v->kill = size;
                v->kill_param = 0;
            }
        }
    }
    for (int k = 0; k < np; k++) {
        if (b->kill[k] > 0 && (!v->kill_found || b->kill[k] < v->kill)) {
            v->kill_found = 1;
            v->kill = b->kill[k];
            v->kill_param = k + 1;
        }
    }
    v->robust_done = 1;
}

/* the seeded perturbations, drawn up front in one stream: ntot rows of np parameters */
static void perturb(const double *force, int np, unsigned long seed, int nrobust,
                    const double *levels, double *pf, gsl_rng *g) {
    gsl_rng_set(g, seed);
    for (int i = 0; i < ZP_VERIFY_LEVELS * nrobust; i++) {
        for (int k = 0; k < np; k++) {
            double u = 2 * gsl_rng_uniform(g) - 1;
            pf[(size_t)i * np + k] = force[k] * (1 + levels[i / nrobust] * u);
        }
    }
}

/* the run and the tighter run agree: same outcome, close finish times, margin kept */
static void agree(const zp_objective *ob, zp_verify *v) {
    double angle = zp_model_angle_used(ob->m, v->tight->max_rel_angle);
    v->agree = v->run->outcome == v->tight->outcome &&
               fabs(v->run->time - v->tight->time) <= ZP_VERIFY_DT && angle <= ob->limit;
}

void zp_verify_free(zp_verify *v) {
    free(v->run);
    free(v->tight);
    v->run = v->tight = NULL;
}

zp_status zp_verify_begin(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                          zp_sim **sim_out, zp_verify *v, char *err, size_t errlen) {
    const zp_model *m = ob->m;
    memset(v, 0, sizeof *v);
    *sim_out = zp_sim_create(m, so);
    v->run = malloc(sizeof *v->run);
    v->tight = malloc(sizeof *v->tight);
    if (!v->run || !v->tight || !*sim_out) {
        snprintf(err, errlen, "out of memory for the verification");
        return ZP_ERR_NOMEM;
    }
    zp_schedule sched = zp_objective_schedule(ob, force);
    zp_input in = {.sched = &sched};
    if (zp_sim_run(m, *sim_out, &in, v->run)) {
        snprintf(err, errlen, "re-running the best schedule: %s", v->run->message);
        return ZP_ERR_NUMERIC;
    }
    return ZP_OK;
}

/* the checks of force in one parallel batch: with_tight, the tighter run (v->rtol, atol and
   agree); nrobust > 0, the robustness runs and bisections (v->rob, kill) */
static zp_status check(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                       unsigned long seed, int nrobust, int with_tight, int nthreads, zp_verify *v,
                       zp_pool_done progress, void *user, char *err, size_t errlen) {
    const zp_model *m = ob->m;
    int np = zp_objective_nparams(ob), ntot = ZP_VERIFY_LEVELS * nrobust;
    if (!(v->level[0] > 0)) {
        memcpy(v->level, default_levels, sizeof v->level);
    }
    zp_sim_opts to = zp_estimate_tighter(so), fast = zp_problem_verdict(so);
    if (with_tight) {
        v->rtol = to.rtol;
        v->atol = to.atol;
    }
    zp_schedule sched = zp_objective_schedule(ob, force);
    zp_input in = {.sched = &sched};
    check_batch b = {.ob = ob,
                     .force = force,
                     .nkill = nrobust > 0 ? np : 0,
                     .ntot = ntot,
                     .with_tight = with_tight,
                     .tight_sim = with_tight ? zp_sim_create(m, &to) : NULL,
                     .in = &in,
                     .v = v};
    b.pf = malloc(sizeof *b.pf * (ntot + 1) * np);
    b.pe = malloc(sizeof *b.pe * (ntot + 1));
    b.kill = calloc(np, sizeof *b.kill);
    /* the tighter run alone: no pool of workspaces for one job */
    zp_pool *pool = nrobust > 0 ? zp_pool_create(m, &fast, nthreads) : NULL;
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    int made = (b.tight_sim || !with_tight) && b.pf && b.pe && b.kill && (pool || !nrobust) && g;
    zp_status ret = made ? ZP_OK : ZP_ERR_NOMEM;
    if (ret == ZP_OK && pool) {
        perturb(force, np, seed, nrobust, v->level, b.pf, g);
        zp_pool_map(pool, b.nkill + with_tight + ntot, check_job, &b, progress, user);
    } else if (ret == ZP_OK && with_tight) {
        check_job(&b, 0, NULL, NULL);
    }
    if (ret == ZP_OK) {
        if (b.tight_st) {
            snprintf(err, errlen, "re-running the best schedule: %s", v->tight->message);
            ret = ZP_ERR_NUMERIC;
        } else if (nrobust > 0) {
            tally(v, &b, nrobust);
        }
    } else {
        snprintf(err, errlen, "out of memory for the verification");
    }
    if (ret == ZP_OK && with_tight) {
        agree(ob, v);
    }
    gsl_rng_free(g);
    zp_pool_free(pool);
    zp_sim_free(b.tight_sim);
    free(b.pf);
    free(b.pe);
    free(b.kill);
    return ret;
}

zp_status zp_verify_tight(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                          zp_verify *v, char *err, size_t errlen) {
    return check(ob, so, force, 0, 0, 1, 0, v, NULL, NULL, err, errlen);
}

zp_status zp_verify_robustness(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                               unsigned long seed, int nrobust, int nthreads, zp_verify *v,
                               zp_pool_done progress, void *user, char *err, size_t errlen) {
    return nrobust > 0 ? check(ob, so, force, seed, nrobust, 0, nthreads, v, progress, user, err,
                               errlen)
                       : ZP_OK;
}

zp_status zp_verify_run(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                        unsigned long seed, int nrobust, int nthreads, zp_sim **sim_out,
                        zp_verify *v, zp_pool_done progress, void *user, char *err, size_t errlen) {
    zp_status st = zp_verify_begin(ob, so, force, sim_out, v, err, errlen);
    return st ? st
              : check(ob, so, force, seed, nrobust, 1, nthreads, v, progress, user, err, errlen);
}

/* the answer rerun from one step tighter than so until its estimate meets acc; then the
   verification's tighter run of that answer */
static zp_status rerun(const zp_objective *ob, const zp_sim_opts *so, const zp_input *in,
                       double acc, zp_sim **sim_out, zp_verify *v, zp_sim_opts *answer,
                       zp_accuracy *a, char *err, size_t errlen) {
    const zp_model *m = ob->m;
    zp_sim_opts t = zp_estimate_tighter(so);
    answer->rtol = t.rtol;
    answer->atol = t.atol;
    zp_sim *s = NULL;
    zp_estimate e;
    zp_result *r = malloc(sizeof *r);
    zp_status st = r ? zp_accuracy_run(m, answer, in, acc, &s, r, &e, a) : ZP_ERR_NOMEM;
    if (st) {
        snprintf(err, errlen, "re-running the best schedule for [solver] accuracy: %s",
                 r ? r->message : "out of memory");
        zp_sim_free(s);
        free(r);
        return st;
    }
    a->reruns++; /* the [solver] run was the first pick */
    zp_sim_free(*sim_out);
    *sim_out = s;
    free(v->run);
    v->run = r;
    zp_sim_opts to = zp_estimate_tighter(answer);
    v->rtol = to.rtol;
    v->atol = to.atol;
    zp_sim *ts = zp_sim_create(m, &to);
    st = ts ? zp_sim_run(m, ts, in, v->tight) : ZP_ERR_NOMEM;
    zp_sim_free(ts);
    if (st) {
        snprintf(err, errlen, "re-running the best schedule: %s",
                 ts ? v->tight->message : "out of memory");
        return st;
    }
    agree(ob, v);
    return ZP_OK;
}

zp_status zp_verify_accuracy(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                             double acc, zp_sim **sim_out, zp_verify *v, zp_sim_opts *answer,
                             zp_accuracy *a, char *err, size_t errlen) {
    *answer = *so;
    double met = fabs(v->run->time - v->tight->time);
    if (v->run->outcome == v->tight->outcome && met <= acc) {
        *a = (zp_accuracy){
            .requested = acc, .met = met, .ok = 1, .method = so->method, .rtol = so->rtol};
        return ZP_OK;
    }
    zp_schedule sched = zp_objective_schedule(ob, force);
    zp_input in = {.sched = &sched};
    return rerun(ob, so, &in, acc, sim_out, v, answer, a, err, errlen);
}
