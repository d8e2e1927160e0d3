/* effect.c and the effects of effects.def: the table's promises (every effect named once, one
   with forces on the bodies has a work integral and names for it in every output, the state
   carries every work integral or none), drag's forces and power against the closed form
   -1/2 rho CdA |v - w| (v - w) at given velocities, and the rounded kinks' course against the
   circle it lays (on it, the radius normal to the course, curvature 1/r), the scene's own
   course left bit for bit off the arcs. */
#include <string.h>

#include "check.h"
#include "testutil.h"

#define RHO 1.3
#define WIND -4.0

static double uniform(double lo, double hi) {
    return lo + (hi - lo) * (rand() / (RAND_MAX + 1.0));
}

static void test_table(void) {
    int with_work = 0;
    for (int e = 0; e < ZP_EFFECT_COUNT; e++) {
        const zp_effect *ef = zp_effect_get(e);
        CHECK(ef && ef->name && ef->build && ef->describe);
        for (int o = 0; o < e; o++) {
            CHECK(strcmp(ef->name, zp_effect_get(o)->name) != 0);
        }
        if (ef->forces) {
            CHECK(ef->work.column != NULL);
        }
        with_work += ef->work.column != NULL;
    }
    CHECK(zp_effect_get(ZP_EFFECT_COUNT) == NULL && zp_effect_get(-1) == NULL);
    CHECK(with_work == ZP_EFFECT_NWORK);
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        const zp_effect_work *w = zp_effect_work_names(k);
        CHECK(w && w->column && w->plot && w->key && w->words && w->brief);
        for (int o = 0; w && o < k; o++) {
            const zp_effect_work *v = zp_effect_work_names(o);
            CHECK(strcmp(w->column, v->column) && strcmp(w->plot, v->plot) &&
                  strcmp(w->key, v->key));
        }
    }
    CHECK(zp_effect_nwork(0) == ZP_W_EFFECTS && ZP_W_MAX == ZP_W_EFFECTS + ZP_EFFECT_NWORK);
    /* the [physics] effects' slots together (the layout their answers were made with); the
       brake's own only with it, the slots before it held at 0 */
    const int physics_slots = ZP_W_EFFECTS + ZP_EFFECT_W_FRICTION + 1;
    CHECK(zp_effect_nwork(ZP_PHYS_DRAG) == physics_slots &&
          zp_effect_nwork(ZP_PHYS_ROLLING) == physics_slots);
    CHECK(zp_effect_nwork(ZP_PHYS_ROUNDED) == ZP_W_EFFECTS);
    CHECK(zp_effect_nwork(ZP_PHYS_BRAKE) == ZP_W_MAX &&
          zp_effect_nwork(ZP_PHYS_BRAKE | ZP_PHYS_DRAG) == ZP_W_MAX);
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        int brake = k == ZP_EFFECT_W_BRAKE;
        CHECK(!zp_effect_work_shown(0, k));
        CHECK(zp_effect_work_shown(ZP_PHYS_ROUNDED, k) == !brake);
        CHECK(zp_effect_work_shown(ZP_PHYS_BRAKE, k) == brake);
    }
}

static void test_drag(void) {
    const double cda[4] = {0.05, 0.3, 0.2, 0.1};
    char ini[512];
    snprintf(ini, sizeof ini,
             "[course]\nx_start = 0\nsection = 100 : 50 - 0.3*x\n[trolley]\nmass = 30\n[body]\n"
             "lengths = 1, 1, 1\nmasses = 10, 10, 10\n[physics]\ndrag_area = %g, %g, %g, %g\n"
             "air_density = %g\nwind = %g\n",
             cda[0], cda[1], cda[2], cda[3], RHO, WIND);
    zp_scene sc;
    zp_model *m = tu_model(ini, &sc);
    CHECK(m->physics == ZP_PHYS_DRAG && zp_effect_with_forces(m->physics) == ZP_PHYS_DRAG);
    CHECK(m->nwork == ZP_W_EFFECTS + ZP_EFFECT_W_FRICTION + 1 && m->course_provider == NULL);
    for (int trial = 0; trial < 100; trial++) {
        zp_effect_motion mo = {.nbody = 4};
        for (int b = 0; b < 4; b++) {
            mo.v[b][0] = uniform(-20, 20);
            mo.v[b][1] = uniform(-20, 20);
        }
        double f[ZP_MAX_LINKS + 1][2], pw[ZP_EFFECT_NWORK] = {0}, power = 0;
        zp_effect_forces(m->physics, m, &mo, f, pw);
        for (int b = 0; b < 4; b++) {
            double rx = mo.v[b][0] - WIND, ry = mo.v[b][1], speed = sqrt(rx * rx + ry * ry);
            double fx = -0.5 * RHO * cda[b] * speed * rx, fy = -0.5 * RHO * cda[b] * speed * ry;
            CHECK_NEAR(f[b][0], fx, 1e-12 * (1 + fabs(fx)));
            CHECK_NEAR(f[b][1], fy, 1e-12 * (1 + fabs(fy)));
            power -= fx * mo.v[b][0] + fy * mo.v[b][1];
        }
        CHECK_NEAR(pw[ZP_EFFECT_W_DRAG], power, 1e-12 * (1 + fabs(power)));
        CHECK(pw[ZP_EFFECT_W_FRICTION] == 0);
    }
    zp_model_free(m);
}

static void test_rounded_course(void) {
    zp_scene sc;
    zp_model *m = tu_model("[course]\nx_start = 0\nsection = 60 : 20 - 0.4*x\n"
                           "section = 120 : y0 + 0.02*(x - 60)^2 - 0.1*(x - 60)\n"
                           "section = 200 : y0 + 0.3*(x - 120)\n[trolley]\nmass = 30\n[body]\n"
                           "lengths = 1\nmasses = 10\n[physics]\nkink_radius = 12\n",
                           &sc);
    CHECK(m->physics == ZP_PHYS_ROUNDED && m->narc == 2 && m->course_provider != NULL);
    CHECK(m->nwork == ZP_W_EFFECTS && zp_effect_with_forces(m->physics) == 0);
    for (int i = 0; i < m->narc; i++) {
        const zp_arc *a = &m->arc[i];
        int left = m->kink[a->kink].left;
        for (int side = 0; side < 2; side++) {
            int sec = left + side;
            double x = side ? 0.5 * (m->xb[sec] + a->x2) : 0.5 * (a->x1 + m->xb[sec + 1]);
            zp_track t = zp_model_track(m, m->course, sec, x);
            double dx = x - a->cx, dy = t.f - a->cy;
            CHECK_NEAR(dx * dx + dy * dy, a->r * a->r, 1e-9 * a->r * a->r);
            CHECK_NEAR(dx + t.fp * dy, 0, 1e-9 * a->r); /* the radius normal to the course */
            CHECK_REL(fabs(t.fpp) / pow(1 + t.fp * t.fp, 1.5), 1 / a->r, 1e-9);
            CHECK(zp_model_piece(m, sec, x) == i);
        }
    }
    /* off the arcs the scene's own course, bit for bit */
    for (int sec = 0; sec < m->nsec; sec++) {
        double x = 0.5 * (m->xb[sec] + m->xb[sec + 1]);
        zp_track t = zp_model_track(m, m->course, sec, x), c = zp_course_eval(m->course, sec, x);
        CHECK(zp_model_piece(m, sec, x) == -1);
        CHECK(t.f == c.f && t.fp == c.fp && t.fpp == c.fpp);
    }
    zp_model_free(m);
}

int main(void) {
    srand(3);
    test_table();
    test_drag();
    test_rounded_course();
    return CHECK_DONE();
}
