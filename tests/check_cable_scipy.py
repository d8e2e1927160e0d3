#!/usr/bin/python3
"""An independent cable ride against `zipopt simulate --json` (docs/model.md "A cable that
sags"): a bare trolley (a link of 1e-9 kg for the body) from rest on a loaded elastic cable,
with its own solution of the equilibrium and its own integration by SciPy.

The equilibrium, written from MODEL.md's elastic catenary ends and nothing of zipopt: the
unknowns z = (H_A, V_A, s_A, H_B) (the horizontal tension on each side, the vertical pull of
anchor A, the unstretched cable on the A side) solve
    dx(H_A, V_A, s_A) = x - x_A,   dx(H_B, V_2, L0 - s_A) = x_B - x,
    dy(H_A, V_A, s_A) + dy(H_B, V_2, L0 - s_A) = y_B - y_A,
    H_A^2 + (V_A - w s_A)^2 = H_B^2 + V_2^2          (one tension magnitude at the trolley)
with V_2 = V_A - w s_A - W (the vertical tension drops by the load W across the trolley), by
Newton from the straight-sided (ellipse) guess. f(x) = y_A + dy of the A side; f' by implicit
differentiation, z' = -F_z^-1 F_x, with F_z by the complex step (exact to round-off); f'' a
central difference of that exact f' (its error ~1e-9 relative moves the finish by far less
than the tolerance). The cable's own potential Pi_c (its weight's and its strain energy, in
closed form per segment) is differentiated along the solution by the complex step too, so
the force -dPi_c/dx is not zipopt's identity (H_A - H_B) - W f' but checked against it.

The trolley: L = 1/2 M (1 + f'^2) v^2 - (W f + Pi_c), W = g M, so
    M (1 + f'^2) a + M f' f'' v^2 = -(W f' + dPi_c/dx),
integrated by solve_ivp (DOP853, rtol 1e-12) to x_end (an event). Two lines, the realistic one
of config/zipline.ini's kind and a short steep one: finish time within 1e-6 s, both finish.

usage: check_cable_scipy.py ZIPOPT_EXE SOURCE_DIR   (Debian's python3 with python3-scipy)"""
import cmath
import json
import math
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
    from scipy.integrate import solve_ivp
    from scipy.optimize import fsolve
except ImportError:  # the check needs SciPy: skipped (ctest's SKIP_RETURN_CODE), not passed
    print("check_cable_scipy: SciPy is not installed (python3-scipy): skipped")
    sys.exit(77)

from checklib import check, done

G = 9.81
TOL_T = 1e-6  # s


def segment(h, v, s, w, c, sqrt, asinh):
    """MODEL.md's ends of an elastic catenary (start pulled up by v), and its potential
    energy relative to its start's height: (dx, dy, weight energy, strain energy)."""
    t0, t1 = v / h, (v - w * s) / h
    r0, r1 = sqrt(1 + t0 * t0), sqrt(1 + t1 * t1)
    if w == 0:  # the straight segment, w -> 0
        dx = h * s * c + s * h / sqrt(h * h + v * v)
        dy = -(v * s * c + s * v / sqrt(h * h + v * v))
        return dx, dy, 0, c / 2 * (h * h + v * v) * s
    dx = h * s * c + (h / w) * (asinh(t0) - asinh(t1))
    dy = -(w * s * (v / w - s / 2) * c + (h / w) * (r0 - r1))
    # w * integral of the height along the unstretched length: the elastic part and the
    # catenary part, integral of sqrt(1 + t^2) in closed form
    elastic = -c * (v * s * s / 2 - w * s ** 3 / 6)
    prim = lambda t, r: (t * r + asinh(t)) / 2
    cat = -(h / w) * (s * r0 - (h / w) * (prim(t0, r0) - prim(t1, r1)))
    weight = w * (elastic + cat)
    strain = c / 2 * (h * h * s + (v ** 3 - (v - w * s) ** 3) / (3 * w))
    return dx, dy, weight, strain


class Line:
    def __init__(self, a, b, length, weight, ea, load):
        self.xa, self.ya = a
        self.xb, self.yb = b
        self.L0, self.w, self.c, self.W = length, weight, 1.0 / ea, load
        self.z = None

    def parts(self, z, x, cplx=False):
        sqrt, asinh = (cmath.sqrt, cmath.asinh) if cplx else (math.sqrt, math.asinh)
        ha, va, sa, hb = z
        v2 = va - self.w * sa - self.W
        dxa, dya, wa, ea = segment(ha, va, sa, self.w, self.c, sqrt, asinh)
        dxb, dyb, wb, eb = segment(hb, v2, self.L0 - sa, self.w, self.c, sqrt, asinh)
        res = [dxa - (x - self.xa), dxb - (self.xb - x), dya + dyb - (self.yb - self.ya),
               ha * ha + (va - self.w * sa) ** 2 - hb * hb - v2 * v2]
        # Pi_c: each segment's weight energy from its start's height, and the strain
        pi = (wa + self.w * sa * self.ya + ea + wb +
              self.w * (self.L0 - sa) * (self.ya + dya) + eb)
        return res, self.ya + dya, pi

    def jac(self, z, x):
        """F_z, F_x and the gradients of f and Pi_c in z, by the complex step"""
        hstep = 1e-30
        fz, fy, fp = np.zeros((4, 4)), np.zeros(4), np.zeros(4)
        for j in range(4):
            zc = [complex(v) for v in z]
            zc[j] += 1j * hstep * max(1.0, abs(z[j]))
            r, y, pi = self.parts(zc, complex(x), cplx=True)
            scale = hstep * max(1.0, abs(z[j]))
            fz[:, j] = [ri.imag / scale for ri in r]
            fy[j] = y.imag / scale
            fp[j] = pi.imag / scale
        fx = np.array([-1.0, 1.0, 0.0, 0.0])
        return fz, fx, fy, fp

    def guess(self, x):
        """the weightless inextensible line's point (the ellipse) and its tension"""
        lo, hi = -1e4, self.ya + (self.yb - self.ya) * (x - self.xa) / (self.xb - self.xa)
        for _ in range(200):
            y = 0.5 * (lo + hi)
            if math.hypot(x - self.xa, y - self.ya) + math.hypot(self.xb - x, self.yb - y) > \
                    self.L0:
                lo = y
            else:
                hi = y
        ra, rb = math.hypot(x - self.xa, y - self.ya), math.hypot(self.xb - x, self.yb - y)
        sin_a, sin_b = (self.ya - y) / ra, (self.yb - y) / rb
        t = (self.W + self.w * self.L0) / max(sin_a + sin_b, 1e-3)
        ha = t * (x - self.xa) / ra
        return [ha, t * sin_a + self.w * ra, ra / (ra + rb) * self.L0, ha]

    def newton(self, z, x):
        for _ in range(60):
            r, _, _ = self.parts(z, x)
            fz, _, _, _ = self.jac(z, x)
            dz = np.linalg.solve(fz, -np.array(r))
            z = [zi + di for zi, di in zip(z, dz)]
            if max(abs(d) / max(1.0, abs(zi)) for d, zi in zip(dz, z)) < 1e-15:
                break
        return z

    def solve(self, x):
        if self.z is None:
            # the first: Powell's hybrid method at mid-span from the ellipse's guess, then
            # Newton in small steps of x to the one asked (continuation)
            xm = 0.5 * (self.xa + self.xb)
            z = list(fsolve(lambda z: self.parts(z, xm)[0], self.guess(xm), xtol=1e-13))
            for k in range(1, 101):
                z = self.newton(z, xm + (x - xm) * k / 100)
        else:
            z = self.newton(list(self.z), x)
        r, _, _ = self.parts(z, x)
        if max(abs(v) for v in r) > 1e-6:
            raise RuntimeError("no equilibrium at x = %g: residual %s" % (x, r))
        self.z = z
        return z

    def at(self, x):
        """f, f', the cable's potential Pi_c and dPi_c/dx, H_A - H_B at x"""
        z = self.solve(x)
        _, f, pi = self.parts(z, x)
        fz, fx, fy, fp = self.jac(z, x)
        dz = np.linalg.solve(fz, -fx)
        return f, float(fy @ dz), pi, float(fp @ dz), z[0] - z[3]

    def track(self, x, h=1e-3):
        f, fp, pi, dpi, dh = self.at(x)
        fpp = (self.at(x + h)[1] - self.at(x - h)[1]) / (2 * h)
        self.at(x)  # the Newton start back where the ride is
        return f, fp, fpp, dpi, dh


def ride(line, mass, x0, x1, t_max):
    worst = [0.0]

    def rhs(t, s):
        x, v = s
        f, fp, fpp, dpi, dh = line.track(x)
        # the identity MODEL.md states, dPi_c/dx = (H_A - H_B) - W f', held here on the side
        worst[0] = max(worst[0], abs(dpi - (dh - line.W * fp)) / line.W)
        a = (-(line.W * fp + dpi) - mass * fp * fpp * v * v) / (mass * (1 + fp * fp))
        return [v, a]

    end = lambda t, s: s[0] - x1
    end.terminal, end.direction = True, 1
    sol = solve_ivp(rhs, (0, t_max), [x0, 0.0], method="DOP853", rtol=1e-12, atol=1e-12,
                    events=end)
    finished = sol.status == 1 and len(sol.t_events[0]) == 1
    return finished, (sol.t_events[0][0] if finished else sol.t[-1]), worst[0]


LINES = [
    # name, anchors, L0, w, EA, trolley mass, x_start, sections
    ("realistic", (0, 40), (350, 5), 351.2, 5.7, 7.5e6, 85.0, 3.5, "120, 240, 340"),
    ("short steep", (0, 12), (80, 2), 80.8, 3.0, 3e6, 70.0, 1.5, "30, 55, 76"),
]

exe = sys.argv[1]
with tempfile.TemporaryDirectory() as tmp:
    for name, a, b, L0, w, ea, m0, x0, secs in LINES:
        path = os.path.join(tmp, "line.ini")
        with open(path, "w") as f:
            f.write("[cable]\nstart = %g, %g\nend = %g, %g\nlength = %.17g\nweight = %g\n"
                    "ea = %g\nx_start = %g\nsections = %s\n[trolley]\nmass = %g\n[body]\n"
                    "lengths = 0.5\nmasses = 1e-9\n[solver]\nmethod = gsl-rk8pd\nrtol = 1e-12\n"
                    "atol = 1e-13\nt_max = 200\n"
                    % (a[0], a[1], b[0], b[1], L0, w, ea, x0, secs, m0))
        p = subprocess.run([exe, "simulate", path, "--json", "--out", os.path.join(tmp, "o")],
                           capture_output=True, text=True)
        if not check(p.returncode == 0, "%s: simulate exit %d: %s" % (name, p.returncode,
                                                                    p.stderr[-300:])):
            continue
        d = json.loads(p.stdout)
        mass = m0 + 1e-9
        line = Line(a, b, L0, w, ea, G * mass)
        x1 = float(secs.split(",")[-1])
        finished, t, worst = ride(line, mass, x0, x1, 200)
        print("%s: zipopt %s %.12f s, SciPy %s %.12f s (%.1e s apart); dPi_c/dx against "
              "(H_A - H_B) - W f': %.1e of W" % (name, d["outcome"], d["time"],
                                                "finished" if finished else "not finished", t,
                                                abs(d["time"] - t), worst))
        check(finished and d["outcome"] == "finished", "%s: both finish" % name)
        check(abs(d["time"] - t) <= TOL_T, "%s: finish %.12f s, SciPy %.12f s" % (name,
                                                                                d["time"], t))
        check(worst < 1e-9, "%s: the cable's force identity off by %g of W" % (name, worst))
        # the lowest point: at x_end where the path still falls there
        f_end, fp_end = line.at(x1)[:2]
        low = d["cable"]["lowest_y"]
        check(low <= f_end + 1e-9 and (fp_end > 0 or abs(low - f_end) <= 1e-8),
              "%s: lowest_y %.12g, the path at x_end %.12g (slope %g)" % (name, low, f_end,
                                                                          fp_end))
done("check_cable_scipy")
