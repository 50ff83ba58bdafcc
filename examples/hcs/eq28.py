#!/usr/bin/python3
"""Collision rate Gamma0 of a gas of hard prolate ellipsoids, ellipsoid seed Eq. 28:

    Gamma0 = 4 sqrt(pi T / m) n g_c S_c <D>_c

with n the number density (Eq. 28 is written with rho; with the mass density the units do
not work out), T = (2/3) E_tr(0) / N, and
  - g_c: Song-Mason contact value of the pair distribution of hard convex bodies,
    g_c = [1 + 3 e - (2 + 3 e - 3 e^2) eta + (1 + (B4/v0^3 - 12) e - 7 e^2) eta^2]
          / ((1 + 3 e) (1 - eta)^3),
    from their equation of state Z = 1 + B2 n g_c with B2 = v0 (1 + 3 e), the nonsphericity
    e = R S / (3 V) from Eqs. 29a-b, B4/v0^3 = 18.3648 (hard spheres);
  - S_c <D>_c: computed here from its kinetic-theory definition rather than taken from
    Villemot and Talbot's tables (not in the seed). Two bodies touch when their relative
    position lies on the surface of the excluded body A + (-B); the rate at which contacts
    start is the flux through that surface, n g_c < integral dS <v_n>+ >_orientations, with
    v_n the normal velocity of the contact points. For Maxwellian velocities with
    equipartition (T_rot = T_tr = T), v_n is Gaussian with variance T D, D = 2/m +
    (r_A x n).I_A^-1.(r_A x n) + (r_B x n).I_B^-1.(r_B x n) the contact's inverse mass, so
    <v_n>+ = sqrt(T D / (2 pi)) and
        S_c <D>_c = < integral dS sqrt(m D / 2) > / (4 pi)       (sphere: sigma^2).
    The surface element of A + (-B) over the unit normal n is det(H_A(n) + H_B(n)) dOmega,
    H = Hessian of the support function h(n) = sqrt(n.Q n) (Q = R diag(a^2, b^2, b^2) R^T)
    restricted to the plane normal to n; the contact point of A is r_A = Q_A n / h_A(n).
    Averaged by Monte Carlo over random orientations of A and B and random n.
    S_c alone (D replaced by 2/m) and R (mean of the support function) are checked against the closed form of the mean excluded
    surface of two convex bodies, S_c = S/(2 pi) + 2 R^2 (4 pi S_c: 2S + 8 pi R^2).

Usage: eq28.py [xi ...]   prints e, g_c at eta = 0.058, S_c/b^2, <D>_c per elongation.
"""
import math
import sys

import numpy as np

B4_HS = 18.3648    # fourth virial coefficient of hard spheres / v0^3


def surface(xi, b):
    """Eq. 29a: surface of a prolate ellipsoid a = xi b, b, b."""
    if xi == 1.0:
        return 4.0 * math.pi * b * b
    z = math.sqrt(1.0 - 1.0 / xi ** 2)
    return 2.0 * math.pi * b * b * (1.0 + xi * math.asin(z) / z)


def mean_radius(xi, b):
    """Eq. 29b, corrected: mean radius of curvature (mean half-width) of a prolate ellipsoid,
    R = (a/2) [1 + log((1 + z)/(1 - z)) / (2 z xi^2)]. The seed prints 1/(2 z xi); that does
    not match the mean of the support function (checked by main() with Monte Carlo: 1.380 b
    at xi = 2, where the seed's form gives 1.760 b), this form does."""
    if xi == 1.0:
        return b
    z = math.sqrt(1.0 - 1.0 / xi ** 2)
    return 0.5 * xi * b * (1.0 + math.log((1.0 + z) / (1.0 - z)) / (2.0 * z * xi * xi))


def nonsphericity(xi):
    v = 4.0 / 3.0 * math.pi * xi
    return mean_radius(xi, 1.0) * surface(xi, 1.0) / (3.0 * v)


def g_contact(eta, e):
    """Song-Mason contact value (see module docstring)."""
    num = 1 + 3 * e - (2 + 3 * e - 3 * e * e) * eta + (1 + (B4_HS - 12) * e - 7 * e * e) * eta ** 2
    return num / ((1 + 3 * e) * (1 - eta) ** 3)


def _random_rotations(rng, n):
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], 1)


def sc_dc(xi, samples=2_000_000, seed=1, chunk=200_000):
    """Monte Carlo S_c and S_c <D>_c in units of b^2 (b = 1, m = 1). Returns
    (S_c, S_c <D>_c, standard error of S_c <D>_c, mean support function = R)."""
    rng = np.random.default_rng(seed)
    axes2 = np.array([xi * xi, 1.0, 1.0])
    inertia = np.array([2.0, 1.0 + xi * xi, 1.0 + xi * xi]) / 5.0    # m = 1: (b^2+c^2)/5 ...
    s_acc, x_acc, x2_acc, h_acc, count = 0.0, 0.0, 0.0, 0.0, 0
    while count < samples:
        k = min(chunk, samples - count)
        n = rng.normal(size=(k, 3))
        n /= np.linalg.norm(n, axis=1)[:, None]
        # tangent basis
        t1 = np.cross(n, np.where(np.abs(n[:, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]]))
        t1 /= np.linalg.norm(t1, axis=1)[:, None]
        t2 = np.cross(n, t1)
        H = np.zeros((k, 2, 2))
        dinv = np.full(k, 2.0)
        for sign in (1.0, -1.0):    # A (normal n) and B (normal -n)
            R = _random_rotations(rng, k)
            Q = np.einsum("kij,j,klj->kil", R, axes2, R)
            Qn = np.einsum("kij,kj->ki", Q, n)
            h = np.sqrt(np.einsum("ki,ki->k", n, Qn))
            if sign > 0:
                h_acc += h.sum()
            T = np.stack([t1, t2], 1)    # k x 2 x 3
            QT = np.einsum("kij,kaj->kai", Q, T)
            tQt = np.einsum("kai,kbi->kab", T, QT)
            tQn = np.einsum("kai,ki->ka", T, Qn)
            H += tQt / h[:, None, None] - tQn[:, :, None] * tQn[:, None, :] / h[:, None, None] ** 3
            r = sign * Qn / h[:, None]                # contact point relative to the centre
            g = np.cross(r, n)                        # lever (torque per unit normal force)
            gb = np.einsum("kji,kj->ki", R, g)        # body frame
            dinv += np.sum(gb * gb / inertia, axis=1)
        dS = H[:, 0, 0] * H[:, 1, 1] - H[:, 0, 1] * H[:, 1, 0]
        x = dS * np.sqrt(dinv / 2.0)
        s_acc += dS.sum()
        x_acc += x.sum()
        x2_acc += (x * x).sum()
        count += k
    mean = x_acc / count
    err = math.sqrt(max(x2_acc / count - mean * mean, 0.0) / count)
    return s_acc / count, mean, err, h_acc / count


def gamma0(xi, b, m, n_density, T, eta, sc_dc_b2):
    """Eq. 28 with S_c <D>_c given in units of b^2."""
    return 4.0 * math.sqrt(math.pi * T / m) * n_density * g_contact(eta, nonsphericity(xi)) \
        * sc_dc_b2 * b * b


def main():
    xis = [float(x) for x in sys.argv[1:]] or [1.0, 1.15, 2.0, 3.0]
    print("xi    R/b (Eq. 29b corr.)  R/b (MC)  e (nonsph.)  g_c(0.058)  S_c/b^2 (S/2pi + 2R^2)"
          "  S_c/b^2 (MC)  S_c<D>_c/b^2 (MC)   <D>_c")
    for xi in xis:
        s, x, err, h = sc_dc(xi)
        s_exact = surface(xi, 1.0) / (2 * math.pi) + 2 * mean_radius(xi, 1.0) ** 2
        print(f"{xi:<5g} {mean_radius(xi, 1.0):.5f}              {h:.5f}   {nonsphericity(xi):.5f}"
              f"      {g_contact(0.058, nonsphericity(xi)):.5f}     {s_exact:.5f}                "
              f"{s:.5f}       {x:.5f} +- {err:.5f}  {x / s:.5f}")


if __name__ == "__main__":
    main()
