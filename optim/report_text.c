/* The search's text summary (report_text.h). */
#include "report_text.h"

#include <math.h>

#include "report.h"
#include "report_cable.h"

/* why no schedule was found, when none was, or why the answer is not the search's best */
static void none_text(FILE *f, const zp_answer *a) {
    const zp_answer_fallback *fb = &a->fallback;
    if (a->unheld[0] && fb->tried > 0) {
        fprintf(f,
                "no schedule found: the search's best (ranked with [optimize]'s tolerance) does "
                "not hold: %s; nor do the next %d candidate%s it kept; the best is written as the "
                "closest candidate (tighten [optimize] rtol)\n",
                a->unheld, fb->tried, fb->tried == 1 ? "" : "s");
    } else if (a->unheld[0]) {
        fprintf(f,
                "no schedule found: the search's best (ranked with [optimize]'s tolerance) does "
                "not hold: %s; it is written as the closest candidate (tighten [optimize] rtol)\n",
                a->unheld);
    } else if (fb->taken) {
        char why[512];
        zp_report_fallback(why, sizeof why, a);
        fprintf(f, "fallback: %s\n", why);
    } else if (!a->found) {
        fprintf(f,
                "no schedule keeps the margin%s: none of %ld simulations survived with it; the "
                "closest candidate is written, marked as such\n",
                a->rp.robust || zp_limits_any(&a->pb->lim)
                    ? ", the [limits] and the [robust] scenarios"
                    : "",
                a->res.evals);
    }
}

/* the fresh scenarios' verdict and how far past the stated ranges the answer holds */
static void robust_text(FILE *f, const zp_answer *a) {
    const zp_robust_check *c = &a->rp.check;
    fprintf(f,
            "robust: held to %d scenarios (%d added by the adversary); on %d fresh ones %d "
            "finished, %d kept the margin, %d every limit: P(survivable) >= %.4f (95 %%)\n",
            a->rp.set.n, a->rp.info.added, c->samples, c->survived, c->margin_kept, c->limits_kept,
            c->lower_95);
    const zp_headroom_line *L = &c->headroom.line[ZP_HEADROOM_LINES - 1];
    if (L->range >= 0 && isfinite(L->breaks)) {
        fprintf(f,
                "headroom: holds to %.4fx the stated ranges along the worst direction found, "
                "breaks at %.4fx (%s)%s\n",
                L->holds, L->breaks, L->limited_by,
                zp_headroom_inside(&c->headroom) ? ": inside the stated ranges, so not every "
                                                   "scenario in them is survivable"
                                                 : "");
    } else if (L->range >= 0) {
        fprintf(f,
                "headroom: holds to %.4fx the stated ranges or more along the worst "
                "direction found\n",
                L->holds);
    }
}

void zp_report_text_write(FILE *f, const zp_answer *a) {
    const zp_problem *p = a->pb;
    const zp_search_result *s = &a->res;
    const zp_result *run = a->v.run;
    none_text(f, a);
    fprintf(f, "%sbest schedule (%s):", s->interrupted ? "interrupted; " : "",
            zp_drive_unit(&p->sched));
    for (int k = 0; k < p->sched.np; k++) {
        fprintf(f, " %.4f", s->force[k]);
    }
    double angle = zp_model_angle_used(p->m, run->max_rel_angle);
    fprintf(f, "\noutcome: %s, time %.4f s (+/- %.1e s), margin %.2f deg%s\n",
            zp_sim_outcome_name(run->outcome), run->time, fabs(run->time - a->v.tight->time),
            p->sc.death_angle - angle * 180 / M_PI,
            a->v.agree ? ", verified" : ", NOT verified at the tighter tolerance");
    if (s->base_found) {
        fprintf(f, "best constant push: %.3f N, %.4f s", s->base_force, s->base.time);
        if (a->push.npts > 0) {
            fprintf(f, " (%ld runs besides the search: %d pushes on a grid, then the fastest "
                       "bands' edges)",
                    a->push.evals, a->push.npts);
        } else if (a->rp.robust) { /* no scan of its own: it would run the scenarios per push */
            fputs(" (the fastest of the search's pushes that held the scenarios)", f);
        }
        fputc('\n', f);
    } else {
        fprintf(f, "best constant push: none the search ran survived (finished within the margin, "
                   "[limits] and held scenarios)\n");
    }
    const zp_answer_constant *c = &a->constant;
    if (c->ran && c->found && run->outcome == ZP_OUTCOME_FINISHED) {
        fprintf(f,
                "profile gain: %.4f s against %.4f s for the best constant-per-section "
                "schedule (the same search), %.4f s (%.1f %%) faster\n",
                run->time, c->time, c->time - run->time, 100 * (c->time - run->time) / c->time);
    } else if (c->ran) {
        fprintf(f, "profile gain: the same search over one force per section found none that "
                   "holds\n");
    }
    fprintf(f, "search: %s, %ld simulations in %.2f s on %d threads\n", a->algo, s->evals,
            s->wall_s, s->nthreads);
    if (a->rp.robust) {
        robust_text(f, a);
    }
    zp_report_cable_text(f, a);
    char conv[512];
    zp_report_convergence(conv, sizeof conv, a);
    fprintf(f, "convergence: %s\n", conv);
}
