"""Seed Eqs. 27-28 for the 42-vertex cylinder of Table 1, with the mass and I_yy of
the faceted 20-gon prism (shared by plot.py and stiffness.py)."""
import math

D, LC, RHO, EPS, V = 8e-3, 5.3e-3, 1245.0, 0.85, 0.1
R, n = D / 2, 20
A = Ix = 0.0
for k in range(n):
    p1 = (R * math.cos(2 * math.pi * k / n), R * math.sin(2 * math.pi * k / n))
    p2 = (R * math.cos(2 * math.pi * (k + 1) / n), R * math.sin(2 * math.pi * (k + 1) / n))
    ar = 0.5 * (p1[0] * p2[1] - p1[1] * p2[0])
    A += ar
    Ix += ar / 6 * (p1[1] ** 2 + p2[1] ** 2 + p1[1] * p2[1])
m, Iyy = RHO * A * LC, RHO * (LC * Ix + A * LC ** 3 / 12)


def analytic(th):
    """(omega_y, V_z) after the impact at tilt th (radians)."""
    arm = R * math.cos(th) - LC / 2 * math.sin(th)    # r cos(alpha + theta)
    wy = -m * V * (1 + EPS) * arm / (Iyy + m * arm * arm)    # Eq. 27, about -y
    return wy, EPS * V + wy * arm                          # Eq. 28, z up


def results(path):
    """RESULT lines of an in.impact log: theta -> (omega_y, V_z)."""
    return {float(w[2]): (float(w[4]), float(w[6]))
            for w in (l.split() for l in open(path)) if w and w[0] == "RESULT"}
