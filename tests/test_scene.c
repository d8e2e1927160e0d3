/* scene.c: every rule of docs/scene-file.md on inline INI text. Each bad case must give
   ZP_ERR_INPUT and a message "t.ini:LINE: [section] key:" at the line the case put it on; defaults
   are docs/scene-file.md's; config/seed.ini and zp_scene_load_seed both equal docs/scene-file.md's
   example. */
#include <stdio.h>
#include <string.h>

#include <limits.h>
#include <math.h>

#include "check.h"
#include "model.h"
#include "report.h"
#include "scene_parse.h"
#include "scene_load.h"

/* a small valid scene; cases replace one of its lines (1-based) */
static const char *const base[] = {
    "[scene]",                         /* 1 */
    "gravity = 9.81",                  /* 2 */
    "[course]",                        /* 3 */
    "x_start = 0",                     /* 4 */
    "section = 60 : (x/10 - 3)^2 + 1", /* 5 */
    "section = 100 : -x/10 + 16",      /* 6 */
    "[trolley]",                       /* 7 */
    "mass = 30",                       /* 8 */
    "[body]",                          /* 9 */
    "lengths = 5, 5",                  /* 10 */
    "masses = 15, 5",                  /* 11 */
    "[drive]",                         /* 12 */
    "forces = 100, 100",               /* 13 */
    "[solver]",                        /* 14 */
    "rtol = 1e-8",                     /* 15 */
    "[optimize]",                      /* 16 */
    "margin = 10",                     /* 17 */
};
enum { NBASE = sizeof base / sizeof *base };

/* the base with line n replaced by repl and line m by repl2 (each may hold several lines, or
   none); n = 0 or m = 0: no replacement */
static const char *with_lines(int n, const char *repl, int m, const char *repl2) {
    static char buf[65536];
    buf[0] = '\0';
    for (int i = 1; i <= NBASE; i++) {
        strcat(buf, i == n ? repl : i == m ? repl2 : base[i - 1]);
        strcat(buf, "\n");
    }
    return buf;
}

static const char *with_line(int n, const char *repl) {
    return with_lines(n, repl, 0, NULL);
}

static int has_message(const zp_diag *d, const char *part) {
    for (int i = 0; i < d->n; i++) {
        if (strstr(d->text[i], part)) {
            return 1;
        }
    }
    return 0;
}

static void show(const zp_diag *d) {
    for (int i = 0; i < d->n; i++) {
        fprintf(stderr, "    got: %s\n", d->text[i]);
    }
}

/* text must be refused with a message at `line` about [sec] key, containing hint if given */
static void expect_bad_at(int caller, const char *text, int line, const char *sec, const char *key,
                          const char *hint) {
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    zp_status st = zp_scene_load_string(text, "t.ini", &sc, &d);
    char head[256];
    if (sec) {
        snprintf(head, sizeof head, "t.ini:%d: [%s] %s: ", line, sec, key);
    } else if (key) {
        snprintf(head, sizeof head, "t.ini:%d: %s: ", line, key);
    } else {
        snprintf(head, sizeof head, "t.ini:%d: ", line);
    }
    int ok = st == ZP_ERR_INPUT && has_message(&d, head) && (!hint || has_message(&d, hint));
    CHECK(ok);
    if (!ok) {
        fprintf(stderr, "  case at test line %d: status %d, wanted `%s` with `%s`\n", caller, st,
                head, hint ? hint : "");
        show(&d);
    }
}
#define BAD(n, repl, line, sec, key)                                                               \
    expect_bad_at(__LINE__, with_line(n, repl), line, sec, key, NULL)
#define BAD_HINT(n, repl, line, sec, key, hint)                                                    \
    expect_bad_at(__LINE__, with_line(n, repl), line, sec, key, hint)

/* text must load cleanly */
static void expect_good_at(int caller, const char *text, zp_scene *sc) {
    zp_diag d;
    zp_diag_init(&d);
    zp_status st = zp_scene_load_string(text, "t.ini", sc, &d);
    CHECK(st == ZP_OK && d.n == 0);
    if (st != ZP_OK || d.n) {
        fprintf(stderr, "  case at test line %d refused\n", caller);
        show(&d);
    }
}
#define GOOD(n, repl, sc) expect_good_at(__LINE__, with_line(n, repl), sc)

static void test_numbers(void) {
    BAD(2, "gravity = -1", 2, "scene", "gravity");
    BAD(2, "gravity = abc", 2, "scene", "gravity");
    BAD(2, "gravity = 9.81abc", 2, "scene", "gravity");
    BAD(2, "gravity = 9.81 m/s", 2, "scene", "gravity");
    BAD(2, "gravity = nan", 2, "scene", "gravity");
    BAD(2, "gravity = inf", 2, "scene", "gravity");
    BAD(2, "gravity = 1e999", 2, "scene", "gravity");
    BAD(2, "gravity = 0x10", 2, "scene", "gravity");
    BAD(2, "gravity =", 2, "scene", "gravity");
    BAD(4, "x_start = 1,2", 4, "course", "x_start");
    BAD(8, "mass = -30", 8, "trolley", "mass");
    BAD(8, "mass = 0", 8, "trolley", "mass");
    /* beyond the largest double: said so, not "not a number" (scalars and list items) */
    BAD_HINT(8, "mass = 1e400", 8, "trolley", "mass", "`1e400` is out of range");
    BAD_HINT(11, "masses = 15, 1e400", 11, "body", "masses", "`1e400` is out of range");
    BAD(15, "rtol = 0", 15, "solver", "rtol");
    BAD(15, "atol = -1e-10", 15, "solver", "atol");
    BAD(15, "t_max = 0", 15, "solver", "t_max");
    BAD(15, "output_dt = -0.02", 15, "solver", "output_dt");
    BAD(10, "lengths = 5\ndeath_angle = 0", 11, "body", "death_angle");
    BAD(10, "lengths = 5\ndeath_angle = 360.5", 11, "body", "death_angle");
    BAD(17, "margin = -1", 17, "optimize", "margin");
    BAD(17, "margin = 180", 17, "optimize", "margin"); /* not below the default death angle */
    BAD(17, "max_evals = 0", 17, "optimize", "max_evals");
    BAD(17, "max_evals = 1.5", 17, "optimize", "max_evals");
    BAD(17, "max_evals = 99999999999999999999999", 17, "optimize", "max_evals");
    BAD(17, "seed = -1", 17, "optimize", "seed");
    BAD(17, "seed = 2.5", 17, "optimize", "seed");
    BAD(17, "seed = one", 17, "optimize", "seed");
    BAD(17, "rtol = 0", 17, "optimize", "rtol");
    BAD(13, "forces = 100, 100\nmin = 10\nmax = 5", 15, "drive", "max");
    BAD(2, "gravity = 9.81#comment", 2, "scene", "gravity"); /* a comment needs a space first */

    zp_scene sc;
    GOOD(10, "lengths = 5, 5\ndeath_angle = 360", &sc);
    CHECK(sc.death_angle == 360);
    GOOD(17, "margin = 0\nmax_evals = 1\nseed = 0", &sc);
    CHECK(sc.margin == 0 && sc.max_evals == 1 && sc.seed == 0);
    GOOD(17, "method = cvode-bdf\nrtol = 1e-7", &sc); /* the search's own integrator */
    CHECK(!strcmp(sc.search_method, "cvode-bdf") && sc.search_rtol == 1e-7);
    CHECK(!strcmp(sc.method, "cvode-adams") && sc.rtol == 1e-8); /* [solver] untouched */
    GOOD(13, "forces = -50, 1.5e2\nmin = -100\nmax = -100", &sc);
    CHECK(sc.forces[0] == -50 && sc.forces[1] == 150 && sc.force_min == -100 &&
          sc.force_max == -100);
    GOOD(2, "gravity = 0", &sc);
    CHECK(sc.gravity == 0);
}

/* the margin must stay below the scene's own death angle, not only the default one */
static void test_margin_vs_death(void) {
    zp_scene sc;
    GOOD(11, "masses = 15, 5\ndeath_angle = 90", &sc);
    CHECK(sc.death_angle == 90 && sc.margin == 10);
    char text[4096];
    snprintf(text, sizeof text, "%s", with_line(11, "masses = 15, 5\ndeath_angle = 90"));
    memcpy(strstr(text, "margin = 10"), "margin = 90", 11); /* now on line 18 */
    expect_bad_at(__LINE__, text, 18, "optimize", "margin", "below death_angle");
}

static void test_lists(void) {
    BAD(10, "lengths = 5,,5", 10, "body", "lengths");
    BAD(10, "lengths = 5, 5,", 10, "body", "lengths");
    BAD(10, "lengths =", 10, "body", "lengths");
    BAD(10, "lengths = 5, 0", 10, "body", "lengths");
    BAD(10, "lengths = 5, -1", 10, "body", "lengths");
    BAD(10, "lengths = 5, x", 10, "body", "lengths");
    BAD(11, "masses = 15, -5", 11, "body", "masses");
    BAD(11, "masses = 15, 0", 11, "body", "masses");
    BAD_HINT(11, "masses = 15, 5, 2", 11, "body", "masses", "3 values, expected 2 (one per link)");
    BAD(11, "masses = 15", 11, "body", "masses");
    BAD(11, "masses = 15, 5\ndamping = -1", 12, "body", "damping");
    BAD(11, "masses = 15, 5\ndamping = 1, 2, 3", 12, "body", "damping");
    BAD_HINT(13, "forces = 100, 100, 100", 13, "drive", "forces",
             "3 values, expected 2 (one per section)");
    BAD(13, "forces = 100", 13, "drive", "forces");
    BAD(13, "forces = 100, ", 13, "drive", "forces");
    /* links: 1 to 8 */
    expect_bad_at(__LINE__,
                  with_lines(10, "lengths = 1,1,1,1,1,1,1,1,1", 11, "masses = 1,1,1,1,1,1,1,1,1"),
                  10, "body", "lengths", "9 values");

    zp_scene sc;
    expect_good_at(
        __LINE__, with_lines(10, "lengths = 1,1,1,1,1,1,1,2", 11, "masses = 1,1,1,1,1,1,1,3"), &sc);
    CHECK(sc.nlink == 8 && sc.lengths[7] == 2 && sc.masses[7] == 3);
    expect_good_at(__LINE__, with_lines(10, "lengths = 4", 11, "masses = 7"), &sc);
    CHECK(sc.nlink == 1 && sc.lengths[0] == 4 && sc.masses[0] == 7);
    GOOD(11, "masses = 15, 5\ndamping = 0.5", &sc);
    CHECK(sc.ndamping == 1 && sc.damping[0] == 0.5 && sc.damping[1] == 0.5);
    GOOD(11, "masses = 15, 5\ndamping = 0.5, 0", &sc);
    CHECK(sc.ndamping == 2 && sc.damping[0] == 0.5 && sc.damping[1] == 0);
    GOOD(10, "lengths = 5 ,2.5", &sc);
    CHECK(sc.nlink == 2 && sc.lengths[1] == 2.5);
}

static void test_course_rules(void) {
    BAD(5, "section = 60 (x/10 - 3)^2 + 1", 5, "course", "section");
    BAD(5, "section = sixty : x", 5, "course", "section");
    BAD(5, "section = 60 :", 5, "course", "section");
    BAD(5, "section = 0 : x", 5, "course", "section");  /* not past x_start */
    BAD(5, "section = -5 : x", 5, "course", "section"); /* not past x_start */
    BAD(6, "section = 60 : x", 6, "course", "section"); /* not past the previous */
    BAD(6, "section = 50 : x", 6, "course", "section");
    BAD_HINT(5, "section = 60 : (x/10 - 3^2", 5, "course", "section", "syntax error");
    BAD_HINT(5, "section = 60 : y * x", 5, "course", "section", "`y`");
    BAD_HINT(5, "section = 60 : abs(x)", 5, "course", "section", "`abs`");

    /* at most ZP_MAX_SECTIONS: the first section too many is the one named */
    char repl[65536] = "", line[64];
    for (int i = 1; i <= ZP_MAX_SECTIONS + 1; i++) {
        snprintf(line, sizeof line, "%ssection = %d : x", i > 1 ? "\n" : "", i);
        strcat(repl, line);
    }
    BAD(5, repl, 5 + ZP_MAX_SECTIONS, "course", "section");

    zp_scene sc;
    GOOD(0, "", &sc);
    CHECK(sc.nsec == 2 && sc.x_end[0] == 60 && sc.x_end[1] == 100);
    CHECK(!strcmp(sc.expr[0], "(x/10 - 3)^2 + 1") && !strcmp(sc.expr[1], "-x/10 + 16"));
    CHECK(sc.sec_line[0] == 5 && sc.sec_line[1] == 6);
    GOOD(4, "x_start = -10", &sc);
    CHECK(sc.x_start == -10);
}

static void test_names(void) {
    BAD_HINT(13, "forces = 100, 100\ndirection = sideways", 14, "drive", "direction",
             "horizontal or tangent");
    BAD(15, "method = a-method-name-far-too-long-to-keep", 15, "solver", "method");
    BAD(15, "formulation =", 15, "solver", "formulation");
    BAD(2, "name = ../escape", 2, "scene", "name");
    BAD(2, "name = a/b", 2, "scene", "name");
    zp_scene sc;
    GOOD(13, "forces = 1, 2\ndirection = tangent", &sc);
    CHECK(!strcmp(sc.direction, "tangent"));
    /* method and formulation are checked against the registries later, not here */
    GOOD(15, "method = some-method\nformulation = some-form", &sc);
    CHECK(!strcmp(sc.method, "some-method") && !strcmp(sc.formulation, "some-form"));
    CHECK(sc.line_method == 15 && sc.line_formulation == 16); /* for the registries' messages */
    GOOD(2, "name = run_2.b-c", &sc);
    CHECK(!strcmp(sc.name, "run_2.b-c"));
}

static void test_structure(void) {
    /* unknown keys and sections, with the nearest valid name */
    BAD_HINT(10, "lenghts = 5, 5", 10, "body", "lenghts", "did you mean `lengths`?");
    BAD_HINT(10, "lenghts = 5, 5", 9, "body", "lengths", "missing");
    BAD_HINT(2, "gravty = 9.81", 2, "scene", "gravty", "did you mean `gravity`?");
    BAD_HINT(11, "masses = 15, 5\nmass = 3", 12, "body", "mass", "belongs in [trolley]");
    BAD_HINT(11, "masses = 15, 5\nbogus = 3", 12, "body", "bogus", "expected one of");
    BAD_HINT(16, "[optimise]", 16, NULL, NULL, "did you mean [optimize]?");
    BAD_HINT(16, "[extras]", 16, NULL, NULL, "unknown section [extras]");
    /* a duplicate key (but `section` repeats by design) */
    BAD_HINT(8, "mass = 30\nmass = 31", 9, "trolley", "mass", "duplicate");
    BAD(13, "forces = 1, 2\nforces = 1, 2", 14, "drive", "forces");
    /* required keys, reported at their section's header, or at the end without one */
    BAD_HINT(4, "", 3, "course", "x_start", "missing");
    BAD_HINT(6, "", 13, "drive", "forces", "2 values, expected 1"); /* forces no longer fit */
    BAD_HINT(8, "", 7, "trolley", "mass", "missing");
    BAD_HINT(10, "", 9, "body", "lengths", "missing");
    BAD_HINT(11, "", 9, "body", "masses", "missing");
    /* without its header, mass falls into [course] */
    BAD_HINT(7, "", 8, "course", "mass", "belongs in [trolley]");
    BAD_HINT(7, "", 17, "trolley", "mass", "missing");
    /* shape of lines */
    BAD_HINT(1, "name = early\n[scene]", 1, NULL, "name", "outside any section");
    BAD_HINT(2, "gravity 9.81", 2, NULL, NULL, "key = value");
    BAD_HINT(2, "gravity: 9.81", 2, NULL, NULL, "key = value");
    BAD_HINT(1, "[scene", 1, NULL, NULL, "`]`");
    BAD_HINT(1, "[scene] x", 1, NULL, NULL, "after the section header");
    char longline[400];
    snprintf(longline, sizeof longline, "gravity = 9.81 ; %0300d", 0);
    BAD_HINT(2, longline, 2, NULL, NULL, "characters long");

    /* a whole missing section: named at the last line */
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    const char *no_trolley =
        "[course]\nx_start = 0\nsection = 10 : x\n[body]\nlengths = 1\nmasses = 1\n";
    CHECK(zp_scene_load_string(no_trolley, "t.ini", &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == 1 && has_message(&d, "t.ini:6: [trolley] mass: missing"));
    zp_diag_init(&d);
    const char *no_sections = "[course]\nx_start = 0\n[trolley]\nmass = 1\n[body]\nlengths = 1\n"
                              "masses = 1\n";
    CHECK(zp_scene_load_string(no_sections, "t.ini", &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == 1 && has_message(&d, "t.ini:1: [course] section: missing"));

    /* what is allowed: comments, indentation, CRLF, blank lines, repeated headers */
    GOOD(8, "  mass = 30 # kg\n\n; note\n# note", &sc);
    CHECK(sc.trolley_mass == 30);
    GOOD(8, "mass = 31 ; kg", &sc);
    CHECK(sc.trolley_mass == 31);
    GOOD(17, "margin = 10\n[drive]\nmin = -5", &sc);
    CHECK(sc.force_min == -5);
    zp_diag_init(&d);
    const char *crlf = "[course]\r\nx_start = 1\r\nsection = 10 : x\r\n[trolley]\r\nmass = 2\r\n"
                       "[body]\r\nlengths = 3\r\nmasses = 4\r\n";
    CHECK(zp_scene_load_string(crlf, "t.ini", &sc, &d) == ZP_OK && d.n == 0);
    CHECK(sc.x_start == 1 && sc.trolley_mass == 2 && !strcmp(sc.expr[0], "x"));
}

/* every error is reported, in line order; past ZP_DIAG_MAX they are counted */
static void test_many_errors(void) {
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    const char *text =
        "[course]\nx_start = 0\nsection = 60 : x\n"
        "[trolley]\nmass = -1\n[body]\nlengths = 5, 5\nmasses = 1,2,3\ndamping = -1\n"
        "[solver]\nrtol = -1\n[extras]\n";
    CHECK(zp_scene_load_string(text, "t.ini", &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == 5);
    CHECK(d.n == 5 && strstr(d.text[0], "t.ini:5: [trolley] mass:"));
    CHECK(d.n == 5 && strstr(d.text[1], "t.ini:8: [body] masses:"));
    CHECK(d.n == 5 && strstr(d.text[2], "t.ini:9: [body] damping:"));
    CHECK(d.n == 5 && strstr(d.text[3], "t.ini:11: [solver] rtol:"));
    CHECK(d.n == 5 && strstr(d.text[4], "t.ini:12: unknown section [extras]"));
    if (d.n != 5) {
        show(&d);
    }

    char repl[4096] = "margin = 10";
    for (int i = 0; i < ZP_DIAG_MAX + 5; i++) {
        char line[32];
        snprintf(line, sizeof line, "\nzzz%d = 1", i);
        strcat(repl, line);
    }
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(with_line(17, repl), "t.ini", &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == ZP_DIAG_MAX && d.dropped == 5);
    CHECK(strstr(d.text[0], "t.ini:18: [optimize] zzz0:") != NULL);
}

static void test_defaults(void) {
    const char *minimal = "[course]\nx_start = 0\nsection = 10 : x/2\n[trolley]\nmass = 3\n"
                          "[body]\nlengths = 1, 2\nmasses = 4, 5\n";
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(minimal, "some/dir/minimal.scene.ini", &sc, &d) == ZP_OK);
    CHECK(!strcmp(sc.name, "minimal.scene"));
    CHECK(!strcmp(sc.path, "some/dir/minimal.scene.ini"));
    CHECK_NEAR(sc.gravity, 9.81, 0); /* exactly docs/scene-file.md's default */
    CHECK(sc.nsec == 1 && sc.x_end[0] == 10 && !strcmp(sc.expr[0], "x/2"));
    CHECK(sc.line_method == 0 && sc.line_formulation == 0);
    CHECK(sc.nlink == 2);
    CHECK(sc.ndamping == 1 && sc.damping[0] == 0 && sc.damping[1] == 0);
    CHECK(sc.death_angle == 180);
    CHECK(!strcmp(sc.direction, "horizontal"));
    CHECK(sc.nforce == 0 && sc.forces[0] == 0 && sc.line_forces == 0);
    CHECK(sc.force_min == 0 && sc.force_max == 500);
    CHECK(!strcmp(sc.method, "cvode-adams") && !strcmp(sc.formulation, "lagrange"));
    CHECK(sc.rtol == 1e-8 && sc.atol == 1e-10 && sc.t_max == 120 && sc.output_dt == 0.02);
    CHECK(sc.margin == 10 && sc.max_evals == 5000 && sc.seed == 1);
    CHECK(!strcmp(sc.search_method, "gsl-rk8pd") && sc.search_rtol == 1e-5);
}

/* docs/scene-file.md's example, written out here from the spec */
static void check_is_config_example(const zp_scene *sc) {
    CHECK(!strcmp(sc->name, "seed") && sc->gravity == 9.81 && sc->x_start == 0);
    CHECK(sc->nsec == 3 && sc->x_end[0] == 60 && sc->x_end[1] == 100 && sc->x_end[2] == 140);
    CHECK(!strcmp(sc->expr[0], "(x/10 - 3)^2 + 1") && !strcmp(sc->expr[1], "-x/10 + 16") &&
          !strcmp(sc->expr[2], "-(x/10 - 12)^2 + 10"));
    CHECK(sc->trolley_mass == 30 && sc->nlink == 3);
    for (int i = 0; i < 3; i++) {
        CHECK(sc->lengths[i] == 5 && sc->damping[i] == 1 && sc->forces[i] == 100);
    }
    CHECK(sc->masses[0] == 15 && sc->masses[1] == 5 && sc->masses[2] == 2);
    CHECK(sc->ndamping == 1 && sc->death_angle == 180 && sc->nforce == 3);
    CHECK(!strcmp(sc->direction, "horizontal") && sc->force_min == 0 && sc->force_max == 500);
    CHECK(!strcmp(sc->method, "cvode-adams") && !strcmp(sc->formulation, "lagrange"));
    CHECK(sc->rtol == 1e-8 && sc->atol == 1e-10 && sc->t_max == 120 && sc->output_dt == 0.02);
    CHECK(sc->margin == 10 && sc->max_evals == 5000 && sc->seed == 1);
}

static void test_seed(void) {
    zp_scene built, file;
    zp_scene_load_seed(&built);
    check_is_config_example(&built);

    zp_diag d;
    zp_diag_init(&d);
    const char *path = ZP_SOURCE_DIR "/config/seed.ini";
    CHECK(zp_scene_load(path, &file, &d) == ZP_OK && d.n == 0);
    check_is_config_example(&file);

    /* the line of each section key, counted here from the file itself */
    FILE *f = fopen(path, "r");
    CHECK(f != NULL);
    char line[512];
    int n = 0, k = 0;
    while (f && fgets(line, sizeof line, f)) {
        n++;
        if (!strncmp(line, "section", 7)) {
            CHECK(k < file.nsec && file.sec_line[k] == n);
            k++;
        } else if (!strncmp(line, "forces", 6)) {
            CHECK(file.line_forces == n);
        }
    }
    CHECK(k == 3);
    if (f) {
        fclose(f);
    }
}

/* [limits]: each a positive ceiling when given, off (0) when not */
static void test_limits(void) {
    BAD(17, "margin = 10\n[limits]\nmax_g = 0", 19, "limits", "max_g");
    BAD(17, "margin = 10\n[limits]\nmax_g = -6", 19, "limits", "max_g");
    BAD(17, "margin = 10\n[limits]\nmax_joint_force = 0", 19, "limits", "max_joint_force");
    BAD(17, "margin = 10\n[limits]\nmax_arrival_speed = -1", 19, "limits", "max_arrival_speed");
    BAD(17, "margin = 10\n[limits]\nmax_kink_dv = 0", 19, "limits", "max_kink_dv");
    BAD_HINT(17, "margin = 10\n[limits]\nmax_gee = 6", 19, "limits", "max_gee", "`max_g`");
    zp_scene sc;
    GOOD(0, "", &sc);
    CHECK(sc.max_g == 0 && sc.max_joint_force == 0 && sc.max_arrival_speed == 0 &&
          sc.max_kink_dv == 0);
    GOOD(17,
         "margin = 10\n[limits]\nmax_g = 6\nmax_joint_force = 3000\nmax_arrival_speed = 24\n"
         "max_kink_dv = 8",
         &sc);
    CHECK(sc.max_g == 6 && sc.max_joint_force == 3000 && sc.max_arrival_speed == 24 &&
          sc.max_kink_dv == 8);
}

/* [robust]: percentages, ranges lo <= hi, angles below 90, counts >= 1 */
static void test_robust(void) {
    BAD_HINT(17, "margin = 10\n[robust]\nforce_error = 100", 19, "robust", "force_error",
             "[0, 100)");
    BAD(17, "margin = 10\n[robust]\nforce_error = -1", 19, "robust", "force_error");
    BAD_HINT(17, "margin = 10\n[robust]\nmass_range = 120, 80", 19, "robust", "mass_range",
             "reversed");
    BAD(17, "margin = 10\n[robust]\nlength_range = 0, 110", 19, "robust", "length_range");
    BAD(17, "margin = 10\n[robust]\ntrolley_mass_range = -5, 110", 19, "robust",
        "trolley_mass_range");
    BAD_HINT(17, "margin = 10\n[robust]\ndamping_range = 50", 19, "robust", "damping_range",
             "1 value, expected 2");
    BAD(17, "margin = 10\n[robust]\ndamping_range = 50, 100, 200", 19, "robust", "damping_range");
    BAD(17, "margin = 10\n[robust]\nstart_angle = 90", 19, "robust", "start_angle");
    BAD(17, "margin = 10\n[robust]\nstart_angle = -1", 19, "robust", "start_angle");
    BAD(17, "margin = 10\n[robust]\nsamples = 0", 19, "robust", "samples");
    BAD(17, "margin = 10\n[robust]\nverify_samples = 0", 19, "robust", "verify_samples");
    BAD(17, "margin = 10\n[robust]\nsamples = 2.5", 19, "robust", "samples");

    zp_scene sc;
    GOOD(0, "", &sc);
    CHECK(sc.robust == 0 && sc.force_error == 0 && sc.mass_range[0] == 100 &&
          sc.mass_range[1] == 100 && sc.robust_samples == 64 && sc.verify_samples == 2000);
    GOOD(17, "margin = 10\n[robust]", &sc); /* the section alone asks for a robust search */
    CHECK(sc.robust == 1);
    GOOD(17,
         "margin = 10\n[robust]\nforce_error = 99.5\nmass_range = 80, 120\nlength_range = 90, "
         "90\ntrolley_mass_range = 90, 110\ndamping_range = 50, 200\nstart_angle = 89.9\n"
         "samples = 1\nverify_samples = 1",
         &sc);
    CHECK(sc.robust == 1 && sc.force_error == 99.5 && sc.mass_range[0] == 80 &&
          sc.mass_range[1] == 120 && sc.length_range[0] == 90 && sc.length_range[1] == 90 &&
          sc.trolley_mass_range[1] == 110 && sc.damping_range[0] == 50 &&
          sc.damping_range[1] == 200 && sc.start_angle == 89.9 && sc.robust_samples == 1 &&
          sc.verify_samples == 1);
}

/* [physics]: drag one area per body (trolley + links), non-negative coefficients */
static void test_physics(void) {
    /* the base scene has 2 links: 3 areas */
    BAD_HINT(17, "margin = 10\n[physics]\ndrag_area = 0.05, 0.2", 19, "physics", "drag_area",
             "2 values, expected 3");
    BAD(17, "margin = 10\n[physics]\ndrag_area = 0.05, 0.2, 0.3, 0.1", 19, "physics", "drag_area");
    BAD(17, "margin = 10\n[physics]\ndrag_area = 0.05, -0.2, 0.3", 19, "physics", "drag_area");
    BAD(17, "margin = 10\n[physics]\nair_density = -1", 19, "physics", "air_density");
    BAD_HINT(17, "margin = 10\n[physics]\ndrag_area = 0.05, 0.2, 0.3\nair_density = 0", 20,
             "physics", "air_density", "air_density > 0");
    BAD(17, "margin = 10\n[physics]\nrolling = -0.01", 19, "physics", "rolling");
    BAD(17, "margin = 10\n[physics]\nkink_radius = -2", 19, "physics", "kink_radius");
    BAD(17, "margin = 10\n[physics]\nwind = inf", 19, "physics", "wind");

    zp_scene sc;
    GOOD(0, "", &sc);
    CHECK(sc.ndrag == 0 && sc.air_density == 1.225 && sc.wind == 0 && sc.rolling == 0 &&
          sc.kink_radius == 0 && sc.line_kink_radius == 0);
    GOOD(17, "margin = 10\n[physics]\nair_density = 0", &sc); /* no drag: no air needed */
    CHECK(sc.air_density == 0);
    GOOD(17,
         "margin = 10\n[physics]\ndrag_area = 0.05, 0, 0.3\nair_density = 1.2\nwind = -3\n"
         "rolling = 0.01\nkink_radius = 2",
         &sc);
    CHECK(sc.ndrag == 3 && sc.drag_area[0] == 0.05 && sc.drag_area[1] == 0 &&
          sc.drag_area[2] == 0.3 && sc.air_density == 1.2 && sc.wind == -3 && sc.rolling == 0.01 &&
          sc.kink_radius == 2 && sc.line_kink_radius == 23);
}

/* [solver] bounds: tolerances within meaningful ranges, t_max and the trajectory's size */
static void test_solver_bounds(void) {
    BAD(15, "rtol = 1e-15", 15, "solver", "rtol");
    BAD(15, "rtol = 0.1", 15, "solver", "rtol");
    BAD(15, "rtol = 1e-300", 15, "solver", "rtol");
    BAD(15, "atol = 1e-17", 15, "solver", "atol");
    BAD(15, "atol = 1e300", 15, "solver", "atol");
    BAD(17, "rtol = 1e-300", 17, "optimize", "rtol");
    BAD_HINT(15, "t_max = 1e50\noutput_dt = 1e45", 15, "solver", "t_max", "(0, 1e6]");
    /* rows: t_max / output_dt + 1 at most ZP_MAX_ROWS, named at the key given */
    BAD_HINT(15, "output_dt = 1e-9", 15, "solver", "output_dt", "trajectory rows");
    BAD_HINT(15, "t_max = 1e5", 15, "solver", "t_max", "trajectory rows");
    zp_scene sc;
    GOOD(15, "rtol = 1e-14\natol = 1e-16", &sc);
    CHECK(sc.rtol == 1e-14 && sc.atol == 1e-16);
    GOOD(15, "rtol = 1e-2\natol = 1", &sc);
    CHECK(sc.rtol == 1e-2 && sc.atol == 1);
    GOOD(15, "t_max = 1e6\noutput_dt = 1.000001", &sc); /* 999 999 + 1 rows */
    CHECK(sc.t_max == 1e6);
}

/* the default margin obeys the rule a given one does: below death_angle */
static void test_default_margin(void) {
    char text[4096];
    snprintf(text, sizeof text, "%s", with_line(11, "masses = 15, 5\ndeath_angle = 5"));
    char *m = strstr(text, "margin = 10\n");
    *m = '\0'; /* drop the explicit margin: the default 10 applies */
    expect_bad_at(__LINE__, text, 12, "body", "death_angle", "default [optimize] margin 10");
    zp_scene sc;
    strcat(text, "margin = 4\n");
    expect_good_at(__LINE__, text, &sc);
    CHECK(sc.death_angle == 5 && sc.margin == 4);
}

static const char *write_bytes(const char *name, const char *bytes, size_t n);

/* a NUL byte is an error at its line, not the file's end; /dev/zero is refused by size */
static void test_file_bytes(void) {
    static const char text[] = "[course]\nx_start = 0\nsection = 10 : x\n[trolley]\nmass = 3\0 0\n"
                               "[body]\nlengths = 1\nmasses = 1\n";
    const char *p = write_bytes("zp_test_nul.ini", text, sizeof text - 1);
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    CHECK(zp_scene_load(p, &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == 1 && strstr(d.text[0], ":5: ") && strstr(d.text[0], "NUL byte at column 9"));
    if (d.n != 1) {
        show(&d);
    }
    remove(p);
    zp_diag_init(&d);
    CHECK(zp_scene_load("/dev/zero", &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == 1 && has_message(&d, "/dev/zero: cannot read") && has_message(&d, "1 MiB"));
}

/* loads text and builds its model: the status of the two, messages in d */
static zp_status build(const char *text, zp_diag *d, zp_scene *sc, double xs[3], double ys[3]) {
    zp_diag_init(d);
    if (zp_scene_load_string(text, "t.ini", sc, d) != ZP_OK) {
        return ZP_ERR_INPUT;
    }
    zp_model *m = zp_model_build(sc, d);
    if (!m) {
        return ZP_ERR_INPUT;
    }
    for (int i = 0; xs && i < 3; i++) {
        int k = xs[i] <= sc->x_end[0] ? 0 : 1;
        ys[i] = zp_course_eval(m->course, k, xs[i]).f;
    }
    zp_model_free(m);
    return ZP_OK;
}

/* `pi`, `e` and `y0` become numbers; names that merely contain them stay names */
static void test_expr_names(void) {
    zp_scene sc;
    zp_diag d;
    double x[3] = {0, 30, 80}, y[3];
    /* e^(x/60) - e + 10 meets -x/10 + 16 at 60; pi likewise */
    CHECK(build(with_line(5, "section = 60 : e^(x/60) - e + 10 + pi*(x-60)/60"), &d, &sc, x, y) ==
          ZP_OK);
    CHECK_REL(y[0], 11 - M_E - M_PI, 1e-15);
    CHECK_REL(y[1], exp(0.5) - M_E + 10 - M_PI / 2, 1e-15);
    /* y0 is 10 here ((60/10 - 3)^2 + 1); a negative y0 stays one operand of ^ */
    CHECK(build(with_line(6, "section = 100 : y0 - (x - 60)/10"), &d, &sc, x, y) == ZP_OK);
    CHECK_REL(y[2], 8, 1e-15);
    CHECK(build(with_lines(5, "section = 60 : x/10 - 8.5", 6, "section = 100 : y0^2 - 8.75 + 0*x"),
                &d, &sc, x, y) == ZP_OK);
    CHECK_REL(y[2], -2.5, 1e-15);
    CHECK(build(with_line(5, "section = 60 : 1e1*x/600 + 9 + 0*exp(x)"), &d, &sc, NULL, NULL) ==
          ZP_OK);
    BAD_HINT(5, "section = 60 : y0 + (x/10 - 3)^2 + 1", 5, "course", "section",
             "first section has none");
    BAD_HINT(5, "section = 60 : pie*x", 5, "course", "section", "`pie`");
    BAD_HINT(5, "section = 60 : 0*pi*pi*pi*pi*pi*pi*pi*pi*pi*pi*pi*pi*pi + x/6", 5, "course",
             "section", "too long");
    /* y0 chains: section 3 starts where section 2, itself written with y0, ends (8) */
    CHECK(build(with_lines(6, "section = 100 : y0 - (x - 60)/20\nsection = 120 : y0 + 0*x", 13,
                           "forces = 1, 2, 3"),
                &d, &sc, NULL, NULL) == ZP_OK);
    CHECK(!strcmp(sc.expr[2], "(8) + 0*x"));
    BAD_HINT(5, "section = 60 : y0e", 5, "course", "section", "`y0e`");
    /* after a section in error, y0 adds no second message */
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(with_lines(5, "section = 60 : (x", 6, "section = 100 : y0 - x"),
                               "t.ini", &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == 1 && has_message(&d, "t.ini:5: "));
}

/* the model's course checks: continuity states its tolerance; a NaN gap and a pole are
   refused, also a pole of residue 1e-9 or 1e-15 (which used to pass: the run "died" at it with
   a 1443 J energy residual) and 1e-12/(x - p)^2; a smooth step whose f'' expression overflows is
   accepted */
static void test_course_probing(void) {
    zp_scene sc;
    zp_diag d;
    CHECK(build(with_line(6, "section = 100 : -x/10 + 16.001"), &d, &sc, NULL, NULL) ==
          ZP_ERR_INPUT);
    CHECK(has_message(&d, "t.ini:6: [course] section: ") && has_message(&d, "1e-9 (1 + |y|)"));
    CHECK(build(with_line(6, "section = 100 : -x/10 + 16 + 0*sqrt((x-80.3)^2-1e-4)"), &d, &sc, NULL,
                NULL) == ZP_ERR_INPUT);
    CHECK(has_message(&d, "t.ini:6: [course] section: ") && has_message(&d, "near x = 80.2"));
    CHECK(build(with_line(6, "section = 100 : -x/10 + 16 + tan(x/10) - tan(6)"), &d, &sc, NULL,
                NULL) == ZP_ERR_INPUT);
    CHECK(has_message(&d, "t.ini:6: [course] section: ") && has_message(&d, "near x = 78.5"));
    /* poles with residues too small for the jump between probes: found where f'' turns */
    CHECK(build(with_line(6, "section = 100 : -x/10 + 16 + 1e-9/(x - 80.3)"), &d, &sc, NULL,
                NULL) == ZP_ERR_INPUT);
    CHECK(has_message(&d, "t.ini:6: [course] section: ") && has_message(&d, "near x = 80.3"));
    CHECK(build(with_line(6, "section = 100 : -x/10 + 16 + 1e-15/(x - 80.3)"), &d, &sc, NULL,
                NULL) == ZP_ERR_INPUT);
    CHECK(has_message(&d, "near x = 80.3"));
    /* and one that f' does not reveal (f'' keeps its sign): the denominator's base turns */
    CHECK(build(with_line(6, "section = 100 : -x/10 + 16 + 1e-12/(x - 80.3)^2"), &d, &sc, NULL,
                NULL) == ZP_ERR_INPUT);
    CHECK(has_message(&d, "t.ini:6: [course] section: ") && has_message(&d, "near x = 80.3"));
    /* a denominator that never vanishes is no pole */
    CHECK(build(with_line(6, "section = 100 : -x/10 + 16 + 1/((x - 80)^2 + 1) - 1/401"), &d,
                &sc, NULL, NULL) == ZP_OK);
    /* -10 tanh(100 (x - 80)): a 20 m drop over a few cm, smooth; f'' = inf/inf far from 80 */
    double x[3] = {60, 80, 100}, y[3];
    zp_status st =
        build(with_line(6, "section = 100 : y0 - 10 - 10*tanh(100*(x-80))"), &d, &sc, x, y);
    CHECK(st == ZP_OK);
    if (st != ZP_OK) {
        show(&d);
    }
    CHECK_NEAR(y[1], 0, 1e-12);
    CHECK_NEAR(y[2], -10, 1e-12);
}

static const char *write_temp(const char *name, const char *text) {
    static char path[2][512];
    static int which;
    char *p = path[which ^= 1];
    snprintf(p, sizeof path[0], "%s/%s", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp", name);
    FILE *f = fopen(p, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return p;
}

static const char *write_bytes(const char *name, const char *bytes, size_t n) {
    const char *p = write_temp(name, "");
    FILE *f = fopen(p, "wb");
    CHECK(f != NULL);
    if (f) {
        fwrite(bytes, 1, n, f);
        fclose(f);
    }
    return p;
}

static void test_schedule(void) {
    zp_scene sc;
    zp_diag d;
    zp_scene_load_seed(&sc);

    zp_diag_init(&d);
    const char *good = write_temp("zp_test_sched_good.ini", "; found by the search\n[drive]\n"
                                                            "forces = 12.5, 0, -3\n");
    CHECK(zp_scene_load_overlay_schedule(good, &sc, &d) == ZP_OK && d.n == 0);
    CHECK(sc.nforce == 3 && sc.forces[0] == 12.5 && sc.forces[1] == 0 && sc.forces[2] == -3);
    CHECK(sc.force_max == 500); /* nothing else changes */

    /* every refusal leaves the forces as they were and names the schedule file */
    static const struct {
        const char *text, *part;
    } bad[] = {
        {"[drive]\nforces = 1, 2\n", ":2: [drive] forces: 2 values, expected 3"},
        {"[drive]\nforces = 1, 2, 3\nmin = 0\n", ":3: [drive] min: unknown key"},
        {"[drive]\nforces = 1, 2, 3\n[body]\nmasses = 1\n", ":3: unknown section [body]"},
        {"[drive]\n", ":1: [drive] forces: missing"},
        {"[drive]\nforces = 1,,3\n", ":2: [drive] forces: item 2 is empty"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        zp_diag_init(&d);
        const char *p = write_temp("zp_test_sched_bad.ini", bad[i].text);
        char want[1024];
        snprintf(want, sizeof want, "%s%s", p, bad[i].part);
        CHECK(zp_scene_load_overlay_schedule(p, &sc, &d) == ZP_ERR_INPUT);
        CHECK(has_message(&d, want));
        CHECK(sc.forces[0] == 12.5 && sc.forces[2] == -3);
        if (!has_message(&d, want)) {
            fprintf(stderr, "  wanted `%s`\n", want);
            show(&d);
        }
    }
    remove(good);

    zp_diag_init(&d);
    CHECK(zp_scene_load_overlay_schedule("/nonexistent/sched.ini", &sc, &d) == ZP_ERR_INPUT);
    CHECK(has_message(&d, "/nonexistent/sched.ini"));
    zp_diag_init(&d);
    CHECK(zp_scene_load("/nonexistent/scene.ini", &sc, &d) == ZP_ERR_INPUT);
    CHECK(d.n == 1 && has_message(&d, "/nonexistent/scene.ini: cannot open"));
}

/* the forces of many sections, in 17 digits each, exceed inih's 200-byte line: a scene's
   [drive] forces line and the search's schedule file (zp_checkpoint_write_schedule) read back
   to the same bits; a longer line than any schedule needs, or another long line, is refused */
static void test_long_forces(void) {
    enum { NSEC = 16 };
    char text[8192];
    size_t len =
        (size_t)snprintf(text, sizeof text, "[scene]\nname = many\n[course]\nx_start = 0\n");
    for (int i = 0; i < NSEC; i++) {
        len += (size_t)snprintf(text + len, sizeof text - len, "section = %d : 20 - x/10\n",
                                5 * (i + 1));
    }
    len += (size_t)snprintf(text + len, sizeof text - len,
                            "[trolley]\nmass = 30\n[body]\nlengths = 1\nmasses = 5\n[drive]\n"
                            "forces = ");
    double want[NSEC];
    for (int i = 0; i < NSEC; i++) {
        want[i] = (i + 1) / 3.0;
        len += (size_t)snprintf(text + len, sizeof text - len, "%s%.17g", i ? ", " : "", want[i]);
    }
    snprintf(text + len, sizeof text - len, " ; long\n");
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(text, "many.ini", &sc, &d) == ZP_OK);
    show(&d);
    CHECK(sc.nforce == NSEC && !memcmp(sc.forces, want, sizeof want));

    /* the search's schedule file of other forces, laid over it */
    zp_schedule sched = zp_drive_of_scene(&sc);
    double other[NSEC];
    for (int i = 0; i < NSEC; i++) {
        other[i] = 100 + (i + 1) / 7.0;
    }
    sched = zp_drive_with(&sched, other);
    const char *path = write_temp("zp_test_sched_long.ini", "");
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        zp_checkpoint_write_schedule(f, &sc, &sched, "found by the search");
        fclose(f);
    }
    zp_diag_init(&d);
    CHECK(zp_scene_load_overlay_schedule(path, &sc, &d) == ZP_OK);
    show(&d);
    CHECK(!memcmp(sc.forces, other, sizeof other));
    remove(path);

    /* past what any schedule needs: refused, with the limit */
    static char huge[ZP_FORCES_TEXT_MAX + 200];
    len = (size_t)snprintf(huge, sizeof huge, "[drive]\nforces = 1");
    while (len + 4 < sizeof huge - 2) {
        len += (size_t)snprintf(huge + len, sizeof huge - len, ", 1");
    }
    snprintf(huge + len, sizeof huge - len, "\n");
    zp_diag_init(&d);
    path = write_temp("zp_test_sched_huge.ini", huge);
    CHECK(zp_scene_load_overlay_schedule(path, &sc, &d) == ZP_ERR_INPUT);
    CHECK(has_message(&d, "characters long"));
    remove(path);
}

static void test_parse_list(void) {
    double v[4];
    char why[128];
    CHECK(zp_scene_values_parse_list("1, 2.5 ,-3e1", v, 4, why, sizeof why) == 3);
    CHECK(v[0] == 1 && v[1] == 2.5 && v[2] == -30);
    CHECK(zp_scene_values_parse_list("7", v, 4, why, sizeof why) == 1 && v[0] == 7);
    CHECK(zp_scene_values_parse_list("1,,2", v, 4, why, sizeof why) == -1 && strstr(why, "item 2"));
    CHECK(zp_scene_values_parse_list("", v, 4, why, sizeof why) == -1);
    CHECK(zp_scene_values_parse_list("1,2,3,4,5", v, 4, why, sizeof why) == -1);
    CHECK(zp_scene_values_parse_list("1,abc", v, 4, why, sizeof why) == -1 && strstr(why, "abc"));
    CHECK(zp_scene_values_parse_list("nan", v, 4, why, sizeof why) == -1);
    /* command-line lists may be longer than any scene line */
    static char many[20000];
    static double big[2000];
    for (int i = 0; i < 2000; i++) {
        snprintf(many + strlen(many), sizeof many - strlen(many), "%s%d.25", i ? ", " : "", i);
    }
    CHECK(zp_scene_values_parse_list(many, big, 2000, why, sizeof why) == 2000);
    CHECK(big[0] == 0.25 && big[1999] == 1999.25);
}

/* the base with [sec] key = value for key k: in place of its lines where the base has it, else
   under its own header at the end; value NULL: without the key */
static const char *base_with(int k, const char *value) {
    const zp_scene_key *key = &zp_scene_keys[k];
    static char text[8192];
    char cur[32] = "";
    size_t len = strlen(key->name);
    int found = 0;
    text[0] = '\0';
    for (int i = 0; i < NBASE; i++) {
        const char *line = base[i];
        if (line[0] == '[') {
            snprintf(cur, sizeof cur, "%.*s", (int)strcspn(line + 1, "]"), line + 1);
        } else if (!strcmp(cur, zp_scene_keys_sections[key->sec].name) &&
                   !strncmp(line, key->name, len) && line[len] == ' ') {
            line = found++ || !value ? "" : value;
        }
        snprintf(text + strlen(text), sizeof text - strlen(text), "%s%s%s\n",
                 line == value ? key->name : "", line == value ? " = " : "", line);
    }
    if (!found && value) {
        snprintf(text + strlen(text), sizeof text - strlen(text), "[%s]\n%s = %s\n",
                 zp_scene_keys_sections[key->sec].name, key->name, value);
    }
    return text;
}

/* key k given value (NULL: not given): refused with `[sec] key: what` (what not NULL) or with
   no refusal of its value (a rule joining it with other keys may still speak) */
static void expect_value(int k, const char *value, const char *what) {
    const zp_scene_key *key = &zp_scene_keys[k];
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    zp_scene_load_string(base_with(k, value), "t.ini", &sc, &d);
    char message[512];
    snprintf(message, sizeof message, "[%s] %s: %s", zp_scene_keys_sections[key->sec].name,
             key->name, what ? what : "");
    char refusal[256];
    snprintf(refusal, sizeof refusal, "; expected %s", key->expect);
    int ok = what ? has_message(&d, message) : !has_message(&d, refusal);
    CHECK(ok);
    if (!ok) {
        fprintf(stderr, "  [%s] %s = %s: wanted %s `%s`\n", zp_scene_keys_sections[key->sec].name,
                key->name, value ? value : "(none)", what ? "" : "none like",
                what ? message : refusal);
        show(&d);
    }
}

/* key k given value: refused with `what; expected ..` (its expected text) */
static void expect_refused(int k, const char *value, const char *what) {
    char message[512];
    snprintf(message, sizeof message, "%s; expected %s", what, zp_scene_keys[k].expect);
    expect_value(k, value, message);
}

/* each end of a plain number's rule is taken or refused as the rule says */
static void check_number_rule(int k) {
    zp_range r = zp_scene_keys[k].rule;
    char text[64], what[96];
    const double ends[2] = {r.lo, r.hi}, outward[2] = {-1, 1};
    const int open[2] = {r.lo_open, r.hi_open};
    for (int e = 0; e < 2; e++) {
        if (isinf(ends[e])) {
            continue;
        }
        /* the end itself, then a number beyond it */
        double v = ends[e];
        snprintf(text, sizeof text, "%.17g", v);
        snprintf(what, sizeof what, "%g is out of range", v);
        if (open[e]) {
            expect_refused(k, text, what);
        } else {
            expect_value(k, text, NULL);
        }
        v = ends[e] + outward[e] * fmax(1, fabs(ends[e]));
        snprintf(text, sizeof text, "%.17g", v);
        snprintf(what, sizeof what, "%g is out of range", v);
        expect_refused(k, text, what);
    }
}

/* each end of a plain whole number's range is taken, a number beyond it refused */
static void check_whole_range(int k) {
    const zp_scene_key *key = &zp_scene_keys[k];
    char text[64], what[128];
    unsigned long beyond[2] = {key->min - 1, key->max + 1};
    for (int e = 0; e < 2; e++) {
        snprintf(text, sizeof text, "%lu", e ? key->max : key->min);
        expect_value(k, text, NULL);
        if (e ? key->max < ULONG_MAX : key->min > 0) {
            snprintf(text, sizeof text, "%lu", beyond[e]);
            snprintf(what, sizeof what, "`%s` is not a whole number in [%lu, %lu]", text,
                     key->min, key->max);
            expect_refused(k, text, what);
        }
    }
}

/* a key's default as the table gives it: what a scene without the key holds, within the key's
   rule, and (a number) written in the docs as it reads back */
static void check_default(const zp_scene *sc, int k) {
    const zp_scene_key *key = &zp_scene_keys[k];
    const char *at = (const char *)sc + key->field;
    if (key->dflt.how == D_OFF) {
        static const char zero[256];
        CHECK(key->size <= sizeof zero && !memcmp(at, zero, key->size));
    } else if (key->dflt.how == D_REQUIRED) {
        char what[256];
        snprintf(what, sizeof what, "missing; required: %s", key->dflt.text);
        expect_value(k, NULL, what);
    } else if (key->dflt.how == D_VALUE && key->type == T_TEXT) {
        CHECK(strlen(key->dflt.text) < key->size && !strcmp(at, key->dflt.text));
    } else if (key->dflt.how == D_VALUE && key->type == T_NUMBER) {
        double v = key->dflt.num;
        zp_range r = key->rule;
        CHECK(*(const double *)at == v && strtod(key->dflt.docs, NULL) == v);
        CHECK((r.lo_open ? v > r.lo : v >= r.lo) && (r.hi_open ? v < r.hi : v <= r.hi));
    } else if (key->dflt.how == D_VALUE) {
        unsigned long v = (unsigned long)key->dflt.num;
        unsigned long held = key->type == T_INT    ? (unsigned long)*(const int *)at
                             : key->type == T_LONG ? (unsigned long)*(const long *)at
                                                   : *(const unsigned long *)at;
        CHECK(held == v && v >= key->min && v <= key->max);
        CHECK(strtod(key->dflt.docs, NULL) == key->dflt.num);
    }
}

/* the key table (src/io/scene_keys.def): every key read, named once in its section, said in
   the docs; each plain key's rule and every default as the table gives them */
static void test_key_table(void) {
    zp_scene sc;
    zp_diag d;
    zp_diag_init(&d);
    CHECK(zp_scene_load_string(with_line(0, NULL), "t.ini", &sc, &d) == ZP_OK);
    for (int k = 0; k < K_COUNT; k++) {
        const zp_scene_key *key = &zp_scene_keys[k];
        CHECK(key->read || key->type != T_OTHER);
        CHECK(key->expect[0] && key->doc[0] && key->dflt.docs[0]);
        for (int j = 0; j < k; j++) {
            CHECK(zp_scene_keys[j].sec != key->sec || strcmp(zp_scene_keys[j].name, key->name));
        }
        check_default(&sc, k);
        if (!key->read && key->type == T_NUMBER) {
            check_number_rule(k);
        } else if (!key->read && key->type != T_TEXT) {
            check_whole_range(k);
        }
    }
}

int main(void) {
    test_numbers();
    test_margin_vs_death();
    test_lists();
    test_course_rules();
    test_names();
    test_structure();
    test_many_errors();
    test_defaults();
    test_seed();
    test_schedule();
    test_long_forces();
    test_parse_list();
    test_limits();
    test_robust();
    test_physics();
    test_solver_bounds();
    test_default_margin();
    test_file_bytes();
    test_expr_names();
    test_course_probing();
    test_key_table();
    return CHECK_DONE();
}
