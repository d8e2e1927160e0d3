/* Figures and the landscape: every figure is a real image of the size its script
   asks for; the data drawn are the trajectory (centres of mass from state.c at each row, link
   ends one link length apart); a missing gnuplot still leaves data and scripts, a failing one
   leaves nothing; bad options exit 2 with nothing written; the landscape's points are what
   independent single runs give, and on the seed show docs/model.md's non-monotone survival: a
   constant push of 5 N dies, 10 finishes, 15 dies, 20 and 25 finish, 30 dies; a landscape
   where nothing finishes or dies still draws. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "landscape.h"
#include "plot.h"
#include "state.h"
#include "testutil.h"

#define DATA_TOL 1e-7 /* relative: plot data are printed with 9 significant digits */
#define LINK_TOL 1e-6 /* m: link ends printed with 9 significant digits */

static char tmp[512];
static char err[65536]; /* stderr of the last binary run */

static const int seed_pattern_force[] = {5, 10, 15, 20, 25, 30};
static const zp_outcome seed_pattern[] = {ZP_OUTCOME_DIED,     ZP_OUTCOME_FINISHED,
                                          ZP_OUTCOME_DIED,     ZP_OUTCOME_FINISHED,
                                          ZP_OUTCOME_FINISHED, ZP_OUTCOME_DIED};

static int exists(const char *dir, const char *name) {
    char path[2048];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static int count_files(const char *dir) {
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "ls -A '%s' 2>/dev/null | wc -l", dir);
    FILE *p = popen(cmd, "r");
    int n = -1;
    if (p) {
        if (fscanf(p, "%d", &n) != 1) {
            n = -1;
        }
        pclose(p);
    }
    return n;
}

static unsigned be32(const unsigned char *b) {
    return (unsigned)b[0] << 24 | (unsigned)b[1] << 16 | (unsigned)b[2] << 8 | b[3];
}

/* a PNG's width and height from its signature and IHDR chunk; 0 if it is not a PNG. Also
   returns the file size in *bytes */
static int png_size(const char *dir, const char *name, unsigned *w, unsigned *h, long *bytes) {
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    unsigned char b[24] = {0};
    FILE *f = fopen(path, "rb");
    if (!f) {
        return 0;
    }
    size_t n = fread(b, 1, sizeof b, f);
    fseek(f, 0, SEEK_END);
    *bytes = ftell(f);
    fclose(f);
    if (n != sizeof b || memcmp(b, sig, 8) || be32(b + 8) != 13 || memcmp(b + 12, "IHDR", 4)) {
        return 0;
    }
    *w = be32(b + 16);
    *h = be32(b + 20);
    return 1;
}

/* checks one PNG: valid, the expected size (0: any of at least 300 px), not a blank picture */
static void check_png(const char *dir, const char *name, unsigned want_w, unsigned want_h) {
    unsigned w = 0, h = 0;
    long bytes = 0;
    int ok = png_size(dir, name, &w, &h, &bytes);
    if (!ok) {
        fprintf(stderr, "not a PNG: %s/%s\n", dir, name);
    }
    CHECK(ok);
    if (want_w) {
        CHECK(w == want_w);
        CHECK(h == want_h);
    } else {
        CHECK(w >= 300 && w <= 4000);
        CHECK(h >= 150 && h <= 4000);
    }
    CHECK(bytes > 8000); /* an empty canvas of this size compresses to a few KB */
}

static char *slurp(const char *dir, const char *name) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) {
        return NULL;
    }
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    rewind(f);
    char *s = malloc((size_t)n + 1);
    if (s) {
        s[fread(s, 1, (size_t)n, f)] = '\0';
    }
    fclose(f);
    return s;
}

/* runs the zipopt binary with env in front (e.g. "PATH=/nowhere"); keeps stderr */
static int run(const char *env, const char *args) {
    char cmd[8192];
    snprintf(cmd, sizeof cmd, "env %s '%s' %s >'%s/stdout' 2>'%s/stderr'", env, ZP_EXE, args, tmp,
             tmp);
    int st = system(cmd);
    char *e = slurp(tmp, "stderr");
    snprintf(err, sizeof err, "%s", e ? e : "");
    free(e);
    return st != -1 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* zp_plot_run in a transaction of its own on dir: committed when it succeeds, else aborted */
static zp_status plot_into(const char *dir, const zp_model *m, const zp_sim *s,
                           const zp_result *r, const zp_plot_opts *o, zp_plot_info *info,
                           char *e, size_t elen) {
    zp_tx t;
    if (zp_tx_begin(&t, dir, NULL, e, elen)) {
        return ZP_ERR_IO;
    }
    zp_status st = zp_plot_run(&t, m, s, r, o, info, e, elen);
    if (st) {
        zp_tx_abort(&t);
        return st;
    }
    return zp_tx_commit(&t, e, elen);
}

static zp_model *seed(zp_scene *sc) {
    char path[1024];
    snprintf(path, sizeof path, "%s/config/seed.ini", ZP_SOURCE_DIR);
    zp_diag d;
    zp_diag_init(&d);
    zp_model *m = zp_scene_load(path, sc, &d) == ZP_OK ? zp_model_build(sc, &d) : NULL;
    if (!m) {
        zp_diag_print(&d, stderr);
        abort();
    }
    return m;
}

/* the column of name in a whitespace header line, or -1 */
static int column(const char *header, const char *name) {
    char buf[8192];
    snprintf(buf, sizeof buf, "%s", header);
    int k = 0;
    for (char *t = strtok(buf, " \n"); t; t = strtok(NULL, " \n"), k++) {
        if (!strcmp(t, name)) {
            return k;
        }
    }
    return -1;
}

/* plot_run.dat against the rows: time and every centre of mass from state.c */
static void check_run_data(const char *dir, const zp_model *m, const zp_row_store *rows) {
    char path[2048];
    snprintf(path, sizeof path, "%s/plot_run.dat", dir);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL);
    if (!f) {
        return;
    }
    char line[8192];
    CHECK(fgets(line, sizeof line, f) != NULL);
    int ct = column(line, "t"), cc[ZP_MAX_LINKS + 1];
    CHECK(ct == 0);
    for (int b = 0; b <= m->nlink; b++) {
        char name[32];
        snprintf(name, sizeof name, "com%d_x", b);
        cc[b] = column(line, name);
        CHECK(cc[b] > 0);
    }
    int k = 0, bad = 0;
    while (fgets(line, sizeof line, f) && k < rows->n) {
        double v[128];
        int nv = 0;
        for (char *t = strtok(line, " \n"); t && nv < 128; t = strtok(NULL, " \n")) {
            v[nv++] = atof(t);
        }
        double com[ZP_MAX_LINKS + 1][2];
        zp_row row;
        zp_row_store_get(rows, k, &row);
        zp_state_com(m, &row.c, com);
        bad += fabs(v[ct] - row.t) > DATA_TOL * fmax(1, row.t);
        for (int b = 0; b <= m->nlink; b++) {
            bad += fabs(v[cc[b]] - com[b][0]) > DATA_TOL * fmax(1, fabs(com[b][0]));
            bad += fabs(v[cc[b] + 1] - com[b][1]) > DATA_TOL * fmax(1, fabs(com[b][1]));
        }
        k++;
    }
    CHECK(k == rows->n);
    CHECK(bad == 0);
    fclose(f);
}

/* plot_frames.dat: block 0 is the frame at x = x0: the trolley there on the course, each link
   its own length long and joined to the next */
static void check_frame_data(const char *dir, const zp_model *m, double x0) {
    char path[2048];
    snprintf(path, sizeof path, "%s/plot_frames.dat", dir);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL);
    if (!f) {
        return;
    }
    double px = 0, py = 0;
    for (int i = 0; i < m->nlink; i++) {
        double a[7];
        int link;
        CHECK(fscanf(f, "%lf %lf %lf %lf %d %lf %lf", &a[0], &a[1], &a[2], &a[3], &link, &a[5],
                     &a[6]) == 7);
        CHECK(link == i + 1);
        if (i == 0) {
            /* the simulator's state where the trolley reaches x0: on the course, to the
               9 digits printed */
            CHECK_NEAR(a[0], x0, LINK_TOL);
            CHECK_NEAR(a[1], zp_course_eval(m->course, 0, x0).f, LINK_TOL);
        } else {
            CHECK_NEAR(a[0], px, LINK_TOL);
            CHECK_NEAR(a[1], py, LINK_TOL);
        }
        CHECK_NEAR(hypot(a[2] - a[0], a[3] - a[1]), m->len[i], LINK_TOL);
        CHECK_NEAR(a[5], 0.5 * (a[0] + a[2]), LINK_TOL); /* uniform rod: centre mid-link */
        CHECK_NEAR(a[6], 0.5 * (a[1] + a[3]), LINK_TOL);
        px = a[2];
        py = a[3];
    }
    fclose(f);
}

static void test_figures(void) {
    zp_scene sc;
    zp_model *m = seed(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    o.output_dt = 0.02;
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    double force[3] = {20, 20, 20};
    zp_schedule in_sched = tu_sched(m, force);
    zp_input in = {.sched = &in_sched};
    zp_plot_opts po;
    zp_plot_opts_default(&po);
    char why[256];
    CHECK(zp_plot_opts_parse_frames(m, "x=60,0,20,139.5,20", &po, why, sizeof why) == 0);
    CHECK(po.nframe == 4 && po.frame_at[0] == 0 && po.frame_at[3] == 139.5); /* sorted, once */
    zp_plot_opts_frames_input(&po, &in);
    CHECK(s && zp_sim_run(m, s, &in, &r) == ZP_OK);
    CHECK(r.outcome == ZP_OUTCOME_FINISHED);
    const zp_row_store *rows = zp_sim_rows(s);

    CHECK(zp_plot_opts_parse_size("480x200", &po, why, sizeof why) == 0);
    po.animate = 1;
    po.fps = 10;
    po.speedup = 4;
    po.margin = 10 * M_PI / 180;
    po.sched = &in_sched;
    char dir[1024], e[2048];
    snprintf(dir, sizeof dir, "%s/figs", tmp);
    zp_plot_info info;
    CHECK(plot_into(dir, m, s, &r, &po, &info, e, sizeof e) == ZP_OK);
    CHECK(!info.no_gnuplot);
    CHECK(info.nframe == 4 && info.nskipped == 0);
    /* the animation: every speedup/fps seconds of the run, plus its last instant */
    CHECK(info.anim_frames == (int)floor(r.time / 0.4) + 2);

    check_png(dir, "course.png", 0, 0);
    /* the course also as SVG: a vector image of the same size */
    unsigned cw = 0, ch = 0;
    long cbytes = 0;
    png_size(dir, "course.png", &cw, &ch, &cbytes);
    char viewbox[64];
    snprintf(viewbox, sizeof viewbox, "viewBox=\"0 0 %u %u\"", cw, ch);
    char *svg = slurp(dir, "course.svg");
    CHECK(svg && strstr(svg, "<svg") && strstr(svg, viewbox) && strstr(svg, "<path"));
    free(svg);
    check_png(dir, "energy.png", 0, 0);
    check_png(dir, "angles.png", 0, 0);
    check_png(dir, "loads.png", 0, 0);
    check_png(dir, "along.png", 0, 0);
    check_png(dir, "drive.png", 0, 0);
    /* the drive against distance and speed, from the columns plot_run.dat adds for it */
    char *drive = slurp(dir, "drive.gp"), *data = slurp(dir, "plot_run.dat");
    CHECK(drive && strstr(drive, "using 'x':'drive_force'") &&
          strstr(drive, "using 'drive_speed':'drive_force'"));
    CHECK(data && strstr(data, " drive_speed drive_force\n"));
    free(drive);
    free(data);
    /* against distance: every curve of along.gp is drawn over the run's x */
    char *along = slurp(dir, "along.gp");
    CHECK(along && strstr(along, "using 'x':'phi1'") && strstr(along, "using 'x':'felt_g'") &&
          strstr(along, "using 'x':'joint1'") && strstr(along, "set xlabel 'x (m)'"));
    free(along);
    const char *frames[] = {"frame_x0.png", "frame_x20.png", "frame_x60.png", "frame_x139.5.png"};
    for (int i = 0; i < 4; i++) {
        unsigned w = 0, h = 0;
        long bytes;
        CHECK(png_size(dir, frames[i], &w, &h, &bytes));
        CHECK(w == h && w >= 300); /* equal axis scales in a square picture */
        check_png(dir, frames[i], w, h);
    }
    /* run.gif: a GIF of the asked size (logical screen, little-endian) with many frames */
    char *gif = slurp(dir, "run.gif");
    CHECK(gif && !memcmp(gif, "GIF89a", 6));
    if (gif) {
        const unsigned char *u = (const unsigned char *)gif;
        CHECK((u[6] | u[7] << 8) == 480);
        CHECK((u[8] | u[9] << 8) == 200);
    }
    free(gif);
    const char *scripts[] = {"course.gp",       "energy.gp",    "angles.gp",       "loads.gp",
                             "frames.gp",       "run.gp",       "plot_course.dat", "plot_run.dat",
                             "plot_frames.dat", "plot_anim.dat"};
    for (int i = 0; i < 10; i++) {
        CHECK(exists(dir, scripts[i]));
    }
    check_run_data(dir, m, rows);
    check_frame_data(dir, m, 0); /* block 0: the frame at x = 0 */
    /* no hidden working folder is left behind */
    char cmd[2400];
    snprintf(cmd, sizeof cmd, "ls -A '%s' | grep -q '^\\.'", dir);
    CHECK(system(cmd) != 0);

    /* a failing gnuplot: nothing is written, and its message is passed on */
    char fake[1024];
    snprintf(fake, sizeof fake, "%s/fakebin", tmp);
    mkdir(fake, 0777);
    snprintf(cmd, sizeof cmd,
             "printf '#!/bin/sh\\necho no such terminal >&2\\nexit 1\\n' > '%s/gnuplot' && "
             "chmod +x '%s/gnuplot'",
             fake, fake);
    CHECK(system(cmd) == 0);
    const char *path = getenv("PATH");
    char *saved = strdup(path ? path : "");
    setenv("PATH", fake, 1);
    snprintf(dir, sizeof dir, "%s/figs_fail", tmp);
    po.animate = 0;
    CHECK(plot_into(dir, m, s, &r, &po, &info, e, sizeof e) == ZP_ERR_IO);
    CHECK(strstr(e, "no such terminal") != NULL);
    setenv("PATH", saved, 1);
    free(saved);
    CHECK(count_files(dir) == 0);

    /* frames the run never reaches are counted, not drawn */
    zp_plot_opts late = po;
    CHECK(zp_plot_opts_parse_frames(m, "t=1,1000", &late, why, sizeof why) == 0);
    zp_plot_opts_frames_input(&late, &in);
    CHECK(zp_sim_run(m, s, &in, &r) == ZP_OK);
    snprintf(dir, sizeof dir, "%s/figs_late", tmp);
    CHECK(plot_into(dir, m, s, &r, &late, &info, e, sizeof e) == ZP_OK);
    CHECK(info.nframe == 1 && info.nskipped == 1);
    CHECK(exists(dir, "frame_t1.png") && !exists(dir, "frame_t1000.png"));
    zp_sim_free(s);
    zp_model_free(m);
}

/* a frame at x = 20 m: its data block against the course and the link lengths */
static void test_frame_geometry(void) {
    zp_scene sc;
    zp_model *m = seed(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    o.output_dt = 0.02;
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    double force[3] = {100, 100, 100};
    zp_schedule in_sched = tu_sched(m, force);
    zp_input in = {.sched = &in_sched};
    zp_plot_opts po;
    zp_plot_opts_default(&po);
    char why[256], dir[1024], e[2048];
    CHECK(zp_plot_opts_parse_frames(m, "x=20", &po, why, sizeof why) == 0);
    zp_plot_opts_frames_input(&po, &in);
    CHECK(s && zp_sim_run(m, s, &in, &r) == ZP_OK);
    snprintf(dir, sizeof dir, "%s/figs20", tmp);
    zp_plot_info info;
    CHECK(plot_into(dir, m, s, &r, &po, &info, e, sizeof e) == ZP_OK);
    check_frame_data(dir, m, 20);
    check_png(dir, "frame_x20.png", 640, 640);
    zp_sim_free(s);
    zp_model_free(m);
}

static void test_cli(void) {
    char scene[1024], args[4096], dir[1024];
    snprintf(scene, sizeof scene, "%s/config/seed.ini", ZP_SOURCE_DIR);

    /* no gnuplot on PATH: exit 1, a message naming it, data and scripts written, no image */
    snprintf(dir, sizeof dir, "%s/nognu", tmp);
    snprintf(args, sizeof args, "simulate '%s' --force 20,20,20 --plot --out '%s'", scene, dir);
    CHECK(run("PATH=/nonexistent", args) == 1);
    CHECK(strstr(err, "gnuplot is not installed") != NULL);
    CHECK(strstr(err, "gnuplot-nox") != NULL);
    CHECK(exists(dir, "plot_run.dat") && exists(dir, "course.gp") && exists(dir, "energy.gp"));
    CHECK(exists(dir, "trajectory.csv"));
    CHECK(!exists(dir, "course.png"));

    /* a frame at the kink x = 60: the trolley on the course (f(60) = 10), after the impulse,
       and the run's answer the same with the frame as without */
    snprintf(dir, sizeof dir, "%s/kinkframe", tmp);
    snprintf(args, sizeof args, "simulate '%s' --force 20,20,20 --json --frames-at x=60 --out '%s'",
             scene, dir);
    CHECK(run("ZIPOPT_TEST=1", args) == 0);
    char *with = slurp(tmp, "stdout"), *dat = slurp(dir, "plot_frames.dat");
    CHECK(dat && !strncmp(dat, "60 10 ", 6));
    snprintf(args, sizeof args, "simulate '%s' --force 20,20,20 --json --out '%s/noframe'", scene,
             tmp);
    CHECK(run("ZIPOPT_TEST=1", args) == 0);
    char *without = slurp(tmp, "stdout");
    const char *tw = with ? strstr(with, "\"time\"") : NULL;
    const char *to = without ? strstr(without, "\"time\"") : NULL;
    CHECK(tw && to && !strncmp(tw, to, strcspn(to, "\n")));
    free(with);
    free(without);
    free(dat);

    /* bad plot options: exit 2, the option named, nothing written */
    const struct {
        const char *opt, *name;
    } bad[] = {{"--frames-at x=200", "--frames-at"}, {"--frames-at y=3", "--frames-at"},
               {"--frames-at t=-1", "--frames-at"},  {"--animate --fps 0", "--fps"},
               {"--animate --size 10x10", "--size"}, {"--animate --speedup -2", "--speedup"}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        snprintf(dir, sizeof dir, "%s/bad%zu", tmp, i);
        snprintf(args, sizeof args, "simulate '%s' %s --out '%s'", scene, bad[i].opt, dir);
        CHECK(run("ZIPOPT_TEST=1", args) == 2);
        CHECK(strstr(err, bad[i].name) != NULL);
        CHECK(count_files(dir) <= 0);
    }
    const char *badland[] = {"--slice 1,1",
                             "--slice 1,4",
                             "--force-range 5:1:3",
                             "--force-range 0:10:1",
                             "--slice 1,2 --range 0:10",
                             "--range 0:10:3",
                             "--force 1,2"};
    for (size_t i = 0; i < sizeof badland / sizeof badland[0]; i++) {
        snprintf(dir, sizeof dir, "%s/badland%zu", tmp, i);
        snprintf(args, sizeof args, "landscape '%s' %s --out '%s'", scene, badland[i], dir);
        CHECK(run("ZIPOPT_TEST=1", args) == 2);
        CHECK(count_files(dir) <= 0);
    }
}

/* a plan's schedules: the constant pushes, then the slice's with its first axis varying fastest
   and the other sections at the base's (rows written out by hand) */
static void test_landscape_plan(void) {
    const double base_p[3] = {7, 8, 9};
    zp_schedule base = zp_drive_sections(3, base_p, 0, 0);
    zp_landscape_plan plan = {
        .push = {0, 10, 3}, .si = 0, .sj = 2, .rx = {0, 1, 2}, .ry = {5, 7, 3}};
    const double want[9][3] = {{0, 0, 0}, {5, 5, 5}, {10, 10, 10}, {0, 8, 5}, {1, 8, 5},
                               {0, 8, 6}, {1, 8, 6},  {0, 8, 7},    {1, 8, 7}};
    CHECK(zp_landscape_slice_runs(&plan) == 6);
    double *p = zp_landscape_params(&plan, &base);
    CHECK(p != NULL);
    for (int k = 0; p && k < 9; k++) {
        for (int j = 0; j < 3; j++) {
            CHECK(p[3 * k + j] == want[k][j]);
        }
    }
    free(p);
    plan.si = -1; /* no slice: the pushes alone */
    CHECK(zp_landscape_slice_runs(&plan) == 0);
}

/* the landscape's points against independent single runs, and the seed's survival windows */
static void test_landscape(void) {
    zp_scene sc;
    zp_model *m = seed(&sc);
    zp_sim_opts o = tu_opts(&sc, sc.rtol);
    o.atol = sc.atol;
    enum { NP = 6 };
    double force[NP * 3];
    for (int k = 0; k < NP; k++) {
        force[3 * k] = force[3 * k + 1] = force[3 * k + 2] = seed_pattern_force[k];
    }
    zp_landscape_point pt[NP];
    zp_schedule shape = tu_sched(m, force);
    CHECK(zp_landscape_sweep(m, &o, &shape, force, NP, pt, NULL, NULL, NULL) == ZP_OK);
    for (int k = 0; k < NP; k++) {
        zp_schedule in_sched = tu_sched(m, force + 3 * k);
        zp_input in = {.sched = &in_sched};
        const zp_result *r = tu_run(m, &o, &in);
        CHECK(!pt[k].failed);
        CHECK(pt[k].outcome == r->outcome);
        CHECK(pt[k].time == r->time); /* the same run, bit for bit */
        CHECK(pt[k].died_link == r->died_link);
        CHECK(r->outcome == seed_pattern[k]);
        if (r->outcome != seed_pattern[k]) {
            fprintf(stderr, "constant push %d N: %s\n", seed_pattern_force[k],
                    zp_sim_outcome_name(r->outcome));
        }
    }

    /* the command: the same outcomes in landscape.csv, and a slice cell against its run */
    char scene[1024], args[4096], dir[1024];
    snprintf(scene, sizeof scene, "%s/config/seed.ini", ZP_SOURCE_DIR);
    snprintf(dir, sizeof dir, "%s/land", tmp);
    snprintf(args, sizeof args,
             "landscape '%s' --force-range 5:30:6 --slice 1,2 "
             "--range 5:30:6 --out '%s'",
             scene, dir);
    CHECK(run("ZIPOPT_TEST=1", args) == 0);
    /* the windows: runs of consecutive finishing points, a lone point as a point */
    char *said = slurp(tmp, "stdout");
    CHECK(said && strstr(said, "finishes at 10 N; 20, 25 N\n") != NULL);
    free(said);
    check_png(dir, "landscape.png", 0, 0);
    check_png(dir, "landscape_slice.png", 0, 0);
    char *csv = slurp(dir, "landscape.csv");
    CHECK(csv != NULL);
    int rowsread = 0;
    for (char *line = csv ? strchr(csv, '\n') : NULL; line && line[1];
         line = strchr(line + 1, '\n')) {
        double f;
        char outcome[32];
        if (sscanf(line + 1, "%lf,%31[^,]", &f, outcome) == 2 && rowsread < NP) {
            CHECK(f == seed_pattern_force[rowsread]);
            CHECK(!strcmp(outcome, zp_sim_outcome_name(seed_pattern[rowsread])));
            rowsread++;
        }
    }
    CHECK(rowsread == NP);
    free(csv);
    /* slice cell F1 = 10, F2 = 25 with section 3 at the scene's 100 N */
    csv = slurp(dir, "landscape_slice.csv");
    CHECK(csv && !strncmp(csv, "f1,f2,outcome", 13));
    double cell[3] = {10, 25, sc.forces[2]};
    zp_schedule in_sched = tu_sched(m, cell);
    zp_input in = {.sched = &in_sched};
    const zp_result *r = tu_run(m, &o, &in);
    char want[64];
    snprintf(want, sizeof want, "\n10,25,%s,", zp_sim_outcome_name(r->outcome));
    CHECK(csv && strstr(csv, want) != NULL);
    int lines = 0;
    for (char *p = csv; p && *p; p++) {
        lines += *p == '\n';
    }
    CHECK(lines == 1 + 36);
    free(csv);
    zp_model_free(m);
}

/* a landscape where no push finishes or dies (every one rolls back up a slope it cannot
   climb) still draws its figures: the time panel has no point to scale its axis by */
static void test_landscape_all_stalled(void) {
    char scene[1024], args[4096], dir[1024];
    snprintf(scene, sizeof scene, "%s/uphill.ini", tmp);
    FILE *f = fopen(scene, "w");
    CHECK(f != NULL);
    if (!f) {
        return;
    }
    fputs("[scene]\nname = uphill\n[course]\nx_start = 0\nsection = 20 : x/2\n"
          "section = 40 : y0 + (x - 20)/2\n[trolley]\nmass = 10\n[body]\nlengths = 1\n"
          "masses = 5\n[drive]\nforces = 10, 10\nmin = 0\nmax = 20\n",
          f);
    fclose(f);
    snprintf(dir, sizeof dir, "%s/land_stalled", tmp);
    snprintf(args, sizeof args,
             "landscape '%s' --force-range 0:20:3 --slice 1,2 --range 0:20:3 --out '%s'",
             scene, dir);
    CHECK(run("ZIPOPT_TEST=1", args) == 0);
    check_png(dir, "landscape.png", 0, 0);
    check_png(dir, "landscape_slice.png", 0, 0);
    char *csv = slurp(dir, "landscape.csv");
    CHECK(csv && !strstr(csv, ",finished,") && !strstr(csv, ",died,") && strstr(csv, ",stalled,"));
    free(csv);
}

/* scripts drawn several to a gnuplot process: each in a fresh session (nothing one leaves
   behind reaches the next), and a failing one named with its own message */
static void test_gnuplot_groups(void) {
    enum { N = 9 };
    for (int bad = -1; bad < N; bad += 4) { /* none fails, then the first, then one later */
        char dir[1024], e[1400], name[N][16];
        const char *scripts[N];
        snprintf(dir, sizeof dir, "%s/groups%d", tmp, bad + 1);
        zp_tx t;
        CHECK(zp_tx_begin(&t, dir, NULL, e, sizeof e) == ZP_OK);
        for (int i = 0; i < N; i++) {
            snprintf(name[i], sizeof name[i], "s%d.gp", i);
            scripts[i] = name[i];
            FILE *f = zp_tx_open(&t, name[i], e, sizeof e);
            CHECK(f != NULL);
            if (f) {
                fprintf(f,
                        "if (exists('leak')) exit status 3\nleak = %d\n%s"
                        "set print 's%d.txt'\nprint 'drawn'\nunset print\n",
                        i, i == bad ? "plot no_such_variable_here\n" : "", i);
            }
        }
        int missing = 0;
        zp_status st = zp_gnuplot_run(&t, scripts, N, &missing, e, sizeof e);
        CHECK(!missing);
        if (bad < 0) {
            CHECK(st == ZP_OK);
            CHECK(zp_tx_commit(&t, e, sizeof e) == ZP_OK);
            for (int i = 0; i < N; i++) {
                char out[16];
                snprintf(out, sizeof out, "s%d.txt", i);
                CHECK(exists(dir, out));
            }
        } else {
            char want[64];
            snprintf(want, sizeof want, "gnuplot s%d.gp failed: ", bad);
            CHECK(st == ZP_ERR_IO && strstr(e, want) == e);
            CHECK(strstr(e, "no_such_variable_here") != NULL || strstr(e, "undefined") != NULL);
            CHECK(strstr(e, ZP_GNUPLOT_MARK) == NULL);
            zp_tx_abort(&t);
            CHECK(count_files(dir) == 0);
        }
    }
}

int main(void) {
    snprintf(tmp, sizeof tmp, "%s/zp_plot_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(tmp)) {
        perror("mkdtemp");
        return 1;
    }
    test_figures();
    test_frame_geometry();
    test_cli();
    test_landscape_plan();
    test_landscape();
    test_landscape_all_stalled();
    test_gnuplot_groups();
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    if (system(cmd)) {
        fprintf(stderr, "could not remove %s\n", tmp);
    }
    return CHECK_DONE();
}
