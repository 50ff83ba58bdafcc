/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - rigid-body rotation kernels shared by fix nve/polyhedron and
   fix nve/polyhedron/kk (host and device). No LAMMPS includes.

   Free-rotor step: symmetric splitting of the torque-free Euler equations
   into exact rotations about the principal axes (Dullweber, Leimkuhler &
   McLachlan, J. Chem. Phys. 107, 5840 (1997); seed polyhedral §2.5):
       R1(h/2) R2(h/2) R3(h) R2(h/2) R1(h/2).
   Each sub-flow is exact, so the composition is symplectic, time reversible,
   keeps |L| exactly and the lab-frame L up to round-off; the gyroscopic term
   of the body-frame Euler equations is integrated, not dropped.
------------------------------------------------------------------------- */

#ifndef POLYDEM_RIGID_H
#define POLYDEM_RIGID_H

#include "polydem_math.h"

namespace polydem {

// sin x and cos x. A step's rotation angles are small (|x| of order
// 1e-4 - 1e-2 in DEM). For |x| <= 1/16 the Taylor series to x^9 and x^10
// leaves a truncation below 3e-20 of the result, and the terms after the
// first are a correction of at most 1/500 of it, so their round-off is
// below 1e-3 units of the last place: the sum is the correctly rounded
// value, as libm's, except where the exact value lies that close to a
// rounding boundary (then one unit apart). Larger angles take libm's.
template <typename T> POLYDEM_FN void rotor_sincos(T x, T &s, T &c)
{
  if (fabs(x) <= T(0.0625)) {
    const T x2 = x * x;
    s = x + x * x2 * (T(-1) / T(6) + x2 * (T(1) / T(120) + x2 * (T(-1) / T(5040) +
                                                                   x2 * (T(1) / T(362880)))));
    c = T(1) + x2 * (T(-0.5) + x2 * (T(1) / T(24) + x2 * (T(-1) / T(720) +
                                                         x2 * (T(1) / T(40320) +
                                                               x2 * (T(-1) / T(3628800))))));
  } else {
    s = sin(x);
    c = cos(x);
  }
}

// Exact rotation about body axis K for time h: body-frame angular momentum
// Lb rotates by -phi about e_K, orientation q by +phi about e_K (body frame),
// phi = h Lb_K / I_K. Lab-frame L = R(q) Lb is unchanged. K is a constant
// of the call (no store to a run-time slot of an array that a wider load
// then reads back: a store-forwarding stall in the hot loop).
template <int K, typename T> POLYDEM_FN void free_rotor_substep(T h, const T inertia[3], T Lb[3], T q[4])
{
  if (!(inertia[K] > T(0))) return;    // massless axis (degenerate template): no rotation
  const T phi = h * Lb[K] / inertia[K];
  // one sine and cosine, of the half angle: cos phi = 1 - 2 sin^2(phi/2),
  // sin phi = 2 sin(phi/2) cos(phi/2)
  T sh, ch;
  rotor_sincos(T(0.5) * phi, sh, ch);
  const T c = T(1) - T(2) * sh * sh, s = T(2) * sh * ch;
  constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
  // Lb <- Rot_K(-phi) Lb
  const T la = Lb[a], lb = Lb[b];
  Lb[a] = c * la + s * lb;
  Lb[b] = -s * la + c * lb;
  // q <- q * (cos(phi/2), sin(phi/2) e_K): qmul's products with the zero
  // components left out (the same sums, value for value)
  const T w = q[0], vk = q[1 + K], va = q[1 + a], vb = q[1 + b];
  q[0] = w * ch - vk * sh;
  q[1 + K] = w * sh + vk * ch;
  q[1 + a] = va * ch + vb * sh;
  q[1 + b] = vb * ch - va * sh;
}

// One free-rotor step of length h. L (lab, in/out) is recomputed from the
// rotated frame so that it stays consistent with q; q is renormalised.
template <typename T> POLYDEM_FN void free_rotor_step(T h, const T inertia[3], T L[3], T q[4])
{
  Mat3<T> r = quat_to_mat(make_quat(q[0], q[1], q[2], q[3]));
  Vec3<T> lb = matTvec(r, make_vec3(L[0], L[1], L[2]));
  T Lb[3] = {lb.x, lb.y, lb.z};
  free_rotor_substep<0>(T(0.5) * h, inertia, Lb, q);
  free_rotor_substep<1>(T(0.5) * h, inertia, Lb, q);
  free_rotor_substep<2>(h, inertia, Lb, q);
  free_rotor_substep<1>(T(0.5) * h, inertia, Lb, q);
  free_rotor_substep<0>(T(0.5) * h, inertia, Lb, q);
  const Quat<T> qn = qnormalize(make_quat(q[0], q[1], q[2], q[3]));
  q[0] = qn.w;
  q[1] = qn.x;
  q[2] = qn.y;
  q[3] = qn.z;
  r = quat_to_mat(qn);
  const Vec3<T> ll = matvec(r, make_vec3(Lb[0], Lb[1], Lb[2]));
  L[0] = ll.x;
  L[1] = ll.y;
  L[2] = ll.z;
}

// out = R D^{+-1} R^T in for a body with principal diagonal D (the inertia)
// and orientation q: inverse divides by D (0 where D is 0), else multiplies.
template <typename T>
POLYDEM_FN void body_diagonal_apply(const T d[3], bool inverse, const T in[3], const T q[4], T out[3])
{
  const Mat3<T> r = quat_to_mat(make_quat(q[0], q[1], q[2], q[3]));
  Vec3<T> b = matTvec(r, make_vec3(in[0], in[1], in[2]));
  if (inverse) {
    b.x = d[0] > T(0) ? b.x / d[0] : T(0);
    b.y = d[1] > T(0) ? b.y / d[1] : T(0);
    b.z = d[2] > T(0) ? b.z / d[2] : T(0);
  } else {
    b.x *= d[0];
    b.y *= d[1];
    b.z *= d[2];
  }
  const Vec3<T> o = matvec(r, b);
  out[0] = o.x;
  out[1] = o.y;
  out[2] = o.z;
}

// Lab-frame angular velocity from lab angular momentum: w = R I^-1 R^T L.
template <typename T> POLYDEM_FN void omega_from_angmom(const T inertia[3], const T L[3], const T q[4], T w[3])
{
  body_diagonal_apply(inertia, true, L, q, w);
}

// Lab angular momentum from lab angular velocity: L = R I R^T w.
template <typename T> POLYDEM_FN void angmom_from_omega(const T inertia[3], const T w[3], const T q[4], T L[3])
{
  body_diagonal_apply(inertia, false, w, q, L);
}

// Rotational kinetic energy 1/2 sum_k Lb_k^2 / I_k.
template <typename T> POLYDEM_FN T rotational_energy(const T inertia[3], const T L[3], const T q[4])
{
  const Mat3<T> r = quat_to_mat(make_quat(q[0], q[1], q[2], q[3]));
  const Vec3<T> b = matTvec(r, make_vec3(L[0], L[1], L[2]));
  T e = T(0);
  if (inertia[0] > T(0)) e += b.x * b.x / inertia[0];
  if (inertia[1] > T(0)) e += b.y * b.y / inertia[1];
  if (inertia[2] > T(0)) e += b.z * b.z / inertia[2];
  return T(0.5) * e;
}

// A particle is its shape template (volume V, principal moments J at unit
// density, both at scale 1) at scale s with density rho: volume V s^3, mass
// m = rho V s^3, moments rho s^5 J = m s^2 J / V.
template <typename T> POLYDEM_FN T scaled_mass(T rho, T V, T s)
{
  return rho * V * s * s * s;
}
template <typename T> POLYDEM_FN T scaled_density(T m, T V, T s)
{
  return m / (V * s * s * s);
}
template <typename T> POLYDEM_FN void scaled_moments(T m, T s, T V, const T J[3], T I[3])
{
  const T f = m * s * s / V;
  for (int k = 0; k < 3; k++) I[k] = f * J[k];
}


// Principal moments of a solid ellipsoid of mass m, semi-axes (a, b, c):
// I = m (b^2 + c^2, a^2 + c^2, a^2 + b^2) / 5; and their inverses.
template <typename T> POLYDEM_FN Vec3<T> ellipsoid_moments(T m, const Vec3<T> &ax)
{
  const T a = ax.x, b = ax.y, c = ax.z;
  return make_vec3(m * (b * b + c * c) / T(5), m * (a * a + c * c) / T(5), m * (a * a + b * b) / T(5));
}
template <typename T> POLYDEM_FN Vec3<T> ellipsoid_inverse_moments(T m, const Vec3<T> &ax)
{
  const T a2 = ax.x * ax.x, b2 = ax.y * ax.y, c2 = ax.z * ax.z;
  return make_vec3(T(5) / (m * (b2 + c2)), T(5) / (m * (a2 + c2)), T(5) / (m * (a2 + b2)));
}

// Mass a contact point sees (point-mass form of an impulse J along n at
// r from the centroid: the point's normal velocity changes by J / m_c):
// 1/m_c = im0 + sum_k (r x n)_k^2 / I_k, rn = r x n in the principal frame,
// Iinv the inverse principal moments; im0 the translational part (1/m for
// one body against a wall, |J|^2 (1/m_A + 1/m_B) for a pair). Returns 1/m_c;
// add the second body's rotational part by calling again with im0 = this.
template <typename T>
POLYDEM_FN T point_inverse_mass(T im0, const Vec3<T> &Iinv, const Vec3<T> &rn)
{
  return im0 + rn.x * rn.x * Iinv.x + rn.y * rn.y * Iinv.y + rn.z * rn.z * Iinv.z;
}

// Rigid motion of a mesh (its frame is the lab frame at the time it was
// defined): p_lab = o + d + Rm (p_mesh - o); wall velocity at p_lab:
// vw + w x (p_lab - o - d).
template <typename T> struct MeshPose {
  Vec3<T> o, d;    // rotation origin (mesh frame = lab at t=0), displacement
  Mat3<T> R;       // rotation
  Quat<T> q;       // same rotation as a quaternion
  Vec3<T> vw, w;   // translation velocity, angular velocity (lab)
};

// lab -> mesh frame: a point, an orientation
template <typename T> POLYDEM_FN Vec3<T> mesh_point(const MeshPose<T> &mp, const Vec3<T> &x)
{
  return mp.o + matTvec(mp.R, x - mp.o - mp.d);
}
template <typename T> POLYDEM_FN Quat<T> mesh_orientation(const MeshPose<T> &mp, const Quat<T> &q)
{
  return qmul(qconj(mp.q), q);
}
// mesh -> lab frame: the axis point o + d (lab), a point (given the axis point xw)
template <typename T> POLYDEM_FN Vec3<T> mesh_axis_point(const MeshPose<T> &mp)
{
  return mp.o + mp.d;
}
template <typename T>
POLYDEM_FN Vec3<T> lab_point(const MeshPose<T> &mp, const Vec3<T> &xw, const Vec3<T> &p)
{
  return xw + matvec(mp.R, p - mp.o);
}

}    // namespace polydem

#endif
