/* out_columns.c: each quantity is found where trajectory.csv's header (docs/commands.md "Files")
   names it, as many columns as it spans, and its value in the CSV's unit is the row's own
   field, bit for bit: what simulate --json's samples read from the same table; the effects'
   work columns those the scene shows (a brake's alone, or after drag's and friction's). */
#include <string.h>

#include "check.h"
#include "out_columns.h"
#include "testutil.h"

#define DEG_PER_RAD (180.0 / M_PI) /* the JSON samples' degrees before the table served them */

/* quantity q at the column whose CSV name is first (per link: first with 1), spanning n */
static void check_found(const zp_model *m, const zp_out_column *col, zp_out_quantity q,
                        const char *first, int n) {
    int k, j = zp_out_columns_find(m, q, &k);
    CHECK(k == n);
    CHECK(j >= 0 && !strcmp(col[j].csv, first));
}

static void check_table(const zp_model *m) {
    zp_out_column col[ZP_OUT_COLUMNS_MAX];
    zp_out_columns(m, col);
    check_found(m, col, ZP_OUT_Q_T, "t", 1);
    check_found(m, col, ZP_OUT_Q_SECTION, "section", 1);
    check_found(m, col, ZP_OUT_Q_X, "x", 1);
    check_found(m, col, ZP_OUT_Q_Y, "y", 1);
    check_found(m, col, ZP_OUT_Q_THETA, "theta1_deg", m->nlink);
    check_found(m, col, ZP_OUT_Q_OMEGA, "omega1_deg_s", m->nlink);
    check_found(m, col, ZP_OUT_Q_NORMAL, "normal_force", 1);
    check_found(m, col, ZP_OUT_Q_ACC, "acc1_g", m->nlink);
    /* a pair's columns alternate (com0_x, com0_y, ..): not one quantity's run */
    int n;
    CHECK(zp_out_columns_find(m, ZP_OUT_Q_COM_X, &n) == -1 && n == 0);
}

/* a row's values at the found columns, in the CSV's unit, against the row's fields */
static void check_values(const zp_model *m) {
    zp_out_column col[ZP_OUT_COLUMNS_MAX];
    zp_out_columns(m, col);
    zp_row r;
    memset(&r, 0, sizeof r);
    r.t = 1.25;
    r.sec = 1;
    for (int j = 0; j < 2 + m->nlink; j++) {
        r.c.q[j] = 0.1 * (j + 1) - 0.17;
        r.c.v[j] = 0.3 * (j + 1) - 0.71;
    }
    r.loads.normal = 123.456;
    double v[ZP_OUT_COLUMNS_MAX];
    zp_out_columns_values(m, &r, v);
    int n, t = zp_out_columns_find(m, ZP_OUT_Q_T, &n),
           sec = zp_out_columns_find(m, ZP_OUT_Q_SECTION, &n);
    int x = zp_out_columns_find(m, ZP_OUT_Q_X, &n),
        normal = zp_out_columns_find(m, ZP_OUT_Q_NORMAL, &n);
    CHECK(v[t] == r.t && v[sec] == r.sec + 1 && v[x] == r.c.q[0] && v[normal] == r.loads.normal);
    int th = zp_out_columns_find(m, ZP_OUT_Q_THETA, &n),
        om = zp_out_columns_find(m, ZP_OUT_Q_OMEGA, &n);
    for (int i = 0; i < m->nlink; i++) {
        CHECK(v[th + i] * col[th + i].csv_scale == r.c.q[2 + i] * DEG_PER_RAD);
        CHECK(v[om + i] * col[om + i].csv_scale == r.c.v[2 + i] * DEG_PER_RAD);
    }
}

int main(void) {
    zp_scene sc;
    zp_model *seed = tu_seed_model(&sc);
    check_table(seed);
    check_values(seed);
    zp_model_free(seed);
    zp_model *one = tu_model("[scene]\nname = one\n[course]\nx_start = 0\n"
                             "section = 100 : 10 - x/10\n[trolley]\nmass = 20\n"
                             "[body]\nlengths = 2\nmasses = 8\n[drive]\nforces = 0\n",
                             &sc);
    check_table(one);
    check_values(one);
    zp_model_free(one);
    /* the effects' work: a brake's column alone, or after the [physics] ones */
    static const char *const braked[] = {"", "[physics]\ndrag_area = 0.1, 0.2\n"};
    for (int k = 0; k < 2; k++) {
        char ini[512];
        snprintf(ini, sizeof ini,
                 "[scene]\nname = braked\n[course]\nx_start = 0\nsection = 100 : 10 - x/10\n"
                 "[trolley]\nmass = 20\n[body]\nlengths = 2\nmasses = 8\n[drive]\n"
                 "forces = 0\n[brake]\nstart = 50\neddy = 10\n%s",
                 braked[k]);
        zp_model *m = tu_model(ini, &sc);
        zp_out_column col[ZP_OUT_COLUMNS_MAX];
        zp_out_columns(m, col);
        check_table(m);
        check_values(m);
        check_found(m, col, ZP_OUT_Q_WORK, k ? "drag_work" : "brake_work", k ? 3 : 1);
        zp_model_free(m);
    }
    return CHECK_DONE();
}
