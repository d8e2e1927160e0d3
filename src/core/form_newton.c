/* Formulation "newton-euler": the study's maximal coordinates. Every body has its own
 * position: trolley P0 = (X, Y); link i its centre c_i = (x_i, y_i) and angle th_i, with
 * e_i = (sin th, -cos th) down the link, n_i = (cos th, sin th) = de/dth, w_i = th_i'.
 * At each instant the unknowns are the 2 + 3N accelerations, the N joint reactions R_i
 * (force of the parent on link i at joint i, x and y) and the normal force (Nx, Ny): 5N + 4
 * of them (19 for N = 3), found from one linear system (GSL LU):
 *   trolley   m0 a0 = F + (Nx, Ny) - R_1 + m0 g
 *   link i    m_i a_i = R_i - R_{i+1} + m_i g                        (R_{N+1} = 0)
 *             I_i th_i'' = -d_i (c R_i,x + s R_i,y) - (l_i - d_i)(c R_{i+1},x + s R_{i+1},y)
 *                          - c_i w_i + c_{i+1} w_{i+1}   (about c_i; docs/model.md dampers, w_i
 *                          the joint rates, c, s of th_i)
 *   joint i   J_i = (end of the parent: P0, or c_{i-1} + (l_{i-1} - d_{i-1}) e_{i-1})
 *                   - (c_i - d_i e_i) = 0, at acceleration level with e'' = th'' n - th'^2 e
 *   course    K = Y - f(X) = 0:  a0y - f' a0x = f'' X'^2
 *   no friction  Nx + f' Ny = 0 (the normal force has no tangential part)
 * Drift control (Baumgarte): the acceleration-level rows demand J'' = -2 a J' - a^2 J and
 * K'' = -2 a K' - a^2 K instead of 0, so a position or velocity error left by the integrator
 * decays as (1 + a t) exp(-a t) instead of growing with time. On the constraints (J = J' = 0)
 * the equations are the exact ones. Design note: CVODE's projection (CVodeSetProjFn) would
 * keep the constraints to the nonlinear-solver tolerance, but SUNDIALS supports it only with
 * BDF; the default method is Adams, so the stabilization lives in the equations and serves
 * every method. A kink restart goes through from_chain, which puts the state back exactly on
 * the constraints.
 * Optional effects (docs/model.md, effect.h): their force on each body adds to that body's
 * momentum row;
 * rolling resistance replaces the frictionless row by (C.t) = -mu sgn(X') |C.n| for the course
 * force C = (Nx, Ny), t and n the unit tangent and normal, with the sign of C.n taken + and
 * the system solved again with - when that was wrong; held at rest, the row is a0x = 0.
 * State: y = (X, Y, x_1, y_1, th_1, .., X', Y', x_1', .., the model's work integrals). */
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>

#include "formulation.h"

/* 1/s, Baumgarte rate: just above the seed chain's fastest small swing (3.4 rad/s), so the
   constraint error dies within a swing without adding a much faster time scale that the
   integrator would have to follow (50/s cuts the drift 10x but costs 1.5x the steps) */
#define NE_STAB_RATE 5.0

typedef struct newton_work {
    gsl_matrix *A, *lu; /* lu: A's factors where A must be kept (rolling resistance) */
    gsl_vector *b, *z;
    gsl_permutation *perm;
    int forces;   /* 1: effects give forces on the bodies */
    int rolling;  /* 1: rolling resistance */
    int sgn_free; /* sign of det A with the frictionless course row, found on first need: it
                     never vanishes, so it is one sign for every state */
} newton_work;

/* positions per body coordinate: trolley (X, Y), link i (x, y, th) at 2 + 3i */
static int npos(const zp_model *m) { return 2 + 3 * m->nlink; }

static int newton_nstate(const zp_model *m) { return 2 * npos(m) + m->nwork; }

static void newton_free(void *work) {
    newton_work *w = work;
    if (!w) {
        return;
    }
    gsl_matrix_free(w->A);
    gsl_matrix_free(w->lu);
    gsl_vector_free(w->b);
    gsl_vector_free(w->z);
    gsl_permutation_free(w->perm);
    free(w);
}

static void *newton_create(const zp_model *m) {
    newton_work *w = calloc(1, sizeof *w);
    if (!w) {
        return NULL;
    }
    size_t nz = 5 * m->nlink + 4;
    w->A = gsl_matrix_alloc(nz, nz);
    w->lu = gsl_matrix_alloc(nz, nz);
    w->b = gsl_vector_alloc(nz);
    w->z = gsl_vector_alloc(nz);
    w->perm = gsl_permutation_alloc(nz);
    w->forces = zp_effect_with_forces(m->physics) != 0;
    w->rolling = m->stick != 0;
    if (!w->A || !w->lu || !w->b || !w->z || !w->perm) {
        newton_free(w);
        return NULL;
    }
    return w;
}

static void newton_from_chain(const zp_model *m, const zp_chain *c, const double *wk,
                              double *y) {
    int np = npos(m);
    double pos[ZP_MAX_LINKS + 1][2], vel[ZP_MAX_LINKS + 1][2];
    zp_state_com(m, c, pos);
    zp_state_com_vel(m, c, vel);
    for (int b = 0; b <= m->nlink; b++) {
        int k = b ? 2 + 3 * (b - 1) : 0;
        y[k] = pos[b][0];
        y[k + 1] = pos[b][1];
        y[np + k] = vel[b][0];
        y[np + k + 1] = vel[b][1];
        if (b) {
            y[k + 2] = c->q[1 + b];
            y[np + k + 2] = c->v[1 + b];
        }
    }
    for (int k = 0; k < m->nwork; k++) {
        y[2 * np + k] = wk[k];
    }
}

/* the trolley and the angles are chain coordinates already; the centres follow from them */
static void newton_to_chain(const zp_model *m, const zp_track *tr, const double *y,
                            zp_chain *c) {
    int np = npos(m);
    (void)tr;
    c->q[0] = y[0];
    c->q[1] = y[1];
    c->v[0] = y[np];
    c->v[1] = y[np + 1];
    for (int i = 0; i < m->nlink; i++) {
        c->q[2 + i] = y[4 + 3 * i];
        c->v[2 + i] = y[np + 4 + 3 * i];
    }
}

static void newton_relative(const zp_model *m, const double *y, double *phi, double *w) {
    int np = npos(m);
    double th_prev = 0, w_prev = 0; /* the trolley does not rotate */
    for (int i = 0; i < m->nlink; i++) {
        phi[i] = y[4 + 3 * i] - th_prev;
        w[i] = y[np + 4 + 3 * i] - w_prev;
        th_prev = y[4 + 3 * i];
        w_prev = y[np + 4 + 3 * i];
    }
}

/* joint i's gap J_i (m) and its rate J_i' (m/s): the parent's end minus link i's top */
static void joint_gap(const zp_model *m, const double *y, int i, double J[2], double Jd[2]) {
    int np = npos(m), k = 2 + 3 * i;
    double s = sin(y[k + 2]), c = cos(y[k + 2]), d = m->half[i], w = y[np + k + 2];
    double px = y[0], py = y[1], vx = y[np], vy = y[np + 1]; /* the trolley */
    if (i > 0) {
        int p = k - 3;
        double sp = sin(y[p + 2]), cp = cos(y[p + 2]), L = m->len[i - 1] - m->half[i - 1];
        double wp = y[np + p + 2];
        px = y[p] + L * sp;
        py = y[p + 1] - L * cp;
        vx = y[np + p] + L * cp * wp;
        vy = y[np + p + 1] + L * sp * wp;
    }
    J[0] = px - (y[k] - d * s);
    J[1] = py - (y[k + 1] + d * c);
    Jd[0] = vx - (y[np + k] - d * c * w);
    Jd[1] = vy - (y[np + k + 1] - d * s * w);
}

static double newton_residual(const zp_model *m, const zp_track *tr, const double *y) {
    double r = fabs(y[1] - tr->f);
    for (int i = 0; i < m->nlink; i++) {
        double J[2], Jd[2];
        joint_gap(m, y, i, J, Jd);
        r = fmax(r, hypot(J[0], J[1]));
    }
    return r;
}

/* the effects' forces on every body added to its momentum rows, each effect's power into pw */
static void newton_effects(const zp_model *m, const zp_drive_now *dn, const double *y,
                           gsl_vector *b, double *pw) {
    int np = npos(m);
    zp_effect_motion mo;
    zp_effect_place(&mo, dn->zone, dn->hold, dn->slide, y[np], dn->tr.fp);
    mo.nbody = m->nlink + 1;
    mo.x = y[0];
    for (int bd = 0; bd <= m->nlink; bd++) {
        int k = bd ? 2 + 3 * (bd - 1) : 0;
        mo.v[bd][0] = y[np + k];
        mo.v[bd][1] = y[np + k + 1];
    }
    double f[ZP_MAX_LINKS + 1][2];
    zp_effect_forces(m->physics, m, &mo, f, pw);
    for (int bd = 0; bd <= m->nlink; bd++) {
        int k = bd ? 2 + 3 * (bd - 1) : 0;
        gsl_vector_set(b, k, gsl_vector_get(b, k) + f[bd][0]);
        gsl_vector_set(b, k + 1, gsl_vector_get(b, k + 1) + f[bd][1]);
    }
}

/* the course row: frictionless (cf = 0), or the course force's tangential part cf |normal
   part| with the normal part's sign sn, or (hold) the trolley at rest along the course */
static void course_row(gsl_matrix *A, int rn, double fp, double cf, double sn, int hold) {
    for (int j = 0; j < (int)A->size2; j++) {
        gsl_matrix_set(A, rn + 1, j, 0);
    }
    if (hold) {
        gsl_matrix_set(A, rn + 1, 0, 1);
        return;
    }
    gsl_matrix_set(A, rn + 1, rn, 1 + cf * sn * fp);
    gsl_matrix_set(A, rn + 1, rn + 1, fp - cf * sn);
}

/* A z = b, A kept (its LU factors go to lu); the sign of det A in *sgn */
static int newton_solve(newton_work *nw, int *sgn) {
    int sign = 0;
    gsl_matrix_memcpy(nw->lu, nw->A);
    if (gsl_linalg_LU_decomp(nw->lu, nw->perm, &sign) ||
        gsl_linalg_LU_solve(nw->lu, nw->perm, nw->b, nw->z)) {
        return 1;
    }
    *sgn = gsl_linalg_LU_sgndet(nw->lu, sign);
    return 0;
}

/* A z = b with the course row of rolling resistance: against the way it slides (dn->slide,
   else x', from rest against the motion the frictionless system starts), or held. The
   friction changes A by one row, so det A / det A_frictionless is lagrange's 1 - cf nu for the
   normal part's sign tried (+ first), and the choice is friction_terms' (form_lagrange.c): the
   solution that continues the frictionless regime, ZP_RHS_FRICTION_INCONSISTENT where it does
   not exist or has grown past ZP_FRICTION_NORMAL_MAX. 0, or 1 when a solve fails. */
static int newton_friction(const zp_model *m, newton_work *nw, const zp_drive_now *dn,
                           double xd) {
    const int rn = npos(m) + 2 * m->nlink;
    const double fp = dn->tr.fp, *z = gsl_vector_const_ptr(nw->z, 0);
    double dir = dn->slide ? dn->slide : xd;
    int sgn = 0;
    if (dn->hold || dir == 0 || !nw->sgn_free) {
        course_row(nw->A, rn, fp, 0, 1, dn->hold);
        if (newton_solve(nw, &sgn)) {
            return 1;
        }
        if (dn->hold) {
            return 0;
        }
        nw->sgn_free = sgn;
        dir = dir == 0 ? z[0] : dir;
    }
    double cf = -m->mu * ((dir > 0) - (dir < 0));
    course_row(nw->A, rn, fp, cf, 1, 0);
    if (newton_solve(nw, &sgn)) {
        return 1;
    }
    double normal = -fp * z[rn] + z[rn + 1], normal_max = ZP_FRICTION_NORMAL_MAX * m->mtot;
    normal_max *= sqrt(1 + fp * fp); /* normal is |(-f', 1)| times N */
    int gain_below_1 = sgn == nw->sgn_free; /* 1 - cf nu > 0 */
    if (gain_below_1 && normal >= 0) {
        return normal > normal_max ? ZP_RHS_FRICTION_INCONSISTENT : 0; /* n0 >= 0 */
    }
    if (!gain_below_1 && normal <= 0) {
        return ZP_RHS_FRICTION_INCONSISTENT; /* n0 >= 0 with 1 - cf nu <= 0 */
    }
    course_row(nw->A, rn, fp, cf, -1, 0);
    if (newton_solve(nw, &sgn)) {
        return 1;
    }
    normal = -fp * z[rn] + z[rn + 1];
    return normal > 0 || -normal > normal_max ? ZP_RHS_FRICTION_INCONSISTENT : 0;
}

/* link i's rows: its linear and angular momentum (with the dampers of joints i and i + 1) and
   joint i at acceleration level; returns joint i's damper power */
static double link_rows(const zp_model *m, const double *y, int i, gsl_matrix *A, gsl_vector *b) {
    const int n = m->nlink, np = npos(m), rr = np; /* the reaction columns */
    const double a = NE_STAB_RATE;
    int k = 2 + 3 * i, ri = rr + 2 * i, rj = ri + 2; /* link i; R_i, R_{i+1} columns */
    double s = sin(y[k + 2]), c = cos(y[k + 2]), d = m->half[i], lo = m->len[i] - d;
    double w = y[np + k + 2];
    double wj = w - (i ? y[np + k - 1] : 0);
    double wj_below = i + 1 < n ? y[np + k + 5] - w : 0;

    /* linear momentum: m a - R_i + R_{i+1} = m g */
    for (int r = 0; r < 2; r++) {
        gsl_matrix_set(A, k + r, k + r, m->mass[i]);
        gsl_matrix_set(A, k + r, ri + r, -1);
    }
    gsl_vector_set(b, k + 1, -m->mass[i] * m->g);
    /* angular momentum about the centre, with the dampers of joints i and i + 1 */
    gsl_matrix_set(A, k + 2, k + 2, m->inertia[i]);
    gsl_matrix_set(A, k + 2, ri, d * c);
    gsl_matrix_set(A, k + 2, ri + 1, d * s);
    double tau = -m->damp[i] * wj;
    if (i + 1 < n) {
        gsl_matrix_set(A, k, rj, 1);
        gsl_matrix_set(A, k + 1, rj + 1, 1);
        gsl_matrix_set(A, k + 2, rj, lo * c);
        gsl_matrix_set(A, k + 2, rj + 1, lo * s);
        tau += m->damp[i + 1] * wj_below;
    }
    gsl_vector_set(b, k + 2, tau);

    /* joint i: parent end'' - link top'' = -2a J' - a^2 J */
    double J[2], Jd[2];
    joint_gap(m, y, i, J, Jd);
    int p = i ? k - 3 : 0; /* the parent's x column */
    double bx = d * w * w * s - 2 * a * Jd[0] - a * a * J[0];
    double by = -d * w * w * c - 2 * a * Jd[1] - a * a * J[1];
    if (i > 0) {
        double sp = sin(y[p + 2]), cp = cos(y[p + 2]), L = m->len[i - 1] - m->half[i - 1];
        double wp = y[np + p + 2];
        gsl_matrix_set(A, ri, p + 2, L * cp);
        gsl_matrix_set(A, ri + 1, p + 2, L * sp);
        bx += L * wp * wp * sp;
        by -= L * wp * wp * cp;
    }
    gsl_matrix_set(A, ri, p, 1);
    gsl_matrix_set(A, ri + 1, p + 1, 1);
    gsl_matrix_set(A, ri, k, -1);
    gsl_matrix_set(A, ri + 1, k + 1, -1);
    gsl_matrix_set(A, ri, k + 2, d * c);
    gsl_matrix_set(A, ri + 1, k + 2, d * s);
    gsl_vector_set(b, ri, bx);
    gsl_vector_set(b, ri + 1, by);
    return m->damp[i] * wj * wj;
}

/* the system A z = b at state y with the frictionless course row; returns the dampers' power */
static double newton_assemble(const zp_model *m, newton_work *nw, const zp_drive_now *dn,
                              const double *y) {
    const int np = npos(m), rr = np, rn = np + 2 * m->nlink; /* reaction, normal columns */
    const double a = NE_STAB_RATE, fp = dn->tr.fp;
    gsl_matrix *A = nw->A;
    gsl_vector *b = nw->b;
    gsl_matrix_set_zero(A);
    gsl_vector_set_zero(b);

    /* trolley: m0 a0 - N + R_1 = F + m0 g */
    for (int r = 0; r < 2; r++) {
        gsl_matrix_set(A, r, r, m->m0);
        gsl_matrix_set(A, r, rn + r, -1);
        gsl_matrix_set(A, r, rr + r, 1);
    }
    gsl_vector_set(b, 0, dn->fx);
    gsl_vector_set(b, 1, dn->fy - m->m0 * m->g);

    double pdamp = 0;
    for (int i = 0; i < m->nlink; i++) {
        pdamp += link_rows(m, y, i, A, b);
    }

    /* course: a0y - f' a0x = f'' X'^2 - 2a K' - a^2 K; frictionless: Nx + f' Ny = 0 */
    double xd = y[np], K = y[1] - dn->tr.f, Kd = y[np + 1] - fp * xd;
    gsl_matrix_set(A, rn, 0, -fp);
    gsl_matrix_set(A, rn, 1, 1);
    gsl_vector_set(b, rn, dn->tr.fpp * xd * xd - 2 * a * Kd - a * a * K);
    gsl_matrix_set(A, rn + 1, rn, 1);
    gsl_matrix_set(A, rn + 1, rn + 1, fp);
    return pdamp;
}

/* the rates from the solution z (1 on a non-finite acceleration): the work integrals (the
   effects' powers pw with work, friction's from the course force), the loads when asked for */
static int newton_store(const zp_model *m, const zp_drive_now *dn, int work, const double *y,
                        const double *z, double pdamp, double *pw, double *ydot,
                        zp_loads *loads) {
    const int n = m->nlink, np = npos(m), rr = np, rn = np + 2 * n; /* reaction, normal cols */
    const double fp = dn->tr.fp, xd = y[np];
    for (int j = 0; j < np; j++) {
        if (!isfinite(z[j])) {
            return 1;
        }
        ydot[j] = y[np + j];
        ydot[np + j] = z[j];
    }
    ydot[2 * np + ZP_W_DRIVE] = dn->fx * xd + dn->fy * y[np + 1];
    ydot[2 * np + ZP_W_DAMP] = pdamp;
    if (work) {
        /* friction's power is the course force's tangential part's (0 to round-off without it) */
        double sq = sqrt(1 + fp * fp), ft = (z[rn] + fp * z[rn + 1]) / sq; /* tangential */
        pw[ZP_EFFECT_W_FRICTION] = -ft * (xd + fp * y[np + 1]) / sq;
        for (int k = ZP_W_EFFECTS; k < m->nwork; k++) {
            ydot[2 * np + k] = pw[k - ZP_W_EFFECTS];
        }
    }
    if (loads) {
        loads->hold = (z[rn] + fp * z[rn + 1]) / sqrt(1 + fp * fp);
        loads->normal = (-fp * z[rn] + z[rn + 1]) / sqrt(1 + fp * fp);
        loads->acc[0][0] = z[0];
        loads->acc[0][1] = z[1];
        for (int i = 0; i < n; i++) {
            loads->joint[i][0] = z[rr + 2 * i];
            loads->joint[i][1] = z[rr + 2 * i + 1];
            loads->acc[i + 1][0] = z[2 + 3 * i];
            loads->acc[i + 1][1] = z[3 + 3 * i];
        }
    }
    return 0;
}

/* Design note: one function for every set of effects, tested at run time: unlike lagrange's
   fixed-size path, a copy per kind of effect gains nothing against the LU solve */
static int newton_rhs(const zp_model *m, void *work, const zp_drive_now *dn, const double *y,
                      double *ydot, zp_loads *loads) {
    newton_work *nw = work;
    double pdamp = newton_assemble(m, nw, dn, y), pw[ZP_EFFECT_NWORK] = {0};
    if (nw->forces) {
        newton_effects(m, dn, y, nw->b, pw);
    }
    int sign = 0;
    if (nw->rolling) {
        int rc = newton_friction(m, nw, dn, y[npos(m)]);
        if (rc) {
            return rc;
        }
    } else if (gsl_linalg_LU_decomp(nw->A, nw->perm, &sign) ||
               gsl_linalg_LU_solve(nw->A, nw->perm, nw->b, nw->z)) {
        return 1;
    }
    return newton_store(m, dn, m->nwork > ZP_W_EFFECTS, y, gsl_vector_const_ptr(nw->z, 0), pdamp,
                        pw, ydot, loads);
}

const zp_formulation zp_form_newton = {
    .name = "newton-euler",
    .doc = "Newton-Euler in maximal coordinates: accelerations, joint reactions and normal "
           "force from one linear system per step (Baumgarte-stabilized)",
    .nstate = newton_nstate,
    .create = newton_create,
    .free = newton_free,
    .from_chain = newton_from_chain,
    .to_chain = newton_to_chain,
    .relative = newton_relative,
    .rhs = newton_rhs,
    .constraint_residual = newton_residual,
};
