/* Rounded kinks (docs/model.md "Optional effects", [physics] kink_radius): every kink replaced by
   the circular arc of the given radius that touches both sections, a course provider whose
   pieces are the arcs. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <math.h>

#include "effect.h"
#include "model.h"

/* the circle of radius r and side sd tangent to section kl at x1 and to kl + 1 at x2: the
   centre seen from both touching points coincides */
typedef struct arc_fit {
    const zp_model *m;
    int kl;
    double r, sd;
} arc_fit;

static void centre_from(const zp_model *m, int sec, double x, double r, double sd, double c[2]) {
    zp_track t = zp_course_eval(m->course, sec, x);
    double nrm = sqrt(1 + t.fp * t.fp);
    c[0] = x - sd * r * t.fp / nrm;
    c[1] = t.f + sd * r / nrm;
}

static int arc_gap(const gsl_vector *v, void *p, gsl_vector *out) {
    const arc_fit *a = p;
    double c1[2], c2[2];
    centre_from(a->m, a->kl, gsl_vector_get(v, 0), a->r, a->sd, c1);
    centre_from(a->m, a->kl + 1, gsl_vector_get(v, 1), a->r, a->sd, c2);
    gsl_vector_set(out, 0, c1[0] - c2[0]);
    gsl_vector_set(out, 1, c1[1] - c2[1]);
    return GSL_SUCCESS;
}

/* the touching points, from those of the two tangent lines at the kink refined on the curved
   sections (GSL hybrid root finder); 0 on success */
static int fit_arc(const zp_model *m, const zp_kink *k, double r, zp_arc *arc) {
    double t1 = atan(k->slope_in), t2 = atan(k->slope_out), run = r * tan(fabs(t2 - t1) / 2);
    arc_fit a = {m, k->left, r, k->slope_out > k->slope_in ? 1 : -1};
    gsl_multiroot_function fn = {arc_gap, 2, &a};
    gsl_vector *v = gsl_vector_alloc(2);
    gsl_multiroot_fsolver *s = gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, 2);
    int status = GSL_FAILURE;
    if (v && s) {
        gsl_vector_set(v, 0, k->x - run * cos(t1));
        gsl_vector_set(v, 1, k->x + run * cos(t2));
        gsl_multiroot_fsolver_set(s, &fn, v);
        for (int it = 0; it < 100 && status != GSL_SUCCESS; it++) {
            if (gsl_multiroot_fsolver_iterate(s)) {
                break;
            }
            status = gsl_multiroot_test_residual(s->f, 1e-12 * (1 + r));
        }
    }
    if (status == GSL_SUCCESS) {
        double c[2];
        arc->x1 = gsl_vector_get(s->x, 0);
        arc->x2 = gsl_vector_get(s->x, 1);
        centre_from(m, k->left, arc->x1, r, a.sd, c);
        arc->cx = c[0];
        arc->cy = c[1];
        arc->r = r;
        arc->side = a.sd;
    }
    gsl_multiroot_fsolver_free(s);
    gsl_vector_free(v);
    return status != GSL_SUCCESS;
}

/* every kink replaced by its arc; a radius that does not fit names the kink */
static int round_kinks(zp_model *m, const zp_scene *sc, zp_diag *d) {
    int ok = 1;
    for (int i = 0; i < m->nkink; i++) {
        const zp_kink *k = &m->kink[i];
        zp_arc *a = &m->arc[i];
        a->kink = i;
        int bad = fit_arc(m, k, sc->kink_radius, a);
        const char *why = bad ? "no circle of that radius touches both sections" : NULL;
        if (!bad && !(a->x1 > m->xb[k->left] && a->x1 < k->x)) {
            why = "the arc would start before the section on the left does";
        } else if (!bad && !(a->x2 < m->xb[k->left + 2] && a->x2 > k->x)) {
            why = "the arc would end after the section on the right does";
        } else if (!bad && i > 0 && m->arc[i - 1].x2 >= a->x1) {
            why = "the arc would overlap the arc of the kink before";
        }
        if (why) {
            zp_diag_add(d, sc->path, sc->line_kink_radius, "physics", "kink_radius",
                        "a radius of %g m does not fit the kink at x = %g between sections %d "
                        "and %d: %s (arc [%g, %g] m, sections [%g, %g] and [%g, %g] m); "
                        "expected a smaller radius",
                        sc->kink_radius, k->x, k->left + 1, k->left + 2, why, a->x1, a->x2,
                        m->xb[k->left], k->x, k->x, m->xb[k->left + 2]);
            ok = 0;
            continue;
        }
        m->arc_at[k->left + 1] = i;
    }
    m->narc = ok ? m->nkink : 0;
    return ok;
}

static int rounded_build(zp_model *m, const zp_scene *sc, zp_diag *d) {
    for (int k = 0; k <= m->nsec; k++) {
        m->arc_at[k] = -1;
    }
    if (sc->kink_radius > 0 && !round_kinks(m, sc, d)) {
        return -1;
    }
    return m->narc > 0;
}

static void rounded_describe(const zp_model *m, const zp_scene *sc, FILE *f) {
    (void)m;
    fprintf(f, " kinks rounded, radius %g m;", sc->kink_radius);
}

/* the arc around the section's left end while x is short of its end, the one around its right
   end once x is past its start */
static int rounded_piece(const zp_model *m, int sec, double x) {
    int lo = m->arc_at[sec], hi = m->arc_at[sec + 1];
    return lo >= 0 && x < m->arc[lo].x2 ? lo : hi >= 0 && x > m->arc[hi].x1 ? hi : -1;
}

/* the arc's circle, its lower or upper half as the arc's side says */
static zp_track rounded_on_piece(const zp_model *m, const zp_course *course, int sec, int arc,
                                 double x) {
    (void)course;
    (void)sec;
    const zp_arc *a = &m->arc[arc];
    double u = x - a->cx, h = sqrt(a->r * a->r - u * u);
    return (zp_track){a->cy - a->side * h, a->side * u / h, a->side * a->r * a->r / (h * h * h)};
}

static const zp_effect_course arcs = {rounded_piece, rounded_on_piece};

const zp_effect zp_effect_rounded = {
    .name = "rounded",
    .build = rounded_build,
    .describe = rounded_describe,
    .course = &arcs,
};
