/* The public C API (include/zipopt.h) over the floors: handles own copies of everything they
   hand out, problems come back as text, nothing is printed. */
#define ZIPOPT_BUILDING
#include "zipopt.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "answer.h"
#include "estimate.h"
#include "out_columns.h"
#include "prep.h"
#include "scene_load.h"
#include "sens.h"

/* the stop flag is handed to the search as its sig_atomic_t flag */
_Static_assert(_Generic((sig_atomic_t)0, int : 1, default : 0), "sig_atomic_t is int");


/* the named numbers of a run and of a search (zipopt.h), in the order *_numbers fills them; a
   run's: run_head, each effect's work (its key in effects.def's order), run_tail */
static const char *const run_head[] = {
    "time",    "x",         "speed",  "died_link", "kinks",           "e_initial",
    "e_final", "w_drive",   "w_damp", "e_impulse", "energy_residual", "constraint_residual",
    "steps",   "rhs_evals", "wall_s"};
static const char *const run_tail[] = {"peak_g",           "peak_joint_force", "max_kink_dv",
                                       "arrival_kmh",      "normal_min",       "normal_max",
                                       "rejected_steps",   "drive_peak_power", "drive_energy",
                                       "drive_time_at_cap"};
#define NRUN_HEAD ((int)(sizeof run_head / sizeof *run_head))
#define NRUN_TAIL ((int)(sizeof run_tail / sizeof *run_tail))
#define NRUN_KEYS (NRUN_HEAD + ZP_EFFECT_NWORK + NRUN_TAIL)
static const char *const search_keys[] = {
    "found",          "time",           "angle",          "evals",           "feasible",
    "failed",         "threads",        "wall_s",         "interrupted",     "base_found",
    "base_force",     "base_time",      "rounds",         "polishes",        "basins",
    "reached_best",   "converged",      "budget_ran_out", "time_ran_out",    "unseen_basins",
    "budget_to_help", "islands",        "islands_polished", "scenarios",     "verify_samples",
    "verify_survived", "verify_margin_kept", "verify_limits_kept", "verify_all_kept",
    "lower_95",       "worst_margin_deg", "headroom",     "headroom_breaks", "fastest_s",
    "slowest_s",      "arrival_low_kmh", "arrival_high_kmh", "headroom_force_error",
    "headroom_rider_mass", "headroom_rider_size", "headroom_trolley_mass",
    "headroom_joint_damping", "headroom_start_angle", "headroom_wind"};
#define NSEARCH_KEYS ((int)(sizeof search_keys / sizeof *search_keys))

/* libmatheval's parser keeps globals and nlopt_srand is process-wide: loads and searches take
   turns; the lock is the library's only static and holds no data */
static pthread_mutex_t turn = PTHREAD_MUTEX_INITIALIZER;

struct zipopt_scene {
    zp_problem st;
    zp_sim *sim; /* owned: the workspace every zipopt_simulate of this scene reuses */
};

struct zipopt_run {
    zp_result r;
    double num[NRUN_KEYS];
    int nlink;
    int nrow, ncol;
    double *traj; /* owned, nrow x ncol */
    char col[ZP_OUT_COLUMNS_MAX][ZP_OUT_COLUMN_NAME];
    int nkink;
    double *kinks; /* owned, nkink x 6 */
};

struct zipopt_search {
    zp_search_result res;
    zp_robust_check check; /* the robust verification (samples 0: none) */
    int nscen;             /* scenarios held */
    double num[NSEARCH_KEYS];
    int np; /* parameters of the schedule */
};

__attribute__((format(printf, 3, 4))) static void say(char *err, size_t errlen, const char *fmt,
                                                      ...) {
    if (err && errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
}

/* every message of d, one per line, as zp_diag_print would print them */
static void diag_text(const zp_diag *d, char *err, size_t errlen) {
    if (!err || !errlen) {
        return;
    }
    size_t len = 0;
    err[0] = '\0';
    for (int i = 0; i < d->n && len < errlen; i++) {
        len += (size_t)snprintf(err + len, errlen - len, "%s%s", i ? "\n" : "", d->text[i]);
    }
    if (d->dropped && len < errlen) {
        snprintf(err + len, errlen - len, "\n(%d more)", d->dropped);
    }
}

const char *zipopt_version(void) {
    return ZIPOPT_VERSION_TEXT;
}

static zipopt_scene *load(const char *path, const char *text, char *err, size_t errlen) {
    zipopt_scene *s = calloc(1, sizeof *s);
    if (!s) {
        say(err, errlen, "out of memory");
        return NULL;
    }
    zp_diag d;
    zp_diag_init(&d);
    pthread_mutex_lock(&turn);
    gsl_set_error_handler_off();
    /* nothing is written under the scene's name: a scene without one is fine here */
    zp_overrides ov = {.unnamed_ok = 1};
    int rc = zp_prep_load("library", path, text, &ov, &s->st, &d);
    if (rc == 0) {
        /* the peaks [limits] judge located exactly, as `zipopt simulate` locates them */
        s->sim = zp_sim_create(s->st.m, &s->st.answer);
    }
    pthread_mutex_unlock(&turn);
    if (rc) {
        diag_text(&d, err, errlen);
        free(s);
        return NULL;
    }
    if (!s->sim) {
        say(err, errlen, "cannot create the simulator (out of memory)");
        zipopt_scene_free(s);
        return NULL;
    }
    return s;
}

zipopt_scene *zipopt_scene_load(const char *path, char *err, size_t errlen) {
    if (!path) {
        say(err, errlen, "no scene file given");
        return NULL;
    }
    return load(path, NULL, err, errlen);
}

zipopt_scene *zipopt_scene_load_string(const char *text, const char *name, char *err,
                                       size_t errlen) {
    if (!text) {
        say(err, errlen, "no scene text given");
        return NULL;
    }
    return load(name ? name : "<string>", text, err, errlen);
}

void zipopt_scene_free(zipopt_scene *s) {
    if (s) {
        zp_sim_free(s->sim);
        zp_problem_free(&s->st);
        free(s);
    }
}

/* Every entry point takes a NULL handle and a NULL output array (zipopt.h): a caller's
   mistake comes back as -1, NaN or NULL, never as a crash inside the library. */

const char *zipopt_scene_name(const zipopt_scene *s) {
    return s ? s->st.sc.name : NULL;
}

int zipopt_scene_sections(const zipopt_scene *s) {
    return s ? s->st.m->nsec : -1;
}

int zipopt_scene_links(const zipopt_scene *s) {
    return s ? s->st.m->nlink : -1;
}

int zipopt_scene_params(const zipopt_scene *s) {
    return s ? s->st.sched.np : -1;
}

int zipopt_scene_param_label(const zipopt_scene *s, int k, char *buf, size_t cap) {
    if (!s || k < 0 || k >= s->st.sched.np) {
        return -1;
    }
    char label[64];
    zp_drive_param_label(&s->st.sched, k, label, sizeof label);
    return snprintf(buf, buf ? cap : 0, "%s", label);
}

const char *zipopt_scene_param_unit(const zipopt_scene *s) {
    return s ? zp_drive_unit(&s->st.sched) : NULL;
}

int zipopt_scene_param_bounds(const zipopt_scene *s, double *lo, double *hi, int n) {
    if (!s) {
        return -1;
    }
    const zp_schedule *sh = &s->st.sched;
    for (int k = 0; k < sh->np && k < n; k++) {
        if (lo) {
            lo[k] = sh->lo[k];
        }
        if (hi) {
            hi[k] = sh->hi[k];
        }
    }
    return sh->np;
}

int zipopt_scene_forces(const zipopt_scene *s, double *force, int n) {
    if (!s) {
        return -1;
    }
    const zp_schedule *sh = &s->st.sched;
    for (int k = 0; force && k < sh->np && k < n; k++) {
        force[k] = sh->p[k];
    }
    return sh->np;
}

int zipopt_scene_set_forces(zipopt_scene *s, const double *force, int n, char *err, size_t errlen) {
    if (!s || !force) {
        say(err, errlen, "%s", !s ? "no scene given" : "forces: no array given");
        return -1;
    }
    const zp_schedule *sh = &s->st.sched;
    if (n != sh->np) {
        say(err, errlen, "forces: %d values, expected %d (one per %s, %s)", n, sh->np,
            zp_drive_param_noun(sh, 0), zp_drive_unit(sh));
        return -1;
    }
    for (int k = 0; k < n; k++) {
        if (!isfinite(force[k])) {
            say(err, errlen, "forces: item %d is not a finite number; expected N", k + 1);
            return -1;
        }
    }
    s->st.sched = zp_drive_with(sh, force);
    return 0;
}

int zipopt_scene_load_schedule(zipopt_scene *s, const char *path, char *err, size_t errlen) {
    if (!s || !path) {
        say(err, errlen, "%s", !s ? "no scene given" : "no schedule file given");
        return -1;
    }
    /* read onto a copy, so that a bad file leaves the scene as it was */
    zp_scene *sc = malloc(sizeof *sc);
    zp_diag d;
    zp_diag_init(&d);
    if (!sc) {
        say(err, errlen, "out of memory");
        return -1;
    }
    *sc = s->st.sc;
    int rc = zp_scene_load_overlay_schedule(path, sc, &d) == ZP_OK ? 0 : -1;
    if (rc) {
        diag_text(&d, err, errlen);
    } else {
        zp_schedule given = zp_drive_of_scene(sc);
        s->st.sched = zp_drive_with(&s->st.sched, given.p);
    }
    free(sc);
    return rc;
}

/* the trajectory columns the library hands out (zipopt.h): those of the trajectory's table
   with a library name, into u's names and each one's index in the table into which */
static int columns(zipopt_run *u, const zp_model *m, int *which) {
    zp_out_column all[ZP_OUT_COLUMNS_MAX];
    int n = zp_out_columns(m, all), j = 0;
    for (int i = 0; i < n; i++) {
        if (all[i].lib[0]) {
            snprintf(u->col[j], ZP_OUT_COLUMN_NAME, "%s", all[i].lib);
            which[j++] = i;
        }
    }
    return j;
}

/* the run's rows and kink crossings copied out of the workspace, which the next run reuses */
static int copy_out(zipopt_run *u, const zp_model *m, const zp_sim *sim) {
    int nk;
    const zp_row_store *rows = zp_sim_rows(sim);
    int nrow = rows->n;
    const zp_crossing *cr = zp_sim_crossings(sim, &nk);
    int which[ZP_OUT_COLUMNS_MAX];
    u->nlink = m->nlink;
    u->ncol = columns(u, m, which);
    u->traj = malloc(sizeof *u->traj * (size_t)(nrow > 0 ? nrow : 1) * (size_t)u->ncol);
    u->kinks = malloc(sizeof *u->kinks * (size_t)(nk > 0 ? nk : 1) * 6);
    if (!u->traj || !u->kinks) {
        return -1;
    }
    u->nrow = nrow;
    for (int i = 0; i < nrow; i++) {
        zp_row row;
        double v[ZP_OUT_COLUMNS_MAX];
        zp_row_store_get(rows, i, &row);
        zp_out_columns_values(m, &row, v);
        for (int j = 0; j < u->ncol; j++) {
            u->traj[(size_t)i * (size_t)u->ncol + j] = v[which[j]];
        }
    }
    u->nkink = nk;
    for (int i = 0; i < nk; i++) {
        double *k = u->kinks + (size_t)i * 6;
        k[0] = cr[i].t;
        k[1] = cr[i].x;
        k[2] = cr[i].from + 1;
        k[3] = cr[i].to + 1;
        k[4] = cr[i].impulse;
        k[5] = cr[i].energy_lost;
    }
    return 0;
}

static void run_numbers(const zp_model *m, const zp_result *r, double *v) {
    double reached[ZP_LIMIT_COUNT];
    zp_limits_reached(m, r, reached);
    const double head[] = {r->time,
                           r->x,
                           r->v,
                           r->died_link,
                           r->ncross,
                           r->e_initial,
                           r->e_final,
                           r->w_drive,
                           r->w_damp,
                           r->e_impulse,
                           zp_estimate_energy_residual(r),
                           r->constraint_residual,
                           (double)r->steps,
                           (double)r->rhs_evals,
                           r->wall_s};
    const double tail[] = {reached[ZP_LIMIT_G],
                           reached[ZP_LIMIT_JOINT],
                           reached[ZP_LIMIT_KINK_DV],
                           zp_limits_reached_in(r, ZP_LIMIT_ARRIVAL) ? reached[ZP_LIMIT_ARRIVAL]
                                                                     : NAN,
                           r->peaks.normal_min,
                           r->peaks.normal_max,
                           (double)r->rejected,
                           r->drive_peak_power,
                           r->w_drive,
                           r->drive_time_at_cap};
    _Static_assert(sizeof head / sizeof *head == NRUN_HEAD, "one number per key");
    _Static_assert(sizeof tail / sizeof *tail == NRUN_TAIL, "one number per key");
    memcpy(v, head, sizeof head);
    memcpy(v + NRUN_HEAD, r->w_effect, sizeof r->w_effect);
    memcpy(v + NRUN_HEAD + ZP_EFFECT_NWORK, tail, sizeof tail);
}

zipopt_run *zipopt_simulate(zipopt_scene *s, char *err, size_t errlen) {
    if (!s) {
        say(err, errlen, "no scene given");
        return NULL;
    }
    zipopt_run *u = calloc(1, sizeof *u);
    if (!u) {
        say(err, errlen, "out of memory");
        return NULL;
    }
    const zp_model *m = s->st.m;
    zp_input in = {.sched = &s->st.sched};
    if (zp_sim_run(m, s->sim, &in, &u->r)) {
        say(err, errlen, "%s", u->r.message);
        free(u);
        return NULL;
    }
    run_numbers(m, &u->r, u->num);
    if (copy_out(u, m, s->sim)) {
        say(err, errlen, "out of memory");
        zipopt_run_free(u);
        return NULL;
    }
    return u;
}

/* 0 when the gradient of s fits room for n parameters (outputs given: outputs_given), else -1
   with why in err */
static int gradient_room(const zipopt_scene *s, int outputs_given, int n, char *err,
                         size_t errlen) {
    if (!s || !outputs_given) {
        say(err, errlen, "no scene or no room for the gradient given");
        return -1;
    }
    if (n < s->st.sched.np) {
        say(err, errlen, "room for %d parameters, the schedule has %d", n, s->st.sched.np);
        return -1;
    }
    return 0;
}

int zipopt_gradient(zipopt_scene *s, double *dtime, double *dmargin, int n, int *smooth,
                    char *err, size_t errlen) {
    if (gradient_room(s, dtime && dmargin && smooth, n, err, errlen)) {
        return -1;
    }
    const zp_schedule *sh = &s->st.sched;
    zp_sens_result g;
    /* its own workspace builds course evaluators, which may be libmatheval's: in turn */
    pthread_mutex_lock(&turn);
    zp_status st = zp_sens_run(s->st.m, &s->st.sim, sh, NULL, &g);
    pthread_mutex_unlock(&turn);
    if (st) {
        say(err, errlen, "%s", g.message);
        return -1;
    }
    for (int k = 0; k < g.np; k++) {
        dtime[k] = g.dtime[k];
        dmargin[k] = g.dmargin[k] * (180 / M_PI); /* as the JSON scales it: the same bits */
    }
    *smooth = g.smooth;
    return g.np;
}

const char *zipopt_limit_key(int i) {
    return i >= 0 && i < ZP_LIMIT_COUNT ? zp_limits_name(i) : NULL;
}

int zipopt_gradient_limits(zipopt_scene *s, double *d, int n, int *smooth, char *err,
                           size_t errlen) {
    if (gradient_room(s, d && smooth, n, err, errlen)) {
        return -1;
    }
    const zp_schedule *sh = &s->st.sched;
    zp_sens_result *g = malloc(sizeof *g);
    if (!g) {
        say(err, errlen, "out of memory");
        return -1;
    }
    pthread_mutex_lock(&turn);
    zp_status st = zp_sens_run(s->st.m, &s->st.sim, sh, &s->st.lim, g);
    pthread_mutex_unlock(&turn);
    if (st) {
        say(err, errlen, "%s", g->message);
        free(g);
        return -1;
    }
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        int given = g->limits.set[i] && g->limits.has[i];
        for (int k = 0; k < n; k++) {
            d[(size_t)i * (size_t)n + k] = given && k < g->np ? g->limits.d[i][k] : NAN;
        }
        smooth[i] = given && g->smooth && !g->limits.why_not[i][0];
    }
    int np = g->np;
    free(g);
    return np;
}

void zipopt_run_free(zipopt_run *r) {
    if (r) {
        free(r->traj);
        free(r->kinks);
        free(r);
    }
}

int zipopt_run_outcome(const zipopt_run *r) {
    return r ? (int)r->r.outcome : -1;
}

const char *zipopt_outcome_name(int outcome) {
    return outcome >= 0 && outcome < ZP_OUTCOME_COUNT ? zp_sim_outcome_name(outcome) : NULL;
}

const char *zipopt_run_stall(const zipopt_run *r) {
    if (!r) {
        return NULL;
    }
    return r->r.outcome == ZP_OUTCOME_STALLED ? zp_sim_stall_name(r->r.stall) : "";
}

/* the value of key in keys (n of them) from v; NaN when no key matches */
static double lookup(const char *const *keys, int n, const double *v, const char *key) {
    for (int i = 0; key && i < n; i++) {
        if (!strcmp(keys[i], key)) {
            return v[i];
        }
    }
    return NAN;
}

/* the name of a run's number i (0 <= i < NRUN_KEYS) */
static const char *run_key(int i) {
    return i < NRUN_HEAD                     ? run_head[i]
           : i < NRUN_HEAD + ZP_EFFECT_NWORK ? zp_effect_work_names(i - NRUN_HEAD)->key
                                             : run_tail[i - NRUN_HEAD - ZP_EFFECT_NWORK];
}

double zipopt_run_get(const zipopt_run *r, const char *key) {
    for (int i = 0; r && key && i < NRUN_KEYS; i++) {
        if (!strcmp(run_key(i), key)) {
            return r->num[i];
        }
    }
    return NAN;
}

const char *zipopt_run_key(int i) {
    return i >= 0 && i < NRUN_KEYS ? run_key(i) : NULL;
}

int zipopt_run_max_angles(const zipopt_run *r, double *angle, int n) {
    if (!r) {
        return -1;
    }
    for (int i = 0; angle && i < r->nlink && i < n; i++) {
        angle[i] = r->r.max_rel_angle[i];
    }
    return r->nlink;
}

int zipopt_run_kinks(const zipopt_run *r, double *out, int max) {
    if (!r) {
        return -1;
    }
    if (out && max > 0) {
        int n = r->nkink < max ? r->nkink : max;
        memcpy(out, r->kinks, sizeof *out * (size_t)n * 6);
    }
    return r->nkink;
}

int zipopt_run_rows(const zipopt_run *r) {
    return r ? r->nrow : -1;
}

int zipopt_run_columns(const zipopt_run *r) {
    return r ? r->ncol : -1;
}

const char *zipopt_run_column(const zipopt_run *r, int j) {
    return r && j >= 0 && j < r->ncol ? r->col[j] : NULL;
}

const double *zipopt_run_trajectory(const zipopt_run *r) {
    return r ? r->traj : NULL;
}

/* the caller's progress function behind the search's; its nonzero return raises the flag */
typedef struct progress_ctx {
    zipopt_progress_fn fn;
    void *user;
    int np;
    volatile sig_atomic_t *flag;
} progress_ctx;

static void on_progress(void *user, const zp_search_progress *p, int improved) {
    progress_ctx *c = user;
    if (c->fn(c->user, p->evals, p->wall_s, p->found, p->time, p->force, c->np, improved)) {
        *c->flag = 1;
    }
}

/* the factor on range l (zp_headroom's order) up to which the answer holds; NaN unverified or
   not varied */
static double range_headroom(const zp_robust_check *c, int l) {
    const zp_headroom_line *line = &c->headroom.line[l];
    return c->samples > 0 && line->range >= 0 ? line->holds : NAN;
}

static void search_numbers(const zp_search_result *r, const zp_robust_check *c, int nscen,
                           double *v) {
    int verified = c->samples > 0;
    const zp_headroom_line *box = &c->headroom.line[ZP_HEADROOM_LINES - 1];
    int headroom = verified && box->range >= 0;
    const double n[] = {r->found,
                        r->found ? r->best.time : NAN,
                        r->found ? r->best.angle : NAN,
                        (double)r->evals,
                        (double)r->nfeasible,
                        (double)r->nfailed,
                        r->nthreads,
                        r->wall_s,
                        r->interrupted,
                        r->base_found,
                        r->base_found ? r->base_force : NAN,
                        r->base_found ? r->base.time : NAN,
                        r->nrounds,
                        r->nstarts,
                        r->nbasins,
                        r->nreached,
                        r->converged,
                        r->budget_out,
                        r->timed_out,
                        r->nstarts > 0 ? r->unseen : NAN,
                        !r->converged && r->found && (r->budget_out || r->timed_out)
                            ? (double)r->help_evals
                            : NAN,
                        r->nislands,
                        r->npolished,
                        nscen,
                        c->samples,
                        verified ? c->survived : NAN,
                        verified ? c->margin_kept : NAN,
                        verified ? c->limits_kept : NAN,
                        verified ? c->all_kept : NAN,
                        verified ? c->lower_95 : NAN,
                        verified ? c->worst_margin_deg : NAN,
                        headroom ? box->holds : NAN,
                        headroom && isfinite(box->breaks) ? box->breaks : NAN,
                        verified ? c->fastest.value : NAN,
                        verified ? c->slowest.value : NAN,
                        verified ? c->arrival_low.value : NAN,
                        verified ? c->arrival_high.value : NAN,
                        range_headroom(c, 0),
                        range_headroom(c, 1),
                        range_headroom(c, 2),
                        range_headroom(c, 3),
                        range_headroom(c, 4),
                        range_headroom(c, 5),
                        range_headroom(c, 6)};
    _Static_assert(sizeof n / sizeof *n == NSEARCH_KEYS, "one number per key");
    memcpy(v, n, sizeof n);
}

/* the answer's search and fresh-scenario check into u; the libraries' globals take turns */
static zp_status solve(const zp_problem *st, const zp_answer_opts *o, zipopt_search *u, char *err,
                       size_t errlen) {
    zp_answer *a = malloc(sizeof *a); /* large: kept off the stack */
    if (!a) {
        snprintf(err, errlen, "out of memory");
        return ZP_ERR_NOMEM;
    }
    pthread_mutex_lock(&turn);
    zp_status rc = zp_answer_solve(st, o, a, err, errlen);
    pthread_mutex_unlock(&turn);
    u->res = a->res;
    u->check = a->rp.check;
    u->nscen = zp_answer_scenarios(a);
    zp_answer_free(a);
    free(a);
    return rc;
}

zipopt_search *zipopt_search_run(zipopt_scene *s, long max_evals, long seed,
                                 zipopt_progress_fn progress, void *user, volatile int *stop,
                                 char *err, size_t errlen) {
    if (!s) {
        say(err, errlen, "no scene given");
        return NULL;
    }
    zipopt_search *u = calloc(1, sizeof *u);
    if (!u) {
        say(err, errlen, "out of memory");
        return NULL;
    }
    const zp_problem *st = &s->st;
    volatile sig_atomic_t own = 0;
    progress_ctx pc = {progress, user, st->sched.np, stop ? stop : &own};
    /* the search as the command runs it: held to the scene's [limits] and [robust] scenarios
       when it has them, the answer checked on fresh scenarios */
    zp_answer_opts o = zp_answer_opts_of(st, ZP_ANSWER_SEARCHED);
    if (max_evals > 0) {
        o.search.max_evals = max_evals;
    }
    if (seed >= 0) {
        o.search.seed = (unsigned long)seed;
    }
    o.search.stop = pc.flag;
    o.search.progress = progress ? on_progress : NULL;
    o.search.user = &pc;
    char why[512] = "";
    zp_status rc = ZP_OK;
    if (*pc.flag) {
        /* stopped before it began: nothing run, the scene's forces stand */
        u->res.interrupted = 1;
        memcpy(u->res.force, st->sched.p, sizeof *u->res.force * (size_t)st->sched.np);
    } else {
        rc = solve(st, &o, u, why, sizeof why);
    }
    if (rc) {
        say(err, errlen, "%s", why);
        free(u);
        return NULL;
    }
    u->np = st->sched.np;
    search_numbers(&u->res, &u->check, u->nscen, u->num);
    return u;
}

void zipopt_search_free(zipopt_search *r) {
    free(r);
}

double zipopt_search_get(const zipopt_search *r, const char *key) {
    return r ? lookup(search_keys, NSEARCH_KEYS, r->num, key) : NAN;
}

const char *zipopt_search_key(int i) {
    return i >= 0 && i < NSEARCH_KEYS ? search_keys[i] : NULL;
}

int zipopt_search_forces(const zipopt_search *r, double *force, int n) {
    if (!r) {
        return -1;
    }
    for (int k = 0; force && k < r->np && k < n; k++) {
        force[k] = r->res.force[k];
    }
    return r->np;
}
