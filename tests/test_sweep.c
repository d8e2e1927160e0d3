/* The study's grid (sweep.c) and rows (sweep_csv.c): --vary checks, grid values that end
   exactly at B, each point's scene text read back by the scene reader with the value set (and
   every other key untouched), list keys scaled item by item, and rows that read back from the
   CSV to the same line; the grid's middle point, the grid schedule's checkpoint line read back
   to the same bits, and a scenario judged by criteria of its own. Independent expectations:
   the reader's own parse of hand-written values, and products computed here. */
#include <string.h>

#include "check.h"
#include "robust.h"
#include "scene_load.h"
#include "sweep_csv.h"
#include "testutil.h"

static const char *base = "; a scene with comments\n"
                          "[scene]\nname = t\n[course]\nx_start = 0\nsection = 20 : -x/10 + 10\n"
                          "[trolley]\nmass = 30   ; kg\n"
                          "[body]\nlengths = 1, 2\nmasses = 5, 3 # kg\ndamping = 2\n"
                          "[drive]\nforces = 100\n";

static zp_sweep grid(const char *v1, const char *v2) {
    zp_sweep s = {0};
    char why[512];
    zp_sweep_vary v;
    CHECK(zp_sweep_vary_parse(v1, &v, why, sizeof why) == 0 &&
          zp_sweep_add(&s, &v, why, sizeof why) == 0);
    if (v2) {
        CHECK(zp_sweep_vary_parse(v2, &v, why, sizeof why) == 0 &&
              zp_sweep_add(&s, &v, why, sizeof why) == 0);
    }
    return s;
}

static int load(const char *text, zp_scene *sc) {
    zp_diag d;
    zp_diag_init(&d);
    int rc = zp_scene_load_string(text, "t.ini", sc, &d);
    zp_diag_print(&d, stderr);
    return rc;
}

static void bad_vary(const char *text, const char *says) {
    zp_sweep_vary v;
    char why[1024] = "";
    CHECK(zp_sweep_vary_parse(text, &v, why, sizeof why) == -1);
    if (!strstr(why, says)) {
        fprintf(stderr, "--vary %s: '%s' does not say '%s'\n", text, why, says);
        CHECK(0);
    }
}

/* the grid schedule's line written, read back and written again: the same line, the same bits */
static void grid_line(void) {
    zp_grid_result g = {.found = 1,
                        .nominal = 10,
                        .ncorner = 4,
                        .nscen = 260,
                        .evals = 4321,
                        .np = 3,
                        .force = {1.0 / 3, 500, 0},
                        .time = 9.045890546185342,
                        .margin = 10.000999951619107,
                        .worst = 20,
                        .worst_margin = NAN,
                        .survived = 20,
                        .rounds = 3,
                        .kept = 2,
                        .nheld = 1,
                        .nadded = 2},
                   back;
    for (int p = 0; p < 21; p++) {
        g.ok[p / 8] |= (unsigned char)((p != 7) << (p % 8));
        g.added[p / 8] |= (unsigned char)((p == 7 || p == 19) << (p % 8));
    }
    snprintf(g.message, sizeof g.message, "%s", "a, b");
    char *l1 = NULL, *l2 = NULL;
    size_t n1, n2;
    FILE *f = open_memstream(&l1, &n1);
    zp_sweep_csv_grid(f, &g, 21);
    fclose(f);
    l1[strcspn(l1, "\n")] = '\0';
    CHECK(zp_sweep_csv_grid_parse(l1, 3, 21, &back) == 0);
    CHECK(back.found && back.nominal == 10 && back.ncorner == 4 && back.nscen == 260 &&
          back.evals == 4321 && back.worst == 20 && back.survived == 20 && back.rounds == 3 &&
          back.kept == 2 && back.nheld == 1 && back.nadded == 2 && !back.last_found);
    CHECK(back.force[0] == 1.0 / 3 && back.time == g.time && back.margin == g.margin &&
          isnan(back.worst_margin));
    for (int p = 0; p < 21; p++) {
        CHECK(zp_grid_survived_at(&back, p) == (p != 7));
        CHECK(zp_grid_added_at(&back, p) == (p == 7 || p == 19));
    }
    f = open_memstream(&l2, &n2);
    zp_sweep_csv_grid(f, &back, 21);
    fclose(f);
    l2[strcspn(l2, "\n")] = '\0';
    CHECK(!strcmp(l1, l2));
    CHECK(zp_sweep_csv_grid_parse(l1, 2, 21, &back) == -1); /* another study's width */
    CHECK(zp_sweep_csv_grid_parse(l1, 3, 30, &back) == -1); /* another study's points */
    /* the line of a zipopt before the rounds (no rounds, no points added) is refused (a
       resumed study searches the grid schedule again) */
    const char *old = "grid,0,1,10,4,260,4321,9.045890546185342,10.000999951619107,20,nan,20,"
                      "0.33333333333333331,500,0,7fff1f,a; b";
    CHECK(zp_sweep_csv_grid_parse(old, 3, 21, &back) == -1);
    free(l1);
    free(l2);
}

/* line with its field k (comma-separated, 0-based) replaced by value, into out */
static void edit_field(const char *line, int k, const char *value, char *out, size_t cap) {
    size_t len = 0;
    for (int i = 0;; i++) {
        size_t n = strcspn(line, ",");
        len += (size_t)snprintf(out + len, cap - len, "%s%.*s", i ? "," : "",
                                i == k ? (int)strlen(value) : (int)n, i == k ? value : line);
        if (!line[n]) {
            break;
        }
        line += n + 1;
    }
}

/* a checkpoint is a text a user may edit: every field read back is range-checked, so a
   value zipopt never writes (inf or nan, a negative count, a point off the grid, a count
   past the grid's size) is refused, while the line as written reads back */
static void hand_edited(void) {
    zp_sweep s = grid("trolley.mass=10:20:3", NULL);
    zp_study_row r = {.found = 1,
                      .outcome = ZP_OUTCOME_FINISHED,
                      .time = 2.5,
                      .margin = 12,
                      .verified = 1,
                      .evals = 300,
                      .np = 2,
                      .force = {90, 120},
                      .limit = "margin"},
                 back;
    char *row = NULL, edited[1024];
    size_t n;
    FILE *f = open_memstream(&row, &n);
    zp_sweep_csv_row(f, &s, 1, &r);
    fclose(f);
    row[strcspn(row, "\n")] = '\0';
    int p;
    CHECK(zp_sweep_csv_parse(row, &s, 2, &p, &back) == 0);
    /* point, trolley.mass, status, found, outcome, time, margin, limit, verified, evals, the
       four limited quantities, F1, F2, message */
    const struct {
        int k;
        const char *value;
    } bad_row[] = {{0, "99999"},
                   {0, "-1"},
                   {3, "2"},
                   {5, "inf"},
                   {5, "nan"},
                   {5, "-1"},
                   {6, "nan"},
                   {6, "-inf"},
                   {7, "x y"},
                   {8, "7"},
                   {9, "-5"},
                   {9, "1e3"},
                   {9, "99999999999999999999999"},
                   {10, "-1"},
                   {13, "inf"},
                   {14, "nan"},
                   {15, "inf"}};
    for (size_t i = 0; i < sizeof bad_row / sizeof bad_row[0]; i++) {
        edit_field(row, bad_row[i].k, bad_row[i].value, edited, sizeof edited);
        if (zp_sweep_csv_parse(edited, &s, 2, &p, &back) != -1) {
            fprintf(stderr, "row accepted: %s\n", edited);
            CHECK(0);
        }
    }
    free(row);

    zp_grid_result g = {.found = 1,
                        .nominal = 10,
                        .ncorner = 4,
                        .nscen = 260,
                        .evals = 4321,
                        .np = 3,
                        .force = {1, 500, 0},
                        .time = 9,
                        .margin = 10,
                        .worst = 20,
                        .worst_margin = 11,
                        .survived = 20,
                        .rounds = 3,
                        .kept = 2,
                        .nheld = 1,
                        .nadded = 2},
                   gback;
    for (int q = 0; q < 21; q++) {
        g.ok[q / 8] |= (unsigned char)((q != 7) << (q % 8));
    }
    char *line = NULL;
    f = open_memstream(&line, &n);
    zp_sweep_csv_grid(f, &g, 21);
    fclose(f);
    line[strcspn(line, "\n")] = '\0';
    CHECK(zp_sweep_csv_grid_parse(line, 3, 21, &gback) == 0);
    /* grid, failed, found, nominal, ncorner, nscen, evals, rounds, kept, nheld, nadded,
       last_found, time, margin, worst, worst_margin, survived, F1..F3, ok, added, message */
    const struct {
        int k;
        const char *value;
    } bad_grid[] = {{1, "2"},       {3, "99999"},  {4, "2147483647"}, {5, "-3"},  {6, "-5"},
                    {8, "9"},       {9, "22"},     {12, "inf"},       {12, "-1"}, {13, "inf"},
                    {14, "99999"},  {14, "-2"},    {15, "-inf"},      {16, "21"}, {17, "inf"},
                    {20, "7fff3f"}, {21, "zz0000"}};
    for (size_t i = 0; i < sizeof bad_grid / sizeof bad_grid[0]; i++) {
        edit_field(line, bad_grid[i].k, bad_grid[i].value, edited, sizeof edited);
        if (zp_sweep_csv_grid_parse(edited, 3, 21, &gback) != -1) {
            fprintf(stderr, "grid line accepted: %s\n", edited);
            CHECK(0);
        }
    }
    free(line);
}

/* the seed's answer survives the seed (README), and its spy swings more than 1 deg: a scenario
   of the same model passes under the search's criteria and breaks under a 1 deg limit */
static void own_judge(void) {
    static zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-8);
    zp_objective ob = tu_objective(m, &sc, &o), strict = ob;
    strict.limit = M_PI / 180;
    zp_scenario nominal;
    zp_scenario_nominal(&nominal);
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    const double f[3] = {59.58914569124449, 500, 500};
    for (int own = 0; own <= 1; own++) {
        zp_scen_set set = {0};
        CHECK(zp_scen_set_add_model(&set, m, &nominal, NULL, NULL) == ZP_OK);
        CHECK(zp_scen_set_add_model(&set, m, &nominal, NULL, own ? &strict : NULL) == ZP_OK);
        ob.set = &set;
        zp_eval e;
        zp_objective_eval(&ob, s, f, &e, &r);
        CHECK(zp_objective_feasible(&e) == !own);
        CHECK(e.scenario == (own ? 1 : -1));
        zp_scen_set_free(&set);
    }
    zp_sim_free(s);
    zp_model_free(m);
}

int main(void) {
    bad_vary("body.mass=1:2:3", "unknown key body.mass");
    bad_vary("bodi.masses=1:2:3", "unknown key");
    bad_vary("body.masses=2:1:3", "expected A <= B");
    bad_vary("body.masses=1:2:0", "N = 0");
    bad_vary("drive.direction=1:2:3", "not a number");
    bad_vary("body.masses", "not SECTION.KEY=A:B:N");
    bad_vary("body.masses=1:2", "not A:B:N");
    bad_vary("body.masses=1:x:2", "A and B must be numbers");
    bad_vary("optimize.seed=1:2:3", "whole numbers");

    /* the grid: first key fastest, the ends exactly A and B */
    zp_sweep s = grid("trolley.mass=0.1:0.7:7", "body.masses=0.8:1.2:3");
    CHECK(s.npoint == 21);
    CHECK(zp_sweep_value(&s, 0, 6) == 0.7 && zp_sweep_value(&s, 0, 7) == 0.1);
    CHECK(zp_sweep_value(&s, 1, 6) == 0.8 && zp_sweep_value(&s, 1, 7) == 1.0);
    CHECK(zp_sweep_value(&s, 1, 20) == 1.2);
    char why[512];
    zp_sweep_vary v;
    CHECK(zp_sweep_vary_parse("trolley.mass=1:2:2", &v, why, sizeof why) == 0);
    CHECK(zp_sweep_add(&s, &v, why, sizeof why) == -1 && strstr(why, "twice"));

    /* each point's text through the reader: the value set, the rest as in base */
    static zp_scene sc0, sc;
    CHECK(load(base, &sc0) == ZP_OK);
    for (int p = 0; p < s.npoint; p++) {
        char *t = zp_sweep_point_text(&s, base, p, why, sizeof why);
        CHECK(t && load(t, &sc) == ZP_OK);
        double f = zp_sweep_value(&s, 1, p);
        CHECK(sc.trolley_mass == zp_sweep_value(&s, 0, p));
        CHECK(sc.nlink == 2 && sc.masses[0] == 5 * f && sc.masses[1] == 3 * f);
        CHECK(sc.lengths[1] == 2 && sc.damping[0] == 2 && sc.forces[0] == 100);
        CHECK(strstr(t, "; a scene with comments") != NULL);
        free(t);
    }
    /* a key the scene lacks joins its section; a section the scene lacks is added */
    s = grid("body.death_angle=90:90:1", "solver.t_max=33:33:1");
    char *t = zp_sweep_point_text(&s, base, 0, why, sizeof why);
    CHECK(t && load(t, &sc) == ZP_OK && sc.death_angle == 90 && sc.t_max == 33);
    CHECK(sc.masses[0] == 5 && sc.trolley_mass == 30);
    free(t);
    /* the brake's keys: each point's zone and forces as set, the rest of [brake] untouched */
    static const char *braked =
        "[scene]\nname = t\n[course]\nx_start = 0\nsection = 20 : 10 - x/10\n"
        "[trolley]\nmass = 30\n[body]\nlengths = 1\nmasses = 5\n"
        "[brake]\nstart = 10\nend = 18\neddy = 40\n";
    s = grid("brake.eddy=20:120:6", "brake.start=4:12:3");
    CHECK(s.npoint == 18);
    for (int p = 0; p < s.npoint; p++) {
        t = zp_sweep_point_text(&s, braked, p, why, sizeof why);
        CHECK(t && load(t, &sc) == ZP_OK && sc.brake);
        CHECK(sc.brake_eddy == zp_sweep_value(&s, 0, p) && sc.brake_eddy == 20 + 20 * (p % 6));
        CHECK(sc.brake_start == zp_sweep_value(&s, 1, p) && sc.brake_end == 18);
        CHECK(sc.brake_friction == 0);
        free(t);
    }
    s = grid("brake.friction=0:300:4", "brake.end=15:20:2");
    t = zp_sweep_point_text(&s, braked, 7, why, sizeof why);
    CHECK(t && load(t, &sc) == ZP_OK && sc.brake_friction == 300 && sc.brake_end == 20);
    CHECK(sc.brake_start == 10 && sc.brake_eddy == 40);
    free(t);

    /* a list key that is absent has nothing to scale */
    s = grid("drive.forces=1:2:2", NULL);
    t = zp_sweep_point_text(&s, "[drive]\nmin = 0\n", 0, why, sizeof why);
    CHECK(t == NULL && strstr(why, "nothing to scale"));

    /* numbers in the fewest digits that read back exactly */
    const double xs[] = {
        100, 0.1, 1.0 / 3, 1e-300, -2.5e17, 123456789.123456789, 0, 9.045888853521665};
    for (int i = 0; i < (int)(sizeof xs / sizeof xs[0]); i++) {
        char buf[32];
        zp_sweep_format(xs[i], buf, sizeof buf);
        CHECK(strtod(buf, NULL) == xs[i]);
    }
    char buf[32];
    zp_sweep_format(100, buf, sizeof buf);
    CHECK(!strcmp(buf, "100"));

    /* a row written, read back and written again: the same line */
    s = grid("trolley.mass=10:20:3", NULL);
    zp_study_row r = {.found = 1,
                      .outcome = ZP_OUTCOME_FINISHED,
                      .time = 1.0 / 3,
                      .margin = 10.000000000000002,
                      .verified = 1,
                      .evals = 1234,
                      .np = 2,
                      .force = {0.1, 500},
                      .limit = "margin+drive.max"},
                 back;
    char *l1 = NULL, *l2 = NULL;
    size_t n1, n2;
    for (int failed = 0; failed <= 1; failed++) {
        r.failed = failed;
        snprintf(r.message, sizeof r.message, "%s", failed ? "t = 3, x = 4: \"no\" progress" : "");
        FILE *f = open_memstream(&l1, &n1);
        zp_sweep_csv_row(f, &s, 1, &r);
        fclose(f);
        l1[strcspn(l1, "\n")] = '\0';
        int p = -1;
        CHECK(zp_sweep_csv_parse(l1, &s, 2, &p, &back) == 0 && p == 1);
        CHECK(back.failed == failed);
        CHECK(failed || (back.time == r.time && back.margin == r.margin && back.force[0] == 0.1 &&
                         back.evals == 1234 && !strcmp(back.limit, r.limit)));
        f = open_memstream(&l2, &n2);
        zp_sweep_csv_row(f, &s, p, &back);
        fclose(f);
        l2[strcspn(l2, "\n")] = '\0';
        CHECK(!strcmp(l1, l2));
        CHECK(zp_sweep_csv_parse(l1, &s, 3, &p, &back) == -1); /* another study's width */
        free(l1);
        free(l2);
    }

    /* the middle: index (n - 1) / 2 along each key */
    s = grid("trolley.mass=0.1:0.7:7", "body.masses=0.8:1.2:4");
    int mid = zp_grid_nominal(&s);
    CHECK(zp_sweep_value(&s, 0, mid) == 0.4 && zp_sweep_value(&s, 1, mid) == 0.8 + 0.4 / 3);
    grid_line();
    hand_edited();
    own_judge();
    return CHECK_DONE();
}
