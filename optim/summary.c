/* summary.json of the search (docs/commands.md "The search's summary.json"): the answer, its
   verification, the baseline, robustness and the evidence of convergence. */
#include <math.h>

#include "headroom.h"
#include "method.h"
#include "out_json.h"
#include "report.h"
#include "report_cable.h"

#define DEG (180.0 / M_PI)

static double largest_angle(const zp_model *m, const zp_result *r) {
    return zp_model_angle_used(m, r->max_rel_angle);
}

static void json_number_or_null(FILE *f, double v) {
    if (isfinite(v)) {
        zp_out_json_number(f, v);
    } else {
        fputs("null", f);
    }
}

static void json_convergence(FILE *f, const zp_answer *a) {
    const zp_search_result *s = &a->res;
    char sentence[768];
    zp_report_convergence(sentence, sizeof sentence, a);
    fprintf(f,
            "{\"rounds\": %d, \"polishes\": %d, \"basins\": %d, \"reached_best\": %d, "
            "\"converged\": %s, \"budget_ran_out\": %s, \"time_ran_out\": %s, "
            "\"search_time\": ",
            s->nrounds, s->nstarts, s->nbasins, s->nreached, s->converged ? "true" : "false",
            s->budget_out ? "true" : "false", s->timed_out ? "true" : "false");
    if (a->found) {
        zp_out_json_number(f, s->best.time);
    } else {
        fputs("null", f);
    }
    fprintf(f, ", \"minima\": %d, \"unseen_basins\": ", s->nminima);
    json_number_or_null(f, s->nstarts > 0 ? s->unseen : NAN);
    fprintf(f, ", \"populations\": %d, \"populations_best\": ", s->npops);
    json_number_or_null(f, s->npops > 0 ? s->pops_best : NAN);
    fprintf(f, ", \"windows\": %ld, \"bang_bang\": %ld", s->nwindows, s->npinned);
    fputs(", \"budget_to_help\": ", f);
    if (!s->converged && a->found && (s->budget_out || s->timed_out)) {
        fprintf(f, "%ld", s->help_evals);
    } else {
        fputs("null", f);
    }
    fputs(", \"sentence\": ", f);
    zp_out_json_string(f, sentence);
    fputc('}', f);
}

/* the map's islands: how many, how many polished, the fastest survivable point of the best */
static void json_islands(FILE *f, const zp_search_result *s, int nparam) {
    fprintf(f, "{\"found\": %d, \"polished\": %d, \"best\": [", s->nislands, s->npolished);
    for (int i = 0; i < s->nshown; i++) {
        fprintf(f, "%s{\"time\": ", i ? ", " : "");
        zp_out_json_number(f, s->island_time[i]);
        fputs(", \"forces\": [", f);
        for (int k = 0; k < nparam; k++) {
            fputs(k ? ", " : "", f);
            zp_out_json_number(f, s->island_force[i][k]);
        }
        fprintf(f, "], \"survivable_points\": %d}", s->island_pts[i]);
    }
    fputs("]}", f);
}

/* the search's best did not hold with [solver] and the next candidates were tried: how many
   failed (the best among them), whether one holds (the answer), and the best's ranked time,
   forces and why */
static void json_fallback(FILE *f, const zp_answer_fallback *fb, int nparam) {
    fprintf(f, ",\n  \"fallback\": {\"rejected\": %d, \"taken\": %s, \"first_time\": ",
            fb->tried + !fb->taken, fb->taken ? "true" : "false");
    zp_out_json_number(f, fb->first_time);
    fputs(", \"first_forces\": [", f);
    for (int k = 0; k < nparam; k++) {
        fputs(k ? ", " : "", f);
        zp_out_json_number(f, fb->first_force[k]);
    }
    fputs("], \"why\": ", f);
    zp_out_json_string(f, fb->why);
    fputc('}', f);
}

/* the smallest kill names the parameter as the kind calls it ("section": 2) */
static void json_robust(FILE *f, const zp_verify *v, const zp_schedule *shape) {
    if (!v->robust_done) {
        fputs("null", f);
        return;
    }
    fputs("{\"levels\": [", f);
    for (int i = 0; i < ZP_VERIFY_LEVELS; i++) {
        const zp_robust *rb = &v->rob[i];
        fprintf(f, "{\"level\": %g, \"runs\": %d, \"survived\": %d, \"margin_kept\": %d}%s",
                rb->level, rb->n, rb->survived, rb->kept, i + 1 < ZP_VERIFY_LEVELS ? ", " : "");
    }
    fputs("], \"smallest_kill\": ", f);
    if (v->kill_found) {
        fprintf(f, "{\"relative\": %.6g, \"%s\": ", v->kill, zp_drive_param_noun(shape, 0));
        if (v->kill_param) {
            fprintf(f, "%d}", v->kill_param);
        } else {
            fputs("null}", f);
        }
    } else {
        fputs("null", f);
    }
    fputc('}', f);
}

/* [solver] accuracy: what the answer's run met, rerun tighter where the first pick missed */
static void json_accuracy(FILE *f, const zp_accuracy *a) {
    fputs(",\n  \"accuracy\": {\"requested\": ", f);
    zp_out_json_number(f, a->requested);
    fputs(", \"met\": ", f);
    zp_out_json_number(f, a->met);
    fprintf(f, ", \"ok\": %s, \"method\": \"%s\", \"rtol\": ", a->ok ? "true" : "false",
            zp_method_get(a->method)->name);
    zp_out_json_number(f, a->rtol);
    fprintf(f, ", \"reruns\": %d}", a->reruns);
}

/* one headroom line's members: how far it holds, what breaks past it, how far the rider at
   least finishes alive and how the ride ends past that; null where the range is not varied */
static void headroom_members(FILE *f, const zp_headroom_line *L) {
    int on = L->range >= 0;
    fputs("\"factor\": ", f);
    zp_out_json_number(f, on ? L->holds : NAN);
    fputs(", \"limited_by\": ", f);
    zp_out_json_string(f, on ? L->limited_by : "");
    fputs(", \"breaks_at\": ", f);
    zp_out_json_number(f, on && isfinite(L->breaks) ? L->breaks : NAN);
    fputs(", \"alive_to\": ", f);
    zp_out_json_number(f, on ? L->alive : NAN);
    fputs(", \"ends_at\": ", f);
    zp_out_json_number(f, on && isfinite(L->dies) ? L->dies : NAN);
    fputs(", \"ends_by\": ", f);
    zp_out_json_string(f, on ? L->ends_by : "");
}

void zp_summary_headroom_json(FILE *f, const zp_headroom *h) {
    fputc('{', f);
    headroom_members(f, &h->line[ZP_HEADROOM_LINES - 1]); /* the whole box */
    fputs(", \"safety_factor\": ", f);
    zp_out_json_number(f, h->safety_factor);
    fputs(", \"ranges\": [", f);
    int first = 1;
    for (int l = 0; l + 1 < ZP_HEADROOM_LINES; l++) {
        const zp_headroom_line *L = &h->line[l];
        if (L->range < 0) {
            continue;
        }
        fprintf(f, "%s{\"range\": ", first ? "" : ", ");
        zp_out_json_string(f, zp_headroom_range_name(L->range));
        fputs(", ", f);
        headroom_members(f, L);
        fputc('}', f);
        first = 0;
    }
    fputs("]}", f);
}

/* the robust search's key (docs/commands.md): its scenarios, and the answer on fresh ones */
static void json_scenarios(FILE *f, const zp_answer *a) {
    const zp_robust_check *c = &a->rp.check;
    const zp_scen_set *set = &a->rp.set;
    fprintf(f, ",\n  \"robust\": {\"scenarios\": %d, \"corners\": %d, \"added\": %d, "
               "\"rounds\": %d, \"worst_margin_deg\": ",
            set->n, set->ncorner, a->rp.info.added, a->rp.info.rounds);
    /* the smallest margin over everything held and verified (the adversary's worst included) */
    zp_out_json_number(f, c->worst_margin_deg);
    fprintf(f, ", \"scenario_runs\": %ld, \"verify\": {\"samples\": %d, \"survived\": %d, "
               "\"margin_kept\": %d, \"limits_kept\": %d, \"all_kept\": %d, \"lower_95\": ",
            set->runs, c->samples, c->survived, c->margin_kept, c->limits_kept, c->all_kept);
    zp_out_json_number(f, c->lower_95);
    fputs("}, \"headroom\": ", f);
    zp_summary_headroom_json(f, &c->headroom);
    /* the population's spread over the finishing fresh scenarios, each with its scenario */
    const zp_spread_end *ends[4] = {&c->fastest, &c->slowest, &c->arrival_low,
                                    &c->arrival_high};
    const char *keys[4] = {"fastest_s", "slowest_s", "arrival_low_kmh", "arrival_high_kmh"};
    fputs(", \"spread\": {", f);
    for (int k = 0; k < 4; k++) {
        fprintf(f, "%s\"%s\": {\"value\": ", k ? ", " : "", keys[k]);
        zp_out_json_number(f, ends[k]->value);
        fprintf(f, ", \"sample\": %d, \"u\": [", ends[k]->sample);
        for (int d = 0; ends[k]->sample >= 0 && d < a->rp.box.d; d++) {
            fputs(d ? ", " : "", f);
            zp_out_json_number(f, ends[k]->u[d]);
        }
        fputs("]}", f);
    }
    fputs("}", f);
    if (a->diag) {
        fputs(", \"diagnosis\": ", f);
        zp_report_diagnosis_json(f, a->diag);
    }
    fputs("}", f);
}

void zp_summary_write_json(FILE *f, const zp_answer *a) {
    const zp_search_result *s = &a->res;
    const zp_result *run = a->v.run;
    const zp_model *m = a->pb->m;
    fputs("{\n  \"scene\": ", f);
    zp_out_json_string(f, a->pb->sc.name);
    fputs(",\n  \"forces\": [", f);
    for (int k = 0; k < a->pb->sched.np; k++) {
        zp_out_json_number(f, s->force[k]);
        fputs(k + 1 < a->pb->sched.np ? ", " : "]", f);
    }
    fprintf(f, ",\n  \"found\": %s,\n  \"outcome\": \"%s\",\n  \"time\": ",
            a->found ? "true" : "false", zp_sim_outcome_name(run->outcome));
    zp_out_json_number(f, run->time);
    fputs(",\n  \"time_error\": ", f);
    zp_out_json_number(f, fabs(run->time - a->v.tight->time));
    /* what the search minimised: the nominal rider's finish, or the slowest held finish (at
       the search's own tolerance) */
    fprintf(f, ",\n  \"objective\": \"%s\", \"objective_s\": ",
            a->pb->sc.objective_slowest ? "slowest" : "nominal");
    zp_out_json_number(f, s->best.obj);
    if (a->pb->sc.accuracy > 0) {
        json_accuracy(f, &a->acc);
    }
    fputs(",\n  \"margin_deg\": ", f);
    zp_out_json_number(f, (m->phi_max - largest_angle(m, run)) * DEG);
    fputs(",\n  \"max_rel_angle\": [", f);
    for (int i = 0; i < m->nlink; i++) {
        zp_out_json_number(f, run->max_rel_angle[i] * DEG);
        fputs(i + 1 < m->nlink ? ", " : "]", f);
    }
    fprintf(f, ",\n  \"verified\": %s,\n  \"arrival_speed\": ", a->v.agree ? "true" : "false");
    zp_out_json_number(f, run->v);
    fputs(",\n  \"peak_speed\": ", f);
    zp_out_json_number(f, run->max_speed);
    fprintf(f, ",\n  \"evaluations\": %ld,\n  \"wall_s\": ", s->evals);
    zp_out_json_number(f, s->wall_s);
    fprintf(f, ",\n  \"algorithm\": \"%s\",\n  \"seed\": %lu,\n  \"interrupted\": %s", a->algo,
            a->seed, s->interrupted ? "true" : "false");
    if (a->fallback.tried > 0) {
        json_fallback(f, &a->fallback, a->pb->sched.np);
    }
    fputs(",\n  \"baseline\": ", f);
    if (s->base_found) {
        fputs("{\"force\": ", f);
        zp_out_json_number(f, s->base_force);
        fputs(", \"time\": ", f);
        zp_out_json_number(f, s->base.time);
        fprintf(f, ", \"pushes_run\": %ld}", a->push.evals); /* besides the search's */
    } else {
        fputs("null", f);
    }
    fputs(",\n  \"scene_forces\": ", f);
    if (a->given) {
        char breaks[64];
        zp_report_breaks(a->pb, a->given, breaks, sizeof breaks);
        fprintf(f, "{\"outcome\": \"%s\", \"time\": ", zp_sim_outcome_name(a->given->outcome));
        zp_out_json_number(f, a->given->time);
        fputs(", \"breaks\": ", f);
        zp_out_json_string(f, breaks);
        fputc('}', f);
    } else {
        fputs("null", f);
    }
    fputs(",\n  \"robustness\": ", f);
    json_robust(f, &a->v, &a->pb->sched);
    fputs(",\n  \"limits\": ", f);
    zp_out_json_limits(f, m, run, &a->pb->lim);
    zp_report_cable_json(f, a);
    if (a->rp.robust) {
        json_scenarios(f, a);
    }
    fputs(",\n  \"convergence\": ", f);
    json_convergence(f, a);
    fputs(",\n  \"islands\": ", f);
    json_islands(f, s, a->pb->sched.np);
    fputs(",\n  \"history\": [", f);
    for (int i = 0; i < s->nhist; i++) {
        fprintf(f, "[%ld, ", s->hist[i].evals);
        zp_out_json_number(f, s->hist[i].time);
        fputs(i + 1 < s->nhist ? "], " : "]", f);
    }
    fputs("]\n}\n", f);
}
