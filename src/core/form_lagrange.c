/* Formulation "lagrange": minimal coordinates q = (x, theta_1..N) with y = f(x) substituted.
 *
 * Body points (docs/model.md): trolley P0 = (x, f); link i's centre c_i = P0 + sum_{j<i} l_j e_j
 * + d_i e_i with e = (sin th, -cos th), n = de/dth = (cos th, sin th). With
 *   B_j  = m_j d_j + l_j sum_{i>j} m_i                          (kg m)
 *   C_jk = l_j B_k (j < k),  C_jj = m_j d_j^2 + I_j + l_j^2 sum_{i>j} m_i   (kg m^2)
 * the kinetic energy T = 1/2 q'^T M q' has
 *   M_xx = m_tot (1 + f'^2),  M_x,j = B_j (cos th_j + f' sin th_j),  M_jk = C_jk cos(th_j - th_k),
 * and Lagrange's equations M q'' = R, with R = Q - (velocity terms), are
 *   R_x = -m_tot f' f'' x'^2 + sum_k B_k (sin th_k - f' cos th_k) th_k'^2 - m_tot g f'
 *         + F . (1, f')
 *   R_j = -B_j sin th_j f'' x'^2 + sum_k C_jk sin(th_k - th_j) th_k'^2 - g B_j sin th_j
 *         - c_j w_j + c_{j+1} w_{j+1}
 * (w_j = th_j' - th_{j-1}' the joint rates; F the drive force vector). M is symmetric
 * positive definite: Cholesky. Loads come from the accelerations: the normal force from
 * the whole system's momentum balance, the joint reactions from each link's, bottom up.
 * Optional effects (docs/model.md, effect.h): their forces F_b at each centre of mass add the
 * generalized forces J^T F,
 *   Q_x = sum_b F_b . (1, f'),  Q_j = n_j . (d_j F_j + l_j sum_{i>j} F_i);
 * rolling resistance -mu |N| sgn(s') along the tangent adds Q_x = -mu |N| sgn(x') |(1, f')| in
 * the x row only, and N is affine in q'': with u = M^-1 e_x, q'' = q''_0 + Q_x u and
 * N = N_0 + Q_x N_u, solved for |N| in closed form (N_u = sum_j B_j (s_j - f' c_j) u_j / |.|).
 * State: y = (x, th_1..N, x', th_1'..N', the model's work integrals).
 *
 * Design note: the simulations take the fixed-size path (fast_rhs: arrays on the stack,
 * unrolled per N, the velocity sums of R in O(N) from C_jk = l_j B_k (j < k), a Cholesky of
 * M's lower triangle written out); the general path (GSL matrices and Cholesky) stays as
 * zp_form_lagrange_general, the reference the tests hold the fast one to. */
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>

#include "formulation.h"

typedef int (*fast_fn)(const zp_model *, const zp_drive_now *, const double *, double *,
                       zp_loads *);

typedef struct lagrange_work {
    gsl_matrix *M;
    gsl_vector *R, *acc, *u;
    fast_fn fast; /* the fixed-size equations for this model's N and kinds of effects */
} lagrange_work;

/* the forces on the system besides gravity and the course, in one evaluation */
typedef struct lagrange_forces {
    double f[2];                    /* N, their sum: the drive's and the effects' */
    double fd[ZP_MAX_LINKS + 1][2]; /* N, the effects' on each body (where some give forces) */
    double pw[ZP_EFFECT_NWORK];     /* W, the power each effect takes out */
    double hold;                    /* N, with dn->hold the force that keeps the trolley still */
} lagrange_forces;

static int lagrange_nstate(const zp_model *m) {
    return 2 * (m->nlink + 1) + m->nwork;
}

static void lagrange_free(void *work) {
    lagrange_work *w = work;
    if (!w) {
        return;
    }
    gsl_matrix_free(w->M);
    gsl_vector_free(w->R);
    gsl_vector_free(w->acc);
    gsl_vector_free(w->u);
    free(w);
}

static fast_fn fast_for(const zp_model *m);

static void *lagrange_create(const zp_model *m) {
    lagrange_work *w = calloc(1, sizeof *w);
    if (!w) {
        return NULL;
    }
    int nq = m->nlink + 1;
    w->M = gsl_matrix_alloc(nq, nq);
    w->R = gsl_vector_alloc(nq);
    w->acc = gsl_vector_alloc(nq);
    w->u = gsl_vector_alloc(nq);
    w->fast = fast_for(m);
    if (!w->M || !w->R || !w->acc || !w->u) {
        lagrange_free(w);
        return NULL;
    }
    return w;
}

static void lagrange_from_chain(const zp_model *m, const zp_chain *c, const double *wk,
                                double *y) {
    int nq = m->nlink + 1;
    y[0] = c->q[0];
    y[nq] = c->v[0];
    for (int i = 0; i < m->nlink; i++) {
        y[1 + i] = c->q[2 + i];
        y[nq + 1 + i] = c->v[2 + i];
    }
    for (int k = 0; k < m->nwork; k++) {
        y[2 * nq + k] = wk[k];
    }
}

static void lagrange_to_chain(const zp_model *m, const zp_track *tr, const double *y, zp_chain *c) {
    int nq = m->nlink + 1;
    c->q[0] = y[0];
    c->q[1] = tr->f;
    c->v[0] = y[nq];
    c->v[1] = tr->fp * y[nq];
    for (int i = 0; i < m->nlink; i++) {
        c->q[2 + i] = y[1 + i];
        c->v[2 + i] = y[nq + 1 + i];
    }
}

static void lagrange_relative(const zp_model *m, const double *y, double *phi, double *w) {
    int nq = m->nlink + 1;
    double th_prev = 0, w_prev = 0;
    for (int i = 0; i < m->nlink; i++) {
        phi[i] = y[1 + i] - th_prev;
        w[i] = y[nq + 1 + i] - w_prev;
        th_prev = y[1 + i];
        w_prev = y[nq + 1 + i];
    }
}

/* centre-of-mass accelerations, joint reactions and normal force from q''; fx, fy the force on
   the system other than gravity and the course, fd NULL or the effects' force on each body;
   sn, cs the sines and cosines of the angles, which the equations computed already */
static void lagrange_loads(const zp_model *m, const zp_drive_now *dn, double fx, double fy,
                           double (*fd)[2], const double *y, const double *qdd, const double *sn,
                           const double *cs, zp_loads *ld) {
    int n = m->nlink, nq = n + 1;
    double xd = y[nq], fp = dn->tr.fp;
    double ax = qdd[0], ay = fp * qdd[0] + dn->tr.fpp * xd * xd; /* joint above the link */
    ld->acc[0][0] = ax;
    ld->acc[0][1] = ay;
    double sx = m->m0 * ax, sy = m->m0 * (ay + m->g); /* sum of m (a - g) */
    for (int i = 0; i < n; i++) {
        double w = y[nq + 1 + i], s = sn[i], c = cs[i];
        double tx = c * qdd[1 + i] - s * w * w, ty = s * qdd[1 + i] + c * w * w;
        ld->acc[i + 1][0] = ax + m->half[i] * tx;
        ld->acc[i + 1][1] = ay + m->half[i] * ty;
        ax += m->len[i] * tx;
        ay += m->len[i] * ty;
        sx += m->mass[i] * ld->acc[i + 1][0];
        sy += m->mass[i] * (ld->acc[i + 1][1] + m->g);
    }
    /* momentum of the whole system: sum m (a - g) = F + N n, n = (-f', 1)/|.| */
    ld->normal = ((sx - fx) * -fp + (sy - fy)) / sqrt(1 + fp * fp);
    /* link i: m_i (a_i - g) = R_i - R_{i+1}, with R the force of the parent on the child */
    double rx = 0, ry = 0;
    for (int i = n - 1; i >= 0; i--) {
        rx += m->mass[i] * ld->acc[i + 1][0];
        ry += m->mass[i] * (ld->acc[i + 1][1] + m->g);
        if (fd) {
            rx -= fd[i + 1][0];
            ry -= fd[i + 1][1];
        }
        ld->joint[i][0] = rx;
        ld->joint[i][1] = ry;
    }
}

/* ef with the drive's force alone, every effect's power 0 */
static inline void forces_start(lagrange_forces *ef, const zp_drive_now *dn) {
    ef->f[0] = dn->fx;
    ef->f[1] = dn->fy;
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        ef->pw[k] = 0;
    }
    ef->hold = 0;
}

/* the effects' forces on every body from the trolley's x and the bodies' velocities (thd the
   angle rates): each
   body's in ef->fd, their sum added to ef->f, each effect's power in ef->pw, and their
   generalized forces J^T f in Q (x, then each angle) */
static inline void effect_terms(const zp_model *m, const zp_drive_now *dn, double x, double xd,
                                const double *s, const double *c, const double *thd, int n,
                                lagrange_forces *ef, double *Q) {
    double fp = dn->tr.fp;
    zp_effect_motion mo;
    zp_effect_place(&mo, dn->zone, dn->hold, dn->slide, xd, fp);
    mo.nbody = n + 1;
    mo.x = x;
    double px = xd, py = fp * xd; /* velocity of the joint above the current link */
    mo.v[0][0] = px;
    mo.v[0][1] = py;
    for (int i = 0; i < n; i++) {
        mo.v[1 + i][0] = px + m->half[i] * c[i] * thd[i];
        mo.v[1 + i][1] = py + m->half[i] * s[i] * thd[i];
        px += m->len[i] * c[i] * thd[i];
        py += m->len[i] * s[i] * thd[i];
    }
    zp_effect_forces(m->physics, m, &mo, ef->fd, ef->pw);
    double (*fd)[2] = ef->fd, sx = 0, sy = 0; /* the forces on the links below link j */
    for (int j = n - 1; j >= 0; j--) {
        Q[1 + j] = c[j] * (m->half[j] * fd[j + 1][0] + m->len[j] * sx) +
                   s[j] * (m->half[j] * fd[j + 1][1] + m->len[j] * sy);
        sx += fd[j + 1][0];
        sy += fd[j + 1][1];
    }
    double ftot[2] = {sx + fd[0][0], sy + fd[0][1]};
    Q[0] = ftot[0] + fp * ftot[1];
    ef->f[0] += ftot[0];
    ef->f[1] += ftot[1];
}

/* 1 when every effect's power is finite */
static inline int powers_finite(const double *pw) {
    for (int k = 0; k < ZP_EFFECT_NWORK; k++) {
        if (!isfinite(pw[k])) {
            return 0;
        }
    }
    return 1;
}

/* rolling resistance: its generalized force (x row only) along u = M^-1 e_x added to qdd,
   with N affine in it; with dn->hold the force that keeps x'' = 0 instead, its tangential
   value in *hold. fx, fy: the force on the system other than gravity, course and friction.
   The power the friction takes out in *pout. Sliding, N = n0 + cf |N| nu has one solution
   while mu |(1, f')| |nu| < 1; past that (Painleve) either none, which returns
   ZP_RHS_FRICTION_INCONSISTENT, or two, of which the one continuing the regular regime is
   taken (the other appears from infinity). 0 otherwise. */
static inline int friction_terms(const zp_model *m, const zp_drive_now *dn, double xd, double fx,
                                 double fy, const double *s, const double *c, const double *wd2,
                                 int n, const double *u, double *qdd, double *hold, double *pout) {
    double fp = dn->tr.fp, sq = sqrt(1 + fp * fp);
    double sx = m->mtot * qdd[0], sy = m->mtot * (fp * qdd[0] + dn->tr.fpp * xd * xd), nu = 0;
    for (int j = 0; j < n; j++) {
        sx += m->B[j] * (c[j] * qdd[1 + j] - s[j] * wd2[j]);
        sy += m->B[j] * (s[j] * qdd[1 + j] + c[j] * wd2[j]);
        nu += m->B[j] * (s[j] - fp * c[j]) * u[1 + j];
    }
    double n0 = (-fp * (sx - fx) + (sy + m->mtot * m->g - fy)) / sq, q;
    nu /= sq;
    if (dn->hold) {
        q = -qdd[0] / u[0];
        *hold = q / sq;
    } else {
        /* the way the simulator keeps, else x's sign; from rest against the motion it starts */
        double dir = dn->slide ? dn->slide : xd != 0 ? xd : qdd[0];
        double cf = -m->mu * ((dir > 0) - (dir < 0)) * sq;
        /* N >= 0 needs 1 - cf nu > 0, N < 0 needs 1 + cf nu > 0: the one solution of the
           regular regime, which continues into Painleve's where the other sign appears too */
        double den = n0 >= 0 ? 1 - cf * nu : 1 + cf * nu, N = n0 / den;
        if (!(den > 0) || fabs(N) > ZP_FRICTION_NORMAL_MAX * m->mtot) {
            return ZP_RHS_FRICTION_INCONSISTENT;
        }
        q = cf * fabs(N);
    }
    for (int i = 0; i <= n; i++) {
        qdd[i] += q * u[i];
    }
    *pout = -q * xd;
    return 0;
}

/* the rates both paths end with: q' and q'' (1 on a non-finite acceleration), the work
   integrals (power of the drive and dampers, and with work (a constant where inlined) the
   effects' ef->pw), and the loads when asked for (the effects' forces on the bodies where
   forces; s, c: the angles' sines and cosines) */
__attribute__((always_inline)) static inline int
store_rates(const zp_model *m, const zp_drive_now *dn, int work, int forces, const double *y,
            const double *qdd, double xd, double fp, double pdamp, lagrange_forces *ef,
            const double *s, const double *c, double *ydot, zp_loads *loads) {
    int nq = m->nlink + 1;
    for (int i = 0; i < nq; i++) {
        ydot[i] = y[nq + i];
        ydot[nq + i] = qdd[i];
        if (!isfinite(qdd[i])) {
            return 1;
        }
    }
    ydot[2 * nq + ZP_W_DRIVE] = (dn->fx + dn->fy * fp) * xd;
    ydot[2 * nq + ZP_W_DAMP] = pdamp;
    for (int k = ZP_W_EFFECTS; work && k < m->nwork; k++) {
        ydot[2 * nq + k] = ef->pw[k - ZP_W_EFFECTS];
    }
    if (loads) {
        lagrange_loads(m, dn, ef->f[0], ef->f[1], forces ? ef->fd : NULL, y, qdd, s, c, loads);
        loads->hold = ef->hold;
    }
    return 0;
}

static int lagrange_rhs_general(const zp_model *m, void *work, const zp_drive_now *dn,
                                const double *y, double *ydot, zp_loads *loads) {
    lagrange_work *lw = work;
    int n = m->nlink, nq = n + 1;
    double fp = dn->tr.fp, fpp = dn->tr.fpp, xd = y[nq];
    double s[ZP_MAX_LINKS], c[ZP_MAX_LINKS], wd2[ZP_MAX_LINKS], wj[ZP_MAX_LINKS + 1];
    for (int j = 0; j < n; j++) {
        s[j] = sin(y[1 + j]);
        c[j] = cos(y[1 + j]);
        wd2[j] = y[nq + 1 + j] * y[nq + 1 + j];
        wj[j] = y[nq + 1 + j] - (j ? y[nq + j] : 0);
    }
    wj[n] = 0; /* no joint below the last link */

    gsl_matrix *M = lw->M;
    double Rx = -m->mtot * fp * (fpp * xd * xd + m->g) + dn->fx + dn->fy * fp;
    gsl_matrix_set(M, 0, 0, m->mtot * (1 + fp * fp));
    double pdamp = 0;
    for (int j = 0; j < n; j++) {
        gsl_matrix_set(M, 1 + j, 0, m->B[j] * (c[j] + fp * s[j]));
        Rx += m->B[j] * (s[j] - fp * c[j]) * wd2[j];
        double Rj = -m->B[j] * s[j] * (fpp * xd * xd + m->g) - m->damp[j] * wj[j] +
                    (j + 1 < n ? m->damp[j + 1] * wj[j + 1] : 0);
        for (int k = 0; k < n; k++) {
            /* sin(th_k - th_j) and cos(th_j - th_k) from the stored sines and cosines */
            gsl_matrix_set(M, 1 + j, 1 + k, m->C[j][k] * (c[j] * c[k] + s[j] * s[k]));
            Rj += m->C[j][k] * (s[k] * c[j] - c[k] * s[j]) * wd2[k];
        }
        gsl_vector_set(lw->R, 1 + j, Rj);
        pdamp += m->damp[j] * wj[j] * wj[j];
    }
    gsl_vector_set(lw->R, 0, Rx);
    int forces = zp_effect_with_forces(m->physics) != 0, rolling = m->stick;
    lagrange_forces ef;
    forces_start(&ef, dn);
    if (forces) {
        double Q[ZP_MAX_LINKS + 1];
        effect_terms(m, dn, y[0], xd, s, c, y + nq + 1, n, &ef, Q);
        for (int i = 0; i < nq; i++) {
            gsl_vector_set(lw->R, i, gsl_vector_get(lw->R, i) + Q[i]);
        }
    }
    if (!isfinite(Rx) || !isfinite(pdamp) || !powers_finite(ef.pw)) {
        return 1;
    }
    /* only the lower triangle is read by the Cholesky factorization */
    if (gsl_linalg_cholesky_decomp1(M) || gsl_linalg_cholesky_solve(M, lw->R, lw->acc)) {
        return 1;
    }
    double *qdd = gsl_vector_ptr(lw->acc, 0);
    if (rolling) {
        gsl_vector_set_basis(lw->R, 0);
        if (gsl_linalg_cholesky_solve(M, lw->R, lw->u)) {
            return 1;
        }
        int rc = friction_terms(m, dn, xd, ef.f[0], ef.f[1], s, c, wd2, n,
                                gsl_vector_const_ptr(lw->u, 0), qdd, &ef.hold,
                                &ef.pw[ZP_EFFECT_W_FRICTION]);
        if (rc) {
            return rc;
        }
    }
    return store_rates(m, dn, m->nwork > ZP_W_EFFECTS, forces, y, qdd, xd, fp, pdamp, &ef, s, c,
                       ydot, loads);
}

/* M's Cholesky factor in its lower triangle (M SPD of size nq, lower triangle read); 0, or 1
   when M is not positive definite */
static inline int cholesky_factor(double M[ZP_MAX_LINKS + 1][ZP_MAX_LINKS + 1], int nq) {
    for (int j = 0; j < nq; j++) {
        double d = M[j][j];
        for (int k = 0; k < j; k++) {
            d -= M[j][k] * M[j][k];
        }
        if (!(d > 0)) {
            return 1;
        }
        M[j][j] = sqrt(d);
        for (int i = j + 1; i < nq; i++) {
            double v = M[i][j];
            for (int k = 0; k < j; k++) {
                v -= M[i][k] * M[j][k];
            }
            M[i][j] = v / M[j][j];
        }
    }
    return 0;
}

/* M y = R with M's factor from cholesky_factor */
static inline void cholesky_subst(double M[ZP_MAX_LINKS + 1][ZP_MAX_LINKS + 1], const double *R,
                                  double *yout, int nq) {
    for (int i = 0; i < nq; i++) {
        double v = R[i];
        for (int k = 0; k < i; k++) {
            v -= M[i][k] * yout[k];
        }
        yout[i] = v / M[i][i];
    }
    for (int i = nq - 1; i >= 0; i--) {
        double v = yout[i];
        for (int k = i + 1; k < nq; k++) {
            v -= M[k][i] * yout[k];
        }
        yout[i] = v / M[i][i];
    }
}

/* the equations of motion for n links, with forces: effects that give forces on the bodies,
   with rolling: rolling resistance; all three constants where it is inlined (always: a copy
   per (n, forces, rolling) with no test of them left at run time) */
__attribute__((always_inline)) static inline int fast_rhs(const zp_model *m,
                                                         const zp_drive_now *dn, const double *y,
                                                         double *ydot, zp_loads *loads, int n,
                                                         int forces, int rolling) {
    const int nq = n + 1;
    double fp = dn->tr.fp, fpp = dn->tr.fpp, xd = y[nq];
    double s[ZP_MAX_LINKS], c[ZP_MAX_LINKS], wd2[ZP_MAX_LINKS], wj[ZP_MAX_LINKS + 1];
    for (int j = 0; j < n; j++) {
        s[j] = sin(y[1 + j]);
        c[j] = cos(y[1 + j]);
        wd2[j] = y[nq + 1 + j] * y[nq + 1 + j];
        wj[j] = y[nq + 1 + j] - (j ? y[nq + j] : 0);
    }
    wj[n] = 0;
    /* suffix sums over k > j of B_k (s_k, c_k) th_k'^2, prefix sums over k < j of
       l_k (s_k, c_k) th_k'^2: sum_k C_jk sin(th_k - th_j) th_k'^2 in O(N) */
    double ps[ZP_MAX_LINKS + 1], pc[ZP_MAX_LINKS + 1];
    ps[n] = pc[n] = 0;
    for (int k = n - 1; k >= 0; k--) {
        ps[k] = ps[k + 1] + m->B[k] * s[k] * wd2[k];
        pc[k] = pc[k + 1] + m->B[k] * c[k] * wd2[k];
    }
    double M[ZP_MAX_LINKS + 1][ZP_MAX_LINKS + 1], R[ZP_MAX_LINKS + 1], qdd[ZP_MAX_LINKS + 1];
    double acc_n = fpp * xd * xd + m->g; /* normal acceleration terms shared by every row */
    M[0][0] = m->mtot * (1 + fp * fp);
    R[0] = -m->mtot * fp * acc_n + dn->fx + dn->fy * fp;
    double us = 0, uc = 0, pdamp = 0;
    for (int j = 0; j < n; j++) {
        M[1 + j][0] = m->B[j] * (c[j] + fp * s[j]);
        R[0] += m->B[j] * (s[j] - fp * c[j]) * wd2[j];
        for (int k = 0; k <= j; k++) {
            M[1 + j][1 + k] = m->C[j][k] * (c[j] * c[k] + s[j] * s[k]);
        }
        double above = m->B[j] * (c[j] * us - s[j] * uc);
        double below = m->len[j] * (c[j] * ps[j + 1] - s[j] * pc[j + 1]);
        R[1 + j] = -m->B[j] * s[j] * acc_n - m->damp[j] * wj[j] +
                   (j + 1 < n ? m->damp[j + 1] * wj[j + 1] : 0) + above + below;
        us += m->len[j] * s[j] * wd2[j];
        uc += m->len[j] * c[j] * wd2[j];
        pdamp += m->damp[j] * wj[j] * wj[j];
    }
    lagrange_forces ef;
    forces_start(&ef, dn);
    if (forces) {
        double Q[ZP_MAX_LINKS + 1];
        effect_terms(m, dn, y[0], xd, s, c, y + nq + 1, n, &ef, Q);
        for (int i = 0; i < nq; i++) {
            R[i] += Q[i];
        }
    }
    if (!isfinite(R[0]) || !isfinite(pdamp) || (forces && !powers_finite(ef.pw)) ||
        cholesky_factor(M, nq)) {
        return 1;
    }
    cholesky_subst(M, R, qdd, nq);
    if (rolling) {
        double ex[ZP_MAX_LINKS + 1] = {1}, u[ZP_MAX_LINKS + 1];
        cholesky_subst(M, ex, u, nq);
        int rc = friction_terms(m, dn, xd, ef.f[0], ef.f[1], s, c, wd2, n, u, qdd, &ef.hold,
                                &ef.pw[ZP_EFFECT_W_FRICTION]);
        if (rc) {
            return rc;
        }
    }
    /* a conservative force alone (the cable's) has no work integral to store */
    return store_rates(m, dn, (forces || rolling) && m->nwork > ZP_W_EFFECTS, forces, y, qdd, xd,
                       fp, pdamp, &ef, s, c, ydot, loads);
}

#define FAST_RHS_P(N, F, R, NAME)                                                                  \
    static int NAME(const zp_model *m, const zp_drive_now *dn, const double *y, double *ydot,     \
                    zp_loads *loads) {                                                             \
        return fast_rhs(m, dn, y, ydot, loads, N, F, R);                                           \
    }
#define FAST_RHS(N)                                                                                \
    FAST_RHS_P(N, 0, 0, fast_rhs##N)                                                               \
    FAST_RHS_P(N, 1, 0, fast_rhs##N##_forces)                                                      \
    FAST_RHS_P(N, 0, 1, fast_rhs##N##_roll)                                                        \
    FAST_RHS_P(N, 1, 1, fast_rhs##N##_forces_roll)
FAST_RHS(1)
FAST_RHS(2)
FAST_RHS(3)
FAST_RHS(4)
FAST_RHS(5)
FAST_RHS(6)
FAST_RHS(7)
FAST_RHS(8)
#define FAST_ROW(N)                                                                                \
    {fast_rhs##N, fast_rhs##N##_forces, fast_rhs##N##_roll, fast_rhs##N##_forces_roll}

/* the variant with exactly the model's kinds of terms: chosen here once, never tested per
   evaluation. Design note: a copy per kind of effect (forces on the bodies, rolling
   resistance), not per effect, so a new effect with forces needs no copy of its own */
static fast_fn fast_for(const zp_model *m) {
    static const fast_fn by_n[ZP_MAX_LINKS][4] = {FAST_ROW(1), FAST_ROW(2), FAST_ROW(3),
                                                  FAST_ROW(4), FAST_ROW(5), FAST_ROW(6),
                                                  FAST_ROW(7), FAST_ROW(8)};
    int forces = zp_effect_with_forces(m->physics) != 0;
    return by_n[m->nlink - 1][forces + 2 * (m->stick != 0)];
}

static int lagrange_rhs(const zp_model *m, void *work, const zp_drive_now *dn, const double *y,
                        double *ydot, zp_loads *loads) {
    return ((const lagrange_work *)work)->fast(m, dn, y, ydot, loads);
}

const zp_formulation zp_form_lagrange = {
    .name = "lagrange",
    .doc = "Euler-Lagrange in minimal coordinates (x, theta_1..N), y = f(x) substituted",
    .nstate = lagrange_nstate,
    .create = lagrange_create,
    .free = lagrange_free,
    .from_chain = lagrange_from_chain,
    .to_chain = lagrange_to_chain,
    .relative = lagrange_relative,
    .rhs = lagrange_rhs,
    .constraint_residual = NULL,
};

const zp_formulation zp_form_lagrange_general = {
    .name = "lagrange-general",
    .doc = "lagrange with GSL matrices and Cholesky, any N: the reference for the fixed-size path",
    .nstate = lagrange_nstate,
    .create = lagrange_create,
    .free = lagrange_free,
    .from_chain = lagrange_from_chain,
    .to_chain = lagrange_to_chain,
    .relative = lagrange_relative,
    .rhs = lagrange_rhs_general,
    .constraint_residual = NULL,
};
