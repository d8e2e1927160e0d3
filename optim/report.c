/* report.md of the search (docs/commands.md "Files"), one function per section. Angles in degrees,
   speeds in m/s and km/h, everything else SI. */
#include "report.h"

#include <math.h>

#include "headroom.h"
#include "report_cable.h"

#define DEG (180.0 / M_PI)
#define KMH 3.6
#define BRAKE_KMH 10  /* zip-line practice: arriving faster than this needs a brake */
#define ACTIVE_KMH 24 /* ... and active brakes stop riders up to about this */

void zp_report_fallback(char *buf, size_t n, const zp_answer *a) {
    const zp_answer_fallback *fb = &a->fallback;
    snprintf(buf, n,
             "the fastest ranked schedule (%.4f s at [optimize]'s tolerance) failed the rerun "
             "with [solver]: %s; the answer is the search's next candidate by ranked time (its "
             "island's best or a polish end; %d rejected), which holds",
             fb->first_time, fb->why, fb->tried);
}

static const char *rerun_scene(const zp_report_place *w) {
    return w->scene_arg ? w->scene_arg : "config/seed.ini";
}

void zp_report_convergence(char *buf, size_t n, const zp_answer *a) {
    const zp_search_result *s = &a->res;
    int k = 0;
    if (!a->found) {
        k = snprintf(buf, n, "no survivable schedule was found in %d rounds", s->nrounds);
    } else if (s->nstarts == 0) {
        k = snprintf(buf, n, "the scan found this schedule; no local polish ran");
    } else {
        /* with a fallback taken the polishes' count is of the rejected fastest schedule */
        k = snprintf(buf, n,
                     "%d of %d polishes reached %s (within %g %% of its "
                     "time); they ended at %d distinct survivable schedule%s, in %d "
                     "basin%s (the map's islands, or apart from them)",
                     s->nreached, s->nstarts,
                     a->fallback.taken ? "the fastest ranked schedule, which failed its rerun"
                                       : "this schedule",
                     100 * ZP_SEARCH_REACH, s->nbasins,
                     s->nbasins == 1 ? "" : "s", s->nminima, s->nminima == 1 ? "" : "s");
    }
    char unseen[160] = "";
    if (s->nstarts > 0 && isfinite(s->unseen)) {
        snprintf(unseen, sizeof unseen,
                 "; Boender and Rinnooy Kan's estimate from them: %.2f basins not yet visited",
                 s->unseen);
    } else if (s->nstarts > 0) {
        snprintf(unseen, sizeof unseen,
                 "; too few polishes for that many minima to estimate the basins not yet "
                 "visited (Boender and Rinnooy Kan)");
    }
    char pops[160] = "", who[32];
    snprintf(who, sizeof who, s->npops == 1 ? "the population" : "the %d populations", s->npops);
    if (a->found && zp_search_populations_reached(s)) {
        snprintf(pops, sizeof pops, "; %s reached it too", who);
    } else if (a->found && s->npops > 0 && isfinite(s->pops_best)) {
        snprintf(pops, sizeof pops,
                 "; %s had not reached it (%s fastest: %.4f s), so the search has not "
                 "converged",
                 who, s->npops == 1 ? "its" : "their", s->pops_best);
    } else if (a->found && s->npops > 0) {
        snprintf(pops, sizeof pops, "; %s had found nothing survivable", who);
    }
    char tail[300];
    double cable_max = a->pb->lim.max[ZP_LIMIT_CABLE_TENSION];
    double floor = cable_max > 0 ? zp_limits_cable_floor(a->pb->m) : 0;
    if (!a->found && floor > cable_max) {
        snprintf(tail, sizeof tail,
                 "; no schedule can keep max_cable_tension = %.0f N: every ride that finishes "
                 "loads an anchor to %.0f N, which the rider's weight sets, not the drive: a "
                 "larger budget cannot help",
                 cable_max, floor);
    } else if (s->converged) {
        /* the estimate counts the basins the polishes' starts can reach, which come from the
           map: an island the map never touched is not in it (docs/search.md, m4_8link) */
        snprintf(tail, sizeof tail,
                 "; the last round found nothing better: a larger budget of this search is "
                 "unlikely to help (islands its map never reached are not counted: another "
                 "--algorithm may find one)");
    } else if (s->interrupted) {
        snprintf(tail, sizeof tail, "; interrupted before the search converged");
    } else if (s->timed_out || s->budget_out) {
        snprintf(tail, sizeof tail,
                 "; the %s ran out first: a larger budget may help (about --max-evals %ld)",
                 s->timed_out ? "time (--max-time)" : "budget", s->help_evals);
    } else {
        snprintf(tail, sizeof tail,
                 "; the search's %d rounds ran out first: a larger budget would run nothing more",
                 s->nrounds);
    }
    if (k >= 0 && (size_t)k < n) {
        snprintf(buf + k, n - k, "%s%s%s", unseen, pops, tail);
    }
}

static void md_islands(FILE *f, const zp_search_result *s, const zp_schedule *shape) {
    fprintf(f, "- the map: %d island%s of near-survivable schedules, %d of them polished",
            s->nislands, s->nislands == 1 ? "" : "s", s->npolished);
    if (s->nshown > 0) {
        fputs("; the fastest survivable point of each of the best:", f);
    }
    fputs("\n", f);
    for (int i = 0; i < s->nshown; i++) {
        fprintf(f, "  %d. %.4f s at", i + 1, s->island_time[i]);
        for (int k = 0; k < shape->np; k++) {
            fprintf(f, "%s %.2f", k ? "," : "", s->island_force[i][k]);
        }
        fprintf(f, " %s (%d survivable point%s mapped)\n", zp_drive_unit(shape), s->island_pts[i],
                s->island_pts[i] == 1 ? "" : "s");
    }
}

static void md_gain(FILE *f, const char *what, double t_best, double t_other) {
    fprintf(f, "- over %s: %.3f s faster (%.1f %%)\n", what, t_other - t_best,
            100 * (t_other - t_best) / t_other);
}

static void md_head(FILE *f, const zp_answer *a) {
    fprintf(f, "# Best forcing: %s\n\n", a->pb->sc.name);
    if (a->res.interrupted) {
        fputs("**Interrupted**: the search was stopped before its end; this is the best found "
              "so far.\n\n",
              f);
    }
    if (!a->found) {
        fputs("**No survivable schedule was found** within the budget: below is the schedule "
              "that came closest.\n\n",
              f);
    }
    const zp_answer_fallback *fb = &a->fallback;
    if (fb->taken) {
        char why[512];
        zp_report_fallback(why, sizeof why, a);
        fprintf(f, "**Fallback**: %s.\n\n", why);
    } else if (fb->tried > 0) {
        fprintf(f,
                "The search's best (%.4f s at [optimize]'s tolerance) failed the rerun with "
                "[solver]: %s; the next %d candidate%s it kept failed it too.\n\n",
                fb->first_time, fb->why, fb->tried, fb->tried == 1 ? "" : "s");
    }
}

/* one row per parameter: the section it acts on, where on the course, its value */
static void md_schedule(FILE *f, const zp_answer *a) {
    const zp_model *m = a->pb->m;
    const zp_schedule *sh = &a->pb->sched;
    const char *unit = zp_drive_unit(sh);
    fprintf(f,
            "## Schedule\n\n| section | x from (m) | x to (m) | force (%s) |\n"
            "|---|---|---|---|\n",
            unit);
    for (int k = 0; k < sh->np; k++) {
        double from, to;
        zp_drive_param_span(sh, k, m->xb, &from, &to);
        fprintf(f, "| %d | %g | %g | %.4f |\n", zp_drive_param_section(sh, k) + 1, from, to,
                a->res.force[k]);
    }
    double lo, hi;
    zp_drive_constant_bounds(sh, &lo, &hi);
    fprintf(f, "\nDrive: %s; bounds [%g, %g] %s.\n\n", zp_drive_dir_name(m->drive), lo, hi, unit);
}

static void md_result(FILE *f, const zp_answer *a) {
    const zp_verify *v = &a->v;
    const zp_result *run = v->run;
    fputs("## Result\n\n", f);
    double err = fabs(run->time - v->tight->time);
    if (run->outcome == ZP_OUTCOME_FINISHED) {
        fprintf(f,
                "Finish time: **%.4f s** (error estimate %.1e s: the same run at a %gx "
                "tighter tolerance finishes at %.6f s).\n",
                run->time, err, ZP_ESTIMATE_FACTOR, v->tight->time);
    } else {
        fprintf(f, "Outcome: **%s** at t = %.4f s, x = %.2f m.\n",
                zp_sim_outcome_name(run->outcome), run->time, run->x);
    }
    if (a->pb->sc.objective_slowest && a->rp.robust) {
        fprintf(f, "\nThe search minimised the slowest finish over the nominal scene and the %d "
                   "scenarios held ([optimize] objective = slowest): %.4f s for this schedule "
                   "(at the search's tolerance); the nominal rider's is above.\n",
                a->rp.set.n, a->res.best.obj);
    }
    fprintf(f, "Verification at rtol %.0e, atol %.0e: ", v->rtol, v->atol);
    if (v->agree) {
        fprintf(f, "same outcome, finish times agree within %g s, margin kept.\n\n", ZP_VERIFY_DT);
    } else {
        fputs("**does not agree** (outcome, finish time or margin differ).\n\n", f);
    }
}

static void md_margins(FILE *f, const zp_answer *a) {
    const zp_scene *sc = &a->pb->sc;
    const zp_model *m = a->pb->m;
    fprintf(f,
            "## Margin per joint\n\nDeath at %g deg; the search keeps %g deg below it "
            "(limit %g deg).\n\n| joint | largest relative angle (deg) | margin (deg) |\n"
            "|---|---|---|\n",
            sc->death_angle, sc->margin, sc->death_angle - sc->margin);
    for (int i = 0; i < m->nlink; i++) {
        double angle = a->v.run->max_rel_angle[i] * DEG;
        fprintf(f, "| %d | %.3f | %.3f |\n", i + 1, angle, m->phi_max_j[i] * DEG - angle);
    }
}

void zp_report_breaks(const zp_problem *p, const zp_result *run, char *out, size_t cap) {
    static const char *const said[] = {[ZP_BREAKS_NOTHING] = "", [ZP_BREAKS_DEATH] = "death",
                                       [ZP_BREAKS_STALL] = "a stall",
                                       [ZP_BREAKS_MARGIN] = "the margin"};
    int which;
    zp_breaks b = zp_problem_breaks(p, run, &which);
    snprintf(out, cap, "%s", b == ZP_BREAKS_LIMIT ? zp_limits_name(which) : said[b]);
}

/* a profile's gain over the best constant-per-section schedule of the same scene */
static void md_profile_gain(FILE *f, const zp_answer *a) {
    const zp_answer_constant *c = &a->constant;
    if (!c->ran) {
        return;
    }
    char forces[256] = "";
    for (int k = 0, len = 0; k < c->nsec && len < (int)sizeof forces; k++) {
        len += snprintf(forces + len, sizeof forces - (size_t)len, "%s%.3f", k ? ", " : "",
                        c->force[k]);
    }
    if (!c->found) {
        fprintf(f,
                "- over the best constant-per-section schedule: missing (the same search over "
                "one force per section, %ld simulations, found none that holds)\n",
                c->evals);
        return;
    }
    char what[400];
    snprintf(what, sizeof what,
             "the best constant-per-section schedule of the same scene (the same search, budget "
             "and seed over one force per section: %s N, %.4f s; this profile %.4f s)",
             forces, c->time, a->v.run->time);
    md_gain(f, what, a->v.run->time, c->time);
}

static void md_gains(FILE *f, const zp_answer *a) {
    const zp_search_result *s = &a->res;
    const zp_schedule *shape = &a->pb->sched;
    const zp_result *run = a->v.run, *study = a->given;
    int fin = run->outcome == ZP_OUTCOME_FINISHED;
    fputs("\n## Gain\n\n", f);
    if (fin && s->base_found) {
        char what[128];
        snprintf(what, sizeof what, "the best constant push (%.3f N, %.4f s)", s->base_force,
                 s->base.time);
        md_gain(f, what, run->time, s->base.time);
    } else if (fin) {
        fputs("- over the best constant push: missing (no constant push the search ran survived: "
              "finished within the margin, [limits] and held scenarios)\n",
              f);
    }
    md_profile_gain(f, a);
    if (!study) {
        return;
    }
    char forces[256] = "", breaks[64];
    for (int k = 0, len = 0; k < shape->np && len < (int)sizeof forces; k++) {
        len += snprintf(forces + len, sizeof forces - (size_t)len, "%s%g", k ? ", " : "",
                        shape->p[k]);
    }
    zp_report_breaks(a->pb, study, breaks, sizeof breaks);
    if (fin && study->outcome == ZP_OUTCOME_FINISHED) {
        char what[400];
        snprintf(what, sizeof what, "the scene's own [drive] forces (%s N: %.4f s%s%s)", forces,
                 study->time, breaks[0] ? ", breaks " : "", breaks);
        md_gain(f, what, run->time, study->time);
    } else {
        fprintf(f, "- the scene's own [drive] forces (%s N) do not finish: %s at t = %.3f s, x = "
                   "%.2f m",
                forces, zp_sim_outcome_name(study->outcome), study->time, study->x);
        if (study->died_link) {
            fprintf(f, " (joint of link %d looped)", study->died_link);
        }
        fputs("\n", f);
    }
}

/* the drive a motor is bought for: its peak power, its energy, the time its cap bound */
static void md_drive(FILE *f, const zp_answer *a) {
    const zp_result *run = a->v.run;
    const zp_schedule *sh = &a->pb->sched;
    fputs("\n## Drive\n\n| peak power | energy | time at the power cap |\n|---|---|---|\n", f);
    char cap[64] = "no cap";
    if (sh->power > 0) {
        snprintf(cap, sizeof cap, "%.3f s (cap %.0f W)", run->drive_time_at_cap, sh->power);
    }
    fprintf(f, "| %.0f W | %.3f kJ | %s |\n", run->drive_peak_power, run->w_drive / 1000, cap);
}

/* the arrival judged by zip-line practice; braked: the scene's brake zone already slowed it */
static void md_speeds(FILE *f, const zp_result *run, int braked) {
    fputs("\n## Speeds\n\n", f);
    fprintf(f, "- arrival: %.2f m/s = %.1f km/h\n- peak: %.2f m/s = %.1f km/h\n\n", run->v,
            run->v * KMH, run->max_speed, run->max_speed * KMH);
    double arr = run->v * KMH;
    if (arr > ACTIVE_KMH) {
        fprintf(f,
                "Arrival above %d km/h%s: faster than active zip-line brakes stop (about %d "
                "km/h); this schedule needs a longer run-out or %s.\n\n",
                ACTIVE_KMH, braked ? " after the brake zone" : "", ACTIVE_KMH,
                braked ? "a stronger or longer brake zone" : "a braking section");
    } else if (braked) {
        fprintf(f,
                "Arrival at %.1f km/h after the brake zone: within what active zip-line "
                "brakes stop (about %d km/h).\n\n",
                arr, ACTIVE_KMH);
    } else if (arr > BRAKE_KMH) {
        fprintf(f,
                "Arrival above %d km/h: zip-line practice calls for a brake (active brakes "
                "stop up to about %d km/h).\n\n",
                BRAKE_KMH, ACTIVE_KMH);
    } else {
        fprintf(f, "Arrival at or below %d km/h: no brake needed by zip-line practice.\n\n",
                BRAKE_KMH);
    }
}

/* the brake zone: what it took out of the best run and how hard it braked: the deceleration
   of trolley and rider its force gives on entering, and the felt g (any link's centre) there
   and at its peak in the zone */
static void md_brake(FILE *f, const zp_answer *a) {
    const zp_model *m = a->pb->m;
    const zp_result *run = a->v.run;
    const zp_arc_peaks *zp = zp_sim_zone_peaks(a->best);
    double v = run->brake_speed_in, g = (m->brake_eddy * v + m->brake_friction) / (m->mtot * m->g);
    fprintf(f,
            "## Brake zone\n\nx from %g m to %g m: eddy %g N s/m, friction %g N. Brake work "
            "(energy taken out): %.0f J.\n\n",
            m->brake_zone[0], m->brake_zone[1], m->brake_eddy, m->brake_friction,
            run->w_effect[ZP_EFFECT_W_BRAKE]);
    if (v > 0) {
        fprintf(f,
                "Entering it at %.2f m/s = %.1f km/h, the brake decelerates trolley and rider "
                "at %.2f g (an eddy brake's force falls as the speed does). Braking g (felt "
                "acceleration of any link's centre): %.2f g on entering, peak %.2f g in the "
                "zone.\n\n",
                v, v * KMH, g, run->brake_g_in, zp->visited ? zp->acc_g : run->brake_g_in);
    } else {
        fputs("The best run never enters it.\n\n", f);
    }
}

/* the rounded kinks: each arc's peak normal force and felt acceleration in the best run */
static void md_arcs(FILE *f, const zp_answer *a) {
    const zp_model *m = a->pb->m;
    int n;
    const zp_arc_peaks *ap = zp_sim_arc_peaks(a->best, &n);
    fputs("## Arcs (rounded kinks: no impulse)\n\n| kink at x (m) | arc x (m) | radius (m) | "
          "normal force (N) | peak felt acceleration (g) |\n|---|---|---|---|---|\n",
          f);
    for (int i = 0; i < n; i++) {
        const zp_arc *arc = &m->arc[i];
        fprintf(f, "| %g | %.2f to %.2f | %g |", m->kink[arc->kink].x, arc->x1, arc->x2, arc->r);
        if (ap[i].visited) {
            fprintf(f, " %.1f to %.1f | %.2f |\n", ap[i].normal_min, ap[i].normal_max, ap[i].acc_g);
        } else {
            fputs(" not reached | not reached |\n", f);
        }
    }
}

/* the kinks crossed; section ends where the slopes agree knock nothing and are no kinks */
static void md_kinks(FILE *f, const zp_answer *a) {
    fputs("## Kink impulses\n\n", f);
    int n, nkink = 0;
    const zp_crossing *cross = zp_sim_crossings(a->best, &n);
    for (int i = 0; i < n; i++) {
        const zp_crossing *c = &cross[i];
        if (!zp_model_is_kink(a->pb->m, c->from < c->to ? c->from : c->to)) {
            continue;
        }
        if (!nkink++) {
            fputs("| t (s) | x (m) | sections | impulse (N s) | energy lost (J) |\n"
                  "|---|---|---|---|---|\n",
                  f);
        }
        fprintf(f, "| %.4f | %g | %d -> %d | %.3f | %.2f |\n", c->t, c->x, c->from + 1, c->to + 1,
                c->impulse, c->energy_lost);
    }
    if (!nkink) {
        fputs("No kinks crossed.\n", f);
    }
    if (nkink < n) {
        fprintf(f, "%s%d crossing%s of section ends where the slopes agree (no impulse).\n",
                nkink ? "\n" : "", n - nkink, n - nkink == 1 ? "" : "s");
    }
}

/* design loads of the best run, sampled at every step (docs/model.md sign conventions) */
static void md_loads(FILE *f, const zp_answer *a) {
    const zp_load_peaks *pk = &a->v.run->peaks;
    fputs("\n## Loads\n\n| joint | peak reaction (N) | link | peak felt acceleration (g) |\n"
          "|---|---|---|---|\n",
          f);
    for (int i = 0; i < a->pb->m->nlink; i++) {
        fprintf(f, "| %d | %.1f | %d | %.2f |\n", i + 1, pk->joint[i], i + 1, pk->acc_g[i]);
    }
    fprintf(f,
            "\nNormal force of the course on the trolley: %.1f N to %.1f N%s. Felt "
            "acceleration is |a - g| at a link's centre of mass (1 g hanging at rest).\n",
            pk->normal_min, pk->normal_max,
            pk->normal_min < 0 ? " (negative: the trolley pulls on the course, which must "
                                 "hold it from above too)"
                               : "");
}

/* each [limits] value of the best run against its limit */
static void md_limits(FILE *f, const zp_answer *a) {
    const zp_limits *lim = &a->pb->lim;
    const zp_result *run = a->v.run;
    if (!zp_limits_any(lim)) {
        return;
    }
    double v[ZP_LIMIT_COUNT];
    zp_limits_reached(a->pb->m, run, v);
    fputs("\n## Limits\n\n| limit | reached | allowed | |\n|---|---|---|---|\n", f);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        if (lim->max[i] > 0 && !zp_limits_reached_in(run, i)) {
            fprintf(f, "| %s | not reached (did not arrive) | %g %s | |\n", zp_limits_name(i),
                    lim->max[i], zp_limits_unit(i));
        } else if (lim->max[i] > 0) {
            fprintf(f, "| %s | %.4g %s | %g %s | %s |\n", zp_limits_name(i), v[i],
                    zp_limits_unit(i), lim->max[i], zp_limits_unit(i),
                    zp_limits_kept(i, v[i], lim->max[i]) ? "kept" : "**broken**");
        }
    }
}

/* one [robust] range as the designer reads it, if it is varied */
static void md_range(FILE *f, const char *what, const double range[2]) {
    if (range[0] != 100 || range[1] != 100) {
        fprintf(f, "- %s from %g %% to %g %% of nominal\n", what, range[0], range[1]);
    }
}

/* the scenario at u of the stated box, in words */
static void scenario_text(const zp_answer *a, const double *u, char *buf, size_t n) {
    zp_scenario s;
    zp_box_scenario(&a->rp.box, u, &s);
    int used = snprintf(buf, n, "forces x");
    for (int k = 0; k < a->pb->m->nsec && used < (int)n; k++) {
        used += snprintf(buf + used, n - used, " %.4f", s.force[k]);
    }
    if (used < (int)n) {
        snprintf(buf + used, n - used,
                 ", masses x %.3f, lengths x %.3f, trolley x %.3f, damping x %.3f", s.mass,
                 s.length, s.trolley, s.damping);
    }
}

/* the population's spread over the fresh scenarios, with the scenario at each end */
static void md_spread(FILE *f, const zp_answer *a) {
    const zp_robust_check *c = &a->rp.check;
    if (c->samples == 0 || c->fastest.sample < 0) {
        return;
    }
    const zp_spread_end *ends[5] = {&c->fastest, &c->slowest, &c->arrival_low,
                                    &c->arrival_high, &c->tension_high};
    const char *what[5] = {"fastest finish", "slowest finish", "lowest arrival speed",
                           "highest arrival speed", "highest anchor tension"};
    const char *fmt[5] = {"%.4f s", "%.4f s", "%.2f km/h", "%.2f km/h", "%.0f N"};
    int n = a->pb->m->cable_paths ? 5 : 4;
    fprintf(f, "\nSpread over the %d fresh scenarios that finished (of %d):\n\n", c->survived,
            c->samples);
    for (int k = 0; k < n; k++) {
        char sc[512];
        scenario_text(a, ends[k]->u, sc, sizeof sc);
        fprintf(f, "- %s: ", what[k]);
        fprintf(f, fmt[k], ends[k]->value);
        fprintf(f, " (fresh scenario %d: %s)\n", ends[k]->sample + 1, sc);
    }
}

/* how far past the stated box the answer holds (headroom.c) */
static void md_headroom(FILE *f, const zp_answer *a) {
    const zp_headroom *h = &a->rp.check.headroom;
    double force_error = a->pb->sc.force_error;
    if (a->rp.check.samples == 0) {
        return;
    }
    if (h->safety_factor != 1) {
        fprintf(f, "\nHeld to the ranges widened %gx about the nominal ([robust] safety_factor); "
                   "the verification above is on the stated ranges.\n",
                h->safety_factor);
    }
    fputs("\nHeadroom past the stated ranges (along the worst direction found, by bisection; "
          "1x is the stated range; holds: finishes with the margin and every limit kept):\n\n"
          "| range | holds to | breaks at | what breaks | finishes alive to | then |\n"
          "|---|---|---|---|---|---|\n",
          f);
    for (int l = 0; l < ZP_HEADROOM_LINES; l++) {
        const zp_headroom_line *L = &h->line[l];
        if (L->range < 0) {
            continue;
        }
        fprintf(f, "| %s | %.4fx", zp_headroom_range_name(L->range), L->holds);
        if (L->range == 0) {
            fprintf(f, " (+/-%.4g %%)", L->holds * force_error);
        }
        if (isfinite(L->breaks)) {
            fprintf(f, " | %.4fx", L->breaks);
            if (L->range == 0) {
                fprintf(f, " (+/-%.4g %%)", L->breaks * force_error);
            }
            fprintf(f, " | %s", L->limited_by);
        } else {
            fputs(" or more | not found | -", f);
        }
        fprintf(f, " | %.4fx", L->alive);
        if (L->range == 0) {
            fprintf(f, " (+/-%.4g %%)", L->alive * force_error);
        }
        if (isfinite(L->dies)) {
            fprintf(f, " | %s at %.4fx |\n", L->ends_by, L->dies);
        } else {
            fputs(" or more | - |\n", f);
        }
    }
}

/* where zp_held.worst lies, in words */
static const char *held_where(const zp_scen_set *set, int worst) {
    static _Thread_local char buf[64];
    if (worst < 0) {
        return "the nominal scene";
    }
    if (worst >= set->n) {
        return "the adversary's worst";
    }
    snprintf(buf, sizeof buf, "%s %d of the set", worst < set->ncorner ? "corner" : "scenario",
             worst + 1);
    return buf;
}

/* the ranges held, the verification on fresh scenarios, the worst scenario found */
static void md_survivable(FILE *f, const zp_answer *a) {
    const zp_scene *sc = &a->pb->sc;
    const zp_robust_check *c = &a->rp.check;
    const zp_scen_set *set = &a->rp.set;
    const zp_robust_info *info = &a->rp.info;
    const zp_robust_worst *w = &info->worst;
    fputs("\n## Survivable for\n\n", f);
    if (sc->force_error > 0) {
        fprintf(f, "- every section's force off by up to +/-%g %%, independently\n",
                sc->force_error);
    }
    md_range(f, "rider mass (all links)", sc->mass_range);
    md_range(f, "rider size (all link lengths)", sc->length_range);
    md_range(f, "trolley mass", sc->trolley_mass_range);
    md_range(f, "joint damping", sc->damping_range);
    if (sc->wind_varied) {
        fprintf(f, "- the horizontal wind anywhere from %g to %g m/s\n", sc->wind_range[0],
                sc->wind_range[1]);
    }
    if (sc->start_angle > 0) {
        fprintf(f, "- each link starting swung by up to +/-%g deg\n", sc->start_angle);
    }
    /* the ranges are what the search held, not a proof: say so where the headroom found a
       scenario inside them that breaks */
    const zp_headroom_line *in = zp_headroom_inside(&c->headroom);
    if (c->samples > 0 && in) {
        fprintf(f, "\n**Not everywhere in these ranges**: along the worst direction found the "
                   "answer breaks (%s) at %.4fx the stated ranges (headroom below).\n",
                in->limited_by, in->breaks);
    }
    fprintf(f, "\nHeld during the search to %d scenarios (%d corners of the ranges, %d "
               "quasi-random, %d added where the answer broke) besides the nominal scene: %ld "
               "scenario runs in %d rounds, and %ld runs of the adversary.\n",
            set->n, set->ncorner, set->n - set->ncorner - info->added, info->added, set->runs,
            info->rounds, info->sims);
    if (c->samples > 0) {
        fprintf(f, "\nChecked on %d fresh random scenarios at rtol %.0e: %d finished alive, %d "
                   "kept the margin, %d kept every limit; survivable (both) in %d, so the "
                   "probability of a survivable ride is at least **%.2f %%** (95 %% confidence, "
                   "Clopper-Pearson). Smallest margin over everything held and checked: "
                   "%.2f deg (over the nominal scene, the scenarios held and the adversary's "
                   "worst, rerun at the same tolerance: %.2f deg, %s).\n",
                c->samples, a->v.rtol, c->survived, c->margin_kept,
                c->limits_kept, c->all_kept, 100 * c->lower_95, c->worst_margin_deg,
                c->held_margin_deg, held_where(set, c->held_worst));
    }
    md_spread(f, a);
    md_headroom(f, a);
    if (info->rounds > 0 && isfinite(w->cons)) {
        zp_scenario s;
        zp_box hold; /* the adversary searched the box held */
        zp_box_widen(&a->rp.box, sc->safety_factor, &hold);
        zp_box_scenario(&hold, w->u, &s);
        fprintf(f, "\nWorst scenario found (the adversary's search of the ranges): forces x");
        for (int k = 0; k < a->pb->m->nsec; k++) {
            fprintf(f, " %.4f", s.force[k]);
        }
        fprintf(f, ", masses x %.3f, lengths x %.3f, trolley x %.3f, damping x %.3f: %s, "
                   "margin %.2f deg at joint %d",
                s.mass, s.length, s.trolley, s.damping, zp_sim_outcome_name(w->outcome),
                w->margin_deg, w->joint);
        if (w->limit >= 0) {
            fprintf(f, "; nearest limit %s at %+.1f %% of it", zp_limits_name(w->limit),
                    100 * w->excess);
        }
        fprintf(f, " (%s).\n", w->cons > 0 ? "**broken**: the search ran out of rounds"
                                             : "kept");
    }
    if (a->diag) {
        zp_report_diagnosis_md(f, a->diag);
    }
}

static void md_search(FILE *f, const zp_answer *a) {
    const zp_search_result *s = &a->res;
    const zp_sim_opts *search = &a->pb->search;
    fputs("\n## Search\n\n", f);
    fprintf(f, "- algorithm: %s, seed %lu, budget %ld simulations\n", a->algo, a->seed,
            a->max_evals);
    fprintf(f,
            "- simulations: %ld (%ld survived with the margin, %ld gave the integrator up) "
            "in %d rounds of scan and polish, %d local polishes\n",
            s->evals, s->nfeasible, s->nfailed, s->nrounds, s->nstarts);
    fprintf(f, "- wall time: %.2f s on %d threads (%.0f simulations/s)\n", s->wall_s, s->nthreads,
            s->evals / fmax(s->wall_s, 1e-9));
    fprintf(f,
            "- integrators: the search's runs %s at rtol %g, atol %g ([optimize]); the best\n"
            "  schedule rerun with %s at rtol %g, atol %g ([solver]) and verified %gx tighter\n",
            zp_method_get(search->method)->name, search->rtol, search->atol,
            zp_method_get(a->pb->sim.method)->name, a->run_opts.rtol, a->run_opts.atol,
            ZP_ESTIMATE_FACTOR);
    if (a->pb->sc.accuracy > 0) {
        const zp_accuracy *acc = &a->acc;
        fprintf(f,
                "- accuracy: %.2g s requested ([solver] accuracy: method and rtol from the "
                "work-precision table), %.2g s met%s, by %s at rtol %g after %d rerun%s\n",
                acc->requested, acc->met, acc->ok ? "" : " - NOT MET",
                zp_method_get(acc->method)->name, acc->rtol, acc->reruns,
                acc->reruns == 1 ? "" : "s");
    }
    if (s->nhist > 0) {
        fputs("- best finish time against simulations spent:", f);
        int step = s->nhist > 12 ? s->nhist / 12 : 1;
        for (int i = 0; i < s->nhist - 1; i += step) {
            fprintf(f, " %ld: %.4f s;", s->hist[i].evals, s->hist[i].time);
        }
        fprintf(f, " %ld: %.4f s\n", s->hist[s->nhist - 1].evals, s->hist[s->nhist - 1].time);
    }
    md_islands(f, s, &a->pb->sched);
    char sentence[768];
    zp_report_convergence(sentence, sizeof sentence, a);
    fprintf(f, "\n### Convergence\n\n%c%s.\n",
            sentence[0] >= 'a' && sentence[0] <= 'z' ? sentence[0] - 'a' + 'A' : sentence[0],
            sentence + 1);
}

static void md_robustness(FILE *f, const zp_verify *v, const zp_limits *lim,
                          const zp_schedule *shape) {
    fputs("\n## Robustness\n\n", f);
    if (!v->robust_done) {
        fputs("Not measured (the search was interrupted).\n", f);
        return;
    }
    /* a run counts as kept when it keeps what the search kept: the margin, and the limits */
    fprintf(f,
            "Every force scaled by 1 + p u, u uniform in [-1, 1] (seeded):\n\n"
            "| p | runs | finished alive | margin%s kept |\n|---|---|---|---|\n",
            zp_limits_any(lim) ? " and every limit" : "");
    for (int i = 0; i < ZP_VERIFY_LEVELS; i++) {
        const zp_robust *rb = &v->rob[i];
        fprintf(f, "| %g %% | %d | %.1f %% | %.1f %% |\n", 100 * rb->level, rb->n,
                100.0 * rb->survived / rb->n, 100.0 * rb->kept / rb->n);
    }
    if (!v->kill_found) {
        fprintf(f, "\nNo change of up to %g %% killed the spy.\n",
                100 * v->rob[ZP_VERIFY_LEVELS - 1].level);
    } else if (v->kill_param) {
        char label[64];
        zp_drive_param_label(shape, v->kill_param - 1, label, sizeof label);
        fprintf(f, "\nSmallest change found that kills: %.3f %% of the force in %s alone.\n",
                100 * v->kill, label);
    } else {
        fprintf(f,
                "\nSmallest change found that kills: %.3f %% (largest part of a random "
                "change of all forces).\n",
                100 * v->kill);
    }
}

static void md_figures_rerun(FILE *f, const zp_answer *a, const zp_report_place *w) {
    if (w->figures) {
        fputs("\n## Figures\n\n"
              "The best run: the course with every centre-of-mass path, the energy account, the\n"
              "relative joint angles against the death angle and the margin, and the loads;\n"
              "then the angles, the felt g and the loads against distance, and the drive's\n"
              "applied force against distance and against speed.\n\n"
              "![course and paths](course.png)\n\n![energy](energy.png)\n\n"
              "![joint angles](angles.png)\n\n![loads](loads.png)\n\n"
              "![the ride against distance](along.png)\n\n"
              "![the drive against distance and speed](drive.png)\n",
              f);
        if (a->pb->m->nenv > 0) {
            fputs("\n![felt g against the g-duration envelope](envelope.png)\n", f);
        }
    }
    fprintf(f,
            "\n## Rerun\n\n```\nzipopt %s --out %s          # this search\n"
            "zipopt simulate %s --schedule %s/schedule.ini   # this schedule\n```\n",
            rerun_scene(w), w->out_dir, rerun_scene(w), w->out_dir);
}

void zp_report_write_md(FILE *f, const zp_answer *a, const zp_report_place *w) {
    md_head(f, a);
    md_schedule(f, a);
    md_result(f, a);
    md_margins(f, a);
    md_gains(f, a);
    md_drive(f, a);
    md_speeds(f, a->v.run, (a->pb->m->physics & ZP_PHYS_BRAKE) != 0);
    if (a->pb->m->physics & ZP_PHYS_BRAKE) {
        md_brake(f, a);
    }
    if (a->pb->m->narc) {
        md_arcs(f, a);
    } else {
        md_kinks(f, a);
    }
    md_loads(f, a);
    zp_report_cable_md(f, a);
    md_limits(f, a);
    if (a->rp.robust) {
        md_survivable(f, a);
    }
    md_search(f, a);
    md_robustness(f, &a->v, &a->pb->lim, &a->pb->sched);
    md_figures_rerun(f, a, w);
}
