/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - exact algebraic contact of two ellipsoids (ellipsoid seed §2.1,
   §3.2), host/device, no allocation, bounded loops, no LAMMPS includes.

   Ellipsoid k: centre x_k, rotation R_k (quaternion, body -> lab), semi-axes
   (a,b,c)_k along the body axes. In homogeneous coordinates X = (p, 1) it is
   X A X^T = 0 with A = T R S R^T T^T (Eqs. 3-8): upper 3x3 block
   M = R diag(a^-2, b^-2, c^-2) R^T, last row/column -M x, corner x.M.x - W^2.

   Shrinking both ellipsoids by the common factor W only changes the corner
   (Eq. 2, 4): A(W) = A(0) - W^2 e4 e4^T. Hence (the seed's factorisation,
   with s = W^2 and coordinates centred on ellipsoid A)

     f(lambda, s) = det(lambda A + B) = G(lambda) - s (1 + lambda) H(lambda)   (Eq. 9)

   with H = det(lambda M_A + M_B) (cubic) and G = det(lambda A(0) + B(0))
   (cubic, G(0) = 0); their coefficients are computed once per pair and the
   quartic a..e (Eq. 10) for any s follows with a few multiply-adds.

   Classification at W = 1: separated iff Delta > 0 and P = 8ac - 3b^2 < 0
   (Eq. 11) and, as the seed omits, two of the four real roots are positive
   (deeply overlapping pairs can have four negative roots; Descartes' rule
   of signs counts them exactly when all roots are real). Delta is a sum of large terms; when it is within round-off of
   zero relative to the sum of their magnitudes we fall back to root
   isolation (below).

   Shrink-to-touch: Delta(s) changes sign where f(., s) gets a double positive
   root, i.e. at s0 = max over lambda > 0 of sigma(lambda) = G / ((1+lambda) H)
   (f(lambda, s) >= 0 iff s <= sigma(lambda)). With mu = lambda / (1 + lambda)
   in (0,1), sigma is the Perram-Wertheim function, concave in mu, so its
   maximum is the unique sign change of sigma'(mu): bracketed Newton on a
   polynomial, bounded iterations. W0 = sqrt(s0): overlapping iff W0 < 1.
   This is also the root-isolation fallback of the classification.

   At W0 the two positive eigenvalues of -A_s^-1 B_s merge at lambda0; the
   eigenvectors V2 = V3 = C (the contact point) solve (lambda0 M_A + M_B) p =
   M_B d (upper rows of (lambda0 A_s + B_s) X = 0). V0, V1 lie on the polar
   plane of C, which is the common tangent plane (self-polar tetrahedron), so
   the normal of Eq. 22 equals the gradient M_A (C - x_A) of A at C; we use
   the gradient (V0, V1 may be points at infinity, e.g. for spheroids).

   Overlap delta: at W0 the V2-V3 segment has collapsed to C, so delta is the
   length of the chord of the original ellipsoids' overlap along the normal
   line through C (exact: two quadratic equations, solved in stable form).
   For spheres this is r_A + r_B - |d|.
------------------------------------------------------------------------- */

#ifndef POLYDEM_ELLIPSOID_H
#define POLYDEM_ELLIPSOID_H

#include "polydem_math.h"

namespace polydem {

// Iteration cap of the bracketed Newton search for the touching point
// (bisection alone halves a unit interval to 1e-16 in 53 steps).
constexpr int ELLIPSOID_MAX_ITER = 100;

template <typename T> struct Sym3 {
  T xx, yy, zz, xy, xz, yz;
};

template <typename T> POLYDEM_FN Vec3<T> symvec(const Sym3<T> &m, const Vec3<T> &v)
{
  return make_vec3(m.xx * v.x + m.xy * v.y + m.xz * v.z, m.xy * v.x + m.yy * v.y + m.yz * v.z,
                   m.xz * v.x + m.yz * v.y + m.zz * v.z);
}
template <typename T> POLYDEM_FN T symdet(const Sym3<T> &m)
{
  return m.xx * (m.yy * m.zz - m.yz * m.yz) - m.xy * (m.xy * m.zz - m.yz * m.xz) +
      m.xz * (m.xy * m.yz - m.yy * m.xz);
}
template <typename T> POLYDEM_FN Sym3<T> symadj(const Sym3<T> &m)
{
  Sym3<T> r;
  r.xx = m.yy * m.zz - m.yz * m.yz;
  r.yy = m.xx * m.zz - m.xz * m.xz;
  r.zz = m.xx * m.yy - m.xy * m.xy;
  r.xy = m.xz * m.yz - m.xy * m.zz;
  r.xz = m.xy * m.yz - m.xz * m.yy;
  r.yz = m.xy * m.xz - m.xx * m.yz;
  return r;
}
template <typename T> POLYDEM_FN Sym3<T> symlin(T s, const Sym3<T> &a, T t, const Sym3<T> &b)
{
  Sym3<T> r;
  r.xx = s * a.xx + t * b.xx;
  r.yy = s * a.yy + t * b.yy;
  r.zz = s * a.zz + t * b.zz;
  r.xy = s * a.xy + t * b.xy;
  r.xz = s * a.xz + t * b.xz;
  r.yz = s * a.yz + t * b.yz;
  return r;
}
// trace(X Y) of symmetric matrices
template <typename T> POLYDEM_FN T symtrprod(const Sym3<T> &x, const Sym3<T> &y)
{
  return x.xx * y.xx + x.yy * y.yy + x.zz * y.zz + T(2) * (x.xy * y.xy + x.xz * y.xz + x.yz * y.yz);
}

// Shape matrix M = R diag(k0, k1, k2) R^T (k = a^-2 for the quadric, a^2 for its inverse)
template <typename T> POLYDEM_FN Sym3<T> ellipsoid_matrix(const Mat3<T> &r, T k0, T k1, T k2)
{
  Sym3<T> m;
  m.xx = k0 * r.m[0][0] * r.m[0][0] + k1 * r.m[0][1] * r.m[0][1] + k2 * r.m[0][2] * r.m[0][2];
  m.yy = k0 * r.m[1][0] * r.m[1][0] + k1 * r.m[1][1] * r.m[1][1] + k2 * r.m[1][2] * r.m[1][2];
  m.zz = k0 * r.m[2][0] * r.m[2][0] + k1 * r.m[2][1] * r.m[2][1] + k2 * r.m[2][2] * r.m[2][2];
  m.xy = k0 * r.m[0][0] * r.m[1][0] + k1 * r.m[0][1] * r.m[1][1] + k2 * r.m[0][2] * r.m[1][2];
  m.xz = k0 * r.m[0][0] * r.m[2][0] + k1 * r.m[0][1] * r.m[2][1] + k2 * r.m[0][2] * r.m[2][2];
  m.yz = k0 * r.m[1][0] * r.m[2][0] + k1 * r.m[1][1] * r.m[2][1] + k2 * r.m[1][2] * r.m[2][2];
  return m;
}

// One ellipsoid as the kernels see it: centre, orientation, semi-axes (lab units).
template <typename T> struct EllipsoidPose {
  Vec3<T> x;
  Quat<T> q;    // unit quaternion, body -> lab
  Vec3<T> axes; // semi-axes along body x, y, z
};

// The same with the orientation as a rotation matrix (body -> lab): an
// ellipsoid part of a composite, posed by the product of the body's and the
// part's rotations (pair_style polyhedron).
template <typename T> struct EllipsoidFrame {
  Vec3<T> x;
  Mat3<T> R;
  Vec3<T> axes;
};

template <typename T> POLYDEM_FN EllipsoidFrame<T> ellipsoid_frame(const EllipsoidPose<T> &p)
{
  EllipsoidFrame<T> f;
  f.x = p.x;
  f.R = quat_to_mat(p.q);
  f.axes = p.axes;
  return f;
}

// Quartic discriminant (Eq. 11) and the sum of the magnitudes of its terms.
template <typename T>
POLYDEM_FN T quartic_discriminant(T a, T b, T c, T d, T e, T &mag)
{
  const T t[16] = {T(256) * a * a * a * e * e * e,   T(-192) * a * a * b * d * e * e,
                   T(-128) * a * a * c * c * e * e,  T(144) * a * a * c * d * d * e,
                   T(-27) * a * a * d * d * d * d,   T(144) * a * b * b * c * e * e,
                   T(-6) * a * b * b * d * d * e,    T(-80) * a * b * c * c * d * e,
                   T(18) * a * b * c * d * d * d,    T(16) * a * c * c * c * c * e,
                   T(-4) * a * c * c * c * d * d,    T(-27) * b * b * b * b * e * e,
                   T(18) * b * b * b * c * d * e,    T(-4) * b * b * b * d * d * d,
                   T(-4) * b * b * c * c * c * e,    b * b * c * c * d * d};
  T s = T(0);
  mag = T(0);
  for (int k = 0; k < 16; k++) {
    s += t[k];
    mag += fabs(t[k]);
  }
  return s;
}

// Coefficients of the pencil of one pair (see header comment). Lengths are
// divided by L so that all numbers are O(1).
template <typename T> struct EllipsoidPencil {
  Sym3<T> ma, mb;    // M_A, M_B (scaled units)
  Vec3<T> d;         // x_B - x_A (scaled units)
  T h[4];            // H(lambda) = sum h[k] lambda^k
  T g[4];            // G(lambda) = sum g[k] lambda^k, g[0] = 0
  T L;               // length unit
};

template <typename T>
POLYDEM_FN void ellipsoid_pencil(const EllipsoidFrame<T> &A, const EllipsoidFrame<T> &B,
                                 EllipsoidPencil<T> &pc)
{
  T L = A.axes.x;
  if (A.axes.y > L) L = A.axes.y;
  if (A.axes.z > L) L = A.axes.z;
  if (B.axes.x > L) L = B.axes.x;
  if (B.axes.y > L) L = B.axes.y;
  if (B.axes.z > L) L = B.axes.z;
  pc.L = L;
  const T ia = L / A.axes.x, ib = L / A.axes.y, ic = L / A.axes.z;
  const T ja = L / B.axes.x, jb = L / B.axes.y, jc = L / B.axes.z;
  pc.ma = ellipsoid_matrix(A.R, ia * ia, ib * ib, ic * ic);
  pc.mb = ellipsoid_matrix(B.R, ja * ja, jb * jb, jc * jc);
  pc.d = (T(1) / L) * (B.x - A.x);

  // det(lambda X + Y) = l^3 det X + l^2 tr(adj X Y) + l tr(X adj Y) + det Y
  const Sym3<T> adja = symadj(pc.ma), adjb = symadj(pc.mb);
  pc.h[3] = symdet(pc.ma);
  pc.h[2] = symtrprod(adja, pc.mb);
  pc.h[1] = symtrprod(pc.ma, adjb);
  pc.h[0] = symdet(pc.mb);

  // G = H (d.u) - u^T adj(lambda M_A + M_B) u with u = M_B d (Schur complement);
  // adj(lX + Y) = l^2 adj X + l C + adj Y, C = adj(X + Y) - adj X - adj Y
  const Vec3<T> u = symvec(pc.mb, pc.d);
  const T du = dot(pc.d, u);
  const Sym3<T> sum = symlin(T(1), pc.ma, T(1), pc.mb);
  const Sym3<T> adjs = symadj(sum);
  const Sym3<T> mixed = symlin(T(1), symlin(T(1), adjs, T(-1), adja), T(-1), adjb);
  pc.g[3] = pc.h[3] * du;
  pc.g[2] = pc.h[2] * du - dot(u, symvec(adja, u));
  pc.g[1] = pc.h[1] * du - dot(u, symvec(mixed, u));
  pc.g[0] = T(0);    // h0 du - u.adj(M_B).u = h0 du - det(M_B) d.M_B.d
}

// Quartic a..e of f(lambda, s) (Eq. 10)
template <typename T>
POLYDEM_FN void pencil_quartic(const EllipsoidPencil<T> &pc, T s, T *q)
{
  q[0] = -s * pc.h[3];
  q[1] = pc.g[3] - s * (pc.h[3] + pc.h[2]);
  q[2] = pc.g[2] - s * (pc.h[2] + pc.h[1]);
  q[3] = pc.g[1] - s * (pc.h[1] + pc.h[0]);
  q[4] = -s * pc.h[0];
}

// Classification from Eqs. 9-11 at W = 1: +1 separated, -1 overlapping,
// 0 undecided (|Delta| within round-off of zero).
template <typename T> POLYDEM_FN int pencil_classify(const EllipsoidPencil<T> &pc)
{
  T q[5];
  pencil_quartic(pc, T(1), q);
  T m = T(0);
  for (int k = 0; k < 5; k++)
    if (fabs(q[k]) > m) m = fabs(q[k]);
  if (!(m > T(0))) return 0;
  for (int k = 0; k < 5; k++) q[k] /= m;    // scaled coefficients
  T mag;
  const T disc = quartic_discriminant(q[0], q[1], q[2], q[3], q[4], mag);
  const T P = T(8) * q[0] * q[2] - T(3) * q[1] * q[1];
  if (fabs(disc) <= T(1.0e3) * Eps<T>::value * mag) return 0;
  if (!(disc > T(0) && P < T(0))) return -1;
  // four real roots: all negative is possible for deep overlaps, so count the
  // positive ones by Descartes' rule (exact when every root is real)
  int changes = 0;
  for (int k = 0; k < 4; k++)
    if ((q[k] > T(0)) != (q[k + 1] > T(0))) changes++;
  return changes == 2 ? 1 : -1;
}

// Perram-Wertheim form in mu = lambda/(1+lambda):
// sigma(mu) = N(mu)/D(mu), N = (1-mu) mu [g3 mu^2 + g2 mu (1-mu) + g1 (1-mu)^2],
// D = h3 mu^3 + h2 mu^2 (1-mu) + h1 mu (1-mu)^2 + h0 (1-mu)^3.
// Returns N, D and their first two derivatives.
template <typename T>
POLYDEM_FN void pencil_sigma_parts(const EllipsoidPencil<T> &pc, T mu, T *N, T *D)
{
  // power-basis coefficients in mu, computed on the fly (cheap)
  const T g1 = pc.g[1], g2 = pc.g[2], g3 = pc.g[3];
  // inner(mu) = g1 + (g2 - 2 g1) mu + (g3 - g2 + g1) mu^2
  const T i0 = g1, i1 = g2 - T(2) * g1, i2 = g3 - g2 + g1;
  // N = (mu - mu^2) inner: coefficients n1..n4
  const T n1 = i0, n2 = i1 - i0, n3 = i2 - i1, n4 = -i2;
  N[0] = mu * (n1 + mu * (n2 + mu * (n3 + mu * n4)));
  N[1] = n1 + mu * (T(2) * n2 + mu * (T(3) * n3 + mu * T(4) * n4));
  N[2] = T(2) * n2 + mu * (T(6) * n3 + mu * T(12) * n4);
  const T h0 = pc.h[0], h1 = pc.h[1], h2 = pc.h[2], h3 = pc.h[3];
  const T d0 = h0, d1 = h1 - T(3) * h0, d2 = h2 - T(2) * h1 + T(3) * h0,
          d3 = h3 - h2 + h1 - h0;
  D[0] = d0 + mu * (d1 + mu * (d2 + mu * d3));
  D[1] = d1 + mu * (T(2) * d2 + mu * T(3) * d3);
  D[2] = T(2) * d2 + mu * T(6) * d3;
}

// Touching state: mu0 in (0,1) maximising sigma, s0 = sigma(mu0) = W0^2.
// Returns STATUS_OK or STATUS_NO_CONVERGENCE / STATUS_DEGENERATE.
template <typename T>
POLYDEM_FN int pencil_touch(const EllipsoidPencil<T> &pc, T &mu0, T &s0)
{
  // sign of sigma' = sign of N' D - N D' (D > 0): decreasing in mu (concavity)
  T lo = T(0), hi = T(1), mu = T(0.5);
  T N[3], D[3];
  int it = 0;
  for (; it < ELLIPSOID_MAX_ITER; it++) {
    pencil_sigma_parts(pc, mu, N, D);
    const T p = N[1] * D[0] - N[0] * D[1];
    const T dp = N[2] * D[0] - N[0] * D[2];
    if (p > T(0)) lo = mu;
    else hi = mu;
    T next = (dp < T(0)) ? mu - p / dp : T(0.5) * (lo + hi);
    if (!(next > lo && next < hi)) next = T(0.5) * (lo + hi);
    if (fabs(next - mu) <= T(2) * Eps<T>::value * mu || hi - lo <= Eps<T>::value) {
      mu = next;
      break;
    }
    mu = next;
  }
  if (it == ELLIPSOID_MAX_ITER) return STATUS_NO_CONVERGENCE;
  pencil_sigma_parts(pc, mu, N, D);
  if (!(D[0] > T(0)) || !(N[0] >= T(0))) return STATUS_DEGENERATE;
  mu0 = mu;
  s0 = N[0] / D[0];
  return STATUS_OK;
}

// Contact of two ellipsoids.
template <typename T> struct EllipsoidContact {
  int status;      // STATUS_OK (overlapping), STATUS_SEPARATED, or an error
  int classified;  // +1/-1 from Delta and P (Eqs. 9-11), 0: decided by root isolation
  T W0;            // common shrink factor at touching (< 1: overlapping)
  T delta;         // overlap (length of the normal chord through C)
  Vec3<T> n;       // unit normal, from A towards B
  Vec3<T> c;       // contact point C (lab frame)
  Vec3<T> gB;      // d(W0^2)/d(x_B) = 2 (1-mu0) M_B (x_B - C) (envelope theorem); parallel
                   // to n. Rotating B by theta changes W0^2 by ((C - x_B) x gB).theta,
                   // and d/dx_A = -gB (translation invariance).
};

template <typename T>
POLYDEM_FN EllipsoidContact<T> ellipsoid_contact(const EllipsoidFrame<T> &A,
                                                 const EllipsoidFrame<T> &B)
{
  EllipsoidContact<T> r;
  r.status = STATUS_DEGENERATE;
  r.classified = 0;
  r.W0 = T(0);
  r.delta = T(0);
  r.n = make_vec3(T(0), T(0), T(0));
  r.c = A.x;
  r.gB = r.n;
  if (!(A.axes.x > T(0) && A.axes.y > T(0) && A.axes.z > T(0) && B.axes.x > T(0) &&
        B.axes.y > T(0) && B.axes.z > T(0)))
    return r;

  EllipsoidPencil<T> pc;
  ellipsoid_pencil(A, B, pc);
  if (!(norm2(pc.d) > T(0))) return r;    // coincident centres: no normal
  r.classified = pencil_classify(pc);
  if (r.classified > 0) {
    r.status = STATUS_SEPARATED;
    return r;
  }

  T mu0, s0;
  const int st = pencil_touch(pc, mu0, s0);
  if (st != STATUS_OK) {
    r.status = st;
    return r;
  }
  r.W0 = sqrt(s0);
  if (!(s0 < T(1))) {    // root isolation says separated (or just touching)
    r.status = STATUS_SEPARATED;
    return r;
  }

  // contact point: (mu M_A + (1-mu) M_B) p = (1-mu) M_B d  (A centred at 0)
  const Sym3<T> k = symlin(mu0, pc.ma, T(1) - mu0, pc.mb);
  const T det = symdet(k);
  if (!(det > T(0))) return r;
  const Vec3<T> rhs = (T(1) - mu0) * symvec(pc.mb, pc.d);
  const Vec3<T> p = (T(1) / det) * symvec(symadj(k), rhs);

  // normal: gradient of A at C (equal to Eq. 22, see header)
  const Vec3<T> ga = symvec(pc.ma, p);
  const T gn = norm(ga);
  if (!(gn > T(0))) return r;
  const Vec3<T> n = (T(1) / gn) * ga;

  // chord along p + t n: A's surface at t_A > 0, B's at t_B < 0 (stable roots)
  const T alA = dot(n, symvec(pc.ma, n)), beA = dot(n, ga), gaA = dot(p, ga) - T(1);
  const Vec3<T> qb = p - pc.d;
  const Vec3<T> gb = symvec(pc.mb, qb);
  const T alB = dot(n, symvec(pc.mb, n)), beB = dot(n, gb), gaB = dot(qb, gb) - T(1);
  const T discA = beA * beA - alA * gaA, discB = beB * beB - alB * gaB;
  if (!(discA >= T(0)) || !(discB >= T(0))) return r;
  const T tA = -gaA / (beA + sqrt(discA));
  const T tB = gaB / (-beB + sqrt(discB));

  r.status = STATUS_OK;
  r.delta = pc.L * (tA - tB);
  r.n = n;
  r.c = A.x + pc.L * p;
  r.gB = (T(2) * (T(1) - mu0) / pc.L) * symvec(pc.mb, pc.d - p);
  return r;
}

template <typename T>
POLYDEM_FN EllipsoidContact<T> ellipsoid_contact(const EllipsoidPose<T> &A,
                                                 const EllipsoidPose<T> &B)
{
  return ellipsoid_contact(ellipsoid_frame(A), ellipsoid_frame(B));
}

}    // namespace polydem

#endif
