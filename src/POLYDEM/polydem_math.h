/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - small fixed-size vector and quaternion algebra, and the closest
   point of a triangle, host/device.
   Quaternions are (w, x, y, z); q rotates body-frame vectors into the
   lab frame: v_lab = q v_body q^* (same convention as LAMMPS MathExtra).
------------------------------------------------------------------------- */

#ifndef POLYDEM_MATH_H
#define POLYDEM_MATH_H

#include "polydem_defs.h"

#include <cmath>

namespace polydem {

using std::cos;
using std::fabs;
using std::fma;
using std::sin;
using std::sqrt;

template <typename T> struct Vec3 {
  T x, y, z;
  POLYDEM_FN T &operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  POLYDEM_FN const T &operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

template <typename T> POLYDEM_FN Vec3<T> make_vec3(T x, T y, T z)
{
  Vec3<T> v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}
template <typename T> POLYDEM_FN Vec3<T> operator+(const Vec3<T> &a, const Vec3<T> &b)
{
  return make_vec3(a.x + b.x, a.y + b.y, a.z + b.z);
}
template <typename T> POLYDEM_FN Vec3<T> operator-(const Vec3<T> &a, const Vec3<T> &b)
{
  return make_vec3(a.x - b.x, a.y - b.y, a.z - b.z);
}
template <typename T> POLYDEM_FN Vec3<T> operator-(const Vec3<T> &a)
{
  return make_vec3(-a.x, -a.y, -a.z);
}
template <typename T> POLYDEM_FN Vec3<T> operator*(T s, const Vec3<T> &a)
{
  return make_vec3(s * a.x, s * a.y, s * a.z);
}
template <typename T> POLYDEM_FN Vec3<T> operator*(const Vec3<T> &a, T s)
{
  return make_vec3(s * a.x, s * a.y, s * a.z);
}
template <typename T> POLYDEM_FN Vec3<T> &operator+=(Vec3<T> &a, const Vec3<T> &b)
{
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
template <typename T> POLYDEM_FN Vec3<T> &operator-=(Vec3<T> &a, const Vec3<T> &b)
{
  a.x -= b.x;
  a.y -= b.y;
  a.z -= b.z;
  return a;
}
template <typename T> POLYDEM_FN T dot(const Vec3<T> &a, const Vec3<T> &b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T> POLYDEM_FN Vec3<T> cross(const Vec3<T> &a, const Vec3<T> &b)
{
  return make_vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
template <typename T> POLYDEM_FN T norm2(const Vec3<T> &a)
{
  return dot(a, a);
}
template <typename T> POLYDEM_FN T norm(const Vec3<T> &a)
{
  return sqrt(dot(a, a));
}

// h - a . b with the products and sums of a . b carried error-free (fma
// TwoProduct + TwoSum): when the result is small against the terms (a plane
// moved to a point just beside it), it is accurate to round-off of the
// result instead of round-off of the terms.
template <typename T> POLYDEM_FN T offset_minus_dot(T h, const Vec3<T> &a, const Vec3<T> &b)
{
  T hi = h, lo = T(0);
  const T ab[3][2] = {{a.x, b.x}, {a.y, b.y}, {a.z, b.z}};
  for (int k = 0; k < 3; ++k) {
    const T p = -ab[k][0] * ab[k][1];
    const T pe = fma(-ab[k][0], ab[k][1], -p);    // exact error of the product
    const T s = hi + p;
    const T bb = s - hi;
    lo += ((hi - (s - bb)) + (p - bb)) + pe;    // exact error of the sum
    hi = s;
  }
  return hi + lo;
}

// a unit vector perpendicular to the unit vector u
template <typename T> POLYDEM_FN Vec3<T> any_perpendicular(const Vec3<T> &u)
{
  const T ax = fabs(u.x), ay = fabs(u.y), az = fabs(u.z);
  // cross with the axis least aligned with u
  // clang-format off
  const Vec3<T> c = (ax <= ay && ax <= az) ? make_vec3(T(0), u.z, -u.y)
                    : (ay <= az)           ? make_vec3(-u.z, T(0), u.x)
                                           : make_vec3(u.y, -u.x, T(0));
  // clang-format on
  return (T(1) / norm(c)) * c;
}

template <typename T> struct Quat {
  T w, x, y, z;
};

template <typename T> POLYDEM_FN Quat<T> make_quat(T w, T x, T y, T z)
{
  Quat<T> q;
  q.w = w;
  q.x = x;
  q.y = y;
  q.z = z;
  return q;
}
// Hamilton product a*b
template <typename T> POLYDEM_FN Quat<T> qmul(const Quat<T> &a, const Quat<T> &b)
{
  // clang-format off
  return make_quat(a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
                   a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                   a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                   a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w);
  // clang-format on
}
template <typename T> POLYDEM_FN Quat<T> qconj(const Quat<T> &q)
{
  return make_quat(q.w, -q.x, -q.y, -q.z);
}
template <typename T> POLYDEM_FN Quat<T> qnormalize(const Quat<T> &q)
{
  T n = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  T s = T(1) / n;
  return make_quat(q.w * s, q.x * s, q.y * s, q.z * s);
}

// Rotation matrix R(q) (row-major), v_lab = R v_body
template <typename T> struct Mat3 {
  T m[3][3];
};
template <typename T> POLYDEM_FN Mat3<T> quat_to_mat(const Quat<T> &q)
{
  Mat3<T> r;
  const T w = q.w, x = q.x, y = q.y, z = q.z;
  r.m[0][0] = w * w + x * x - y * y - z * z;
  r.m[0][1] = T(2) * (x * y - w * z);
  r.m[0][2] = T(2) * (x * z + w * y);
  r.m[1][0] = T(2) * (x * y + w * z);
  r.m[1][1] = w * w - x * x + y * y - z * z;
  r.m[1][2] = T(2) * (y * z - w * x);
  r.m[2][0] = T(2) * (x * z - w * y);
  r.m[2][1] = T(2) * (y * z + w * x);
  r.m[2][2] = w * w - x * x - y * y + z * z;
  return r;
}
template <typename T> POLYDEM_FN Vec3<T> matvec(const Mat3<T> &r, const Vec3<T> &v)
{
  return make_vec3(r.m[0][0] * v.x + r.m[0][1] * v.y + r.m[0][2] * v.z,
                   r.m[1][0] * v.x + r.m[1][1] * v.y + r.m[1][2] * v.z,
                   r.m[2][0] * v.x + r.m[2][1] * v.y + r.m[2][2] * v.z);
}
// R^T v (lab -> body)
template <typename T> POLYDEM_FN Vec3<T> matTvec(const Mat3<T> &r, const Vec3<T> &v)
{
  return make_vec3(r.m[0][0] * v.x + r.m[1][0] * v.y + r.m[2][0] * v.z,
                   r.m[0][1] * v.x + r.m[1][1] * v.y + r.m[2][1] * v.z,
                   r.m[0][2] * v.x + r.m[1][2] * v.y + r.m[2][2] * v.z);
}
template <typename T> POLYDEM_FN Vec3<T> qrotate(const Quat<T> &q, const Vec3<T> &v)
{
  return matvec(quat_to_mat(q), v);
}
template <typename T> POLYDEM_FN Vec3<T> qrotate_inv(const Quat<T> &q, const Vec3<T> &v)
{
  return matTvec(quat_to_mat(q), v);
}

// Closest point of triangle (a, b, c) to p by its Voronoi regions (as
// polydem_mesh_grid.h's point_triangle_dist2); face = 1 if it is inside
// the triangle
template <typename T>
POLYDEM_FN Vec3<T> triangle_closest_point(const Vec3<T> &p, const Vec3<T> &a, const Vec3<T> &b,
                                          const Vec3<T> &c, int &face)
{
  face = 0;
  const Vec3<T> ab = b - a, ac = c - a, ap = p - a;
  const T d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= T(0) && d2 <= T(0)) return a;
  const Vec3<T> bp = p - b;
  const T d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= T(0) && d4 <= d3) return b;
  const T vc = d1 * d4 - d3 * d2;
  if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) return a + (d1 / (d1 - d3)) * ab;
  const Vec3<T> cp = p - c;
  const T d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= T(0) && d5 <= d6) return c;
  const T vb = d5 * d2 - d1 * d6;
  if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) return a + (d2 / (d2 - d6)) * ac;
  const T va = d3 * d6 - d5 * d4;
  if (va <= T(0) && (d4 - d3) >= T(0) && (d5 - d6) >= T(0))
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  face = 1;
  const T den = T(1) / (va + vb + vc);
  return a + (vb * den) * ab + (vc * den) * ac;
}

}    // namespace polydem

#endif
