// fix insert/polyhedron kernels (polydem_insert.h): the generator, the draws
// of a candidate against their laws (Kolmogorov-Smirnov and chi^2 tests at
// significance 1e-3, fixed seeds), and the rejection test against the exact
// kernels (GJK distance, overlap volume, ellipsoid contact).

#include "polydem_ellipsoid.h"
#include "polydem_insert.h"
#include "polydem_insert_space.h"
#include "polydem_overlap.h"
#include "polydem_shape_template.h"
#include "insert_stats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace polydem;
using insert_test::ks;
using insert_test::ks_crit;

namespace {


double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

InsertBody<double> body(const ShapeView<double> *v, double s, const Vec3<double> &x,
                        const Quat<double> &q, double rad, double rin)
{
  InsertBody<double> b;
  b.view = v;
  b.x = x;
  b.R = quat_to_mat(q);
  b.s = s;
  b.ax = make_vec3(0.0, 0.0, 0.0);
  b.radius = rad * s;
  b.inradius = rin * s;
  return b;
}

double inradius(const PolyShapeTemplate &t)
{
  double d = 1e300;
  for (int f = 0; f < t.nfaces(); f++) d = std::min(d, t.plane(f)[3]);
  return d;
}

}    // namespace

TEST(InsertRng, UniformAndRestartableState)
{
  InsertRng r;
  r.seed(4711);
  std::vector<double> u(100000);
  for (auto &x : u) {
    x = r.uniform();
    ASSERT_GT(x, 0.0);
    ASSERT_LT(x, 1.0);
  }
  EXPECT_LT(ks(u, [](double x) { return x; }), ks_crit(u.size()));
  // the state is the four words: a copy continues the same sequence
  InsertRng c = r;
  for (int i = 0; i < 100; i++) ASSERT_EQ(r.next(), c.next());
  // and different seeds give different sequences
  InsertRng a, b;
  a.seed(1);
  b.seed(2);
  EXPECT_NE(a.next(), b.next());
}

TEST(InsertDraws, RandomQuatGivesUniformAxes)
{
  // a body axis R e_k of a uniform rotation is uniform on the sphere:
  // cos(theta) uniform in [-1, 1] and phi uniform in [0, 2 pi)
  InsertRng r;
  r.seed(20261201);
  const int n = 50000;
  for (int k = 0; k < 3; k++) {
    std::vector<double> c(n), p(n);
    InsertRng rr = r;
    for (int i = 0; i < n; i++) {
      const Quat<double> q = random_quat(rr);
      ASSERT_NEAR(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, 1.0, 1e-14);
      const Mat3<double> R = quat_to_mat(q);
      const Vec3<double> e = make_vec3(R.m[0][k], R.m[1][k], R.m[2][k]);
      c[i] = e.z;
      p[i] = std::atan2(e.y, e.x);
    }
    EXPECT_LT(ks(c, [](double x) { return 0.5 * (x + 1.0); }), ks_crit(n)) << "axis " << k;
    EXPECT_LT(ks(p, [](double x) { return (x + M_PI) / (2.0 * M_PI); }), ks_crit(n)) << "axis " << k;
  }
}

TEST(InsertDraws, ScaleDistributionsFollowTheirLaws)
{
  InsertRng r;
  r.seed(99);
  const int n = 40000;
  auto sample = [&](const ScaleDist &d) {
    std::vector<double> s(n);
    for (auto &x : s) x = d.draw(r);
    return s;
  };
  ScaleDist u;
  u.kind = ScaleDist::UNIFORM;
  u.a = 2.0;
  u.b = 3.0;
  EXPECT_LT(ks(sample(u), [](double x) { return x - 2.0; }), ks_crit(n));
  EXPECT_NEAR(u.moment(3), (81.0 - 16.0) / 4.0, 1e-12);

  // normal N(1, 0.2) cut to [0.8, 1.5]
  ScaleDist g;
  g.kind = ScaleDist::NORMAL;
  g.a = 1.0;
  g.b = 0.2;
  g.lo = 0.8;
  g.hi = 1.5;
  const double Z = normal_cdf(2.5) - normal_cdf(-1.0);
  EXPECT_NEAR(g.truncated_mass(), Z, 1e-14);
  auto Fg = [&](double x) { return (normal_cdf((x - 1.0) / 0.2) - normal_cdf(-1.0)) / Z; };
  auto sg = sample(g);
  EXPECT_LT(ks(sg, Fg), ks_crit(n));
  for (double x : sg) ASSERT_TRUE(x >= 0.8 && x <= 1.5);
  // mean of the truncated normal: mu + sigma (phi(a) - phi(b)) / Z
  const double phi_a = std::exp(-0.5) / std::sqrt(2 * M_PI), phi_b = std::exp(-3.125) / std::sqrt(2 * M_PI);
  EXPECT_NEAR(g.moment(1), 1.0 + 0.2 * (phi_a - phi_b) / Z, 1e-10);

  // lognormal, median 1e-3, sigma 0.3, cut to [6e-4, 2e-3]
  ScaleDist l;
  l.kind = ScaleDist::LOGNORMAL;
  l.a = 1e-3;
  l.b = 0.3;
  l.lo = 6e-4;
  l.hi = 2e-3;
  const double za = std::log(0.6) / 0.3, zb = std::log(2.0) / 0.3;
  const double Zl = normal_cdf(zb) - normal_cdf(za);
  auto Fl = [&](double x) { return (normal_cdf(std::log(x / 1e-3) / 0.3) - normal_cdf(za)) / Zl; };
  EXPECT_LT(ks(sample(l), Fl), ks_crit(n));
  // E[s^3] = a^3 exp(9 b^2 / 2) [Phi(zb - 3b) - Phi(za - 3b)] / Z
  const double m3 = 1e-9 * std::exp(4.5 * 0.09) * (normal_cdf(zb - 0.9) - normal_cdf(za - 0.9)) / Zl;
  EXPECT_NEAR(l.moment(3) / m3, 1.0, 1e-9);

  // discrete list: chi^2 with 2 degrees of freedom, critical 13.82 at 1e-3
  ScaleDist d;
  d.kind = ScaleDist::LIST;
  d.nlist = 3;
  d.val[0] = 1.0, d.val[1] = 2.0, d.val[2] = 4.0;
  d.cum[0] = 0.2, d.cum[1] = 0.7, d.cum[2] = 1.0;
  double cnt[3] = {0, 0, 0};
  for (double x : sample(d)) cnt[x == 1.0 ? 0 : (x == 2.0 ? 1 : 2)]++;
  const double p[3] = {0.2, 0.5, 0.3};
  double chi2 = 0.0;
  for (int k = 0; k < 3; k++) chi2 += (cnt[k] - n * p[k]) * (cnt[k] - n * p[k]) / (n * p[k]);
  EXPECT_LT(chi2, 13.82);
  EXPECT_NEAR(d.moment(3), 0.2 + 0.5 * 8 + 0.3 * 64, 1e-12);
}

TEST(InsertReject, PolyhedraAgreeWithGjkAndTheOverlapVolume)
{
  // random close pairs: whenever the rejection test says apart, GJK finds
  // them separated and the overlap volume is 0; when it rejects at gap 0,
  // GJK's distance is below 1e-6 of the size (it is not over-conservative)
  const std::string dir = POLYDEM_POTENTIALS_DIR;
  const auto A = PolyShapeTemplate::from_file(dir + "/dodecahedron.shape");
  const auto B = PolyShapeTemplate::from_file(dir + "/catalyst_cylinder.shape");
  const auto va = A.view(), vb = B.view();
  const double sb = 1.0 / B.radius();    // both of radius ~1.4 and 1
  InsertRng r;
  r.seed(7);
  auto ws = std::make_unique<OverlapWorkspace<double>>();
  int napart = 0, nreject = 0;
  for (int t = 0; t < 4000; t++) {
    const Quat<double> qa = random_quat(r), qb = random_quat(r);
    Vec3<double> d = make_vec3(r.uniform() - 0.5, r.uniform() - 0.5, r.uniform() - 0.5);
    d = ((A.radius() + 1.0) * (0.6 + 0.5 * r.uniform()) / norm(d)) * d;
    const auto a = body(&va, 1.0, make_vec3(0.0, 0.0, 0.0), qa, A.radius(), inradius(A));
    const auto b = body(&vb, sb, d, qb, B.radius(), inradius(B));
    Pose<double> pa{a.x, qa, 1.0}, pb{b.x, qb, sb};
    const auto pa_ = make_posed(va, pa), pb_ = make_posed(vb, pb);
    const auto g = gjk_intersect(pa_, pb_);
    if (bodies_apart(a, b, 0.0)) {
      napart++;
      ASSERT_EQ(g.status, STATUS_SEPARATED) << t;
      const auto o = polyhedron_overlap(pa_, pb_, *ws);
      ASSERT_EQ(o.volume, 0.0) << t;
    } else {
      nreject++;
      if (g.status == STATUS_SEPARATED) ASSERT_LT(g.distance, 1e-6) << t;
    }
    // a gap g rejects every pair closer than g
    if (bodies_apart(a, b, 0.05)) ASSERT_TRUE(g.status == STATUS_SEPARATED && g.distance > 0.05 * (1 - 1e-3));
  }
  EXPECT_GT(napart, 400);
  EXPECT_GT(nreject, 400);
}

TEST(InsertReject, EllipsoidsAgreeWithTheAlgebraicContact)
{
  // ellipsoid pairs: apart iff the characteristic-quartic test (ellipsoid
  // seed Eqs. 9-11) separates them
  InsertRng r;
  r.seed(11);
  int napart = 0, nreject = 0;
  for (int t = 0; t < 3000; t++) {
    InsertBody<double> a, b;
    const Quat<double> qa = random_quat(r), qb = random_quat(r);
    a.view = b.view = nullptr;
    a.ax = make_vec3(1.0, 0.5, 0.3);
    b.ax = make_vec3(0.8, 0.8, 0.2);
    a.radius = 1.0, a.inradius = 0.3, b.radius = 0.8, b.inradius = 0.2;
    a.s = b.s = 1.0;
    a.x = make_vec3(0.0, 0.0, 0.0);
    Vec3<double> d = make_vec3(r.uniform() - 0.5, r.uniform() - 0.5, r.uniform() - 0.5);
    b.x = (1.8 * r.uniform() / norm(d)) * d;
    a.R = quat_to_mat(qa);
    b.R = quat_to_mat(qb);
    EllipsoidPose<double> ea{a.x, qa, a.ax}, eb{b.x, qb, b.ax};
    const auto c = ellipsoid_contact(ea, eb);
    ASSERT_TRUE(c.status == STATUS_OK || c.status == STATUS_SEPARATED);
    if (bodies_apart(a, b, 0.0)) {
      napart++;
      ASSERT_EQ(c.status, STATUS_SEPARATED) << t;
    } else {
      nreject++;
      // rejected only if overlapping or nearly touching (GJK upper bound)
      double lb, ub;
      gjk_gap_bounds(a, b, a.x - b.x, 1e-12, 1e300, 1e-6, lb, ub);
      if (c.status == STATUS_SEPARATED) ASSERT_LE(ub, 1e-6) << t;
    }
  }
  EXPECT_GT(napart, 300);
  EXPECT_GT(nreject, 300);
}

TEST(InsertReject, PointWithinIsAnUpperBound)
{
  // point_within(b, p, r) is true only if the distance is <= r (the cube
  // [-1,1]^3: distance from p to it is |max(|p| - 1, 0)|)
  const std::string dir = POLYDEM_POTENTIALS_DIR;
  const auto C = PolyShapeTemplate::from_file(dir + "/cube.shape");
  const auto v = C.view();
  const double half = C.vertex(0)[0] > 0 ? C.vertex(0)[0] : -C.vertex(0)[0];
  const auto b = body(&v, 1.0 / half, make_vec3(0.0, 0.0, 0.0), make_quat(1.0, 0.0, 0.0, 0.0),
                      C.radius(), inradius(C));
  InsertRng r;
  r.seed(5);
  int nin = 0;
  for (int t = 0; t < 5000; t++) {
    const auto p = make_vec3(4 * r.uniform() - 2, 4 * r.uniform() - 2, 4 * r.uniform() - 2);
    const auto q = make_vec3(std::max(std::fabs(p.x) - 1, 0.0), std::max(std::fabs(p.y) - 1, 0.0),
                             std::max(std::fabs(p.z) - 1, 0.0));
    const double dist = norm(q);
    const bool w = point_within(b, p, 0.3);
    if (w) ASSERT_LE(dist, 0.3 * (1 + 1e-12)) << t;
    if (dist < 0.3 * (1 - 2e-3)) ASSERT_TRUE(w) << t;
    nin += w;
  }
  EXPECT_GT(nin, 500);
}

TEST(InsertVoids, DeadCellsHoldNoPlace)
{
  // 150 randomly oriented cubes of half edge 1 in a 12^3 box, candidates of
  // inscribed radius 0.8: a point in a dead cell is within 0.8 of a cube
  // (exact distance in the cube's frame), before and after the checks of
  // cells whose draws failed (the union of several cubes' zones)
  const std::string dir = POLYDEM_POTENTIALS_DIR;
  const auto C = PolyShapeTemplate::from_file(dir + "/cube.shape");
  const auto v = C.view();
  const double half = std::fabs(C.vertex(0)[0]), s = 1.0 / half;
  InsertRng r;
  r.seed(3);
  std::vector<InsertBody<double>> bodies;
  std::vector<Quat<double>> qs;
  for (int i = 0; i < 150; i++) {
    qs.push_back(random_quat(r));
    bodies.push_back(body(&v, s, make_vec3(12 * r.uniform(), 12 * r.uniform(), 12 * r.uniform()),
                          qs.back(), C.radius(), inradius(C)));
  }
  auto dist = [&](const Vec3<double> &p) {
    double d = 1e300;
    for (const auto &b : bodies) {
      const Vec3<double> q = matTvec(b.R, p - b.x);
      const Vec3<double> e = make_vec3(std::max(std::fabs(q.x) - 1, 0.0), std::max(std::fabs(q.y) - 1, 0.0),
                                       std::max(std::fabs(q.z) - 1, 0.0));
      d = std::min(d, norm(e));
    }
    return d;
  };
  const double lo[3] = {0, 0, 0}, hi[3] = {12, 12, 12}, rin = 0.8;
  InsertGrid grid;
  grid.setup(lo, hi, 2 * std::sqrt(3.0) + rin, std::vector<InsertBody<double>>(bodies));
  InsertVoids voids;
  auto inside = [](double, double, double) { return true; };
  auto surface = [](double, double, double, double) { return 1e300; };
  voids.setup(lo, hi, rin, false, inside, surface, grid);
  std::vector<double> pts(3 * 40000);
  for (double &x : pts) x = 12 * r.uniform();
  auto check = [&](int &ndead) {
    ndead = 0;
    for (size_t t = 0; t < pts.size() / 3; t++) {
      const double *x = &pts[3 * t];
      if (!voids.dead_at(x)) continue;
      ndead++;
      ASSERT_LE(dist(make_vec3(x[0], x[1], x[2])), rin * (1 + 1e-12)) << t;
    }
  };
  int dead0 = 0, dead1 = 0;
  check(dead0);
  // draws whose point is covered fail: their cells get checked
  for (int t = 0; t < 1000000; t++) {
    double x[3];
    if (!voids.sample(r, inside, x)) break;
    if (dist(make_vec3(x[0], x[1], x[2])) <= rin) voids.failed(grid);
  }
  check(dead1);
  EXPECT_GT(dead0, 4000);
  EXPECT_GT(dead1, dead0);    // the checks killed cells no single cube covers
}
