// POLYDEM kernel tests: polyhedron-triangle (section clipped by
// Sutherland-Hodgman, prism volume) against CGAL exact geometry; flat
// triangulated walls independent of the triangulation; flat-wall gradients.
#include "cgal_ref.h"
#include "pair_gen.h"

#include "polydem_clip.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace polydem;
using namespace polydem_test;

namespace {

ShapePool &pool()
{
  static ShapePool p(100, 99);
  return p;
}

ClipWorkspace<double> wsd;
ClipWorkspace<float> wsf;

Triangle<double> make_tri(Vec3<double> a, Vec3<double> b, Vec3<double> c)
{
  Triangle<double> t;
  t.v[0] = a;
  t.v[1] = b;
  t.v[2] = c;
  return t;
}

std::array<double, 3> arr(Vec3<double> v)
{
  return {v.x, v.y, v.z};
}
Vec3<double> vec(const std::array<double, 3> &a)
{
  return make_vec3(a[0], a[1], a[2]);
}

}    // namespace

TEST(KernelClip, RandomTrianglesVsCgal)
{
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> pick(0, (int) pool().data.size() - 1);
  double ea = 0, ev = 0, eca = 0, ecv = 0, eaf = 0, evf = 0;
  int npos = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const int s = pick(rng);
    const ShapeData &sd = pool().data[s];
    Pose<double> p = make_pose(make_vec3(u(rng), u(rng), u(rng)), random_quat(rng), 0.5 + u(rng));
    const double L = p.s * sd.radius, Vp = std::pow(p.s, 3) * sd.volume;
    // plane through a point near the centre, random triangle around it
    const Vec3<double> nrm = random_unit(rng);
    Vec3<double> e1 = cross(nrm, random_unit(rng));
    e1 = (1.0 / norm(e1)) * e1;
    const Vec3<double> e2 = cross(nrm, e1);
    const Vec3<double> c = p.x + ((2 * u(rng) - 1) * L) * nrm;
    Vec3<double> v[3];
    const double size = L * (0.2 + 2.0 * u(rng));
    const double ph = 2 * M_PI * u(rng);
    for (int k = 0; k < 3; ++k) {
      const double ang = ph + 2 * M_PI * k / 3 + 0.5 * (u(rng) - 0.5);
      const double rad = size * (0.3 + u(rng));
      v[k] = c + (rad * std::cos(ang) + 0.5 * L * (u(rng) - 0.5)) * e1 + (rad * std::sin(ang)) * e2;
    }
    Triangle<double> t = make_tri(v[0], v[1], v[2]);
    if (dot(cross(v[1] - v[0], v[2] - v[0]), nrm) < 0) std::swap(t.v[1], t.v[2]);
    const RefClip ref = ref_clip(posed_vertices(sd, p), arr(t.v[0]), arr(t.v[1]), arr(t.v[2]));
    const ClipResult<double> r = polyhedron_triangle(make_posed(pool().d[s]->view, p), t, wsd);
    ASSERT_TRUE(r.status == STATUS_OK || r.status == STATUS_SEPARATED) << r.status;
    {    // the caller's posed vertices (fix wall/mesh) give the same result
      std::vector<double> xv;
      for (const auto &q : posed_vertices(sd, p)) xv.insert(xv.end(), q.begin(), q.end());
      const ClipResult<double> r2 =
          polyhedron_triangle(make_posed(pool().d[s]->view, p), t, wsd, xv.data());
      EXPECT_EQ(r2.status, r.status);
      EXPECT_LE(std::fabs(r2.area - r.area), 1e-12 * L * L);
      EXPECT_LE(std::fabs(r2.volume - r.volume), 1e-12 * Vp);
      EXPECT_LE(norm(r2.M - r.M), 1e-12 * L * L * L);
    }
    ea = std::max(ea, std::fabs(r.area - ref.area) / (L * L));
    ev = std::max(ev, std::fabs(r.volume - ref.volume) / Vp);
    EXPECT_LE(std::fabs(r.area - ref.area), 1e-9 * L * L) << i;
    EXPECT_LE(std::fabs(r.volume - ref.volume), 1e-9 * Vp) << i;
    if (ref.area > 1e-6 * L * L) {
      ++npos;
      eca = std::max(eca, norm(r.acentroid - vec(ref.acentroid)) / L);
      EXPECT_LE(norm(r.acentroid - vec(ref.acentroid)), 1e-9 * L);
    }
    if (ref.volume > 1e-6 * Vp) {
      ecv = std::max(ecv, norm(r.vcentroid - vec(ref.vcentroid)) / L);
      EXPECT_LE(norm(r.vcentroid - vec(ref.vcentroid)), 1e-9 * L);
    }
    // float
    Triangle<float> tf;
    for (int k = 0; k < 3; ++k)
      tf.v[k] = make_vec3((float) t.v[k].x, (float) t.v[k].y, (float) t.v[k].z);
    const ClipResult<float> rf =
        polyhedron_triangle(make_posed(pool().f[s]->view, to_float(p)), tf, wsf);
    ASSERT_TRUE(rf.status == STATUS_OK || rf.status == STATUS_SEPARATED);
    eaf = std::max(eaf, std::fabs(rf.area - ref.area) / (L * L));
    evf = std::max(evf, std::fabs(rf.volume - ref.volume) / Vp);
    EXPECT_LE(std::fabs(rf.area - ref.area), 1e-4 * L * L);
    EXPECT_LE(std::fabs(rf.volume - ref.volume), 1e-4 * Vp);
  }
  std::printf("[ clip ] %d cases (%d with section): max |dA|/L^2 double %.2e float %.2e; "
              "max |dV|/Vp double %.2e float %.2e; centroid/L area %.2e volume %.2e\n",
              n, npos, ea, eaf, ev, evf, eca, ecv);
  EXPECT_GE(npos, 1000);
}

// A flat square wall triangulated into 2, 8, 32 and 512 triangles (k x k
// cells, random diagonals, jittered interior vertices) gives the same sums.
TEST(KernelClip, FlatWallTriangulationIndependent)
{
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int s = (int) (u(rng) * pool().data.size()) % (int) pool().data.size();
    const ShapeData &sd = pool().data[s];
    Pose<double> p = make_pose(make_vec3(0.1 * u(rng), 0.1 * u(rng), 0.0), random_quat(rng), 1.0);
    p.x.z = (1.6 * u(rng) - 0.8) * sd.radius;    // wall z = 0, front +z
    const double H = 2.5 * sd.radius;            // square [-H, H]^2 covers the section
    double V0 = 0;
    Vec3<double> S0 = make_vec3(0.0, 0.0, 0.0), M0 = S0;
    for (int k : {1, 2, 4, 16}) {
      std::vector<Vec3<double>> g((k + 1) * (k + 1));
      for (int i = 0; i <= k; ++i)
        for (int j = 0; j <= k; ++j) {
          double x = -H + 2 * H * i / k, y = -H + 2 * H * j / k;
          if (i > 0 && i < k && j > 0 && j < k) {
            x += 0.6 * H / k * (u(rng) - 0.5);
            y += 0.6 * H / k * (u(rng) - 0.5);
          }
          g[i * (k + 1) + j] = make_vec3(x, y, 0.0);
        }
      double V = 0;
      Vec3<double> S = make_vec3(0.0, 0.0, 0.0), M = S;
      auto add = [&](int a, int b, int c) {
        ClipResult<double> r =
            polyhedron_triangle(make_posed(pool().d[s]->view, p), make_tri(g[a], g[b], g[c]), wsd);
        ASSERT_TRUE(r.status == STATUS_OK || r.status == STATUS_SEPARATED);
        V += r.volume;
        S += r.S;
        M += r.M;
      };
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const int a = i * (k + 1) + j, b = (i + 1) * (k + 1) + j, c = (i + 1) * (k + 1) + j + 1,
                    d = i * (k + 1) + j + 1;
          if (u(rng) < 0.5) {
            add(a, b, c);
            add(a, c, d);
          } else {
            add(a, b, d);
            add(b, c, d);
          }
        }
      if (k == 1) {
        V0 = V;
        S0 = S;
        M0 = M;
        continue;
      }
      const double Vp = sd.volume, L = sd.radius;
      double e = std::fabs(V - V0) / Vp;
      e = std::max(e, norm(S - S0) / (L * L));
      e = std::max(e, norm(M - M0) / (L * L * L));
      worst = std::max(worst, e);
      EXPECT_LE(e, 1e-12) << "k " << k << " V " << V << " V0 " << V0;
    }
  }
  std::printf("[ flat wall ] 2/8/32/512 triangles: max relative difference %.2e\n", worst);
}

// flat wall: summed S and M equal finite differences of the summed volume
TEST(KernelClip, FlatWallGradients)
{
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0, 1);
  double emax = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int s = (int) (u(rng) * pool().data.size()) % (int) pool().data.size();
    const ShapeData &sd = pool().data[s];
    const double H = 2.5 * sd.radius;
    const Triangle<double> t1 =
        make_tri(make_vec3(-H, -H, 0.0), make_vec3(H, -H, 0.0), make_vec3(H, H, 0.0));
    const Triangle<double> t2 =
        make_tri(make_vec3(-H, -H, 0.0), make_vec3(H, H, 0.0), make_vec3(-H, H, 0.0));
    Pose<double> p =
        make_pose(make_vec3(0.0, 0.0, (1.2 * u(rng) - 0.6) * sd.radius), random_quat(rng), 1.0);
    auto wall = [&](const Pose<double> &q, Vec3<double> *S, Vec3<double> *M) {
      auto a = polyhedron_triangle(make_posed(pool().d[s]->view, q), t1, wsd);
      auto b = polyhedron_triangle(make_posed(pool().d[s]->view, q), t2, wsd);
      if (S) *S = a.S + b.S;
      if (M) *M = a.M + b.M;
      return a.volume + b.volume;
    };
    Vec3<double> S, M;
    wall(p, &S, &M);
    if (norm(S) < 1e-2 * sd.radius * sd.radius) continue;
    const double h = 1e-7 * sd.radius;
    Vec3<double> fs, fm;
    pose_differences([&](const Pose<double> &x) { return wall(x, nullptr, nullptr); }, p, h,
                     h / sd.radius, fs, fm);
    const double e = std::max(norm(fs - S) / norm(S), norm(fm - M) / (norm(S) * sd.radius));
    emax = std::max(emax, e);
    EXPECT_LE(e, 1e-6);
  }
  std::printf("[ flat wall gradients ] max relative error %.2e\n", emax);
}

// One triangle with open borders (the prism's sides cut the region behind
// it): S and M are still the exact gradient of V, by central finite
// differences in translation and rotation. The section form -n_w A is not
// (it misses the sides' sections): this is what made walls create energy at
// a mesh's open edges.
TEST(KernelClip, OpenBorderGradients)
{
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> pick(0, (int) pool().data.size() - 1);
  double emax = 0, side_max = 0;
  int ncut = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int s = pick(rng);
    const ShapeData &sd = pool().data[s];
    const double L = sd.radius;
    const Pose<double> p = make_pose(make_vec3(0.0, 0.0, (1.2 * u(rng) - 0.8) * L),
                                     random_quat(rng), 1.0);
    // a triangle of the plane z = 0 (front +z) about the particle's size,
    // placed so that its borders cross the part behind the plane
    Vec3<double> v[3];
    const double ph = 2 * M_PI * u(rng), size = L * (0.3 + 1.5 * u(rng));
    const Vec3<double> c = make_vec3(L * (u(rng) - 0.5), L * (u(rng) - 0.5), 0.0);
    for (int k = 0; k < 3; ++k) {
      const double ang = ph + 2 * M_PI * k / 3 + 0.4 * (u(rng) - 0.5);
      v[k] = c + make_vec3(size * std::cos(ang), size * std::sin(ang), 0.0);
    }
    const Triangle<double> t = make_tri(v[0], v[1], v[2]);
    auto vol = [&](const Pose<double> &q) {
      return polyhedron_triangle(make_posed(pool().d[s]->view, q), t, wsd).volume;
    };
    const ClipResult<double> r = polyhedron_triangle(make_posed(pool().d[s]->view, p), t, wsd);
    ASSERT_TRUE(r.status == STATUS_OK || r.status == STATUS_SEPARATED);
    if (r.volume < 1e-3 * sd.volume) continue;
    const double h = 1e-6 * L;
    Vec3<double> fs, fm;
    pose_differences(vol, p, h, h / L, fs, fm);
    // the sides' share of the gradient: S minus the section form
    const double side = norm(r.S + r.area * r.normal) / (L * L);
    if (side > 1e-3) ++ncut;
    side_max = std::max(side_max, side);
    const double e = std::max(norm(fs - r.S) / (L * L), norm(fm - r.M) / (L * L * L));
    emax = std::max(emax, e);
    EXPECT_LE(e, 1e-6) << "trial " << trial << " side share " << side;
  }
  std::printf("[ open border gradients ] %d cases with a side share > 1e-3 L^2 (max %.3f L^2); "
              "max error %.2e\n",
              ncut, side_max, emax);
  EXPECT_GE(ncut, 100);
}

TEST(KernelClip, Workspace)
{
  std::printf("[ workspace ] clip double %lu bytes, float %lu bytes\n",
              clip_workspace_bytes<double>(), clip_workspace_bytes<float>());
  // degenerate triangle -> status, no crash
  Pose<double> p = make_pose(make_vec3(0.0, 0.0, 0.0), make_quat(1.0, 0.0, 0.0, 0.0), 1.0);
  auto r = polyhedron_triangle(
      make_posed(pool().d[0]->view, p),
      make_tri(make_vec3(0.0, 0.0, 0.0), make_vec3(1.0, 0.0, 0.0), make_vec3(2.0, 0.0, 0.0)), wsd);
  EXPECT_EQ(r.status, STATUS_DEGENERATE);
  // cube (side 1) half into a big triangle: V = 1/2, A = 1
  r = polyhedron_triangle(
      make_posed(pool().d[0]->view, p),
      make_tri(make_vec3(-5.0, -5.0, 0.0), make_vec3(5.0, -5.0, 0.0), make_vec3(0.0, 5.0, 0.0)),
      wsd);
  EXPECT_NEAR(r.volume, 0.5, 1e-14);
  EXPECT_NEAR(r.area, 1.0, 1e-14);
  EXPECT_NEAR(r.S.z, -1.0, 1e-14);
  EXPECT_NEAR(r.vcentroid.z, -0.25, 1e-14);
}
