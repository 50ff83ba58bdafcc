#!/usr/bin/python3
"""Per-pair dissipated energy from write_data files out.<tag>.tc<F>.{start,mid,end}.
usage: analyse.py tag F1 F2 ... (the last F is the reference)"""
import sys, re, glob
import numpy as np

tag = sys.argv[1]; fr = [int(x) for x in sys.argv[2:]]
M = np.load(f'meta.{tag}.npz')
a, b, m, T, en, tc = (float(M[k]) for k in ('a', 'b', 'm', 'T', 'en', 'tc'))
cell = float(M['cell'])
Ib = np.array([m * 2 * b * b / 5, m * (a * a + b * b) / 5, m * (a * a + b * b) / 5])


def quat2mat(q):
    w, x, y, z = q.T
    R = np.empty((len(q), 3, 3))
    R[:, 0, 0] = 1 - 2 * (y * y + z * z); R[:, 0, 1] = 2 * (x * y - w * z); R[:, 0, 2] = 2 * (x * z + w * y)
    R[:, 1, 0] = 2 * (x * y + w * z); R[:, 1, 1] = 1 - 2 * (x * x + z * z); R[:, 1, 2] = 2 * (y * z - w * x)
    R[:, 2, 0] = 2 * (x * z - w * y); R[:, 2, 1] = 2 * (y * z + w * x); R[:, 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def read(fn):
    lines = open(fn).read().split('\n')
    ia = lines.index('Atoms # polyhedron'); iv = [i for i, l in enumerate(lines) if l.startswith('Velocities')][0]
    A = np.array([[float(v) for v in l.split()] for l in lines[ia + 2:iv] if l.strip()])
    V = np.array([[float(v) for v in l.split()] for l in lines[iv + 2:] if l.strip()])
    A = A[np.argsort(A[:, 0])]; V = V[np.argsort(V[:, 0])]
    box = float(lines[[i for i, l in enumerate(lines) if 'xlo xhi' in l][0]].split()[1])
    x = A[:, 5:8] + A[:, 12:15] * box
    R = quat2mat(A[:, 8:12] / np.linalg.norm(A[:, 8:12], axis=1)[:, None])
    L = V[:, 4:7]
    Lb = np.einsum('nji,nj->ni', R, L)           # body frame
    ek = 0.5 * m * (V[:, 1:4] ** 2).sum(1) + 0.5 * (Lb ** 2 / Ib).sum(1)
    return x, ek.reshape(-1, 2).sum(1)


def loglast(fn):
    """thermo lines (step time ke erot pe Etot ncoll ncontact) of each run"""
    runs, cur = [], None
    for l in open(fn):
        if l.split()[:2] == ['Step', 'Time']:
            cur = []; runs.append(cur); continue
        if cur is not None:
            p = l.split()
            if len(p) == 8 and re.match(r'^\d+$', p[0]):
                cur.append([float(v) for v in p])
            elif l.startswith('Loop time'):
                wt = float(l.split()[3]); cur.append(wt); cur = None
    return runs


npairs = len(M['lead'])
res = {}
for F in fr:
    x0, e0 = read(f'out.{tag}.tc{F}.start')
    d = {'e0': e0}
    runs = loglast(f'log.{tag}.tc{F}')
    d['wall'] = sum(r[-1] for r in runs)
    d['steps'] = sum(int(r[-2][0]) - int(r[0][0]) for r in runs)
    for st, ri in (('mid', 0), ('end', 1)):
        try:
            x1, e1 = read(f'out.{tag}.tc{F}.{st}')
        except FileNotFoundError:
            continue
        d[st] = e0 - e1
        d[st + '_ncoll'] = sum(r[-2][6] for r in runs[:ri + 1])
        d[st + '_pe'] = runs[ri][-2][4]
        # pairs stay inside their own cells (no cross-pair contact)
        cen = x0.reshape(-1, 2, 3).mean(1)
        dev = np.abs(x1.reshape(-1, 2, 3) - cen[:, None, :]).max()
        d[st + '_maxdev'] = dev
    res[F] = d

ref = fr[-1]
print(f'# {tag}: xi {float(M["xi"]):g}, {npairs} pairs, t_c {tc:.6g}, T = m v0^2 = {T:.6g} J, '
      f'(1-e^2) T = {(1 - en**2) * T:.6g} J, cell {cell} (max centre excursion must stay < {cell / 2 - a:.3f})')
for st in ('mid', 'end'):
    # reference: finest dt that has this stage
    fs = [F for F in fr if st in res[F]]
    if not fs:
        continue
    Fr = fs[-1]
    E = res[Fr][st]; Er = E.sum()
    ncol = (E > 1e-9 * T).sum()
    print(f'## stage {st} (reference dt = t_c/{Fr}): pairs with loss > 0: {ncol}/{npairs}; '
          f'mean loss per pair / ((1-e^2)T) = {Er / npairs / ((1 - en**2) * T):.5f}; '
          f'per counted collision / ((1-e^2)T) = {Er / res[Fr][st + "_ncoll"] / ((1 - en**2) * T):.5f}')
    for F in fs:
        Ed = res[F][st]
        R = Ed.sum() / Er
        se = np.sqrt(((Ed - R * E) ** 2).sum()) / Er
        print(f'  dt = t_c/{F:<5d} loss/loss_ref = {R:.6f} +- {se:.6f}   collisions {res[F][st + "_ncoll"]:.0f}  '
              f'pe_at_stage {res[F][st + "_pe"]:.3g}  max excursion {res[F][st + "_maxdev"]:.3f} m  '
              f'pairs changed >1%: {(np.abs(Ed - E) > 0.01 * np.abs(E) + 1e-9 * T).sum()}')
for F in fr:
    print(f'  wall time t_c/{F}: {res[F]["wall"]:.1f} s ({res[F]["steps"]} steps)')

if float(M['xi']) == 1.0:
    # spheres: analytic loss (1-e^2)/2 m12 v_n^2 from the contact geometry of gen.py
    rc = M['r'] + M['g'] * M['lead'][:, None]
    vn = np.einsum('ni,ni->n', M['g'], rc / np.linalg.norm(rc, axis=1)[:, None])
    Ea = 0.5 * (1 - en**2) * 0.5 * m * vn**2
    for F in fr:
        Ed = res[F]['mid']
        R = Ed.sum() / Ea.sum()
        rel = Ed / Ea
        print(f'  spheres t_c/{F}: sum loss / sum (1-e^2)/2 m12 v_n^2 = {R:.6f}; per pair ratio '
              f'min {rel.min():.5f} max {rel.max():.5f}')
