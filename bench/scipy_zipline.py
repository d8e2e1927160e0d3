#!/usr/bin/python3
"""Independent, straightforward SciPy implementation of the zipline model
(docs/model.md), used as the accuracy reference and the speed
baseline for the C simulator.  Run it with Debian's /usr/bin/python3 (scipy).

Model and derivation
====================
Bodies: a trolley (point mass m0) at P0 = (x, y) on the course y = f(x), and
a chain of N uniform rods hanging from it.  Link i has length l_i, half-length
d_i = l_i/2, mass m_i, inertia I_i = m_i l_i^2/12 about its centre, and
absolute angle theta_i from the downward vertical (counter-clockwise positive):
    e_i = (sin theta_i, -cos theta_i),   n_i = de_i/dtheta_i = (cos theta_i, sin theta_i),
    P_i = P_{i-1} + l_i e_i,             c_i = P_{i-1} + d_i e_i   (centre of mass).

Full coordinates Q = (x, y, theta_1..theta_N) (N + 2 of them).
Velocity of link i's centre:  v_i = (x', y') + sum_{j<i} l_j n_j theta_j' + d_i n_i theta_i'.
Write tail_j = sum_{i>j} m_i (mass hanging below link j) and
    a_j  = m_j d_j + l_j tail_j                      (first moment of the chain below joint j)
    B_jj = I_j + m_j d_j^2 + l_j^2 tail_j
    B_jk = l_min(j,k) a_max(j,k)   (j != k)
The kinetic energy T = 1/2 Q'^T M(theta) Q' with the full mass matrix
    M_xx = M_yy = Mtot = m0 + sum m_i,   M_xy = 0,
    M_x,theta_j = a_j cos theta_j,       M_y,theta_j = a_j sin theta_j,
    M_theta_j,theta_k = B_jk cos(theta_j - theta_k).
Potential energy (y = 0 the zero):
    V = g (Mtot y - sum_j a_j cos theta_j).

Equations of motion in full coordinates (Lagrange, or equivalently virtual
work  sum_i m_i J_i^T a_i + I_i theta_i'' = generalized forces, with
a_i = J_i Q'' + Jdot_i Q' and Jdot_i Q' = -sum_{j<i} l_j e_j theta_j'^2 - d_i e_i theta_i'^2
because dn_j/dt = -e_j theta_j'):
    M Q'' + h(Q, Q') = G + D + C + A^T lambda
with the velocity (centripetal) terms, using n_k . e_j = sin(theta_j - theta_k),
    h_x       = -sum_j a_j sin theta_j theta_j'^2
    h_y       = +sum_j a_j cos theta_j theta_j'^2
    h_theta_k = sum_j B_kj sin(theta_k - theta_j) theta_j'^2,
gravity G = -dV/dQ:  G_x = 0, G_y = -g Mtot, G_theta_j = -g a_j sin theta_j,
drive D = (F_x, F_y, 0..): F (1, 0) horizontal, or F (1, f')/sqrt(1+f'^2) tangent,
dampers C: joint i (relative rate w_i = theta_i' - theta_{i-1}', theta_0' = 0)
    puts -c_i w_i on link i and +c_i w_i on link i-1, so
    C_theta_i = -c_i w_i + c_{i+1} w_{i+1}   (the +c_1 w_1 on the trolley is
    carried by the constraint: the trolley does not rotate),
and the course's normal force A^T lambda, A = (-f'(x), 1, 0..0), i.e. a force
lambda (-f', 1) on the trolley; the reported normal force is lambda sqrt(1+f'^2).

Minimal coordinates q = (x, theta): Q = (x, f(x), theta), so
    Q' = T q',  T = [[1, 0], [f', 0], [0, I_N]],   Q'' = T q'' + (0, f'' x'^2, 0..0).
Multiplying by T^T removes lambda (A T = 0):
    (T^T M T) q'' = T^T (G + D + C - h - M[:, y] f'' x'^2).
This is solved with one numpy.linalg.solve per right-hand side evaluation.
Two extra states integrate the drive work  W_drive' = F_x x' + F_y y'  and the
damper loss  W_damp' = sum_i c_i w_i^2  for the work-energy check
    E(t) - E(0) = W_drive - W_damp - (kinetic energy lost in the kink impulses).

Kinks: at a section boundary b the velocity still obeys the section being left
(y' = f'_left(b) x').  The plastic impulse in full coordinates
    A = (-f'_entered(b), 1, 0..), Lambda = -(A Q'-)/(A M^-1 A^T), Q'+ = Q'- + M^-1 A^T Lambda
puts it on the entered section; then integration restarts in that section.
If the impulse sends the trolley back out of the entered section it is
trapped at the kink (outcome stalled).

Events (terminal, solve_ivp root finding): x reaches the section's right
boundary (direction +1), its left boundary (direction -1), and for each joint
phi_i = theta_i - theta_{i-1} reaching +pi or -pi (death).
"""

import argparse
import json
import math
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

G_DEFAULT = 9.81


class Section:
    """One course section: f, f', f'' on [a, b]."""

    def __init__(self, a, b, f, fp, fpp):
        self.a, self.b = a, b
        self.f, self.fp, self.fpp = f, fp, fpp


def seed_course():
    return [
        Section(0.0, 60.0, lambda x: (x / 10 - 3) ** 2 + 1, lambda x: (x / 10 - 3) / 5, lambda x: 0.02),
        Section(60.0, 100.0, lambda x: -x / 10 + 16, lambda x: -0.1, lambda x: 0.0),
        Section(100.0, 140.0, lambda x: -(x / 10 - 12) ** 2 + 10, lambda x: -(x / 10 - 12) / 5, lambda x: -0.02),
    ]


def smooth_course():
    """A single smooth section (the seed's first parabola extended) for the self-test."""
    return [Section(0.0, 140.0, lambda x: (x / 10 - 3) ** 2 + 1, lambda x: (x / 10 - 3) / 5, lambda x: 0.02)]


class Model:
    def __init__(self, course, m0=30.0, lengths=(5.0, 5.0, 5.0), masses=(15.0, 5.0, 2.0),
                 damping=1.0, g=G_DEFAULT, direction="horizontal", phi_max=math.pi):
        self.course = course
        self.m0 = float(m0)
        self.l = np.array(lengths, dtype=float)
        self.m = np.array(masses, dtype=float)
        self.N = n = len(self.l)
        self.c = np.broadcast_to(np.array(damping, dtype=float), (n,)).copy()
        self.g = g
        self.direction = direction
        self.phi_max = phi_max
        d = self.l / 2
        inertia = self.m * self.l ** 2 / 12
        tail = np.array([self.m[j + 1:].sum() for j in range(n)])
        self.Mtot = self.m0 + self.m.sum()
        self.a = self.m * d + self.l * tail
        B = np.empty((n, n))
        for j in range(n):
            for k in range(n):
                if j == k:
                    B[j, k] = inertia[j] + self.m[j] * d[j] ** 2 + self.l[j] ** 2 * tail[j]
                else:
                    lo, hi = min(j, k), max(j, k)
                    B[j, k] = self.l[lo] * self.a[hi]
        self.B = B

    # --- full-coordinate pieces -------------------------------------------------
    def mass_matrix(self, th):
        n = self.N
        M = np.zeros((n + 2, n + 2))
        M[0, 0] = M[1, 1] = self.Mtot
        M[0, 2:] = M[2:, 0] = self.a * np.cos(th)
        M[1, 2:] = M[2:, 1] = self.a * np.sin(th)
        M[2:, 2:] = self.B * np.cos(th[:, None] - th[None, :])
        return M

    def velocity_terms(self, th, thd):
        n = self.N
        h = np.empty(n + 2)
        w2 = thd ** 2
        h[0] = -np.sum(self.a * np.sin(th) * w2)
        h[1] = np.sum(self.a * np.cos(th) * w2)
        h[2:] = (self.B * np.sin(th[:, None] - th[None, :])) @ w2
        return h

    def joint_rates(self, thd):
        return thd - np.concatenate(([0.0], thd[:-1]))

    def damper_forces(self, thd):
        cw = self.c * self.joint_rates(thd)
        C = -cw
        C[:-1] += cw[1:]
        return C

    def drive(self, F, fp):
        if self.direction == "tangent":
            s = math.sqrt(1 + fp * fp)
            return F / s, F * fp / s
        return F, 0.0

    def energy(self, x, y, th, Qd):
        M = self.mass_matrix(th)
        kin = 0.5 * Qd @ M @ Qd
        pot = self.g * (self.Mtot * y - np.sum(self.a * np.cos(th)))
        return kin + pot

    # --- minimal-coordinate right-hand side --------------------------------------
    def rhs(self, t, s, sec, F):
        n = self.N
        x = s[0]
        th = s[1:n + 1]
        xd = s[n + 1]
        thd = s[n + 2:2 * n + 2]
        fp, fpp = sec.fp(x), sec.fpp(x)
        M = self.mass_matrix(th)
        T = np.zeros((n + 2, n + 1))
        T[0, 0] = 1.0
        T[1, 0] = fp
        T[2:, 1:] = np.eye(n)
        Fx, Fy = self.drive(F, fp)
        Q = np.zeros(n + 2)
        Q[0] = Fx
        Q[1] = Fy - self.g * self.Mtot
        Q[2:] = -self.g * self.a * np.sin(th) + self.damper_forces(thd)
        Q -= self.velocity_terms(th, thd)
        Q -= M[:, 1] * fpp * xd * xd
        qdd = np.linalg.solve(T.T @ M @ T, T.T @ Q)
        return self.rates(s, qdd, Fx, Fy, fp)

    def rates(self, s, qdd, Fx, Fy, fp):
        """The state's rates from the accelerations qdd: positions, velocities, then the drive's
        power and the dampers' as the work integrals."""
        n = self.N
        xd, thd = s[n + 1], s[n + 2:2 * n + 2]
        w = self.joint_rates(thd)
        ds = np.empty_like(s)
        ds[0] = xd
        ds[1:n + 1] = thd
        ds[n + 1:2 * n + 2] = qdd
        ds[2 * n + 2] = Fx * xd + Fy * fp * xd
        ds[2 * n + 3] = np.sum(self.c * w * w)
        return ds

    def full_velocity(self, s, fp):
        n = self.N
        xd = s[n + 1]
        return np.concatenate(([xd, fp * xd], s[n + 2:2 * n + 2]))

    def impulse(self, th, Qd_minus, fp_entered):
        """docs/model.md kink impulse: returns (Qd_plus, Lambda, energy lost)."""
        M = self.mass_matrix(th)
        A = np.zeros(self.N + 2)
        A[0], A[1] = -fp_entered, 1.0
        MinvAT = np.linalg.solve(M, A)
        lam = -(A @ Qd_minus) / (A @ MinvAT)
        Qd_plus = Qd_minus + MinvAT * lam
        lost = 0.5 * Qd_minus @ M @ Qd_minus - 0.5 * Qd_plus @ M @ Qd_plus
        return Qd_plus, lam, lost


def simulate(model, forces, rtol=1e-10, atol=1e-12, t_max=120.0, max_crossings=1000, method="DOP853"):
    """Runs one schedule (one constant force per section) from the docs/model.md start."""
    course = model.course
    n = model.N
    x_start, x_end = course[0].a, course[-1].b
    k = 0
    sec = course[0]
    s = np.zeros(2 * n + 4)
    s[0] = x_start
    e0 = model.energy(x_start, sec.f(x_start), s[1:n + 1], model.full_velocity(s, sec.fp(x_start)))
    t = 0.0
    nrhs = 0
    steps = 0
    kinks = []
    e_impulse = 0.0
    max_phi = np.zeros(n)
    outcome, stall, died_link = None, None, None

    def make_events():
        def right(t, s):
            return s[0] - sec.b
        right.terminal, right.direction = True, 1

        def left(t, s):
            return s[0] - sec.a
        left.terminal, left.direction = True, -1
        evs = [right, left]
        for i in range(n):
            def up(t, s, i=i):
                return s[1 + i] - (s[i] if i > 0 else 0.0) - model.phi_max

            def down(t, s, i=i):
                return s[1 + i] - (s[i] if i > 0 else 0.0) + model.phi_max
            up.terminal, up.direction = True, 1
            down.terminal, down.direction = True, -1
            evs += [up, down]
        return evs

    t_wall = time.perf_counter()
    while True:
        F = forces[k]

        def fun(t, y):
            nonlocal nrhs
            nrhs += 1
            return model.rhs(t, y, sec, F)

        sol = solve_ivp(fun, (t, t_max), s, method=method, rtol=rtol, atol=atol,
                        events=make_events())
        steps += len(sol.t) - 1
        ys = sol.y[:n + 1]
        rel = ys[1:] - np.vstack((np.zeros(ys.shape[1]), ys[1:n]))
        max_phi = np.maximum(max_phi, np.abs(rel).max(axis=1))
        if sol.status == -1:
            raise RuntimeError(f"integration failed at t={sol.t[-1]}: {sol.message}")
        if sol.status == 0:  # reached t_max
            t, s = sol.t[-1], sol.y[:, -1]
            outcome, stall = "stalled", "t_max"
            break
        hit = [j for j, te in enumerate(sol.t_events) if len(te) > 0][0]
        t, s = sol.t_events[hit][0], sol.y_events[hit][0].copy()
        if hit >= 2:  # a joint looped
            outcome, died_link = "died", (hit - 2) // 2 + 1
            break
        going_right = hit == 0
        if going_right and k == len(course) - 1:
            s[0] = x_end
            outcome = "finished"
            break
        if not going_right and k == 0:
            s[0] = x_start
            outcome, stall = "stalled", "rolled_back"
            break
        # a kink: knock the trolley onto the entered section
        b = sec.b if going_right else sec.a
        k_new = k + 1 if going_right else k - 1
        new = course[k_new]
        s[0] = b
        Qd_minus = model.full_velocity(s, sec.fp(b))
        Qd_plus, lam, lost = model.impulse(s[1:n + 1], Qd_minus, new.fp(b))
        s[n + 1] = Qd_plus[0]
        s[n + 2:2 * n + 2] = Qd_plus[2:]
        e_impulse += lost
        kinks.append({"t": t, "x": b, "from": k + 1, "to": k_new + 1, "impulse": lam,
                      "energy_lost": lost, "xdot_before": Qd_minus[0], "xdot_after": Qd_plus[0]})
        k, sec = k_new, new
        if (Qd_plus[0] < 0) if going_right else (Qd_plus[0] > 0):
            outcome, stall = "stalled", "trapped_at_kink"
            break
        if len(kinks) >= max_crossings:
            outcome, stall = "stalled", "trapped_at_kink"
            break
    wall = time.perf_counter() - t_wall

    x = s[0]
    th = s[1:n + 1]
    e1 = model.energy(x, sec.f(x), th, model.full_velocity(s, sec.fp(x)))
    w_drive, w_damp = s[2 * n + 2], s[2 * n + 3]
    return {
        "outcome": outcome, "time": t, "x": x, "died_link": died_link, "stall_reason": stall,
        "kinks": kinks, "max_rel_angle_deg": list(np.degrees(max_phi)),
        "energy": {"initial": e0, "final": e1, "drive_work": w_drive, "damper_work": w_damp,
                   "impulse_loss": e_impulse,
                   "residual": e1 - e0 - w_drive + w_damp + e_impulse},
        "stats": {"steps": steps, "rhs_evals": nrhs, "wall_s": wall},
        "rtol": rtol, "atol": atol,
    }


def fd_lagrange_rhs(model, sec, F, q, qd, h=1e-5):
    """q'' from Lagrange's equations built numerically from the body positions alone
    (complex-step Jacobians, finite-difference dM/dq), as an independent check of the hand-derived rhs."""
    n = model.N
    m_all = np.concatenate(([model.m0], model.m))
    inertia = model.m * model.l ** 2 / 12

    def positions(q):
        x, th = q[0], q[1:]
        p = np.array([x, sec.f(x)])
        out = [p]
        for i in range(n):
            e = np.array([np.sin(th[i]), -np.cos(th[i])])
            out.append(p + model.l[i] / 2 * e)
            p = p + model.l[i] * e
        return np.array(out)  # (n+1, 2): trolley, link centres

    def jac(q):
        J = np.empty((n + 1, 2, n + 1))  # complex step: exact to round-off
        for k in range(n + 1):
            dq = np.zeros(n + 1, dtype=complex)
            dq[k] = 1e-30j
            J[:, :, k] = positions(q + dq).imag / 1e-30
        return J

    def mass(q):
        J = jac(q)
        M = np.einsum("b,bik,bil->kl", m_all, J, J)
        M[1:, 1:] += np.diag(inertia)
        return M

    def potential(q):
        return model.g * np.sum(m_all * positions(q)[:, 1])

    M = mass(q)
    dM = np.empty((n + 1, n + 1, n + 1))
    dV = np.empty(n + 1)
    for k in range(n + 1):
        dq = np.zeros(n + 1)
        dq[k] = h
        dM[k] = (mass(q + dq) - mass(q - dq)) / (2 * h)
        dV[k] = (potential(q + dq) - potential(q - dq)) / (2 * h)
    Mdot = np.einsum("kij,k->ij", dM, qd)
    dTdq = 0.5 * np.einsum("kij,i,j->k", dM, qd, qd)
    J0 = jac(q)[0]
    Fx, Fy = model.drive(F, sec.fp(q[0]))
    Qnc = J0.T @ np.array([Fx, Fy])
    Qnc[1:] += model.damper_forces(qd[1:])
    return np.linalg.solve(M, Qnc - Mdot @ qd + dTdq - dV)


def selftest():
    ok = True
    # 0. The hand-derived rhs against Lagrange's equations built numerically from positions.
    model = Model(seed_course(), direction="tangent")
    rng = np.random.default_rng(1)
    worst = 0.0
    for trial in range(20):
        sec = model.course[trial % 3]
        q = np.concatenate(([rng.uniform(sec.a, sec.b)], rng.uniform(-3, 3, model.N)))
        qd = rng.uniform(-3, 3, model.N + 1)
        F = rng.uniform(-50, 200)
        ds = model.rhs(0.0, np.concatenate((q, qd, [0.0, 0.0])), sec, F)
        ref = fd_lagrange_rhs(model, sec, F, q, qd)
        worst = max(worst, np.max(np.abs(ds[model.N + 1:2 * model.N + 2] - ref)) / (1 + np.max(np.abs(ref))))
    good = worst < 1e-8
    ok &= good
    print(f"rhs vs finite-difference Lagrangian from positions: max rel diff {worst:.1e}  {'ok' if good else 'FAIL'}")
    # 1. F = 0, c = 0 on a smooth single-section course: energy conserved.
    model = Model(smooth_course(), damping=0.0)
    for rtol in (1e-8, 1e-11):
        r = simulate(model, [0.0], rtol=rtol, atol=rtol / 100, t_max=30.0)
        e = r["energy"]
        drift = abs(e["final"] - e["initial"])
        rel = drift / abs(e["initial"])
        good = r["outcome"] == "stalled" and rel < 100 * rtol and e["drive_work"] == 0 and e["damper_work"] == 0
        ok &= good
        print(f"conservative, smooth course, 30 s, rtol {rtol:g}: E0 {e['initial']:.9f} J, "
              f"|dE| {drift:.3e} J (rel {rel:.1e}), x(30) {r['x']:.6f}  {'ok' if good else 'FAIL'}")
    # 2. Work-energy balance on the seed at 10 N (and at 100 N, the seed's own push).
    for F in (10.0, 100.0):
        model = Model(seed_course())
        for rtol in (1e-8, 1e-11):
            r = simulate(model, [F] * 3, rtol=rtol, atol=rtol / 100)
            e = r["energy"]
            scale = e["drive_work"] + e["damper_work"] + abs(e["initial"])
            good = abs(e["residual"]) < 100 * rtol * scale
            ok &= good
            print(f"seed {F:g} N, rtol {rtol:g}: {r['outcome']} t {r['time']:.9f}, "
                  f"W_drive {e['drive_work']:.6f}, W_damp {e['damper_work']:.6f}, "
                  f"impulse loss {e['impulse_loss']:.6f}, residual {e['residual']:.3e} J  "
                  f"{'ok' if good else 'FAIL'}")
    # 3. A kink impulse leaves the velocity on the entered section, and loses energy.
    model = Model(seed_course())
    th = np.array([0.3, -0.2, 0.5])
    Qd = np.array([2.0, 2.0 * 0.6, 0.4, -0.1, 0.7])
    Qp, lam, lost = model.impulse(th, Qd, -0.1)
    good = abs(Qp[1] - (-0.1) * Qp[0]) < 1e-12 and lost >= 0 and lam < 0
    ok &= good
    print(f"impulse: Lambda {lam:.6f} N s, lost {lost:.6f} J, y'+ + 0.1 x'+ = "
          f"{Qp[1] + 0.1 * Qp[0]:.1e}  {'ok' if good else 'FAIL'}")
    # 4. Equal slopes: zero impulse.
    Qp, lam, lost = model.impulse(th, Qd, 0.6)
    good = abs(lam) < 1e-12 and np.allclose(Qp, Qd)
    ok &= good
    print(f"impulse, equal slopes: Lambda {lam:.1e}  {'ok' if good else 'FAIL'}")
    print("selftest", "PASSED" if ok else "FAILED")
    return ok


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--force", default="10,10,10", help="N per section, comma separated")
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--atol", type=float, default=None, help="default rtol/100")
    ap.add_argument("--t-max", type=float, default=120.0)
    ap.add_argument("--damping", type=float, default=1.0)
    ap.add_argument("--direction", default="horizontal", choices=["horizontal", "tangent"])
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--selftest", action="store_true")
    args = ap.parse_args(argv)
    if args.selftest:
        return 0 if selftest() else 1
    forces = [float(v) for v in args.force.split(",")]
    course = seed_course()
    if len(forces) == 1:
        forces *= len(course)
    if len(forces) != len(course):
        ap.error(f"--force needs {len(course)} values")
    atol = args.atol if args.atol is not None else args.rtol / 100
    model = Model(course, damping=args.damping, direction=args.direction)
    r = simulate(model, forces, rtol=args.rtol, atol=atol, t_max=args.t_max)
    if args.json:
        print(json.dumps(r, indent=1))
        return 0
    print(f"outcome {r['outcome']}" + (f" ({r['stall_reason']})" if r["stall_reason"] else "")
          + (f", link {r['died_link']}" if r["died_link"] else ""))
    print(f"time {r['time']:.12f} s   x {r['x']:.9f} m")
    print(f"rhs evals {r['stats']['rhs_evals']}   steps {r['stats']['steps']}   "
          f"wall {r['stats']['wall_s']:.4f} s   (rtol {args.rtol:g}, atol {atol:g})")
    for kk in r["kinks"]:
        print(f"kink x {kk['x']:g} at t {kk['t']:.9f}: {kk['from']}->{kk['to']} "
              f"Lambda {kk['impulse']:.9f} N s, energy lost {kk['energy_lost']:.9f} J, "
              f"x' {kk['xdot_before']:.9f} -> {kk['xdot_after']:.9f}")
    e = r["energy"]
    print("energy: initial {initial:.9f} final {final:.9f} drive {drive_work:.9f} "
          "damper {damper_work:.9f} impulse {impulse_loss:.9f} residual {residual:.3e} J".format(**e))
    print("max |phi| deg: " + ", ".join(f"{v:.4f}" for v in r["max_rel_angle_deg"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
