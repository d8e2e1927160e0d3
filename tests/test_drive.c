/* The drive schedule (drive.h): per-section constants give p[sec] at every t, x and speed and
   have no breaks; the force points along x (horizontal) or along the course's tangent (f' the
   slope: (F, F f') / sqrt(1 + f'^2)); the [drive] forces text reads back bit for bit; bad text
   is refused with why, the count named by the kind's noun; the scene's [drive] becomes the
   schedule with its bounds; each parameter is its section's force, labelled "section k", in N,
   acting over its section; the constant push sets every parameter, within the bounds every
   parameter allows; direction names round-trip. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "drive.h"
#include "scene_load.h"

static void test_sections(void) {
    const double f[3] = {12.5, -3, 0};
    zp_schedule s = zp_drive_sections(3, f, -10, 20);
    CHECK(s.kind == ZP_SCHED_SECTIONS && s.nsec == 3 && s.np == 3);
    const double ts[] = {0, 1e-9, 7.25, 1e6}, xs[] = {-5, 0, 33.3, 1e4};
    for (int k = 0; k < 3; k++) {
        CHECK(s.lo[k] == -10 && s.hi[k] == 20);
        for (int i = 0; i < 4; i++) {
            CHECK(zp_drive_force(&s, &(zp_drive_state){ts[i], xs[i], 0, k}) == f[k]);
        }
    }
    double br[4];
    CHECK(zp_drive_breaks(&s, br, 4) == 0);
    /* the same shape with other parameters keeps kind, sections and bounds */
    const double g[3] = {1, 2, 3};
    zp_schedule w = zp_drive_with(&s, g);
    CHECK(w.np == 3 && w.lo[2] == -10 && w.hi[0] == 20 &&
          zp_drive_force(&w, &(zp_drive_state){5, 5, 0, 1}) == 2);
}

/* the force reads the state it needs: for per-section constants not t, x or the speed */
static void test_state(void) {
    const double f[2] = {40, -7.5};
    zp_schedule s = zp_drive_sections(2, f, 0, 100);
    const double vs[] = {0, -3, 12.5, 1e3};
    for (int sec = 0; sec < 2; sec++) {
        for (int i = 0; i < 4; i++) {
            CHECK(zp_drive_force(&s, &(zp_drive_state){3.5, 70, vs[i], sec}) == f[sec]);
        }
    }
}

/* horizontal: all of F along x; tangent: F along (1, f') / |(1, f')|, so |(fx, fy)| = |F| and
   fy / fx = f' */
static void test_push(void) {
    const double f[1] = {120};
    zp_schedule s = zp_drive_sections(1, f, 0, 500);
    double fx, fy;
    zp_drive_push(&s, ZP_DRIVE_HORIZONTAL, 1, 2, 3, 0, 0.75, &fx, &fy);
    CHECK(fx == 120 && fy == 0);
    /* |(1, 0.75)| = 1.25 exactly in binary: the components are exact too */
    zp_drive_push(&s, ZP_DRIVE_TANGENT, 1, 2, 3, 0, 0.75, &fx, &fy);
    CHECK(fx == 96 && fy == 72);
    zp_drive_push(&s, ZP_DRIVE_TANGENT, 1, 2, 3, 0, 0, &fx, &fy);
    CHECK(fx == 120 && fy == 0);
}

/* per-section constants: parameter k is section k's force, over [xb[k], xb[k + 1]] */
static void test_params(void) {
    const double f[3] = {10, 20, 30}, xb[4] = {0, 60, 100, 140};
    zp_schedule s = zp_drive_sections(3, f, 0, 500);
    CHECK(!strcmp(zp_drive_unit(&s), "N"));
    CHECK(!strcmp(zp_drive_param_noun(&s, 0), "section"));
    CHECK(!strcmp(zp_drive_param_noun(&s, 1), "sections"));
    for (int k = 0; k < 3; k++) {
        char label[32], want[32];
        zp_drive_param_label(&s, k, label, sizeof label);
        snprintf(want, sizeof want, "section %d", k + 1);
        CHECK(!strcmp(label, want));
        CHECK(zp_drive_param_section(&s, k) == k);
        double from, to;
        zp_drive_param_span(&s, k, xb, &from, &to);
        CHECK(from == xb[k] && to == xb[k + 1]);
    }
}

/* the constant push: every parameter F, the shape's kind and bounds kept; its range is the
   pushes every parameter's bounds allow */
static void test_constant(void) {
    const double f[3] = {10, 20, 30};
    zp_schedule s = zp_drive_sections(3, f, -5, 500);
    zp_schedule c = zp_drive_constant(&s, 42.5);
    CHECK(c.kind == s.kind && c.np == 3 && c.lo[1] == -5 && c.hi[2] == 500);
    for (int k = 0; k < 3; k++) {
        CHECK(c.p[k] == 42.5);
        CHECK(zp_drive_force(&c, &(zp_drive_state){0, 0, 0, k}) == 42.5);
    }
    double lo, hi;
    zp_drive_constant_bounds(&s, &lo, &hi);
    CHECK(lo == -5 && hi == 500);
    s.lo[1] = 10;
    s.hi[2] = 300;
    zp_drive_constant_bounds(&s, &lo, &hi);
    CHECK(lo == 10 && hi == 300);
}

/* forces text read as a shape's parameters keeps the shape's bounds, and a wrong count is named
   with the kind's noun */
static void test_parse_shape(void) {
    zp_schedule shape = zp_drive_sections(2, NULL, 5, 50), s;
    char why[128] = "";
    CHECK(zp_drive_parse(&shape, "7, 8.5", &s, why, sizeof why) == 0);
    CHECK(s.np == 2 && s.p[0] == 7 && s.p[1] == 8.5 && s.lo[1] == 5 && s.hi[0] == 50);
    CHECK(zp_drive_parse(&shape, "7", &s, why, sizeof why) == -2);
    CHECK(!strcmp(why, "1 value, expected 2 (one per section)"));
    CHECK(s.p[0] == 7 && s.p[1] == 8.5); /* refused: left as it was */
}

static void test_round_trip(void) {
    const double v[] = {59.589211512356975,  1.0 / 3, -0.1, 5e-324, DBL_MAX, -DBL_MIN, 0, 1e22,
                        -123456789.123456789};
    int n = (int)(sizeof v / sizeof *v);
    zp_schedule s = zp_drive_sections(n, v, 0, 0), back;
    char text[1024], why[256];
    CHECK(zp_drive_format(&s, text, sizeof text) < (int)sizeof text);
    CHECK(zp_drive_parse_sections(text, n, &back, why, sizeof why) == 0);
    CHECK(back.kind == s.kind && back.np == n && !memcmp(back.p, v, sizeof v));
    /* snprintf's contract: the full length even when the buffer is short */
    char small[8];
    CHECK(zp_drive_format(&s, small, sizeof small) == (int)strlen(text));
    CHECK(strlen(small) == sizeof small - 1);
}

static void test_bad_text(void) {
    static const struct {
        const char *text;
        int rc;
        const char *why;
    } cases[] = {
        {"1, 2", -2, "2 values, expected 3 (one per section)"},
        {"1, 2, 3, 4", -2, "4 values, expected 3"},
        {"1,,3", -1, "item 2 is empty"},
        {"", -1, "the list is empty"},
        {"1, x, 3", -1, "item 2 `x` is not a number"},
        {"1, nan, 3", -1, "item 2 `nan` is not a number"},
        {"1, 2, inf", -1, "item 3 `inf` is not a number"},
        {"1, 2, 0x10", -1, "item 3"},
        {"1, 2, 1e999", -1, "item 3"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        zp_schedule s;
        char why[256] = "";
        int rc = zp_drive_parse_sections(cases[i].text, 3, &s, why, sizeof why);
        CHECK(rc == cases[i].rc);
        if (!strstr(why, cases[i].why)) {
            fprintf(stderr, "`%s`: `%s` lacks `%s`\n", cases[i].text, why, cases[i].why);
            CHECK(0);
        }
    }
}

static void test_scene(void) {
    zp_scene sc;
    zp_scene_load_seed(
        &sc); /* docs/scene-file.md's example: 100 N on each of 3 sections, box [0, 500] */
    zp_schedule s = zp_drive_of_scene(&sc);
    CHECK(s.kind == ZP_SCHED_SECTIONS && s.np == 3);
    for (int k = 0; k < 3; k++) {
        CHECK(s.p[k] == 100 && s.lo[k] == 0 && s.hi[k] == 500);
    }
    sc.nforce = 0; /* no forces given: all 0 */
    s = zp_drive_of_scene(&sc);
    CHECK(s.np == 3 && s.p[0] == 0 && s.p[2] == 0);
    char label[32];
    zp_schedule one = zp_drive_sections(1, (double[1]){59.589211512356975}, 0, 1);
    zp_drive_section_label(&one, 0, label, sizeof label);
    CHECK(!strcmp(label, "59.5892 N"));
}

static void test_directions(void) {
    for (int d = 0; d < ZP_DRIVE_COUNT; d++) {
        CHECK(zp_drive_dir_find(zp_drive_dir_name((zp_drive_dir)d)) == d);
    }
    CHECK(!strcmp(zp_drive_dir_name(ZP_DRIVE_TANGENT), "tangent"));
    CHECK(zp_drive_dir_find("sideways") == -1 && zp_drive_dir_find("") == -1);
}

/* a scaled schedule's force is the original's times the section's factor, on every section,
   and the bounds are the original's */
static void test_scaled(void) {
    const double f[] = {59.5, -3, 500}, k[] = {1.05, 0.95, 1};
    zp_schedule s = zp_drive_sections(3, f, -10, 500);
    zp_schedule sc = zp_drive_scaled(&s, k);
    for (int sec = 0; sec < 3; sec++) {
        CHECK(zp_drive_force(&sc, &(zp_drive_state){1.5, 42, 0, sec}) == f[sec] * k[sec]);
        CHECK(sc.lo[sec] == s.lo[sec] && sc.hi[sec] == s.hi[sec]);
    }
}

int main(void) {
    test_sections();
    test_state();
    test_push();
    test_params();
    test_constant();
    test_parse_shape();
    test_scaled();
    test_round_trip();
    test_bad_text();
    test_scene();
    test_directions();
    return CHECK_DONE();
}
