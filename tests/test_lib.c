/* The public C API (include/zipopt.h) through the shared library: a scene from text equals the
   same scene from its file bit for bit; on a straight slope the centre of mass of the whole
   body, rebuilt from the trajectory's x, y and theta columns, moves along the slope with the
   closed-form acceleration (F cos a - M g sin a) / M whatever the chain does; the energy audit
   closes (drag and friction work booked, on seed_real); handles in two threads give the
   sequential bits; bad input and a stopped search come back as values, with nothing printed
   (not even the interpreted-course notice); NULL handles and output arrays are refused as
   zipopt.h says; scene text without a name loads; a schedule file gives the bits of the same
   forces set by hand; the schedule's parameters are [drive] forces' own: one per section,
   labelled by section, in N, bounded by [drive] min and max; the drive's figures (peak power,
   energy, time at the cap) and the gradient (time, margin and every [limits] value's) are
   `zipopt simulate --gradient --json`'s bits. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "zipopt.h"

#define K_RTOL 300.0 /* closed forms are met to a few hundred times the requested rtol */
#define SEED ZP_SOURCE_DIR "/config/seed.ini"

static char *slurp(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        return NULL;
    }
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return buf;
}

static zipopt_run *run_forces(zipopt_scene *s, const double *f, int n) {
    char err[512];
    CHECK(zipopt_scene_set_forces(s, f, n, err, sizeof err) == 0);
    zipopt_run *r = zipopt_simulate(s, err, sizeof err);
    CHECK(r != NULL);
    return r;
}

static int same_run(const zipopt_run *a, const zipopt_run *b) {
    size_t n = (size_t)zipopt_run_rows(a) * (size_t)zipopt_run_columns(a);
    return zipopt_run_get(a, "time") == zipopt_run_get(b, "time") &&
           zipopt_run_rows(a) == zipopt_run_rows(b) &&
           !memcmp(zipopt_run_trajectory(a), zipopt_run_trajectory(b), n * sizeof(double));
}

static int column(const zipopt_run *r, const char *name) {
    for (int j = 0; j < zipopt_run_columns(r); j++) {
        if (!strcmp(zipopt_run_column(r, j), name)) {
            return j;
        }
    }
    return -1;
}

/* file and text give the same bits; the audit and the trajectory's own definitions hold */
static void check_seed(void) {
    char err[4096];
    zipopt_scene *a = zipopt_scene_load(SEED, err, sizeof err);
    zipopt_scene *b = zipopt_scene_load_string(slurp(SEED), "seed-text.ini", err, sizeof err);
    CHECK(a && b);
    CHECK(zipopt_scene_sections(a) == 3 && zipopt_scene_links(a) == 3);
    double f[3] = {10, 10, 10};
    zipopt_run *ra = run_forces(a, f, 3), *rb = run_forces(b, f, 3);
    CHECK(same_run(ra, rb));
    CHECK(zipopt_run_outcome(ra) == ZIPOPT_FINISHED);
    CHECK(!strcmp(zipopt_outcome_name(zipopt_run_outcome(ra)), "finished"));
    /* work-energy: E_final - E_initial = W_drive - W_damp - E_impulse */
    double scale = fmax(zipopt_run_get(ra, "e_initial"), zipopt_run_get(ra, "w_drive"));
    CHECK_NEAR(zipopt_run_get(ra, "energy_residual"), 0, K_RTOL * 1e-8 * scale);
    /* the last row is the end of the run; phi are differences of theta */
    int rows = zipopt_run_rows(ra), cols = zipopt_run_columns(ra);
    const double *last = zipopt_run_trajectory(ra) + (size_t)(rows - 1) * cols;
    CHECK(last[column(ra, "t")] == zipopt_run_get(ra, "time"));
    CHECK(last[column(ra, "x")] == zipopt_run_get(ra, "x"));
    CHECK(last[column(ra, "phi2")] == last[column(ra, "theta2")] - last[column(ra, "theta1")]);
    CHECK(column(ra, "omega3") > 0 && zipopt_run_column(ra, cols) == NULL);
    double kinks[2 * 6], angle[3];
    CHECK(zipopt_run_kinks(ra, kinks, 2) == (int)zipopt_run_get(ra, "kinks"));
    CHECK(zipopt_run_kinks(ra, kinks, 2) == 2 && kinks[1] == 60 && kinks[7] == 100);
    CHECK(zipopt_run_max_angles(ra, angle, 3) == 3 && angle[2] > angle[0]);
    CHECK(isnan(zipopt_run_get(ra, "no such key")) && zipopt_run_key(0) != NULL);
    /* a wrong count or a NaN is refused and leaves the forces as they were */
    double bad[3] = {1, NAN, 1}, now[3];
    CHECK(zipopt_scene_set_forces(a, bad, 2, err, sizeof err) == -1 && strstr(err, "3"));
    CHECK(zipopt_scene_set_forces(a, bad, 3, err, sizeof err) == -1);
    CHECK(zipopt_scene_forces(a, now, 3) == 3 && now[0] == 10 && now[1] == 10);
    zipopt_run_free(ra);
    zipopt_run_free(rb);
    zipopt_scene_free(a);
    zipopt_scene_free(b);
}

/* seed_real's drag and friction take out ~23 kJ: the audit books them (docs/model.md), so its
   residual is the integration error, not their sum */
static void check_audit_with_losses(void) {
    char err[4096];
    zipopt_scene *s = zipopt_scene_load(ZP_SOURCE_DIR "/config/seed_real.ini", err, sizeof err);
    CHECK(s != NULL);
    zipopt_run *r = run_forces(s, (const double[3]){80, 500, 500}, 3);
    double drag = zipopt_run_get(r, "w_drag"), fric = zipopt_run_get(r, "w_fric");
    double audit = zipopt_run_get(r, "e_final") - zipopt_run_get(r, "e_initial") -
                   zipopt_run_get(r, "w_drive") + zipopt_run_get(r, "w_damp") +
                   zipopt_run_get(r, "e_impulse") + drag + fric;
    CHECK(zipopt_run_outcome(r) == ZIPOPT_FINISHED && drag > 1e4 && fric > 0);
    CHECK_NEAR(zipopt_run_get(r, "energy_residual"), audit, 1e-9 * drag);
    CHECK_NEAR(audit, 0, K_RTOL * 1e-8 * drag);
    zipopt_run_free(r);
    zipopt_scene_free(s);
}

/* the whole body's centre of mass along the slope: s(t) = s0 + a t^2 / 2 */
static void check_slope(void) {
    const char *ini = "[course]\nx_start = 0\nsection = 200 : 100 - 0.2*x\n"
                      "[trolley]\nmass = 30\n[body]\nlengths = 5, 4, 3\nmasses = 15, 5, 2\n"
                      "damping = 1\ndeath_angle = 179\n[drive]\nforces = 50\n"
                      "[solver]\nrtol = 1e-10\natol = 1e-12\noutput_dt = 0.1\n";
    char err[4096];
    zipopt_scene *s = zipopt_scene_load_string(ini, "slope.ini", err, sizeof err);
    CHECK(s != NULL);
    if (!s) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    zipopt_run *r = zipopt_simulate(s, err, sizeof err);
    CHECK(r && zipopt_run_outcome(r) == ZIPOPT_FINISHED);
    const double m[4] = {30, 15, 5, 2}, len[3] = {5, 4, 3}, M = 52, F = 50, g = 9.81;
    double al = atan(-0.2), ux = cos(al), uy = sin(al);
    double acc = (F * cos(al) - M * g * sin(al)) / M;
    int cols = zipopt_run_columns(r), jx = column(r, "x"), jth = column(r, "theta1");
    double worst = 0, s0 = 0;
    for (int k = 0; k < zipopt_run_rows(r); k++) {
        const double *row = zipopt_run_trajectory(r) + (size_t)k * cols;
        double px = row[jx], py = row[jx + 1], cx = m[0] * px, cy = m[0] * py;
        for (int i = 0; i < 3; i++) {
            double th = row[jth + i];
            cx += m[i + 1] * (px + len[i] / 2 * sin(th));
            cy += m[i + 1] * (py - len[i] / 2 * cos(th));
            px += len[i] * sin(th);
            py -= len[i] * cos(th);
        }
        double along = (cx * ux + cy * uy) / M, t = row[column(r, "t")];
        s0 = k ? s0 : along;
        worst = fmax(worst, fabs(along - (s0 + acc * t * t / 2)));
    }
    CHECK_NEAR(worst, 0, K_RTOL * 1e-10 * 200);
    zipopt_run_free(r);
    zipopt_scene_free(s);
}

typedef struct job {
    double force;
    zipopt_run *run;
} job;

static void *simulate_job(void *arg) {
    job *j = arg;
    char err[512];
    zipopt_scene *s = zipopt_scene_load(SEED, err, sizeof err);
    double f[3] = {j->force, j->force, j->force};
    if (s && !zipopt_scene_set_forces(s, f, 3, err, sizeof err)) {
        j->run = zipopt_simulate(s, err, sizeof err);
    }
    zipopt_scene_free(s);
    return NULL;
}

/* two handles in two threads at once give the bits each gives alone */
static void check_threads(void) {
    job jobs[2] = {{10, NULL}, {40, NULL}}, alone[2] = {{10, NULL}, {40, NULL}};
    pthread_t th[2];
    for (int i = 0; i < 2; i++) {
        CHECK(pthread_create(&th[i], NULL, simulate_job, &jobs[i]) == 0);
    }
    for (int i = 0; i < 2; i++) {
        pthread_join(th[i], NULL);
        simulate_job(&alone[i]);
        CHECK(jobs[i].run && alone[i].run && same_run(jobs[i].run, alone[i].run));
        zipopt_run_free(jobs[i].run);
        zipopt_run_free(alone[i].run);
    }
}

/* bad input: NULL with file, line and key in the text, and not a byte on stdout or stderr */
static void check_quiet_errors(void) {
    fflush(stdout);
    fflush(stderr);
    FILE *cap = tmpfile();
    int out = dup(1), errfd = dup(2);
    dup2(fileno(cap), 1);
    dup2(fileno(cap), 2);
    char err[4096] = "";
    zipopt_scene *s = zipopt_scene_load_string("[scene]\nname = x\n[body]\nmasses = 1, -2\n",
                                               "bad.ini", err, sizeof err);
    zipopt_scene *t = zipopt_scene_load("/nonexistent/scene.ini", err + 2048, 2048);
    fflush(stdout);
    fflush(stderr);
    dup2(out, 1);
    dup2(errfd, 2);
    close(out);
    close(errfd);
    CHECK(s == NULL && t == NULL);
    CHECK(strstr(err, "bad.ini:4:") && strstr(err, "masses"));
    CHECK(strstr(err + 2048, "/nonexistent/scene.ini"));
    CHECK(ftell(cap) == 0);
    fclose(cap);
}

/* a NULL handle or output array is refused with -1, NaN or NULL (zipopt.h), never followed */
static void check_null(void) {
    char err[256] = "";
    double v[8];
    CHECK(zipopt_simulate(NULL, err, sizeof err) == NULL && strstr(err, "no scene"));
    CHECK(zipopt_search_run(NULL, 10, 1, NULL, NULL, NULL, err, sizeof err) == NULL);
    CHECK(!zipopt_scene_name(NULL) && zipopt_scene_sections(NULL) == -1 &&
          zipopt_scene_links(NULL) == -1 && zipopt_scene_forces(NULL, v, 8) == -1);
    CHECK(zipopt_scene_set_forces(NULL, v, 3, err, sizeof err) == -1);
    CHECK(zipopt_run_outcome(NULL) == -1 && !zipopt_run_stall(NULL) &&
          isnan(zipopt_run_get(NULL, "time")) && zipopt_run_max_angles(NULL, v, 8) == -1 &&
          zipopt_run_kinks(NULL, v, 1) == -1 && zipopt_run_rows(NULL) == -1 &&
          zipopt_run_columns(NULL) == -1 && !zipopt_run_column(NULL, 0) &&
          !zipopt_run_trajectory(NULL));
    CHECK(isnan(zipopt_search_get(NULL, "found")) && zipopt_search_forces(NULL, v, 8) == -1);
    zipopt_scene_free(NULL);
    zipopt_run_free(NULL);
    zipopt_search_free(NULL);
    /* NULL arrays with room claimed: the counts, nothing copied */
    zipopt_scene *s = zipopt_scene_load(SEED, err, sizeof err);
    CHECK(s && zipopt_scene_forces(s, NULL, 3) == 3);
    CHECK(zipopt_scene_set_forces(s, NULL, 3, err, sizeof err) == -1 && strstr(err, "no array"));
    zipopt_run *r = zipopt_simulate(s, err, sizeof err);
    CHECK(r && zipopt_run_max_angles(r, NULL, 3) == 3 && zipopt_run_kinks(r, NULL, 4) >= 0);
    volatile int stop = 1;
    zipopt_search *c = zipopt_search_run(s, 60, 7, NULL, NULL, &stop, err, sizeof err);
    CHECK(c && zipopt_search_forces(c, NULL, 3) == 3);
    zipopt_search_free(c);
    zipopt_run_free(r);
    zipopt_scene_free(s);
}

/* the seed's schedule: one parameter per section, "section k", N, in [min, max] = [0, 500] */
static void check_params(void) {
    char err[512], label[16];
    double lo[4] = {-1, -1, -1, -1}, hi[4] = {-1, -1, -1, -1};
    zipopt_scene *s = zipopt_scene_load(SEED, err, sizeof err);
    CHECK(s && zipopt_scene_params(s) == 3 && zipopt_scene_forces(s, NULL, 0) == 3);
    for (int k = 0; k < 3; k++) {
        char want[16];
        snprintf(want, sizeof want, "section %d", k + 1);
        CHECK(zipopt_scene_param_label(s, k, label, sizeof label) == (int)strlen(want));
        CHECK(!strcmp(label, want));
    }
    CHECK(zipopt_scene_param_label(s, 3, label, sizeof label) == -1);
    CHECK(zipopt_scene_param_label(s, -1, label, sizeof label) == -1);
    CHECK(zipopt_scene_param_label(s, 0, NULL, 0) == (int)strlen("section 1"));
    CHECK(!strcmp(zipopt_scene_param_unit(s), "N"));
    CHECK(zipopt_scene_param_bounds(s, lo, hi, 4) == 3 && lo[2] == 0 && hi[2] == 500);
    CHECK(lo[3] == -1 && hi[3] == -1 && zipopt_scene_param_bounds(s, NULL, NULL, 3) == 3);
    CHECK(zipopt_scene_params(NULL) == -1 && !zipopt_scene_param_unit(NULL) &&
          zipopt_scene_param_label(NULL, 0, label, sizeof label) == -1 &&
          zipopt_scene_param_bounds(NULL, lo, hi, 3) == -1);
    zipopt_scene_free(s);
}

/* the folder rule is the commands': scene text without [scene] name loads, named "" */
static void check_unnamed(void) {
    char text[1 << 16], err[1024] = "";
    snprintf(text, sizeof text, "%s", slurp(SEED));
    char *name = strstr(text, "\nname = seed\n");
    CHECK(name != NULL);
    if (name) {
        memmove(name, name + 12, strlen(name + 12) + 1);
    }
    const char *names[] = {NULL, "my scene.ini"};
    for (int i = 0; i < 2; i++) {
        zipopt_scene *s = zipopt_scene_load_string(text, names[i], err, sizeof err);
        if (!s) {
            fprintf(stderr, "refused: %s\n", err);
        }
        CHECK(s && !strcmp(zipopt_scene_name(s), ""));
        zipopt_run *r = s ? zipopt_simulate(s, err, sizeof err) : NULL;
        CHECK(r && zipopt_run_outcome(r) >= 0);
        zipopt_run_free(r);
        zipopt_scene_free(s);
    }
}

/* the library prints nothing, not even the notice that the course is interpreted
   (ZIPOPT_NO_JIT), which the program prints: a child's stderr is read back */
static void check_no_notice(void) {
    fflush(stderr);
    FILE *cap = tmpfile();
    pid_t pid = fork();
    if (pid == 0) {
        setenv("ZIPOPT_NO_JIT", "1", 1);
        dup2(fileno(cap), 2);
        char err[512];
        zipopt_scene *s = zipopt_scene_load(SEED, err, sizeof err);
        zipopt_run *r = s ? zipopt_simulate(s, err, sizeof err) : NULL;
        _exit(r ? 0 : 1);
    }
    int st;
    CHECK(waitpid(pid, &st, 0) == pid && WIFEXITED(st) && WEXITSTATUS(st) == 0);
    fseek(cap, 0, SEEK_END);
    if (ftell(cap) != 0) {
        char said[512] = "";
        rewind(cap);
        fprintf(stderr, "printed: %s\n", fgets(said, sizeof said, cap) ? said : "?");
    }
    CHECK(ftell(cap) == 0);
    fclose(cap);
}

typedef struct seen {
    int calls;
    int stop_at; /* the call that asks to stop */
} seen;

static int on_progress(void *user, long evals, double wall_s, int found, double time,
                       const double *force, int nsec, int improved) {
    seen *s = user;
    (void)evals, (void)wall_s, (void)found, (void)time, (void)force, (void)improved;
    CHECK(nsec == 3);
    return ++s->calls == s->stop_at;
}

/* the same seed gives the same bits; a raised flag or the callback's answer stops the search */
static void check_search(void) {
    char err[512];
    zipopt_scene *s = zipopt_scene_load(SEED, err, sizeof err);
    zipopt_search *a = zipopt_search_run(s, 60, 7, NULL, NULL, NULL, err, sizeof err);
    zipopt_search *b = zipopt_search_run(s, 60, 7, NULL, NULL, NULL, err, sizeof err);
    CHECK(a && b);
    double fa[3], fb[3];
    CHECK(zipopt_search_forces(a, fa, 3) == 3 && zipopt_search_forces(b, fb, 3) == 3);
    CHECK(!memcmp(fa, fb, sizeof fa) && zipopt_search_get(a, "evals") <= 60);
    CHECK(zipopt_search_get(a, "interrupted") == 0);
    volatile int stop = 1;
    zipopt_search *c = zipopt_search_run(s, 60, 7, NULL, NULL, &stop, err, sizeof err);
    CHECK(c && zipopt_search_get(c, "interrupted") == 1 && zipopt_search_get(c, "evals") == 0);
    CHECK(c && !zipopt_search_get(c, "found") && isnan(zipopt_search_get(c, "time")));
    seen n = {0, 1};
    zipopt_search *d = zipopt_search_run(s, 400, 7, on_progress, &n, NULL, err, sizeof err);
    CHECK(d && n.calls >= 1 && zipopt_search_get(d, "interrupted") == 1);
    zipopt_search_free(a);
    zipopt_search_free(b);
    zipopt_search_free(c);
    zipopt_search_free(d);
    zipopt_scene_free(s);
}

/* a schedule file (what the search writes as schedule.ini) gives the bits of the same forces
   set by hand; a bad one is refused naming its file and line, the scene left as it was */
static void check_schedule(void) {
    char err[1024], dir[] = "/tmp/zp_lib_XXXXXX", good[64], bad[64];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(good, sizeof good, "%s/schedule.ini", dir);
    snprintf(bad, sizeof bad, "%s/bad.ini", dir);
    FILE *f = fopen(good, "w"), *g = fopen(bad, "w");
    CHECK(f && g);
    if (!f || !g) {
        return;
    }
    fputs("; best schedule of the search\n[drive]\nforces = 10, 20.5, 30\n", f);
    fputs("[drive]\nforces = 10, 20\n", g);
    fclose(f);
    fclose(g);
    zipopt_scene *s = zipopt_scene_load(SEED, err, sizeof err);
    double want[3] = {10, 20.5, 30}, got[3];
    CHECK(s && zipopt_scene_load_schedule(s, good, err, sizeof err) == 0);
    CHECK(zipopt_scene_forces(s, got, 3) == 3 && !memcmp(got, want, sizeof got));
    zipopt_run *a = zipopt_simulate(s, err, sizeof err);
    CHECK(zipopt_scene_load_schedule(s, bad, err, sizeof err) == -1);
    CHECK(strstr(err, "bad.ini:2: [drive] forces") != NULL);
    CHECK(zipopt_scene_forces(s, got, 3) == 3 && !memcmp(got, want, sizeof got));
    zipopt_run *b = run_forces(s, want, 3);
    CHECK(a && b && same_run(a, b));
    CHECK(zipopt_scene_load_schedule(s, NULL, err, sizeof err) == -1);
    zipopt_run_free(a);
    zipopt_run_free(b);
    zipopt_scene_free(s);
    remove(good);
    remove(bad);
    rmdir(dir);
}

/* the number after "key": (a number, or a list's first) in the JSON text js from its
   object `in` on (NaN: not there) */
static double json_number(const char *js, const char *in, const char *key) {
    char pat[64];
    const char *from = strstr(js, in);
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *at = from ? strstr(from, pat) : NULL;
    if (!at) {
        return NAN;
    }
    at += strlen(pat);
    return strtod(at + (*at == '['), NULL);
}

/* the drive's figures and the gradient are the program's bits (JSON keeps 17 digits): a
   capped drive on seed_power, every [limits] value's derivatives on gradient_limits.ini */
static void check_drive_and_gradient(void) {
    char err[512], cmd[1024], js[1 << 15], dir[] = "/tmp/zp_lib_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    static const char *const scenes[2] = {ZP_SOURCE_DIR "/config/seed_power.ini",
                                          ZP_SOURCE_DIR "/tests/scenes/gradient_limits.ini"};
    for (int i = 0; i < 2; i++) {
        snprintf(cmd, sizeof cmd, "%s simulate %s %s --gradient --json --out %s 2>/dev/null",
                 ZP_EXE, scenes[i], i == 0 ? "--force 60,500,500" : "", dir);
        FILE *p = popen(cmd, "r");
        CHECK(p != NULL);
        size_t n = p ? fread(js, 1, sizeof js - 1, p) : 0;
        js[n] = '\0';
        CHECK(p && pclose(p) == 0);
        zipopt_scene *s = zipopt_scene_load(scenes[i], err, sizeof err);
        double f0[3] = {60, 500, 500};
        CHECK(s && (i > 0 || zipopt_scene_set_forces(s, f0, 3, err, sizeof err) == 0));
        zipopt_run *r = s ? zipopt_simulate(s, err, sizeof err) : NULL;
        CHECK(r != NULL);
        if (!r) {
            zipopt_scene_free(s);
            continue;
        }
        const char *drive = "\"drive\": {";
        CHECK(zipopt_run_get(r, "drive_peak_power") == json_number(js, drive, "peak_power"));
        CHECK(zipopt_run_get(r, "drive_energy") == json_number(js, drive, "energy"));
        CHECK(zipopt_run_get(r, "drive_time_at_cap") == json_number(js, drive, "time_at_cap"));
        CHECK(i > 0 || zipopt_run_get(r, "drive_time_at_cap") > 0);
        double dt[3], dm[3], dl[16 * 3];
        int smooth, lsmooth[16], nkey = 0;
        while (zipopt_limit_key(nkey)) {
            nkey++;
        }
        CHECK(nkey <= 16 && zipopt_gradient(s, dt, dm, 3, &smooth, err, sizeof err) == 3);
        CHECK(zipopt_gradient_limits(s, dl, 3, lsmooth, err, sizeof err) == 3);
        /* the first parameter's derivatives, as the JSON lists them */
        const char *grad = "\"gradient\": {", *lims = "\"limits\": {";
        CHECK(dt[0] == json_number(js, grad, "time"));
        CHECK(dm[0] == json_number(js, grad, "margin_angle"));
        for (int k = 0; k < nkey; k++) {
            const char *g = strstr(js, grad);
            double want = g ? json_number(g, lims, zipopt_limit_key(k)) : NAN;
            CHECK(isnan(want) ? isnan(dl[k * 3]) : dl[k * 3] == want && lsmooth[k]);
        }
        zipopt_run_free(r);
        zipopt_scene_free(s);
    }
    snprintf(cmd, sizeof cmd, "rm -r %s", dir);
    CHECK(system(cmd) == 0);
}

int main(void) {
    CHECK(!strcmp(zipopt_version(), "0.1.0") || strchr(zipopt_version(), '.'));
    check_schedule();
    check_seed();
    check_slope();
    check_audit_with_losses();
    check_threads();
    check_quiet_errors();
    check_null();
    check_params();
    check_unnamed();
    check_no_notice();
    check_search();
    check_drive_and_gradient();
    return CHECK_DONE();
}
