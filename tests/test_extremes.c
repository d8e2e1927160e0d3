/* The parameters at their extremes (forces 1e6 N and -1e4 N, damping 0..1e5, masses
   1e-3..1e4 kg, links 0.01..50 m, 1 and 8 links, rtol 1e-3..1e-13, a near-vertical section,
   a cusp-like kink). Every case ends, in bounded time, either in a finite, physically
   plausible result (docs/model.md: the work-energy audit closes relative to the energies
   involved, dampers and impulses never add energy, angles and x within their bounds) or in
   a clean ZP_ERR_NUMERIC with a message. Stiff damping: BDF needs fewer rhs evaluations
   than Adams. */
#include <math.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "testutil.h"

/* the audit residual is a global error: up to this many times rtol of the energies
   involved (the sum of |every energy term|), over runs of thousands of steps */
#define K_AUDIT 1e3
/* below this relative size the audit is at round-off of the energies involved */
#define AUDIT_FLOOR 1e-10
/* the state at an event is as accurate as the integration: a death angle may be passed by
   this many times rtol (relative) */
#define K_EVENT 100.0
/* s: the longest a single case may take (bounded time; the step budget ends a stall) */
#define CASE_WALL_MAX 20.0
/* steps per run: small enough that an explicit method on a stiff case fails fast */
#define STEP_BUDGET 50000

static const char *seed_course = "section = 60 : (x/10 - 3)^2 + 1\n"
                                 "section = 100 : -x/10 + 16\n"
                                 "section = 140 : -(x/10 - 12)^2 + 10\n";

typedef struct xcase {
    const char *name;
    const char *course; /* NULL: the seed course from x = 0 */
    double x_start;
    double trolley;             /* kg */
    const char *lengths, *masses; /* lists */
    double damping;             /* N m s/rad */
    double force;               /* N, every section */
    const char *method;
    double rtol;
} xcase;

static int ncase_ok, ncase_numeric;

static const zp_result *run_case(const xcase *c, zp_status *st, double *wall) {
    static char ini[4096];
    static zp_result r;
    int nsec = 0;
    const char *course = c->course ? c->course : seed_course;
    for (const char *p = course; (p = strstr(p, "section")); p++) {
        nsec++;
    }
    char forces[512] = "";
    for (int k = 0; k < nsec; k++) {
        snprintf(forces + strlen(forces), sizeof forces - strlen(forces), "%s%.17g",
                 k ? ", " : "", c->force);
    }
    snprintf(ini, sizeof ini,
             "[course]\nx_start = %.17g\n%s[trolley]\nmass = %.17g\n[body]\nlengths = %s\n"
             "masses = %s\ndamping = %.17g\n[drive]\nforces = %s\nmin = -1e7\nmax = 1e7\n"
             "[solver]\nmethod = %s\nt_max = 60\n",
             c->x_start, course, c->trolley, c->lengths, c->masses, c->damping, forces,
             c->method);
    zp_scene sc;
    zp_model *m = tu_model(ini, &sc);
    zp_sim_opts o = tu_opts(&sc, c->rtol);
    o.max_steps = STEP_BUDGET;
    zp_sim *s = zp_sim_create(m, &o);
    CHECK(s != NULL);
    zp_schedule in_sched = tu_sched(m, sc.forces);
    zp_input in = {.sched = &in_sched};
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    *st = zp_sim_run(m, s, &in, &r);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    *wall = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);

    if (*st == ZP_OK) {
        ncase_ok++;
        double terms[] = {r.e_initial, r.e_final, r.w_drive, r.w_damp, r.e_impulse, r.time,
                          r.x, r.v, r.constraint_residual};
        int finite = 1;
        for (size_t i = 0; i < sizeof terms / sizeof terms[0]; i++) {
            finite = finite && isfinite(terms[i]);
        }
        for (int i = 0; i < m->nlink; i++) {
            finite = finite && isfinite(r.max_rel_angle[i]);
            CHECK(r.max_rel_angle[i] <= m->phi_max * (1 + K_EVENT * c->rtol));
        }
        CHECK(finite);
        CHECK(r.time >= 0 && r.time <= o.t_max);
        CHECK(r.x >= m->xb[0] - 1e-9 && r.x <= m->xb[m->nsec] + 1e-9);
        /* dampers and plastic impulses only take energy out */
        CHECK(r.w_damp >= -AUDIT_FLOOR * fabs(r.e_initial) - 1e-12);
        CHECK(r.e_impulse >= 0);
        double scale = fabs(r.e_initial) + fabs(r.e_final) + fabs(r.w_drive) + fabs(r.w_damp) +
                       fabs(r.e_impulse);
        double res = r.e_final - r.e_initial - r.w_drive + r.w_damp + r.e_impulse;
        CHECK_NEAR(res, 0, fmax(K_AUDIT * c->rtol, AUDIT_FLOOR) * scale);
    } else {
        ncase_numeric++;
        CHECK(*st == ZP_ERR_NUMERIC);
        CHECK(r.message[0] != '\0' && strstr(r.message, "numerical failure") != NULL);
    }
    CHECK(*wall < CASE_WALL_MAX);
    printf("%-26s %-11s rtol %.0e: %-8s %-15s t %-10.6g evals %-8ld wall %.3f s%s%s\n",
           c->name, c->method, c->rtol, *st == ZP_OK ? "ok" : "NUMERIC",
           *st == ZP_OK ? zp_sim_outcome_name(r.outcome) : "", r.time, r.rhs_evals, *wall,
           *st == ZP_OK ? "" : "  ", *st == ZP_OK ? "" : r.message);
    zp_sim_free(s);
    zp_model_free(m);
    return &r;
}

static const char *methods[] = {"cvode-adams", "cvode-bdf", "gsl-rk8pd", "gsl-rk4imp"};
#define NMETHOD 4

int main(void) {
    /* a near-vertical drop (slope -500 for 0.1 m: 50 m down) between two flats */
    const char *cliff = "section = 10 : 0*x\nsection = 10.1 : -500*(x - 10)\n"
                        "section = 60 : -50 + 0*x\n";
    /* a V with slopes -5 and +5 meeting at x = 50: a cusp-like kink */
    const char *cusp = "section = 50 : 250 - 5*x\nsection = 100 : 5*x - 250\n";
    const xcase base = {"seed", NULL, 0, 30, "5, 5, 5", "15, 5, 2", 1, 100, "cvode-adams", 1e-8};
    xcase cases[64];
    int n = 0;
    /* one parameter at a time at each extreme, every method */
    for (int k = 0; k < NMETHOD; k++) {
        xcase c = base;
        c.method = methods[k];
        cases[n] = c, cases[n].name = "force 1e6 N", cases[n++].force = 1e6;
        cases[n] = c, cases[n].name = "force -1e4 N", cases[n++].force = -1e4;
        cases[n] = c, cases[n].name = "damping 0", cases[n++].damping = 0;
        cases[n] = c, cases[n].name = "damping 1e5", cases[n++].damping = 1e5;
        cases[n] = c, cases[n].name = "masses 1e-3 kg", cases[n].trolley = 1e-3,
        cases[n++].masses = "1e-3, 1e-3, 1e-3";
        cases[n] = c, cases[n].name = "masses 1e4 kg", cases[n].trolley = 1e4,
        cases[n++].masses = "1e4, 1e4, 1e4";
        cases[n] = c, cases[n].name = "lengths 0.01 m", cases[n++].lengths = "0.01, 0.01, 0.01";
        cases[n] = c, cases[n].name = "lengths 50 m", cases[n++].lengths = "50, 50, 50";
        cases[n] = c, cases[n].name = "1 link", cases[n].lengths = "5",
        cases[n++].masses = "15";
        cases[n] = c, cases[n].name = "8 links", cases[n].lengths = "2, 2, 2, 2, 2, 2, 2, 2",
        cases[n++].masses = "3, 3, 3, 3, 3, 3, 3, 3";
        cases[n] = c, cases[n].name = "rtol 1e-3", cases[n++].rtol = 1e-3;
        cases[n] = c, cases[n].name = "rtol 1e-13", cases[n++].rtol = 1e-13;
        cases[n] = c, cases[n].name = "near-vertical section", cases[n].course = cliff,
        cases[n++].force = 50;
        cases[n] = c, cases[n].name = "cusp-like kink", cases[n].course = cusp,
        cases[n++].force = 0;
        cases[n] = c, cases[n].name = "light, short, stiff", cases[n].trolley = 1e-3,
        cases[n].masses = "1e-3, 1e-3, 1e-3", cases[n].lengths = "0.01, 0.01, 0.01",
        cases[n++].damping = 1e5;
    }
    for (int i = 0; i < n; i++) {
        zp_status st;
        double wall;
        run_case(&cases[i], &st, &wall);
    }

    /* stiff damping: BDF beats Adams in rhs evaluations (the work-precision study: ~60x) */
    double stiff[] = {1e4, 1e5};
    for (int k = 0; k < 2; k++) {
        long evals[2] = {0, 0};
        for (int j = 0; j < 2; j++) {
            xcase c = base;
            c.name = "stiff: BDF vs Adams";
            c.damping = stiff[k];
            c.rtol = 1e-6;
            c.method = methods[j];
            zp_status st;
            double wall;
            const zp_result *r = run_case(&c, &st, &wall);
            /* Adams may exhaust its budget on the stiffest: then it has spent all of it */
            evals[j] = st == ZP_OK ? r->rhs_evals : 1L << 40;
            CHECK(j == 0 || st == ZP_OK);
        }
        CHECK(evals[1] < evals[0]);
    }
    /* a push backward from rest on a downhill start rolls back at t = 0 */
    xcase back = base;
    back.force = -1e4;
    zp_status st;
    double wall;
    const zp_result *r = run_case(&back, &st, &wall);
    CHECK(st == ZP_OK && r->outcome == ZP_OUTCOME_STALLED && r->stall == ZP_STALL_ROLLED_BACK &&
          r->time == 0);
    printf("%d cases ended in a result, %d in a clean numerical failure\n", ncase_ok,
           ncase_numeric);
    return CHECK_DONE();
}
