/* ----------------------------------------------------------------------
   POLYDEM - host-side convex shape template (seed polyhedral 2.1): mass
   properties. build()'s principal frame and stored volume and moments, the
   analytic ellipsoid template, the checks on both, and the rotation into
   the principal frame as the input orientation.

   Exactness: volume, first and second moments are summed over the hull's
   tetrahedra in exact rational arithmetic and rounded once. Only the
   principal-axis rotation (Jacobi, long double) and the final rounding of
   rotated vertices are inexact.
------------------------------------------------------------------------- */

#include "polydem_shape_template.h"

#include "polydem_shape_template_impl.h"
#include "polydem_rigid.h"

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace polydem {

using namespace shape_impl;

namespace {

  using Q = CGAL::Exact_rational;

  // Relative tolerance on principal moments below which two moments are
  // treated as equal (degenerate axes: see choose_axes()). Round-off splits
  // truly equal moments by ~1e-15; keeping input axes for a split below
  // 1e-11 leaves products of inertia below 1e-11 of the largest moment.
  constexpr double MOMENT_TOL = 1e-11;

  // ---------------------------------------------------------------------
  // Exact mass properties of a closed, outward-oriented triangle surface:
  // sum over tetrahedra (0,a,b,c): det = a.(b x c), V = det/6,
  // int x_i = det/24 s_i, int x_i x_j = det/120 (sum_v v_i v_j + s_i s_j),
  // s = a+b+c (standard tetrahedron moment formulas).
  // ---------------------------------------------------------------------
  struct Moments {
    Q vol6, m1_24[3], m2_120[3][3];    // 6V, 24 int x, 120 int x x^T
  };

  Moments exact_moments(const std::vector<Pt> &v, const std::vector<std::array<int, 3>> &tris)
  {
    Moments m;
    m.vol6 = 0;
    for (int i = 0; i < 3; ++i) {
      m.m1_24[i] = 0;
      for (int j = 0; j < 3; ++j) m.m2_120[i][j] = 0;
    }
    for (const auto &t : tris) {
      Q a[3], b[3], c[3], s[3];
      for (int i = 0; i < 3; ++i) {
        a[i] = v[t[0]][i];
        b[i] = v[t[1]][i];
        c[i] = v[t[2]][i];
        s[i] = a[i] + b[i] + c[i];
      }
      Q det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
          a[2] * (b[0] * c[1] - b[1] * c[0]);
      m.vol6 += det;
      for (int i = 0; i < 3; ++i) {
        m.m1_24[i] += det * s[i];
        for (int j = i; j < 3; ++j)
          m.m2_120[i][j] += det * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
      }
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < i; ++j) m.m2_120[i][j] = m.m2_120[j][i];
    return m;
  }

  // Volume, centroid and inertia tensor (per unit density, about the centroid).
  void mass_properties(const Moments &m, double &vol, Pt &cen, double inertia[3][3])
  {
    Q V = m.vol6 / 6;
    Q c[3], S[3][3];
    for (int i = 0; i < 3; ++i) c[i] = m.m1_24[i] / 24 / V;
    // central second moments S = int x x^T - V c c^T, then I = tr(S) 1 - S
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) S[i][j] = m.m2_120[i][j] / 120 - V * c[i] * c[j];
    Q tr = S[0][0] + S[1][1] + S[2][2];
    vol = CGAL::to_double(V);
    for (int i = 0; i < 3; ++i) {
      cen[i] = CGAL::to_double(c[i]);
      for (int j = 0; j < 3; ++j) inertia[i][j] = CGAL::to_double((i == j ? tr : Q(0)) - S[i][j]);
    }
  }

  // Cyclic Jacobi eigen-decomposition of a symmetric 3x3 matrix.
  // Columns of e are the eigenvectors.
  void jacobi3(const double a_in[3][3], long double w[3], long double e[3][3])
  {
    long double a[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        a[i][j] = a_in[i][j];
        e[i][j] = (i == j);
      }
    for (int sweep = 0; sweep < 60; ++sweep) {
      long double off = std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
      if (off == 0.0L) break;
      for (int p = 0; p < 2; ++p)
        for (int q = p + 1; q < 3; ++q) {
          if (a[p][q] == 0.0L) continue;
          long double theta = (a[q][q] - a[p][p]) / (2.0L * a[p][q]);
          long double t =
              (theta >= 0 ? 1.0L : -1.0L) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0L));
          long double c = 1.0L / std::sqrt(t * t + 1.0L), s = t * c;
          for (int k = 0; k < 3; ++k) {    // A <- A J
            long double akp = a[k][p], akq = a[k][q];
            a[k][p] = c * akp - s * akq;
            a[k][q] = s * akp + c * akq;
          }
          for (int k = 0; k < 3; ++k) {    // A <- J^T A
            long double apk = a[p][k], aqk = a[q][k];
            a[p][k] = c * apk - s * aqk;
            a[q][k] = s * apk + c * aqk;
          }
          for (int k = 0; k < 3; ++k) {
            long double ekp = e[k][p], ekq = e[k][q];
            e[k][p] = c * ekp - s * ekq;
            e[k][q] = s * ekp + c * ekq;
          }
        }
    }
    for (int i = 0; i < 3; ++i) w[i] = a[i][i];
  }

  V3 col(const long double e[3][3], int j)
  {
    return {e[0][j], e[1][j], e[2][j]};
  }
  V3 sign_fix(V3 a)    // largest-magnitude component positive (first one on ties)
  {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(a[i]) > std::fabs(a[k])) k = i;
    if (a[k] < 0) a = {-a[0], -a[1], -a[2]};
    return a;
  }
  // In the plane normal to u: the input axis most nearly in that plane
  // (lowest index on ties), projected. Keeps input axes where they are free.
  V3 plane_axis(const V3 &u)
  {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(u[i]) < std::fabs(u[k]) - 1e-12L) k = i;
    V3 a = {0, 0, 0};
    a[k] = 1;
    long double d = u[k];
    return vunit({a[0] - d * u[0], a[1] - d * u[1], a[2] - d * u[2]});
  }

  // Principal axes as the columns of R (proper rotation), moments ascending.
  // Degenerate moments keep the input axes (see the Howto for the rules).
  void choose_axes(const double inertia[3][3], double rot[3][3])
  {
    long double w[3], e[3][3];
    jacobi3(inertia, w, e);
    int idx[3] = {0, 1, 2};
    std::sort(idx, idx + 3, [&](int a, int b) {
      return w[a] < w[b];
    });
    long double l0 = w[idx[0]], l1 = w[idx[1]], l2 = w[idx[2]];
    long double tol = MOMENT_TOL * std::fabs(l2);
    bool eq01 = l1 - l0 <= tol, eq12 = l2 - l1 <= tol;
    V3 c[3];
    if (eq01 && eq12) {
      c[0] = {1, 0, 0};
      c[1] = {0, 1, 0};
      c[2] = {0, 0, 1};
    } else if (eq01) {
      V3 u = sign_fix(col(e, idx[2]));
      c[0] = plane_axis(u);
      c[1] = vcross(u, c[0]);
      c[2] = u;
    } else if (eq12) {
      V3 u = sign_fix(col(e, idx[0]));
      c[0] = u;
      c[1] = plane_axis(u);
      c[2] = vcross(u, c[1]);
    } else {
      for (int j = 0; j < 3; ++j) c[j] = sign_fix(col(e, idx[j]));
      c[1] = vunit(c[1]);
      c[0] = vunit(c[0]);
      c[2] = vcross(c[0], c[1]);    // right-handed; agrees with e up to sign
    }
    // Snap to a signed permutation when that is what it is up to round-off,
    // so that axis-aligned input stays bit-exact.
    for (int j = 0; j < 3; ++j) {
      int k = 0;
      for (int i = 1; i < 3; ++i)
        if (std::fabs(c[j][i]) > std::fabs(c[j][k])) k = i;
      bool axis = true;
      for (int i = 0; i < 3; ++i)
        if (i != k && std::fabs(c[j][i]) > 1e-13L) axis = false;
      if (axis) {
        long double s = c[j][k] > 0 ? 1 : -1;
        c[j] = {0, 0, 0};
        c[j][k] = s;
      }
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rot[i][j] = (double) c[j][i];
  }

}    // namespace

void shape_impl::principal_axes(const double inertia[3][3], double R[3][3])
{
  choose_axes(inertia, R);
}

// Phase 6, principal frame: exact volume, centroid and inertia of the hull
// in input coordinates; the centroid moves to the origin and the principal
// axes become the body axes (choose_axes). Sets centroid_ and rot_ and
// returns the body-frame corners p_body = R^T (p - c), rounded to double.
std::vector<PolyShapeTemplate::Point>
PolyShapeTemplate::principal_frame(const std::vector<Point> &hv,
                                   const std::vector<std::array<int, 3>> &tri,
                                   const std::string &head)
{
  double vol0, inertia0[3][3];
  Pt cen;
  mass_properties(exact_moments(hv, tri), vol0, cen, inertia0);
  if (!(vol0 > 0)) throw ShapeError(head + ": the hull has zero volume");
  centroid_ = cen;

  double R[3][3];
  choose_axes(inertia0, R);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rot_[i][j] = R[i][j];

  std::vector<Pt> bv(hv.size());
  for (size_t k = 0; k < hv.size(); ++k) {
    V3 d = vsub(hv[k], cen);
    for (int j = 0; j < 3; ++j)
      bv[k][j] = (double) (R[0][j] * d[0] + R[1][j] * d[1] + R[2][j] * d[2]);
  }
  return bv;
}

// Phase 7, stored mass properties: volume and principal moments computed
// again, exactly, from the rounded body-frame vertices actually stored;
// the bounding radius about the centroid. Checked to be normal numbers.
void PolyShapeTemplate::set_mass_properties(const std::vector<Point> &bv,
                                            const std::vector<std::array<int, 3>> &tri,
                                            const std::string &head)
{
  double inertia[3][3];
  Pt c2;
  mass_properties(exact_moments(bv, tri), volume_, c2, inertia);
  for (int i = 0; i < 3; ++i) moments_[i] = inertia[i][i];

  verts_.clear();
  for (const auto &p : bv) verts_.insert(verts_.end(), p.begin(), p.end());
  radius_ = 0;
  for (const auto &p : bv)
    radius_ = std::max(radius_, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));

  check_mass_properties(head);
}

PolyShapeTemplate PolyShapeTemplate::ellipsoid(double a, double b, double c,
                                               const std::string &name)
{
  for (double v : {a, b, c})
    if (!(v > 0.0) || !std::isfinite(v))
      throw ShapeError(name + ": ellipsoid semi-axes must be positive and finite, got " +
                       std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c));
  PolyShapeTemplate t;
  t.name_ = name;
  t.ellipsoid_ = true;
  t.axes_ = {a, b, c};
  t.face_start_ = {0};    // no faces, no vertices
  t.volume_ = 4.0 / 3.0 * M_PI * a * b * c;
  t.radius_ = std::max(a, std::max(b, c));
  const Vec3<double> J = ellipsoid_moments(t.volume_, make_vec3(a, b, c));    // at unit density
  t.moments_ = {J.x, J.y, J.z};
  t.check_mass_properties(name + ": ellipsoid " + fmt_num(a) + " " + fmt_num(b) + " " + fmt_num(c));
  return t;
}

// volume and principal moments must be finite, normal numbers (issue 17: a
// zero volume or moment gave NaN kinetic energy or silently dropped rotation)
void PolyShapeTemplate::check_mass_properties(const std::string &what) const
{
  bool ok = std::isnormal(volume_) && volume_ > 0.0 && std::isnormal(radius_);
  for (double m : moments_) ok = ok && std::isnormal(m) && m > 0.0;
  if (!ok)
    throw ShapeError(what + ": volume " + fmt_num(volume_) + " or principal moments " +
                     fmt_num(moments_[0]) + " " + fmt_num(moments_[1]) + " " +
                     fmt_num(moments_[2]) +
                     " are zero or not finite (size outside [1e-50, 1e50]?)");
}

Quat<double> PolyShapeTemplate::input_orientation() const
{
  return rotation_quat(rot_);
}

// rotation matrix -> unit quaternion (Shepperd's method: largest pivot)
Quat<double> shape_impl::rotation_quat(const std::array<std::array<double, 3>, 3> &m)
{
  double tr = m[0][0] + m[1][1] + m[2][2];
  double w, x, y, z;
  if (tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2]) {
    double s = 2.0 * std::sqrt(1.0 + tr);
    w = 0.25 * s;
    x = (m[2][1] - m[1][2]) / s;
    y = (m[0][2] - m[2][0]) / s;
    z = (m[1][0] - m[0][1]) / s;
  } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
    double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
    w = (m[2][1] - m[1][2]) / s;
    x = 0.25 * s;
    y = (m[0][1] + m[1][0]) / s;
    z = (m[0][2] + m[2][0]) / s;
  } else if (m[1][1] >= m[2][2]) {
    double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
    w = (m[0][2] - m[2][0]) / s;
    x = (m[0][1] + m[1][0]) / s;
    y = 0.25 * s;
    z = (m[1][2] + m[2][1]) / s;
  } else {
    double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
    w = (m[1][0] - m[0][1]) / s;
    x = (m[0][2] + m[2][0]) / s;
    y = (m[1][2] + m[2][1]) / s;
    z = 0.25 * s;
  }
  if (w < 0) {
    w = -w;
    x = -x;
    y = -y;
    z = -z;
  }
  return qnormalize(make_quat(w, x, y, z));
}

}    // namespace polydem
