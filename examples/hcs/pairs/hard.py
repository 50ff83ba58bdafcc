#!/usr/bin/python3
"""Hard-body (impulsive) prediction of the first collision's loss for each pair,
(1-e^2)/2 m_eff v_n^2 at the first-touch state of gen.py (contact point, normal,
lever arms, inertia from Perram-Wertheim), against the soft-contact DEM loss of
stage 'mid' at dt = t_c/F (write_data files).  usage: hard.py tag F"""
import sys
import numpy as np

tag, F = sys.argv[1], sys.argv[2]   # F: file suffix, e.g. tc1600 or kn1.0e10.tc100
src = open('analyse.py').read()
exec(src[src.index('def quat2mat'):src.index('def loglast')])
M = np.load(f'meta.{tag}.npz')
a, b, m, T, en, tc = (float(M[k]) for k in ('a', 'b', 'm', 'T', 'en', 'tc'))
Ipar = m * 2 * b * b / 5.0; Iper = m * (a * a + b * b) / 5.0
Ib = np.array([Ipar, Iper, Iper])


def rotmat(k, ang):
    K = np.zeros(k.shape[:-1] + (3, 3))
    K[..., 0, 1] = -k[..., 2]; K[..., 0, 2] = k[..., 1]; K[..., 1, 0] = k[..., 2]
    K[..., 1, 2] = -k[..., 0]; K[..., 2, 0] = -k[..., 1]; K[..., 2, 1] = k[..., 0]
    s = np.sin(ang)[..., None, None]; c = np.cos(ang)[..., None, None]
    return np.eye(3) + s * K + (1 - c) * (K @ K)


def axis_at(u0, L, t):
    Ln = np.linalg.norm(L, axis=-1)
    return np.einsum('...ij,...j->...i', rotmat(L / Ln[..., None], Ln * t / Iper), u0)


lead = M['lead']
r = M['r'] + M['g'] * lead[:, None]                    # x_B - x_A at first touch
uA = axis_at(M['RA'][:, :, 0], M['LA'], lead); uB = axis_at(M['RB'][:, :, 0], M['LB'], lead)
Ainv = b * b * np.eye(3) + (a * a - b * b) * uA[:, :, None] * uA[:, None, :]
Binv = b * b * np.eye(3) + (a * a - b * b) * uB[:, :, None] * uB[:, None, :]


def F_(lam):
    C = (1 - lam)[:, None, None] * Ainv + lam[:, None, None] * Binv
    x = np.linalg.solve(C, r[..., None])[..., 0]
    return lam * (1 - lam) * (r * x).sum(1), x


lo = np.zeros(len(r)); hi = np.ones(len(r))
for _ in range(200):                                   # ternary search of the PW maximum
    m1 = lo + (hi - lo) / 3; m2 = hi - (hi - lo) / 3
    f1, _ = F_(m1); f2, _ = F_(m2)
    lo = np.where(f1 < f2, m1, lo); hi = np.where(f1 < f2, hi, m2)
lam = 0.5 * (lo + hi)
Fmax, x = F_(lam)
C = np.einsum('nij,nj->ni', Ainv, x) * (1 - lam)[:, None]   # contact point - x_A
n = x / np.linalg.norm(x, axis=1)[:, None]                    # normal (A -> B)
cA = C; cB = C - r                                            # lever arms
def omega(L, u):
    return L / Iper + (1 / Ipar - 1 / Iper) * (L * u).sum(1)[:, None] * u
def Iinv_dot(v, u):
    return v / Iper + (1 / Ipar - 1 / Iper) * (v * u).sum(1)[:, None] * u
wA = omega(M['LA'], uA); wB = omega(M['LB'], uB)
vA = -0.5 * M['g']; vB = 0.5 * M['g']
vrel = (vB + np.cross(wB, cB)) - (vA + np.cross(wA, cA))
vn = (vrel * n).sum(1)
gA = np.cross(cA, n); gB = np.cross(cB, n)
Dn = 2 / m + (gA * Iinv_dot(gA, uA)).sum(1) + (gB * Iinv_dot(gB, uB)).sum(1)
meff = 1 / Dn
Eh = 0.5 * (1 - en**2) * meff * vn**2
_, e0 = read(f'out.{tag}.{F}.start'); _, e1 = read(f'out.{tag}.{F}.mid')
Es = e0 - e1
print(f'{tag}: W0^2 at touch in [{Fmax.min():.9f}, {Fmax.max():.9f}], all approaching: {(vn < 0).all()}, '
      f'm_eff/m12 mean {np.mean(meff / (m / 2)):.4f} min {meff.min() / (m / 2):.4f}')
print(f'  hard-body first-collision loss per pair / ((1-e^2)T) = {Eh.mean() / ((1 - en**2) * T):.5f}')
R = Es.sum() / Eh.sum()
se = np.sqrt(((Es - R * Eh) ** 2).sum()) / Eh.sum()
print(f'  soft DEM ({F}, first encounter to 3 t_c) / hard-body = {R:.5f} +- {se:.5f}')
rel = Es / Eh
# where is the deficit: bins of the 'grazing' parameter (t_c/pi) v^2 / (R v_n): use |g|/|v_n|
gm = np.linalg.norm(M['g'], axis=1); q = gm / np.abs(vn)
for lo_, hi_ in ((0, 1), (1, 1.5), (1.5, 3), (3, 10), (10, 1e9)):
    s = (q >= lo_) & (q < hi_)
    if s.any():
        print(f'  |g|/|v_n| in [{lo_}, {hi_}): {s.sum():5d} pairs, share of hard loss {Eh[s].sum() / Eh.sum():.3f}, '
              f'soft/hard {Es[s].sum() / Eh[s].sum():.4f}')
for lo_, hi_ in ((0, 15), (15, 25), (25, 35), (35, 1e9)):
    s = (gm >= lo_) & (gm < hi_)
    print(f'  |g| in [{lo_}, {hi_}) m/s: {s.sum():5d} pairs, soft/hard {Es[s].sum() / Eh[s].sum():.4f}')
