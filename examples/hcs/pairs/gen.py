#!/usr/bin/python3
"""Independent colliding pairs of identical prolate spheroids (semi-axes a=xi b, b, b),
sampled as the FIRST collisions of a thermal gas (molecular chaos):
  - uniform random orientations, thermal angular momenta (T_rot = T_tr = m v0^2),
  - relative velocity g from the collision-flux-weighted Maxwellian  p(g) ~ |g| exp(-g^2/(4 v0^2)),
  - B enters the pair's bounding sphere (radius 2a) with uniform impact parameter.
Free flight (translation + exact symmetric-top precession) is followed in numpy until
the first contact (Perram-Wertheim W0 < 1); misses are discarded. Each kept pair is put
back in time by a random lead t_lead ~ U(0.3, 1.3) t_c before its contact (random phase
of the contact start on every time-step grid), and placed at the centre of its own cell
of a cubic lattice (spacing `cell`), centre-of-mass velocity zero.
Writes data.<tag> (read_data, atom_style polyhedron) and meta.<tag>.npz.
usage: gen.py xi npairs seed tag
"""
import sys
import numpy as np

xi = float(sys.argv[1]); npairs = int(sys.argv[2]); seed = int(sys.argv[3]); tag = sys.argv[4]
rng = np.random.default_rng(seed)
v0 = 8.0; kn = 1.0e8; en = 0.95
N, L = 4096, 2.0
b = (0.058 * L**3 / (N * 4.0 / 3.0 * np.pi * xi)) ** (1.0 / 3.0)
a = xi * b
m = 2000 * 4.0 / 3.0 * np.pi * a * b * b
tc = np.pi * np.sqrt(0.5 * m / kn)
Ipar = m * 2 * b * b / 5.0          # about the symmetry (body x) axis
Iper = m * (a * a + b * b) / 5.0
T = m * v0**2                        # k_B T
Rb = 2.2 * a                         # entry sphere: 1.1 x the sum of bounding radii


def rotmat(axis, ang):
    """rotation matrices about unit axes (n,3) by angles (n,) (Rodrigues)"""
    k = axis
    K = np.zeros(axis.shape[:-1] + (3, 3))
    K[..., 0, 1] = -k[..., 2]; K[..., 0, 2] = k[..., 1]
    K[..., 1, 0] = k[..., 2]; K[..., 1, 2] = -k[..., 0]
    K[..., 2, 0] = -k[..., 1]; K[..., 2, 1] = k[..., 0]
    s = np.sin(ang)[..., None, None]; c = np.cos(ang)[..., None, None]
    return np.eye(3) + s * K + (1 - c) * (K @ K)


def quat2mat(q):
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    R = np.empty(q.shape[:-1] + (3, 3))
    R[..., 0, 0] = 1 - 2 * (y * y + z * z); R[..., 0, 1] = 2 * (x * y - w * z); R[..., 0, 2] = 2 * (x * z + w * y)
    R[..., 1, 0] = 2 * (x * y + w * z); R[..., 1, 1] = 1 - 2 * (x * x + z * z); R[..., 1, 2] = 2 * (y * z - w * x)
    R[..., 2, 0] = 2 * (x * z - w * y); R[..., 2, 1] = 2 * (y * z + w * x); R[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def mat2quat(R):
    # Shepperd's method, vectorised
    n = R.shape[0]; q = np.empty((n, 4))
    tr = np.trace(R, axis1=1, axis2=2)
    d = np.stack([tr, R[:, 0, 0], R[:, 1, 1], R[:, 2, 2]], 1)
    k = np.argmax(d, 1)
    for i in range(n):
        Ri = R[i]
        if k[i] == 0:
            s = np.sqrt(1 + tr[i]) * 2
            q[i] = [0.25 * s, (Ri[2, 1] - Ri[1, 2]) / s, (Ri[0, 2] - Ri[2, 0]) / s, (Ri[1, 0] - Ri[0, 1]) / s]
        elif k[i] == 1:
            s = np.sqrt(1 + Ri[0, 0] - Ri[1, 1] - Ri[2, 2]) * 2
            q[i] = [(Ri[2, 1] - Ri[1, 2]) / s, 0.25 * s, (Ri[0, 1] + Ri[1, 0]) / s, (Ri[0, 2] + Ri[2, 0]) / s]
        elif k[i] == 2:
            s = np.sqrt(1 + Ri[1, 1] - Ri[0, 0] - Ri[2, 2]) * 2
            q[i] = [(Ri[0, 2] - Ri[2, 0]) / s, (Ri[0, 1] + Ri[1, 0]) / s, 0.25 * s, (Ri[1, 2] + Ri[2, 1]) / s]
        else:
            s = np.sqrt(1 + Ri[2, 2] - Ri[0, 0] - Ri[1, 1]) * 2
            q[i] = [(Ri[1, 0] - Ri[0, 1]) / s, (Ri[0, 2] + Ri[2, 0]) / s, (Ri[1, 2] + Ri[2, 1]) / s, 0.25 * s]
    return q * np.sign(q[:, :1] + 1e-300)


def axis_at(u0, L, t):
    """symmetry axis of a free symmetric top: precession about L at |L|/I_perp"""
    Ln = np.linalg.norm(L, axis=-1)
    Lh = L / Ln[..., None]
    return np.einsum('...ij,...j->...i', rotmat(Lh, Ln * t / Iper), u0)


def pw_W2(r, uA, uB):
    """Perram-Wertheim contact function max_lambda; returns W0^2 (overlap iff < 1)"""
    def F(lam):
        l = lam[..., None, None]
        C = b * b * np.eye(3) + (a * a - b * b) * ((1 - l) * uA[..., :, None] * uA[..., None, :]
                                                     + l * uB[..., :, None] * uB[..., None, :])
        x = np.linalg.solve(C, r[..., None])[..., 0]
        return lam * (1 - lam) * np.einsum('...i,...i->...', r, x)
    lo = np.zeros(r.shape[:-1]); hi = np.ones(r.shape[:-1])
    gr = (np.sqrt(5) - 1) / 2
    x1 = hi - gr * (hi - lo); x2 = lo + gr * (hi - lo)
    f1 = F(x1); f2 = F(x2)
    for _ in range(40):
        left = f1 > f2
        hi = np.where(left, x2, hi); lo = np.where(left, lo, x1)
        nx1 = hi - gr * (hi - lo); nx2 = lo + gr * (hi - lo)
        # reuse one evaluation
        x2n = np.where(left, x1, nx2); x1n = np.where(left, nx1, x2)
        f2n = np.where(left, f1, np.nan); f1n = np.where(left, np.nan, f2)
        need1 = np.isnan(f1n); need2 = np.isnan(f2n)
        f1n = np.where(need1, F(x1n), f1n); f2n = np.where(need2, F(x2n), f2n)
        x1, x2, f1, f2 = x1n, x2n, f1n, f2n
    return np.maximum(f1, f2)


def state(r0, g, uA0, uB0, LA, LB, t):
    return r0 + g * t[..., None], axis_at(uA0, LA, t), axis_at(uB0, LB, t)


def rand_rot(n):
    q = rng.normal(size=(n, 4)); q /= np.linalg.norm(q, axis=1)[:, None]
    return quat2mat(q)


def thermal_L(R):
    Lb = rng.normal(size=(R.shape[0], 3)) * np.sqrt(T * np.array([Ipar, Iper, Iper]))
    return np.einsum('nij,nj->ni', R, Lb)


keep = {k: [] for k in ('r', 'g', 'RA', 'RB', 'LA', 'LB', 'tstar', 'lead')}
ncand = 0; nhit = 0; nhit_all = 0; nentries = 0
NG = 300
while nhit < npairs:
    n = 4000
    ncand += n
    ghat = rng.normal(size=(n, 3)); ghat /= np.linalg.norm(ghat, axis=1)[:, None]
    gmag = 2 * v0 * np.sqrt(rng.gamma(2.0, 1.0, n))  # |g|^2/(2 sigma^2) ~ Gamma(2), sigma = v0 sqrt 2
    g = ghat * gmag[:, None]
    # impact vector perpendicular to ghat, uniform on the disk of radius Rb
    e1 = np.cross(ghat, rng.normal(size=(n, 3))); e1 /= np.linalg.norm(e1, axis=1)[:, None]
    bimp = Rb * np.sqrt(rng.random(n))
    bv = e1 * bimp[:, None]
    s = np.sqrt(Rb**2 - bimp**2) * (1 + 1e-9)
    r0 = bv - s[:, None] * ghat          # r = x_B - x_A, entering the bounding sphere
    texit = 2 * s / gmag
    RA = rand_rot(n); RB = rand_rot(n)
    LA = thermal_L(RA); LB = thermal_L(RB)
    uA0 = RA[:, :, 0]; uB0 = RB[:, :, 0]
    # coarse scan of W0^2 along the free flight
    ts = np.linspace(0, 1, NG)[None, :] * texit[:, None]
    rr, ua, ub = state(r0[:, None, :], g[:, None, :], uA0[:, None, :], uB0[:, None, :],
                       LA[:, None, :], LB[:, None, :], ts)
    W2 = pw_W2(rr, ua, ub)
    hit = W2 < 1
    nentries += int(((W2[:, 1:] < 1) & (W2[:, :-1] >= 1)).sum())
    first = np.where(hit.any(1), hit.argmax(1), -1)
    # grazing candidates missed by the grid: refine around the grid minimum
    graz = (first < 0) & (W2.min(1) < 1.02)
    for i in np.nonzero(graz)[0]:
        j = W2[i].argmin()
        tt = np.linspace(ts[i, max(j - 1, 0)], ts[i, min(j + 1, NG - 1)], 200)
        rr_, ua_, ub_ = state(r0[i], g[i], uA0[i], uB0[i], LA[i], LB[i], tt)
        w = pw_W2(rr_, ua_, ub_)
        if (w < 1).any():
            k = (w < 1).argmax()
            first[i] = -2; ts[i, 0] = tt[k - 1]; ts[i, 1] = tt[k]
    nhit_all += int((first != -1).sum())
    idx = np.nonzero(first != -1)[0]
    t0 = np.empty(len(idx)); t1 = np.empty(len(idx))
    for k, i in enumerate(idx):
        if first[i] == -2:
            t0[k], t1[k] = ts[i, 0], ts[i, 1]
        else:
            if first[i] == 0:
                raise RuntimeError('overlap at entry')
            t0[k], t1[k] = ts[i, first[i] - 1], ts[i, first[i]]
    for _ in range(50):   # bisection of the first contact time, all hits at once
        tm = 0.5 * (t0 + t1)
        rr_, ua_, ub_ = state(r0[idx], g[idx], uA0[idx], uB0[idx], LA[idx], LB[idx], tm)
        inside = pw_W2(rr_, ua_, ub_) < 1
        t1 = np.where(inside, tm, t1); t0 = np.where(inside, t0, tm)
    for k, i in enumerate(idx):
        tstar = t0[k]
        lead = min(tstar, rng.uniform(0.3, 1.3) * tc)
        ts0 = np.array(tstar - lead)
        rr_, _, _ = state(r0[i], g[i], uA0[i], uB0[i], LA[i], LB[i], ts0)
        # full rotation matrices at the start: precession about L applied to R0
        RAs = rotmat(LA[i] / np.linalg.norm(LA[i]), np.array(np.linalg.norm(LA[i]) * ts0 / Iper)) @ RA[i]
        RBs = rotmat(LB[i] / np.linalg.norm(LB[i]), np.array(np.linalg.norm(LB[i]) * ts0 / Iper)) @ RB[i]
        for k_, v_ in (('r', rr_), ('g', g[i]), ('RA', RAs), ('RB', RBs), ('LA', LA[i]), ('LB', LB[i]),
                       ('tstar', tstar), ('lead', lead)):
            keep[k_].append(v_)
        nhit += 1
        if nhit >= npairs:
            break
    print(f'candidates {ncand} hits {nhit}', flush=True)

P = {k: np.array(v) for k, v in keep.items()}
# sanity: no overlap at the start
w0 = pw_W2(P['r'], P['RA'][:, :, 0], P['RB'][:, :, 0])
assert (w0 > 1).all(), w0.min()
ncell = int(np.ceil(npairs ** (1 / 3)))
cell = 1.2
box = ncell * cell
idx = np.arange(npairs)
cen = (np.stack([idx % ncell, (idx // ncell) % ncell, idx // ncell**2], 1) + 0.5) * cell
xA = cen - 0.5 * P['r']; xB = cen + 0.5 * P['r']
vA = -0.5 * P['g']; vB = 0.5 * P['g']
qA = mat2quat(P['RA']); qB = mat2quat(P['RB'])
with open(f'data.{tag}', 'w') as f:
    f.write(f'pairs of spheroids xi {xi} npairs {npairs} seed {seed}\n\n{2 * npairs} atoms\n1 atom types\n\n')
    f.write(f'0 {box} xlo xhi\n0 {box} ylo yhi\n0 {box} zlo zhi\n\nAtoms\n\n')
    for i in range(npairs):
        for j, (x, q) in enumerate(((xA[i], qA[i]), (xB[i], qB[i]))):
            f.write(f'{2 * i + j + 1} 1 1 1.0 2000 {x[0]:.17g} {x[1]:.17g} {x[2]:.17g} '
                    f'{q[0]:.17g} {q[1]:.17g} {q[2]:.17g} {q[3]:.17g}\n')
    f.write('\nVelocities\n\n')
    for i in range(npairs):
        for j, (v, Lv) in enumerate(((vA[i], P['LA'][i]), (vB[i], P['LB'][i]))):
            f.write(f'{2 * i + j + 1} {v[0]:.17g} {v[1]:.17g} {v[2]:.17g} {Lv[0]:.17g} {Lv[1]:.17g} {Lv[2]:.17g}\n')
np.savez(f'meta.{tag}.npz', xi=xi, a=a, b=b, m=m, tc=tc, T=T, en=en, kn=kn, ncand=ncand, nhit_all=nhit_all, nentries=nentries, box=box, cell=cell,
         **P)
print(f'xi {xi} a {a:.6g} b {b:.6g} m {m:.6g} tc {tc:.6g} hit fraction {nhit_all / ncand:.4f} '
      f'(entry-sphere flux), free-flight entries per candidate {nentries / ncand:.4f} box {box:.3g} cell {cell:.3g} max lead/tc {P["lead"].max() / tc:.3f}')
