/* Verification of the best schedule: the same run at a 100x tighter
   tolerance, then seeded random perturbations of every force and, force by force, the
   smallest change that kills. */
#include "verify.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define KILL_TOL 1e-4 /* relative precision of the smallest deadly change, per force */

static const double levels[ZP_VERIFY_LEVELS] = {0.02, 0.05};

static int died(const zp_eval *e) {
    return e->failed || e->outcome == ZP_OUTCOME_DIED;
}

/* one force changed by the relative amount s: does the spy die? */
static int kills(const zp_objective *ob, zp_sim *s, zp_result *r, const double *force, int k,
                 double rel) {
    double f[ZP_MAX_SECTIONS];
    memcpy(f, force, sizeof *f * ob->m->nsec);
    f[k] *= 1 + rel;
    zp_eval e;
    zp_objective_eval(ob, s, f, &e, r);
    return died(&e);
}

/* the smallest change of force k, either way, that kills (bisection), or 0 when none within
   the largest level */
static double kill_of(const zp_objective *ob, zp_sim *s, zp_result *r, const double *force, int k) {
    double best = 0;
    for (int sign = -1; sign <= 1; sign += 2) {
        double top = levels[ZP_VERIFY_LEVELS - 1];
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

/* the robustness runs: ntot perturbed schedules, then one bisection per force */
typedef struct robust_batch {
    const zp_objective *ob;
    const double *force;
    int ntot;
    double *pf;   /* owned, ntot x nsec: the perturbed forces */
    zp_eval *pe;  /* owned, ntot */
    double *kill; /* owned, nsec */
} robust_batch;

static void robust_job(void *user, int i, zp_sim *s, zp_result *r) {
    robust_batch *b = user;
    int nsec = b->ob->m->nsec;
    if (i < b->ntot) {
        zp_objective_eval(b->ob, s, b->pf + (size_t)i * nsec, &b->pe[i], r);
    } else {
        b->kill[i - b->ntot] = kill_of(b->ob, s, r, b->force, i - b->ntot);
    }
}

/* the tally of the robustness runs, in order: survivors per level and the smallest kill */
static void tally(zp_verify *v, const robust_batch *b, int nrobust) {
    int nsec = b->ob->m->nsec;
    const double *force = b->force;
    for (int i = 0; i < b->ntot; i++) {
        const zp_eval *e = &b->pe[i];
        zp_robust *rb = &v->rob[i / nrobust];
        rb->level = levels[i / nrobust];
        rb->n++;
        rb->survived += e->outcome == ZP_OUTCOME_FINISHED && !e->failed;
        rb->kept += zp_objective_feasible(e);
        if (died(e)) {
            /* the size of this mixed change: its largest relative part */
            double size = 0;
            for (int k = 0; k < nsec; k++) {
                if (force[k] != 0) {
                    size = fmax(size, fabs(b->pf[(size_t)i * nsec + k] / force[k] - 1));
                }
            }
            if (!v->kill_found || size < v->kill) {
                v->kill_found = 1;
                v->kill = size;
                v->kill_section = 0;
            }
        }
    }
    for (int k = 0; k < nsec; k++) {
        if (b->kill[k] > 0 && (!v->kill_found || b->kill[k] < v->kill)) {
            v->kill_found = 1;
            v->kill = b->kill[k];
            v->kill_section = k + 1;
        }
    }
    v->robust_done = 1;
}

/* seeded perturbations drawn up front, run in parallel, counted in order */
static zp_status robustness(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                            unsigned long seed, int nrobust, int nthreads, zp_verify *v,
                            zp_pool_done progress, void *user, char *err, size_t errlen) {
    int nsec = ob->m->nsec, ntot = ZP_VERIFY_LEVELS * nrobust;
    zp_sim_opts fast = *so;
    fast.output_dt = 0;
    fast.track_loads = 0;
    robust_batch b = {ob,
                      force,
                      ntot,
                      malloc(sizeof *b.pf * ntot * nsec),
                      malloc(sizeof *b.pe * ntot),
                      calloc(nsec, sizeof *b.kill)};
    zp_pool *pool = zp_pool_create(ob->m, &fast, nthreads);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    zp_status ret = b.pf && b.pe && b.kill && pool && g ? ZP_OK : ZP_ERR_NOMEM;
    if (ret == ZP_OK) {
        gsl_rng_set(g, seed);
        for (int i = 0; i < ntot; i++) {
            for (int k = 0; k < nsec; k++) {
                double u = 2 * gsl_rng_uniform(g) - 1;
                b.pf[(size_t)i * nsec + k] = force[k] * (1 + levels[i / nrobust] * u);
            }
        }
        /* the perturbed runs, then force by force the bisection for the smallest deadly change */
        zp_pool_map(pool, ntot + nsec, robust_job, &b, progress, user);
        tally(v, &b, nrobust);
    } else {
        snprintf(err, errlen, "out of memory for the robustness runs");
    }
    gsl_rng_free(g);
    zp_pool_free(pool);
    free(b.pf);
    free(b.pe);
    free(b.kill);
    return ret;
}

void zp_verify_free(zp_verify *v) {
    free(v->run);
    free(v->tight);
    v->run = v->tight = NULL;
}

zp_status zp_verify_run(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                        unsigned long seed, int nrobust, int nthreads, zp_sim **sim_out,
                        zp_verify *v, zp_pool_done progress, void *user, char *err, size_t errlen) {
    const zp_model *m = ob->m;
    memset(v, 0, sizeof *v);
    *sim_out = NULL;
    zp_sim_opts to = zp_estimate_tighter(so);
    v->rtol = to.rtol;
    v->atol = to.atol;
    v->run = malloc(sizeof *v->run);
    v->tight = malloc(sizeof *v->tight);
    zp_sim *s = zp_sim_create(m, so), *st = zp_sim_create(m, &to);
    if (!v->run || !v->tight || !s || !st) {
        zp_sim_free(s);
        zp_sim_free(st);
        snprintf(err, errlen, "out of memory for the verification");
        return ZP_ERR_NOMEM;
    }
    *sim_out = s;
    zp_schedule sched = zp_objective_schedule(ob, force);
    zp_input in = {.sched = &sched};
    if (zp_sim_run(m, s, &in, v->run) || zp_sim_run(m, st, &in, v->tight)) {
        snprintf(err, errlen, "re-running the best schedule: %s",
                 v->run->message[0] ? v->run->message : v->tight->message);
        zp_sim_free(st);
        return ZP_ERR_NUMERIC;
    }
    zp_sim_free(st);
    double angle = 0;
    for (int i = 0; i < m->nlink; i++) {
        angle = fmax(angle, v->tight->max_rel_angle[i]);
    }
    v->agree = v->run->outcome == v->tight->outcome &&
               fabs(v->run->time - v->tight->time) <= ZP_VERIFY_DT && angle <= ob->limit;
    return nrobust > 0
               ? robustness(ob, so, force, seed, nrobust, nthreads, v, progress, user, err, errlen)
               : ZP_OK;
}
