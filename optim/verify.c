/* Verification of the best schedule (issue 4 item 4): the same run at a 100x tighter
   tolerance, then seeded random perturbations of every force and, force by force, the
   smallest change that kills. */
#include "verify.h"

#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define KILL_TOL 1e-4 /* relative precision of the smallest deadly change, per force */

static const double levels[ZP_VERIFY_LEVELS] = {0.02, 0.05};

static uint64_t splitmix(uint64_t *s) {
    uint64_t z = (*s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static int died(const zp_eval *e) { return e->failed || e->outcome == ZP_OUTCOME_DIED; }

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
static double kill_of(const zp_objective *ob, zp_sim *s, zp_result *r, const double *force,
                      int k) {
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

void zp_verify_free(zp_verify *v) {
    free(v->run);
    free(v->tight);
    v->run = v->tight = NULL;
}

zp_status zp_verify_run(const zp_objective *ob, const zp_sim_opts *so, const double *force,
                        unsigned long seed, int nrobust, int nthreads, zp_sim **sim_out,
                        zp_verify *v, char *err, size_t errlen) {
    const zp_model *m = ob->m;
    int nsec = m->nsec;
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
    if (nrobust <= 0) {
        return ZP_OK;
    }

    /* robustness: seeded perturbations drawn up front, run in parallel, counted in order */
    zp_sim_opts fast = *so;
    fast.output_dt = 0;
    fast.track_loads = 0;
    int nw = nthreads > 0 ? nthreads : omp_get_max_threads();
    int ntot = ZP_VERIFY_LEVELS * nrobust;
    double *pf = malloc(sizeof *pf * ntot * nsec);
    zp_eval *pe = malloc(sizeof *pe * ntot);
    double *kill = calloc(nsec, sizeof *kill);
    zp_sim **ws = calloc(nw, sizeof *ws);
    zp_result **wr = calloc(nw, sizeof *wr);
    zp_status ret = pf && pe && kill && ws && wr ? ZP_OK : ZP_ERR_NOMEM;
    for (int i = 0; ret == ZP_OK && i < nw; i++) {
        ws[i] = zp_sim_create(m, &fast);
        wr[i] = malloc(sizeof *wr[i]);
        ret = ws[i] && wr[i] ? ZP_OK : ZP_ERR_NOMEM;
    }
    if (ret != ZP_OK) {
        snprintf(err, errlen, "out of memory for the robustness runs");
        goto done;
    }
    uint64_t rng = seed;
    for (int i = 0; i < ntot; i++) {
        double level = levels[i / nrobust];
        for (int k = 0; k < nsec; k++) {
            double u = 2 * ((splitmix(&rng) >> 11) * 0x1.0p-53) - 1;
            pf[(size_t)i * nsec + k] = force[k] * (1 + level * u);
        }
    }
#pragma omp parallel num_threads(nw)
    {
        int t = omp_get_thread_num();
#pragma omp for schedule(dynamic, 4) nowait
        for (int i = 0; i < ntot; i++) {
            zp_objective_eval(ob, ws[t], pf + (size_t)i * nsec, &pe[i], wr[t]);
        }
#pragma omp for schedule(dynamic, 1)
        for (int k = 0; k < nsec; k++) {
            kill[k] = kill_of(ob, ws[t], wr[t], force, k);
        }
    }
    for (int i = 0; i < ntot; i++) {
        zp_robust *rb = &v->rob[i / nrobust];
        rb->level = levels[i / nrobust];
        rb->n++;
        rb->survived += pe[i].outcome == ZP_OUTCOME_FINISHED && !pe[i].failed;
        rb->kept += zp_objective_feasible(&pe[i]);
        if (died(&pe[i])) {
            /* the size of this mixed change: its largest relative part */
            double size = 0;
            for (int k = 0; k < nsec; k++) {
                if (force[k] != 0) {
                    size = fmax(size, fabs(pf[(size_t)i * nsec + k] / force[k] - 1));
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
        if (kill[k] > 0 && (!v->kill_found || kill[k] < v->kill)) {
            v->kill_found = 1;
            v->kill = kill[k];
            v->kill_section = k + 1;
        }
    }
    v->robust_done = 1;
done:
    for (int i = 0; ws && i < nw; i++) {
        zp_sim_free(ws[i]);
        free(wr[i]);
    }
    free(pf);
    free(pe);
    free(kill);
    free(ws);
    free(wr);
    return ret;
}
