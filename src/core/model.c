/* zp_model_build: scene (file units) -> model (SI, radians, derived constants); docs/model.md
   "Course" continuity and kinks, "Bodies" rods. */
#include "model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr.h"

/* the chain's constant coefficients: M_x,thj = B_j (cos thj + f' sin thj),
   M_thj,thk = C_jk cos(thj - thk) (derivation in form_lagrange.c) */
void zp_model_derive(zp_model *m) {
    int n = m->nlink;
    m->mtot = m->m0;
    for (int i = 0; i < n; i++) {
        m->mtot += m->mass[i];
    }
    for (int j = 0; j < n; j++) {
        double below = 0; /* mass of the links hanging below link j */
        for (int i = j + 1; i < n; i++) {
            below += m->mass[i];
        }
        m->B[j] = m->mass[j] * m->half[j] + m->len[j] * below;
        m->C[j][j] = m->mass[j] * m->half[j] * m->half[j] + m->inertia[j] +
                     below * m->len[j] * m->len[j];
        for (int k = j + 1; k < n; k++) {
            double below_k = 0;
            for (int i = k + 1; i < n; i++) {
                below_k += m->mass[i];
            }
            m->C[j][k] = m->C[k][j] = m->len[j] * (m->mass[k] * m->half[k] + m->len[k] * below_k);
        }
    }
    if (m->cable_paths) {
        char why[256];
        m->cable_path = zp_cable_paths_get(m->cable_paths, m->g * m->mtot, why, sizeof why);
    }
}

double zp_model_cable_energy(const zp_model *m, double x) {
    if (!m->cable_paths) {
        return 0;
    }
    zp_cable_path_value v;
    return m->cable_path && zp_cable_path_eval(m->cable_path, x, &v) == 0 ? v.energy : NAN;
}

/* probes per section: at least 4096, and no gap over 1 cm below 2^20 of them, so a narrow
   non-finite stretch (a NaN gap, a pole) is met, not stepped over */
static int probe_count(double width) {
    return (int)fmin(fmax(4096, ceil(width / 0.01)), 1 << 20);
}

/* a slope this many times the probes' own (plus 1) where f' or f'' turns between them is a
   pole, not a bend: a smooth f's slope between two probes 1 cm apart lies near theirs, while
   r / (x - p) reaches r / (round-off)^2 at p however small the residue r */
#define ZP_POLE_SLOPE_GROWTH 1e6

/* between neighbouring probes a and b whose f' or f'' differ in sign, where that sign turns
   (bisection to round-off): 1 and there in *at when f is not finite there or its slope has
   grown ZP_POLE_SLOPE_GROWTH-fold (a pole whose residue is too small for the jump test) */
static int pole_between(const zp_model *m, int k, double a, zp_track ta, double b, zp_track tb,
                        double *at) {
    int which = (ta.fp > 0) != (tb.fp > 0) ? 1 : (ta.fpp > 0) != (tb.fpp > 0) ? 2 : 0;
    if (!which) {
        return 0;
    }
    double bound = ZP_POLE_SLOPE_GROWTH * (1 + fmax(fabs(ta.fp), fabs(tb.fp)));
    for (int it = 0; it < 80; it++) {
        double mid = 0.5 * (a + b);
        if (!(mid > a && mid < b)) {
            break;
        }
        zp_track tm = zp_course_eval(m->course, k, mid);
        *at = mid;
        if (!isfinite(tm.f) || !isfinite(tm.fp) || fabs(tm.fp) > bound) {
            return 1;
        }
        double va = which == 1 ? ta.fp : ta.fpp, vm = which == 1 ? tm.fp : tm.fpp;
        if ((va > 0) == (vm > 0)) {
            a = mid;
            ta = tm;
        } else {
            b = mid;
        }
    }
    return 0;
}

/* whether f has a pole where node c of e (a denominator, or a base raised to a negative power)
   changes sign between the probes a and b: its zero bisected to round-off, where f must be
   finite with a slope within ZP_POLE_SLOPE_GROWTH of the probes'; 1 and there in *at if not */
static int pole_at_zero(const zp_model *m, int k, const zp_expr *e, int c, double a, double b,
                        double *at) {
    zp_track ta = zp_course_eval(m->course, k, a), tb = zp_course_eval(m->course, k, b);
    double bound = ZP_POLE_SLOPE_GROWTH * (1 + fmax(fabs(ta.fp), fabs(tb.fp)));
    double va = zp_expr_eval(e, c, a);
    for (int it = 0; it < 80; it++) {
        double mid = 0.5 * (a + b);
        if (!(mid > a && mid < b)) {
            break;
        }
        double vm = zp_expr_eval(e, c, mid);
        if ((va > 0) == (vm > 0)) {
            a = mid;
            va = vm;
        } else {
            b = mid;
        }
    }
    for (int end = 0; end < 2; end++) {
        zp_track tz = zp_course_eval(m->course, k, end ? b : a);
        *at = end ? b : a;
        if (!isfinite(tz.f) || !isfinite(tz.fp) || fabs(tz.fp) > bound) {
            return 1;
        }
    }
    return 0;
}

/* poles the probes of f cannot see: a denominator that vanishes with a residue so small, or
   without changing sign ((x - p)^2), that f and its slope look smooth at every probe. Each
   denominator (the base, when it is a power) and each base raised to a negative power is
   probed itself; where it changes sign there must be no pole. 0 and the x in *bad. */
static int section_no_hidden_pole(const zp_model *m, int k, double *bad) {
    zp_expr e = {0};
    char err[128];
    /* text only libmatheval reads (the compiled course's fallback) keeps the probes' word */
    int ok = 1, parsed = zp_expr_parse(&e, m->expr[k], err, sizeof err) >= 0;
    int n = probe_count(m->xb[k + 1] - m->xb[k]);
    for (int i = 0; parsed && ok && i < e.n; i++) {
        const zp_ex_node *nd = &e.node[i];
        int c = -1;
        if (nd->op == ZP_EX_DIV) {
            c = e.node[nd->b].op == ZP_EX_POW ? e.node[nd->b].a : nd->b;
        } else if (nd->op == ZP_EX_POW && e.node[nd->b].op == ZP_EX_NUM &&
                   e.node[nd->b].value < 0) {
            c = nd->a;
        }
        double prev_x = m->xb[k], prev_v = c >= 0 ? zp_expr_eval(&e, c, prev_x) : 0;
        for (int p = 1; c >= 0 && ok && p <= n; p++) {
            double x = m->xb[k] + (m->xb[k + 1] - m->xb[k]) * p / n;
            double v = zp_expr_eval(&e, c, x);
            if ((v > 0) != (prev_v > 0) && pole_at_zero(m, k, &e, c, prev_x, x, bad)) {
                ok = 0;
            }
            prev_x = x;
            prev_v = v;
        }
    }
    zp_expr_free(&e);
    return ok;
}

/* section k over its range: f and f' finite (an f'' that overflows where f' is finite is the
   derivative expression's overflow, which zp_course_eval replaces by a difference), no jump
   between neighbouring probes that the slopes at both ends do not explain (a pole, where tan
   stays finite in floating point), and no pole where the slope or its rate turns between
   them. 0 and the x that fails in *bad. */
static int section_smooth(const zp_model *m, int k, double *bad) {
    int n = probe_count(m->xb[k + 1] - m->xb[k]);
    double h = (m->xb[k + 1] - m->xb[k]) / n;
    zp_track prev = {0};
    for (int p = 0; p <= n; p++) {
        double x = m->xb[k] + (m->xb[k + 1] - m->xb[k]) * p / n;
        zp_track tr = zp_course_eval(m->course, k, x);
        *bad = x;
        if (!isfinite(tr.f) || !isfinite(tr.fp) || !isfinite(tr.fpp)) {
            return 0;
        }
        double df = tr.f - prev.f, trap = 0.5 * h * (tr.fp + prev.fp);
        if (p > 0 && fabs(df - trap) > 0.5 * (fabs(df) + fabs(trap)) + 1e-9 * (1 + fabs(tr.f))) {
            return 0;
        }
        if (p > 0 && pole_between(m, k, x - h, prev, x, tr, bad)) {
            return 0;
        }
        prev = tr;
    }
    return 1;
}

/* every section's f finite over its range; neighbours meet; slope jumps listed as kinks */
static int check_course(zp_model *m, const zp_scene *sc, zp_diag *d) {
    int ok = 1;
    for (int k = 0; k < m->nsec; k++) {
        double x;
        if (!section_smooth(m, k, &x) || !section_no_hidden_pole(m, k, &x)) {
            zp_diag_add(d, sc->path, sc->sec_line[k], "course", "section",
                        "f(x) = %s is not finite or not continuous near x = %.9g (or its slope "
                        "is not); expected a smooth curve over [%g, %g]",
                        m->expr[k], x, m->xb[k], m->xb[k + 1]);
            ok = 0;
        }
    }
    if (!ok) {
        return 0;
    }
    m->nkink = 0;
    for (int k = 0; k + 1 < m->nsec; k++) {
        double b = m->xb[k + 1];
        zp_track l = zp_course_eval(m->course, k, b), r = zp_course_eval(m->course, k + 1, b);
        if (fabs(l.f - r.f) > 1e-9 * (1 + fabs(l.f))) {
            zp_diag_add(d, sc->path, sc->sec_line[k + 1], "course", "section",
                        "the course is discontinuous at x = %g: section %d ends at y = %.17g, "
                        "section %d starts at y = %.17g (jump %.3g m); expected sections that "
                        "meet within 1e-9 (1 + |y|) m (write `y0` for where the previous ends)",
                        b, k + 1, l.f, k + 2, r.f, r.f - l.f);
            ok = 0;
            continue;
        }
        if (fabs(l.fp - r.fp) > 1e-12 * (1 + fabs(l.fp))) {
            m->kink[m->nkink++] = (zp_kink){k, b, l.f, l.fp, r.fp};
        }
    }
    return ok;
}

double zp_model_angle_used(const zp_model *m, const double *max_rel_angle) {
    double a = 0;
    for (int i = 0; i < m->nlink; i++) {
        a = fmax(a, max_rel_angle[i] + (m->phi_max - m->phi_max_j[i]));
    }
    return a;
}

int zp_model_piece(const zp_model *m, int sec, double x) {
    return m->course_provider ? m->course_provider->piece(m, sec, x) : -1;
}

zp_track zp_model_track_piece(const zp_model *m, const zp_course *course, int sec, int piece,
                              double x) {
    return piece < 0 ? zp_course_eval(course, sec, x)
                     : m->course_provider->on_piece(m, course, sec, piece, x);
}

zp_track zp_model_track(const zp_model *m, const zp_course *course, int sec, double x) {
    return zp_model_track_piece(m, course, sec, zp_model_piece(m, sec, x), x);
}

zp_course *zp_model_course(const zp_model *m, zp_course_err *e) {
    return zp_course_for_thread(m->course, e);
}

zp_model *zp_model_build(const zp_scene *sc, zp_diag *d) {
    zp_model *m = calloc(1, sizeof *m);
    if (!m) {
        zp_diag_add(d, sc->path, 0, NULL, NULL, "out of memory building the model");
        return NULL;
    }
    m->g = sc->gravity;
    m->nsec = sc->nsec;
    m->xb[0] = sc->x_start;
    for (int k = 0; k < sc->nsec; k++) {
        m->xb[k + 1] = sc->x_end[k];
        /* a cable's sections are stretches of x: its path lies under them all, the scene's
           course is a level placeholder the cable's course provider never reads */
        memcpy(m->expr[k], sc->cable ? "0" : sc->expr[k], sc->cable ? 2 : ZP_EXPR_MAX);
    }
    zp_course_err ce;
    const char *exprs[ZP_MAX_SECTIONS];
    for (int k = 0; k < m->nsec; k++) {
        exprs[k] = m->expr[k];
    }
    m->course = zp_course_create(m->nsec, exprs, &ce);
    if (!m->course) {
        /* the line of the failing section's key */
        int k = ce.section;
        int line = (k >= 1 && k <= sc->nsec) ? sc->sec_line[k - 1] : 0;
        zp_diag_add(d, sc->path, line, "course", "section", "%s", ce.what);
        free(m);
        return NULL;
    }

    m->m0 = sc->trolley_mass;
    m->nlink = sc->nlink;
    for (int i = 0; i < m->nlink; i++) {
        m->len[i] = sc->lengths[i];
        m->half[i] = 0.5 * sc->lengths[i];
        m->mass[i] = sc->masses[i];
        m->inertia[i] = sc->masses[i] * sc->lengths[i] * sc->lengths[i] / 12.0;
        m->damp[i] = sc->ndamping == 1 ? sc->damping[0] : sc->damping[i];
    }
    m->phi_max = sc->death_angle * M_PI / 180.0;
    for (int i = 0; i < ZP_MAX_LINKS; i++) {
        m->phi_max_j[i] = sc->death_angles[i] * M_PI / 180.0;
    }
    m->g_links = sc->g_links ? sc->g_links : (1u << sc->nlink) - 1;
    m->scale_links = sc->scale_links ? sc->scale_links : (1u << sc->nlink) - 1;
    m->nenv = sc->nenv;
    memcpy(m->env_g, sc->env_g, sizeof m->env_g);
    memcpy(m->env_s, sc->env_s, sizeof m->env_s);
    int dir = zp_drive_dir_find(sc->direction);
    m->drive = dir < 0 ? ZP_DRIVE_HORIZONTAL : (zp_drive_dir)dir;
    m->drive_response = sc->drive_response;
    m->ndrive = zp_drive_nstate(m->drive_response);
    zp_model_derive(m);

    m->physics = sc->cable || check_course(m, sc, d) ? zp_effect_build(m, sc, d) : -1;
    if (m->physics < 0) {
        zp_model_free(m);
        return NULL;
    }
    m->nwork = zp_effect_nwork(m->physics);
    m->stick =
        (m->physics & ZP_PHYS_ROLLING) || (m->physics & ZP_PHYS_BRAKE && m->brake_friction > 0);
    m->course_provider = zp_effect_course_of(m->physics);
    return m;
}

int zp_model_is_kink(const zp_model *m, int left) {
    for (int i = 0; i < m->nkink; i++) {
        if (m->kink[i].left == left) {
            return 1;
        }
    }
    return 0;
}

void zp_model_free(zp_model *m) {
    if (!m) {
        return;
    }
    zp_course_free(m->course);
    zp_cable_paths_free(m->cable_paths);
    free(m);
}
