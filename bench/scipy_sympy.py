#!/usr/bin/python3
"""The strong SciPy peer: what a Python user would write today.  The equations of motion are
derived by sympy from the Lagrangian in minimal coordinates q = (x, theta_1..theta_N) (the
course enters as the symbols f, f', f'' at the trolley's x), common subexpressions eliminated
(cse) and lambdified to plain-float code; each right-hand side evaluates the mass matrix and
the generalized forces that way and solves the (N+1)x(N+1) system with numpy.  Events,
impulses and the run loop are scipy_zipline.simulate's (DOP853), so the two peers differ only
in the right-hand side.  selftest(): the derived rhs against the hand-derived one.
"""

import math
import sys

import numpy as np
import sympy as sp

import scipy_zipline as sz


def derive(model):
    """Lambdified (mass matrix, generalized forces) of q'' for the model's chain."""
    n = model.N
    x, F, fp_s, fpp_s = sp.symbols("x F fp fpp")
    th = sp.symbols(f"th0:{n}")
    xd = sp.Symbol("xd")
    thd = sp.symbols(f"thd0:{n}")
    t = sp.Symbol("t")
    # positions as functions of time: the course y = f(x(t)) through a function, its
    # derivatives replaced by the symbols fp, fpp afterwards
    X = sp.Function("X")(t)
    TH = [sp.Function(f"TH{i}")(t) for i in range(n)]
    f = sp.Function("f")
    y0 = f(X)
    px, py = X, y0
    T = sp.Rational(1, 2) * model.m0 * (sp.diff(px, t) ** 2 + sp.diff(py, t) ** 2)
    V = model.g * model.m0 * py
    for i in range(n):
        li, mi, di = float(model.l[i]), float(model.m[i]), float(model.l[i]) / 2
        cx = px + di * sp.sin(TH[i])
        cy = py - di * sp.cos(TH[i])
        T += sp.Rational(1, 2) * mi * (sp.diff(cx, t) ** 2 + sp.diff(cy, t) ** 2)
        T += sp.Rational(1, 2) * (mi * li * li / 12) * sp.diff(TH[i], t) ** 2
        V += model.g * mi * cy
        px, py = px + li * sp.sin(TH[i]), py - li * sp.cos(TH[i])
    qs = [X] + TH
    L = T - V
    # generalized forces: the drive's virtual work and the joint dampers (Rayleigh)
    qd_t = [sp.diff(q, t) for q in qs]
    fp_t = sp.diff(y0, X)
    if model.direction == "tangent":
        Qdrive = F * sp.sqrt(1 + fp_t ** 2)
    else:
        Qdrive = F
    w = [qd_t[1 + i] - (qd_t[i] if i > 0 else 0) for i in range(n)]
    R = sum(sp.Rational(1, 2) * float(model.c[i]) * w[i] ** 2 for i in range(n))
    eqs = []
    for k, q in enumerate(qs):
        e = sp.diff(sp.diff(L, qd_t[k]), t) - sp.diff(L, q) + sp.diff(R, qd_t[k])
        eqs.append(e - (Qdrive if k == 0 else 0))
    # to plain symbols: second derivatives first, then rates, then coordinates
    qdd_s = sp.symbols(f"qdd0:{n + 1}")
    subs = {}
    for k, q in enumerate(qs):
        subs[sp.diff(q, t, 2)] = qdd_s[k]
    for k, q in enumerate(qs):
        subs[sp.diff(q, t)] = ([xd] + list(thd))[k]
    eqs = [e.subs(subs) for e in eqs]
    dsub = {sp.Derivative(f(X), (X, 2)): fpp_s, sp.Derivative(f(X), X): fp_s}
    eqs = [e.subs(dsub).subs({sp.Subs(sp.Derivative(f(x), (x, 2)), x, X): fpp_s,
                              sp.Subs(sp.Derivative(f(x), x), x, X): fp_s}) for e in eqs]
    eqs = [e.subs({X: x, **{TH[i]: th[i] for i in range(n)}}) for e in eqs]
    eqs = [e.subs(f(x), 0) for e in eqs]  # V's constant shift: f itself never acts
    # M qdd = rhs, linear in qdd
    M = sp.Matrix([[sp.diff(e, a) for a in qdd_s] for e in eqs])
    rhs = sp.Matrix([-e.subs({a: 0 for a in qdd_s}) for e in eqs])
    args = (x, th, xd, thd, fp_s, fpp_s, F)
    # one function computing the shared subexpressions (cse) once, on plain floats
    return sp.lambdify(args, (M.tolist(), list(rhs)), modules="math", cse=True)


class SympyModel(sz.Model):
    """scipy_zipline.Model with the sympy-derived right-hand side."""

    def __init__(self, course, **kw):
        super().__init__(course, **kw)
        self._eom = derive(self)

    def rhs(self, t, s, sec, F):
        n = self.N
        x = s[0]
        th = s[1:n + 1]
        xd = s[n + 1]
        thd = s[n + 2:2 * n + 2]
        fp, fpp = sec.fp(x), sec.fpp(x)
        M, r = self._eom(x, th, xd, thd, fp, fpp, F)
        qdd = np.linalg.solve(np.array(M, dtype=float), np.array(r, dtype=float))
        Fx, Fy = self.drive(F, fp)
        return self.rates(s, qdd, Fx, Fy, fp)


def selftest():
    """The derived rhs equals the hand-derived one at random states (independent derivations)."""
    rng = np.random.default_rng(1)
    for direction in ("horizontal", "tangent"):
        hand = sz.Model(sz.seed_course(), direction=direction)
        sym = SympyModel(sz.seed_course(), direction=direction)
        for _ in range(20):
            s = rng.normal(size=2 * hand.N + 4)
            s[0] = rng.uniform(0, 140)
            sec = next(c for c in hand.course if c.a <= s[0] <= c.b)
            a = hand.rhs(0.0, s, sec, 37.0)
            b = sym.rhs(0.0, s, sec, 37.0)
            if not np.allclose(a, b, rtol=1e-10, atol=1e-10):
                print(f"selftest ({direction}): rhs differ by {np.max(np.abs(a - b)):.2e}")
                return 1
    print("selftest: the sympy-derived rhs equals the hand-derived one (horizontal, tangent)")
    return 0


if __name__ == "__main__":
    sys.exit(selftest())
