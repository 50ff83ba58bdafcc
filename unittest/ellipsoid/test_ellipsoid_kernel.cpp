// Ellipsoid contact kernel (issue 6, acceptance 1) against an independent
// oracle: the Perram-Wertheim contact function
//   F(mu) = mu (1-mu) d^T [(1-mu) A^-1 + mu B^-1]^-1 d,  A^-1 = R diag(a^2,b^2,c^2) R^T,
// maximised in long double by bisection on the sign of its analytic derivative
//   F'(mu) = (1-2mu) d.y - mu (1-mu) y.(B^-1 - A^-1).y,  y = G^-1 d
// (F is concave). The ellipsoids touch when scaled by W0 = sqrt(max F); the
// touching point is x_A + (1-mu) A^-1 y, the normal is parallel to y, and the
// overlap is the chord of the original ellipsoids along that normal line.
// None of this uses the kernel's quartic/determinant machinery.

#include "polydem_ellipsoid_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace polydem;
using LD = long double;

namespace {

struct M3 {
  LD m[3][3];
};

M3 shape_inv(const EllipsoidPose<double> &e)
{
  // R diag(a^2, b^2, c^2) R^T in long double
  const LD w = e.q.w, x = e.q.x, y = e.q.y, z = e.q.z;
  LD r[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  const LD k[3] = {(LD) e.axes.x * e.axes.x, (LD) e.axes.y * e.axes.y, (LD) e.axes.z * e.axes.z};
  M3 o;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      o.m[i][j] = 0;
      for (int l = 0; l < 3; l++) o.m[i][j] += r[i][l] * k[l] * r[j][l];
    }
  return o;
}

M3 inverse(const M3 &a)
{
  M3 c;
  const auto &m = a.m;
  c.m[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  c.m[0][1] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
  c.m[0][2] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
  c.m[1][0] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  c.m[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
  c.m[1][2] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
  c.m[2][0] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  c.m[2][1] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
  c.m[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  const LD det = m[0][0] * c.m[0][0] + m[0][1] * c.m[1][0] + m[0][2] * c.m[2][0];
  for (auto &row : c.m)
    for (auto &v : row) v /= det;
  return c;
}

void mv(const M3 &a, const LD *v, LD *o)
{
  for (int i = 0; i < 3; i++) o[i] = a.m[i][0] * v[0] + a.m[i][1] * v[1] + a.m[i][2] * v[2];
}

struct Oracle {
  LD W0, delta;
  LD n[3];
};

Oracle oracle(const EllipsoidPose<double> &A, const EllipsoidPose<double> &B)
{
  const M3 ai = shape_inv(A), bi = shape_inv(B);
  const LD d[3] = {(LD) B.x.x - A.x.x, (LD) B.x.y - A.x.y, (LD) B.x.z - A.x.z};
  auto solve_y = [&](LD mu, LD *y) {
    M3 g;
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) g.m[i][j] = (1 - mu) * ai.m[i][j] + mu * bi.m[i][j];
    mv(inverse(g), d, y);
  };
  LD lo = 0, hi = 1;
  for (int it = 0; it < 80; it++) {
    const LD mu = 0.5L * (lo + hi);
    LD y[3], t[3], u[3];
    solve_y(mu, y);
    mv(bi, y, t);
    mv(ai, y, u);
    LD dy = 0, yby = 0;
    for (int k = 0; k < 3; k++) {
      dy += d[k] * y[k];
      yby += y[k] * (t[k] - u[k]);
    }
    const LD fp = (1 - 2 * mu) * dy - mu * (1 - mu) * yby;
    (fp > 0 ? lo : hi) = mu;
  }
  const LD mu = 0.5L * (lo + hi);
  LD y[3], p[3];
  solve_y(mu, y);
  LD dy = 0;
  for (int k = 0; k < 3; k++) dy += d[k] * y[k];
  Oracle o;
  o.W0 = std::sqrt(mu * (1 - mu) * dy);
  mv(ai, y, p);
  for (int k = 0; k < 3; k++) p[k] *= (1 - mu);    // contact point relative to x_A
  const LD yn = std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
  for (int k = 0; k < 3; k++) o.n[k] = y[k] / yn;
  // chord: q(t) = (c + t n - x)^T M (c + t n - x) = 1, M = inverse of shape_inv
  auto chord = [&](const M3 &minv, const LD *rel, bool far) {
    const M3 m = inverse(minv);
    LD mn[3], mr[3];
    mv(m, o.n, mn);
    mv(m, rel, mr);
    LD al = 0, be = 0, ga = -1;
    for (int k = 0; k < 3; k++) {
      al += o.n[k] * mn[k];
      be += o.n[k] * mr[k];
      ga += rel[k] * mr[k];
    }
    const LD sq = std::sqrt(be * be - al * ga);
    return far ? -ga / (be + sq) : ga / (-be + sq);
  };
  const LD relb[3] = {p[0] - d[0], p[1] - d[1], p[2] - d[2]};
  o.delta = chord(ai, p, true) - chord(bi, relb, false);
  return o;
}

Quat<double> random_quat(std::mt19937_64 &g)
{
  std::normal_distribution<double> n(0.0, 1.0);
  return qnormalize(make_quat(n(g), n(g), n(g), n(g)));
}

EllipsoidPose<double> random_ellipsoid(std::mt19937_64 &g, Vec3<double> x)
{
  // semi-axes in [0.2, 1]: aspect ratios up to 5
  std::uniform_real_distribution<double> ax(0.2, 1.0);
  EllipsoidPose<double> e;
  e.x = x;
  e.q = random_quat(g);
  e.axes = make_vec3(ax(g), ax(g), ax(g));
  return e;
}

}    // namespace

// Spheres: W0 = |d| / (rA + rB), delta = rA + rB - |d|, normal along d.
TEST(EllipsoidKernel, Spheres)
{
  EllipsoidPose<double> A, B;
  A.x = make_vec3(0.3, -0.2, 0.1);
  A.q = make_quat(1.0, 0.0, 0.0, 0.0);
  A.axes = make_vec3(0.5, 0.5, 0.5);
  B.q = qnormalize(make_quat(0.3, 0.1, -0.7, 0.2));
  B.axes = make_vec3(0.25, 0.25, 0.25);
  const Vec3<double> dir = (1.0 / sqrt(14.0)) * make_vec3(1.0, 2.0, -3.0);
  for (double dist : {0.1, 0.5, 0.74, 0.7499999, 0.76}) {
    B.x = A.x + dist * dir;
    const auto c = ellipsoid_contact(A, B);
    EXPECT_NEAR(c.W0, dist / 0.75, 1e-14);
    if (dist < 0.75) {
      ASSERT_EQ(c.status, STATUS_OK);
      EXPECT_NEAR(c.delta, 0.75 - dist, 1e-14);
      EXPECT_NEAR(dot(c.n, dir), 1.0, 1e-14);
      // contact point on the centre line, at rA/(rA+rB) of the way
      EXPECT_NEAR(norm(c.c - (A.x + (dist * 0.5 / 0.75) * dir)), 0.0, 1e-14);
    } else {
      EXPECT_EQ(c.status, STATUS_SEPARATED);
    }
  }
}

// Swap A and B: same delta, W0 and contact point, opposite normal; and
// invariance under a rigid motion of the pair.
TEST(EllipsoidKernel, SymmetryAndInvariance)
{
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int n = 0;
  for (int k = 0; k < 2000; k++) {
    auto A = random_ellipsoid(g, make_vec3(u(g), u(g), u(g)));
    auto B = random_ellipsoid(g, A.x + make_vec3(u(g), u(g), u(g)));
    const auto ab = ellipsoid_contact(A, B), ba = ellipsoid_contact(B, A);
    if (ab.status != STATUS_OK) continue;
    n++;
    ASSERT_EQ(ba.status, STATUS_OK);
    EXPECT_NEAR(ab.delta, ba.delta, 1e-11);
    EXPECT_NEAR(norm(ab.n + ba.n), 0.0, 1e-10);
    EXPECT_NEAR(norm(ab.c - ba.c), 0.0, 1e-10);
    const auto q = random_quat(g);
    const Vec3<double> t = make_vec3(u(g), u(g), u(g));
    auto A2 = A, B2 = B;
    A2.x = qrotate(q, A.x) + t;
    B2.x = qrotate(q, B.x) + t;
    A2.q = qmul(q, A.q);
    B2.q = qmul(q, B.q);
    const auto r = ellipsoid_contact(A2, B2);
    ASSERT_EQ(r.status, STATUS_OK);
    EXPECT_NEAR(r.delta, ab.delta, 1e-11);
    EXPECT_NEAR(norm(r.n - qrotate(q, ab.n)), 0.0, 1e-10);
  }
  EXPECT_GT(n, 500);
}

// Acceptance 1: >= 100,000 random pairs, aspect ratio up to 5.
TEST(EllipsoidKernel, AgainstPerramWertheimOracle)
{
  std::mt19937_64 g(20261122);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nd(0.0, 1.0);
  const int npairs = 100000;
  int nover = 0, nsep = 0, nskip = 0, ndelta = 0, nfallback = 0, ndisc = 0;
  double max_dn = 0.0, max_dd = 0.0;
  for (int k = 0; k < npairs; k++) {
    auto A = random_ellipsoid(g, make_vec3(nd(g), nd(g), nd(g)));
    Vec3<double> dir = make_vec3(nd(g), nd(g), nd(g));
    dir = (1.0 / norm(dir)) * dir;
    // centre distances from deep overlap to separated (bounding spheres <= 2)
    auto B = random_ellipsoid(g, A.x + (2.1 * u(g)) * dir);
    const Oracle o = oracle(A, B);
    if (std::fabs((double) o.W0 - 1.0) < 1e-9) {
      nskip++;
      continue;
    }
    const bool sep = o.W0 > 1;
    const auto c = ellipsoid_contact(A, B);
    ASSERT_TRUE(c.status == STATUS_OK || c.status == STATUS_SEPARATED) << "pair " << k;
    ASSERT_EQ(c.status == STATUS_SEPARATED, sep) << "pair " << k << " W0 " << (double) o.W0;
    if (c.classified != 0) {
      ndisc++;
      // Eqs. 9-11 alone decide when Delta is clear of round-off
      ASSERT_EQ(c.classified > 0, sep) << "pair " << k << " W0 " << (double) o.W0;
    } else
      nfallback++;
    if (sep) {
      nsep++;
      continue;
    }
    nover++;
    ASSERT_NEAR(c.W0, (double) o.W0, 1e-13) << "pair " << k;
    double dn = 0.0;
    for (int i = 0; i < 3; i++) dn += std::pow(c.n[i] - (double) o.n[i], 2);
    dn = std::sqrt(dn);
    max_dn = std::max(max_dn, dn);
    EXPECT_LT(dn, 1e-8) << "pair " << k;
    // delta: 1e-8 relative, or a few round-offs of the particle size when the
    // overlap itself is that small (it is computed from 1 - W0^2 in doubles)
    const double dd = std::fabs(c.delta - (double) o.delta);
    max_dd = std::max(max_dd, dd / (double) o.delta);
    EXPECT_LT(dd, 1e-8 * (double) o.delta + 1e-14) << "pair " << k;
    if (dd < 1e-8 * (double) o.delta) ndelta++;
  }
  printf("pairs %d: overlapping %d, separated %d, skipped (|W0-1| < 1e-9) %d; decided by "
         "Delta/P %d, by root isolation %d; max |n - n_ref| %.3g, max rel. delta error %.3g, "
         "delta within 1e-8 rel. %d / %d\n",
         npairs, nover, nsep, nskip, ndisc, nfallback, max_dn, max_dd, ndelta, nover);
  EXPECT_GT(nover, 20000);
  EXPECT_GT(nsep, 20000);
  EXPECT_GT(ndisc, npairs / 2);
}

// Near touching: W0 is proportional to the centre distance along a fixed
// direction, so pairs are placed at W0 = 1 +- eps, eps log-uniform in
// [1e-9, 1e-2]. Classification must be right and delta ~ (1 - W0) accurate.
TEST(EllipsoidKernel, NearTouching)
{
  std::mt19937_64 g(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nd(0.0, 1.0);
  int nfallback = 0, nwrong_delta = 0, nover = 0;
  double max_dn = 0.0;
  for (int k = 0; k < 20000; k++) {
    auto A = random_ellipsoid(g, make_vec3(nd(g), nd(g), nd(g)));
    Vec3<double> dir = make_vec3(nd(g), nd(g), nd(g));
    auto B = random_ellipsoid(g, A.x + dir);
    const LD w = oracle(A, B).W0;
    const double eps = std::pow(10.0, -9.0 + 7.0 * u(g)) * (k % 2 ? 1.0 : -1.0);
    B.x = A.x + (double) ((1.0L + eps) / w) * dir;
    const Oracle o = oracle(A, B);
    if (std::fabs((double) o.W0 - 1.0) < 1e-9) continue;
    const bool sep = o.W0 > 1;
    const auto c = ellipsoid_contact(A, B);
    ASSERT_EQ(c.status == STATUS_SEPARATED, sep) << "pair " << k << " eps " << eps;
    if (c.classified == 0) nfallback++;
    else ASSERT_EQ(c.classified > 0, sep) << "pair " << k << " eps " << eps;
    if (sep) continue;
    nover++;
    double dn = 0.0;
    for (int i = 0; i < 3; i++) dn += std::pow(c.n[i] - (double) o.n[i], 2);
    max_dn = std::max(max_dn, std::sqrt(dn));
    EXPECT_LT(std::sqrt(dn), 1e-8);
    const double dd = std::fabs(c.delta - (double) o.delta);
    EXPECT_LT(dd, 1e-8 * (double) o.delta + 1e-14) << "pair " << k << " eps " << eps;
    if (dd > 1e-8 * (double) o.delta) nwrong_delta++;
  }
  printf("near touching: %d overlapping, %d decided by root isolation, max |n - n_ref| %.3g, "
         "delta beyond 1e-8 rel. (within 1e-14 abs.) %d\n",
         nover, nfallback, max_dn, nwrong_delta);
}

// Energy-conserving overlap delta = r (1/W0 - 1): value against the oracle,
// and its gradient (translation and rotation of B, used as the force) against
// central finite differences of the oracle's delta.
TEST(EllipsoidKernel, CentreOverlapGradient)
{
  std::mt19937_64 g(4242);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nd(0.0, 1.0);
  auto dref = [](const EllipsoidPose<double> &A, const EllipsoidPose<double> &B) {
    const LD w = oracle(A, B).W0;
    const LD r = std::sqrt((LD)(B.x.x - A.x.x) * (B.x.x - A.x.x) +
                           (LD)(B.x.y - A.x.y) * (B.x.y - A.x.y) +
                           (LD)(B.x.z - A.x.z) * (B.x.z - A.x.z));
    return r * (1 / w - 1);
  };
  int n = 0;
  double max_val = 0.0, max_grad = 0.0;
  const double h = 1e-6;
  while (n < 2000) {
    auto A = random_ellipsoid(g, make_vec3(nd(g), nd(g), nd(g)));
    Vec3<double> dir = make_vec3(nd(g), nd(g), nd(g));
    auto B = random_ellipsoid(g, A.x + (2.0 * u(g) / norm(dir)) * dir);
    const auto c = ellipsoid_contact(A, B);
    if (c.status != STATUS_OK || c.W0 < 0.3 || c.W0 > 1.0 - 1e-4) continue;
    n++;
    double delta;
    Vec3<double> J, P;
    centre_overlap(c, A.x, B.x, delta, J, P);
    const double ref = (double) dref(A, B);
    max_val = std::max(max_val, std::fabs(delta - ref) / ref);
    EXPECT_NEAR(delta, ref, 1e-8 * ref + 1e-14);
    const Vec3<double> lB = c.c - B.x;
    const Vec3<double> rot = cross(lB, P);
    for (int k = 0; k < 3; k++) {
      auto Bp = B, Bm = B;
      Bp.x[k] += h;
      Bm.x[k] -= h;
      const double fd = (double) ((dref(A, Bp) - dref(A, Bm)) / (2 * h));
      // rotation of B by +-h about lab axis k
      Vec3<double> ax = make_vec3(0.0, 0.0, 0.0);
      ax[k] = std::sin(h / 2);
      auto Rp = B, Rm = B;
      Rp.q = qmul(make_quat(std::cos(h / 2), ax.x, ax.y, ax.z), B.q);
      Rm.q = qmul(make_quat(std::cos(h / 2), -ax.x, -ax.y, -ax.z), B.q);
      const double fr = (double) ((dref(A, Rp) - dref(A, Rm)) / (2 * h));
      const double scale = norm(J) + norm(rot);
      max_grad = std::max(max_grad, std::max(std::fabs(J[k] - fd), std::fabs(rot[k] - fr)) / scale);
      EXPECT_NEAR(J[k], fd, 1e-6 * scale) << "pair " << n;
      EXPECT_NEAR(rot[k], fr, 1e-6 * scale) << "pair " << n;
    }
  }
  printf("centre overlap: %d pairs, max rel. error of delta %.3g, of its gradient (vs finite "
         "differences, h = 1e-6) %.3g\n", n, max_val, max_grad);
}

// The kernels are templates; in float (not used by the pair styles: the
// quartic's discriminant needs double) spheres still give W0 and delta to
// float precision, and a prolate pair agrees with the double result.
TEST(EllipsoidKernel, Float)
{
  EllipsoidPose<float> A, B;
  A.x = make_vec3(0.0f, 0.0f, 0.0f);
  A.q = make_quat(1.0f, 0.0f, 0.0f, 0.0f);
  A.axes = make_vec3(0.5f, 0.5f, 0.5f);
  B = A;
  B.axes = make_vec3(0.25f, 0.25f, 0.25f);
  B.x = make_vec3(0.3f, 0.4f, 0.0f);    // |d| = 0.5
  auto c = ellipsoid_contact(A, B);
  ASSERT_EQ(c.status, STATUS_OK);
  EXPECT_NEAR(c.W0, 0.5f / 0.75f, 1e-6f);
  EXPECT_NEAR(c.delta, 0.25f, 1e-6f);
  EXPECT_NEAR(c.n.x, 0.6f, 1e-6f);
  EllipsoidPose<double> Ad, Bd;
  Ad.x = make_vec3(0.0, 0.0, 0.0);
  Ad.q = qnormalize(make_quat(1.0, 0.2, -0.3, 0.1));
  Ad.axes = make_vec3(1.0, 0.2, 0.2);
  Bd.x = make_vec3(0.5, 0.4, 0.1);
  Bd.q = qnormalize(make_quat(0.3, 1.0, 0.2, -0.5));
  Bd.axes = make_vec3(0.6, 0.3, 0.3);
  const auto cd = ellipsoid_contact(Ad, Bd);
  ASSERT_EQ(cd.status, STATUS_OK);
  A.x = make_vec3(0.0f, 0.0f, 0.0f);
  A.q = make_quat((float) Ad.q.w, (float) Ad.q.x, (float) Ad.q.y, (float) Ad.q.z);
  A.axes = make_vec3(1.0f, 0.2f, 0.2f);
  B.x = make_vec3(0.5f, 0.4f, 0.1f);
  B.q = make_quat((float) Bd.q.w, (float) Bd.q.x, (float) Bd.q.y, (float) Bd.q.z);
  B.axes = make_vec3(0.6f, 0.3f, 0.3f);
  c = ellipsoid_contact(A, B);
  ASSERT_EQ(c.status, STATUS_OK);
  EXPECT_NEAR(c.W0, cd.W0, 1e-4);
  EXPECT_NEAR(c.delta, cd.delta, 1e-4 * cd.delta + 1e-5);
  EXPECT_NEAR(c.n.x, cd.n.x, 1e-3);
  EXPECT_NEAR(c.n.y, cd.n.y, 1e-3);
  EXPECT_NEAR(c.n.z, cd.n.z, 1e-3);
}
