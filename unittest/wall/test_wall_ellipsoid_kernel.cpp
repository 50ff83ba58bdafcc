// Kernel of ellipsoids on mesh walls (polydem_wall_ellipsoid.h, issue 16),
// float and double, without LAMMPS:
// - plane: the overlap is the support-function depth sigma(n) - h, the
//   deepest point c - M n / sigma, S = -n, M = (p* - c) x (-n), the cap
//   volume fraction (1-r)^2 (2+r)/4; for random orientations, tilted meshes,
//   foot anywhere (vertices, edges, inside) - to 1e-13 (double) / 2e-5 (float)
//   of the semi-axis;
// - S and M are the gradient of delta (central differences in translation
//   and rotation, 1e-7 relative);
// - the same at edges and vertices of an open plate (the exact gradient);
// - a sweep across the border of an open mesh (face -> edge -> vertex ->
//   gone) is continuous: no step of 5e-4 a changes delta by more than
//   2e-3 a nor the gradient S by more than 1e-2;
// - behind the acting side (kept side): the face contact keeps pushing back;
// - NaN poses are counted as degenerate, never a contact;
// - a sphere's liquid bridge on a plate (fix wall/mesh bridge) follows
//   Willett's force with R = 2 a across the gap, also at an open edge.
#include "polydem_damping.h"
#include "polydem_stl.h"
#include "polydem_wall_ellipsoid.h"
#include "wall_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace polydem;
using wall_test::Tris;

namespace {

// a mesh, its grid and its smooth regions at the tests' patch angle (20
// degrees) as kernel data of type T (storage kept here)
template <typename T> struct Mesh {
  std::vector<T> tri, plane, box;
  std::vector<int> region;
  MeshGrid g;
  MeshGridView<T> v;
  explicit Mesh(const Tris &t, double h = 0.05)
  {
    g = build_mesh_grid(t, h);
    tri.assign(t.begin(), t.end());
    plane.assign(g.plane.begin(), g.plane.end());
    box.assign(g.box.begin(), g.box.end());
    v.tri = tri.data();
    v.ntri = (int) (t.size() / 9);
    for (int d = 0; d < 3; d++) {
      v.lo[d] = T(g.lo[d]);
      v.n[d] = g.n[d];
    }
    v.h = T(g.h);
    v.start = g.start.data();
    v.items = g.items.data();
    v.plane = plane.data();
    v.box = box.data();
    region = mesh_regions(t, std::cos(20.0 * M_PI / 180.0), 1e-12);
    v.region = region.data();
  }
};

// rotate the points of t by R about the origin, then shift by d
Tris transformed(const Tris &t, const Mat3<double> &R, const Vec3<double> &d)
{
  Tris o(t.size());
  for (size_t k = 0; k < t.size(); k += 3) {
    const Vec3<double> p = matvec(R, make_vec3(t[k], t[k + 1], t[k + 2])) + d;
    o[k] = p.x, o[k + 1] = p.y, o[k + 2] = p.z;
  }
  return o;
}

Quat<double> random_quat(std::mt19937_64 &rng)
{
  std::normal_distribution<double> g;
  return qnormalize(make_quat(g(rng), g(rng), g(rng), g(rng)));
}

template <typename T> WallEllipsoid<T> posed(const Vec3<double> &c, const Mat3<double> &R,
                                              const Vec3<double> &ax)
{
  WallEllipsoid<T> e;
  e.c = make_vec3(T(c.x), T(c.y), T(c.z));
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++) e.R.m[i][k] = T(R.m[i][k]);
  e.ax = make_vec3(T(ax.x), T(ax.y), T(ax.z));
  return e;
}

// delta of the single patch of e (0 if none)
template <typename T> T depth_of(const WallEllipsoid<T> &e, const MeshGridView<T> &g)
{
  WallPatches<T> P;
  wall_ellipsoid_patches(e, g, T(std::cos(20.0 * M_PI / 180.0)), P);
  return P.n ? P.p[0].depth : T(0);
}

template <typename T> void plane_case(double tol)
{
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3<double> ax = make_vec3(0.02, 0.012, 0.007);
  double worst = 0.0;
  int n = 0;
  for (int trial = 0; trial < 200; trial++) {
    // a flat 4 x 4 mesh (32 triangles) of side 0.2, tilted and shifted
    const Mat3<double> Rw = quat_to_mat(random_quat(rng));
    const Vec3<double> d = make_vec3(0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng));
    const Mesh<T> m(transformed(wall_test::flat(-0.1, 0.1, -0.1, 0.1, 0.0, 4, 4), Rw, d));
    const Vec3<double> nw = matvec(Rw, make_vec3(0.0, 0.0, 1.0));
    const Mat3<double> R = quat_to_mat(random_quat(rng));
    // foot: anywhere, or on a vertex / an edge / the diagonal of the mesh
    Vec3<double> foot = make_vec3(0.09 * u(rng), 0.09 * u(rng), 0.0);
    if (trial % 4 == 1) foot = make_vec3(0.05, -0.05, 0.0);    // a vertex
    if (trial % 4 == 2) foot.x = 0.0;                          // an edge
    if (trial % 4 == 3) foot.y = foot.x;                       // a diagonal
    // support sigma(n) = |A R^T n|, deepest point c - M n / sigma
    const Vec3<double> nb = matTvec(R, nw);
    const Vec3<double> an = make_vec3(ax.x * nb.x, ax.y * nb.y, ax.z * nb.z);
    const double sig = norm(an);
    const double h = sig * (0.5 + 0.49 * u(rng));    // overlap (0.01 .. 0.99) x sigma
    const Vec3<double> c = matvec(Rw, foot) + d + h * nw;
    const Vec3<double> Mn = matvec(R, make_vec3(ax.x * an.x, ax.y * an.y, ax.z * an.z));
    const Vec3<double> ps = c - (1.0 / sig) * Mn;
    const double r = h / sig, frac = (1 - r) * (1 - r) * (2 + r) / 4;
    WallPatches<T> P;
    const auto e = posed<T>(c, R, ax);
    wall_ellipsoid_patches(e, m.v, T(std::cos(20.0 * M_PI / 180.0)), P);
    ASSERT_EQ(P.n, 1) << trial;
    const WallPatch<T> &p = P.p[0];
    const double a = ax.x;
    auto err = [&](const Vec3<T> &x, const Vec3<double> &y) {
      return norm(make_vec3(double(x.x) - y.x, double(x.y) - y.y, double(x.z) - y.z));
    };
    const double e1 = std::fabs(double(p.depth) - (sig - h)) / a;
    const double e2 = err(p.S, -1.0 * nw);
    const double e3 = err(p.vc, ps) / a;
    const double e4 = err(p.M, cross(ps - c, -1.0 * nw)) / a;
    const double e5 = err(p.ac, ps + (sig - h) * nw) / a;    // in the wall's plane
    const double e6 = std::fabs(double(p.volume) / (4.0 / 3.0 * M_PI * ax.x * ax.y * ax.z) - frac);
    for (double x : {e1, e2, e3, e4, e5, e6}) {
      EXPECT_LE(x, tol) << trial << ": " << e1 << " " << e2 << " " << e3 << " " << e4 << " " << e5
                        << " " << e6;
      worst = std::fmax(worst, x);
    }
    EXPECT_FALSE(p.behind);
    n++;
  }
  std::printf("[ ell wall ] %s plane: %d poses, largest error %.3g (of the semi-axis a)\n",
              sizeof(T) == 8 ? "double" : "float", n, worst);
}

// central differences of the kernel's delta for the ellipsoid (centre c,
// orientation q, semi-axes ax) on mesh g: along each lab axis (step eps) and
// for rotations about it (angle phi)
struct Gradient {
  Vec3<double> dx, dtheta;
};
Gradient depth_gradient(const Vec3<double> &c, const Quat<double> &q, const Vec3<double> &ax,
                        const MeshGridView<double> &g, double eps, double phi)
{
  Gradient out;
  const Mat3<double> R = quat_to_mat(q);
  for (int k = 0; k < 3; k++) {
    Vec3<double> d = make_vec3(0.0, 0.0, 0.0);
    d[k] = eps;
    out.dx[k] =
        (depth_of(posed<double>(c + d, R, ax), g) - depth_of(posed<double>(c - d, R, ax), g)) /
        (2 * eps);
    Vec3<double> axis = make_vec3(0.0, 0.0, 0.0);
    axis[k] = 1.0;
    auto rot = [&](double a) {
      const Quat<double> dq = make_quat(std::cos(a / 2), std::sin(a / 2) * axis.x,
                                        std::sin(a / 2) * axis.y, std::sin(a / 2) * axis.z);
      return quat_to_mat(qmul(dq, q));
    };
    out.dtheta[k] = (depth_of(posed<double>(c, rot(phi), ax), g) -
                     depth_of(posed<double>(c, rot(-phi), ax), g)) /
        (2 * phi);
  }
  return out;
}

// the half-width of the ellipsoid of semi-axes ax turned by R along the lab
// direction n (unit): |diag(ax) R^T n|
double support_halfwidth(const Vec3<double> &ax, const Mat3<double> &R, const Vec3<double> &n)
{
  const Vec3<double> nb = matTvec(R, n);
  return norm(make_vec3(ax.x * nb.x, ax.y * nb.y, ax.z * nb.z));
}

// the border tests' scene: an ellipsoid turned by R over an open square
// plate (10 cm, z = 0), its half-width sig along z
struct TiltedOverPlate {
  Vec3<double> ax = make_vec3(0.02, 0.012, 0.007);
  Mesh<double> m{wall_test::flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2)};
  Mat3<double> R = quat_to_mat(qnormalize(make_quat(0.9, 0.2, -0.3, 0.25)));
  double sig = support_halfwidth(ax, R, make_vec3(0.0, 0.0, 1.0));
};

}    // namespace

TEST(WallEllipsoidKernel, PlaneIsTheSupportDepthDouble) { plane_case<double>(1e-13); }
TEST(WallEllipsoidKernel, PlaneIsTheSupportDepthFloat) { plane_case<float>(2e-5); }

// dm/dx = S, dm/dtheta = M (central differences of the kernel's own delta) for
// face contacts (the foot of the centre, along -M n, well inside the mesh)
TEST(WallEllipsoidKernel, GradientOfTheOverlap)
{
  std::mt19937_64 rng(5);
  const Vec3<double> ax = make_vec3(0.02, 0.012, 0.007);
  const Mat3<double> Rw = quat_to_mat(random_quat(rng));
  const Mesh<double> m(transformed(wall_test::flat(-0.1, 0.1, -0.1, 0.1, 0.0, 3, 3), Rw,
                                   make_vec3(0.0, 0.0, 0.0)));
  const Vec3<double> nw = matvec(Rw, make_vec3(0.0, 0.0, 1.0));
  double worst = 0.0;
  for (int trial = 0; trial < 20; trial++) {
    const Quat<double> q = random_quat(rng);
    const Mat3<double> R = quat_to_mat(q);
    const double sig = support_halfwidth(ax, R, nw);
    const Vec3<double> c = matvec(Rw, make_vec3(0.006 * trial - 0.06, 0.02, 0.0)) +
        0.8 * sig * nw;
    WallPatches<double> P;
    wall_ellipsoid_patches(posed<double>(c, R, ax), m.v, std::cos(20.0 * M_PI / 180.0), P);
    ASSERT_EQ(P.n, 1);
    const Gradient gd = depth_gradient(c, q, ax, m.v, 1e-6 * ax.x, 1e-6);
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(gd.dx[k], P.p[0].S[k], 1e-7);
      EXPECT_NEAR(gd.dtheta[k], P.p[0].M[k], 1e-7 * ax.x);
      worst = std::fmax(worst, std::fabs(gd.dx[k] - P.p[0].S[k]));
      worst = std::fmax(worst, std::fabs(gd.dtheta[k] - P.p[0].M[k]) / ax.x);
    }
  }
  std::printf("[ ell wall ] gradient: largest |finite difference - (S, M/a)| %.3g\n", worst);
}

// The same at the borders of an open plate
// (edge and vertex contacts, the centre in front): S and M are the exact
// gradient of delta, so that k delta^2 / 2 is conserved at a mesh's open
// edges and at sharp edges too.
TEST(WallEllipsoidKernel, GradientAtBorders)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3<double> ax = make_vec3(0.02, 0.012, 0.007);
  const Mesh<double> plate(wall_test::flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  double worst = 0.0;
  int nedge = 0, nvert = 0;
  for (int trial = 0; trial < 200; trial++) {
    const Quat<double> q = random_quat(rng);
    const Mat3<double> R = quat_to_mat(q);
    // centre beyond the edge x = 0.05 (or beyond the corner), above the plane
    const bool corner = trial % 2;
    const double off = 0.004 + 0.01 * u(rng);
    const Vec3<double> c = make_vec3(0.05 + off, corner ? 0.05 + off * u(rng) : 0.04 * u(rng),
                                     0.012 * u(rng));
    WallPatches<double> P;
    wall_ellipsoid_patches(posed<double>(c, R, ax), plate.v, std::cos(20.0 * M_PI / 180.0), P);
    if (P.n != 1 || P.p[0].depth < 1e-3 * ax.z) continue;
    (corner ? nvert : nedge)++;
    const Gradient gd = depth_gradient(c, q, ax, plate.v, 1e-7 * ax.x, 1e-7);
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(gd.dx[k], P.p[0].S[k], 1e-6) << trial;
      EXPECT_NEAR(gd.dtheta[k], P.p[0].M[k], 1e-6 * ax.x) << trial;
      worst = std::fmax(worst, std::fabs(gd.dx[k] - P.p[0].S[k]));
      worst = std::fmax(worst, std::fabs(gd.dtheta[k] - P.p[0].M[k]) / ax.x);
    }
  }
  std::printf("[ ell wall ] border gradient: %d edge, %d vertex contacts, largest |finite "
              "difference - (S, M/a)| %.3g\n", nedge, nvert, worst);
  EXPECT_GT(nedge, 30);
  EXPECT_GT(nvert, 30);
}

// An ellipsoid slides off the corner of an open square plate: face, then
// edge, then vertex region, then no contact. delta and the normal change
// continuously.
TEST(WallEllipsoidKernel, ContinuousAcrossTheBorder)
{
  const auto &[ax, m, R, sig] = TiltedOverPlate();
  double dprev = -1.0, jump = 0.0, njump = 0.0;
  Vec3<double> nprev = make_vec3(0.0, 0.0, 0.0);
  int regions[3] = {0, 0, 0};    // face, border, none
  const int nstep = 6000;    // steps of 1e-5 = 5e-4 a
  for (int s = 0; s <= nstep; s++) {
    // from inside across the edge x = 0.05 (at y = 0.045), then past the corner
    const double t = 0.03 + 0.06 * s / nstep;
    const Vec3<double> c = make_vec3(t, 0.9 * t, 0.7 * sig);
    WallPatches<double> P;
    wall_ellipsoid_patches(posed<double>(c, R, ax), m.v, std::cos(20.0 * M_PI / 180.0), P);
    const double d = P.n ? P.p[0].depth : 0.0;
    if (!P.n) regions[2]++;
    else if (std::fabs(P.p[0].S.z + 1.0) < 1e-12) regions[0]++;
    else regions[1]++;
    if (dprev >= 0.0) {
      jump = std::fmax(jump, std::fabs(d - dprev));
      if (P.n && norm(nprev) > 0.0) njump = std::fmax(njump, norm(P.p[0].S - nprev));
    }
    dprev = d;
    nprev = P.n ? P.p[0].S : make_vec3(0.0, 0.0, 0.0);
  }
  std::printf("[ ell wall ] border sweep: %d face, %d edge/vertex, %d apart; largest step of "
              "delta %.3g a, of the normal %.3g\n", regions[0], regions[1], regions[2],
              jump / ax.x, njump);
  EXPECT_GT(regions[0], 10);
  EXPECT_GT(regions[1], 10);
  EXPECT_GT(regions[2], 10);
  EXPECT_LT(jump, 2e-3 * ax.x);
  EXPECT_LT(njump, 1e-2);
}

// Two-sided wall, centre pushed behind the plane while a kept contact claims
// the front: the overlap grows beyond sigma and the normal still points
// into the wall from the front (the particle is pushed back, not through).
TEST(WallEllipsoidKernel, KeptSideBehindThePlane)
{
  const auto &[ax, m, R, sig] = TiltedOverPlate();
  WallSides<double> sides;
  sides.both = 1;
  sides.n = 1;
  sides.nc[0] = make_vec3(0.0, 0.0, -1.0);    // kept: met from the front (+z)
  for (double h : {0.01 * sig, -0.0002, -0.0005}) {
    sides.ec[0] = h;    // the kept plane distance follows the centre
    WallPatches<double> P;
    wall_ellipsoid_patches(posed<double>(make_vec3(0.01, 0.003, h), R, ax), m.v,
                           std::cos(20.0 * M_PI / 180.0), P, &sides);
    ASSERT_EQ(P.n, 1);
    EXPECT_NEAR(P.p[0].depth, sig - h, 1e-15);
    EXPECT_NEAR(P.p[0].S.z, -1.0, 1e-15);
    EXPECT_EQ(P.p[0].behind, h < 0.0 ? 1 : 0);
  }
  // without the kept side the centre's side acts: the back, pushed down
  WallPatches<double> P;
  sides.n = 0;
  wall_ellipsoid_patches(posed<double>(make_vec3(0.01, 0.003, -0.0005), R, ax), m.v,
                         std::cos(20.0 * M_PI / 180.0), P, &sides);
  ASSERT_EQ(P.n, 1);
  EXPECT_NEAR(P.p[0].S.z, 1.0, 1e-15);
  EXPECT_NEAR(P.p[0].depth, sig - 0.0005, 1e-15);
}

TEST(WallEllipsoidKernel, NanIsDegenerate)
{
  const Mesh<double> m(wall_test::flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  WallPatches<double> P;
  const double nan = std::nan("");
  auto e = posed<double>(make_vec3(0.0, 0.0, 0.001), quat_to_mat(make_quat(1.0, 0.0, 0.0, 0.0)),
                         make_vec3(0.02, 0.012, 0.007));
  e.R.m[0][0] = nan;
  wall_ellipsoid_patches(e, m.v, 0.9, P);
  EXPECT_EQ(P.n, 0);
  EXPECT_GT(P.ndegenerate, 0);
}

// Liquid bridge of a sphere on a mesh (fix wall/mesh bridge): Willett et
// al.'s force (Langmuir 16 (2000) 9396, Eq. 13's closed form) with the
// sphere-plane radius R = 2 a, written here independently of the kernel:
// F(s) = 2 pi R gamma cos(theta) / (1 + 1.05 s^ + 2.5 s^2), s^ = s sqrt(R / V).
namespace {
double willett(double s, double R, double V, double gamma, double cth)
{
  const double u = s * std::sqrt(R / V);
  return 2.0 * M_PI * R * gamma * cth / (1.0 + 1.05 * u + 2.5 * u * u);
}

// one step of the wall kernel for a sphere of radius a at c (velocity 0)
WallForce<double> sphere_on_mesh(const Mesh<double> &m, double a, const Vec3<double> &c,
                                 const ContactLaw<double> &law, double *hist, bool update,
                                 WallPatches<double> &P)
{
  MeshPose<double> mp;
  mp.o = mp.d = mp.vw = mp.w = make_vec3(0.0, 0.0, 0.0);
  mp.q = make_quat(1.0, 0.0, 0.0, 0.0);
  mp.R = quat_to_mat(mp.q);
  Pose<double> lab;
  lab.x = c;
  lab.q = mp.q;
  lab.s = 1.0;
  const Vec3<double> z = make_vec3(0.0, 0.0, 0.0);
  return wall_ellipsoid_particle(make_vec3(a, a, a), lab, mp, m.v, law, 1e-3, 1e-6,
                                 std::cos(20.0 * M_PI / 180.0), 1, z, z, hist, update, P);
}
}    // namespace

// Pulled off a flat plate: forms in contact (F(0) added to the contact),
// then across the gap F(s) = Willett's at 1e-12, the pull through the
// centre (no torque), U(s) whose -dU/dz is F (central differences, 1e-7),
// nothing beyond s_c = (1 + theta/2) V^(1/3), and no bridge again after
// the rupture, nor one that never touched.
TEST(WallBridgeKernel, PullOffFollowsWillett)
{
  const double a = 0.01, V = 1e-9, gamma = 0.072, theta = 20.0 * M_PI / 180.0;
  const Mesh<double> m(wall_test::flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  ContactLaw<double> law = ellipsoid_law(1e4, damping_law(0.5, 1), 0.5, 2.0 / 7.0, 0.5);
  law.bridge = make_bridge_law(V, gamma, theta);
  law.bridge.R = 2.0 * a;
  const double sc = (1.0 + 0.5 * theta) * std::cbrt(V);
  EXPECT_NEAR(law.bridge.rupture, sc, 1e-15);
  double hist[WALL_HIST_SIZE] = {};
  WallPatches<double> P;
  // never touched: no force within reach
  WallForce<double> f = sphere_on_mesh(m, a, make_vec3(0.01, 0.0, a + 0.5 * sc), law, hist, true, P);
  EXPECT_EQ(f.f.z, 0.0);
  EXPECT_EQ(hist[0], 0.0);
  // in contact (depth 1e-6): k_n delta + F(0) along the wall's normal
  const double d0 = 1e-6;
  f = sphere_on_mesh(m, a, make_vec3(0.01, 0.0, a - d0), law, hist, true, P);
  const double F0 = willett(0.0, 2.0 * a, V, gamma, std::cos(theta));
  EXPECT_NEAR(f.f.z, 1e4 * d0 - F0, 1e-12 * F0);
  EXPECT_EQ(f.ncontact, 1);
  // across the gap, the history kept (update false: as LAMMPS's setup)
  double worst = 0.0;
  for (double s : {1e-9, 1e-6, 0.1 * sc, 0.37 * sc, 0.8 * sc, 0.999 * sc}) {
    const Vec3<double> c = make_vec3(0.01, 0.0, a + s);
    f = sphere_on_mesh(m, a, c, law, hist, false, P);
    const double F = willett(s, 2.0 * a, V, gamma, std::cos(theta));
    worst = std::fmax(worst, std::fabs(-f.f.z / F - 1.0));
    EXPECT_EQ(f.ncontact, 0);
    EXPECT_NEAR(f.f.x, 0.0, 1e-15 * F);
    EXPECT_NEAR(norm(f.tau), 0.0, 1e-15 * F * a);
    // -dU/dz = F_z
    const double h = 1e-7 * sc;
    double hp[WALL_HIST_SIZE], hm[WALL_HIST_SIZE];
    std::copy(hist, hist + WALL_HIST_SIZE, hp);
    std::copy(hist, hist + WALL_HIST_SIZE, hm);
    const double Up = sphere_on_mesh(m, a, c + make_vec3(0.0, 0.0, h), law, hp, false, P).energy;
    const double Um = sphere_on_mesh(m, a, c - make_vec3(0.0, 0.0, h), law, hm, false, P).energy;
    EXPECT_NEAR(-(Up - Um) / (2.0 * h), f.f.z, 1e-6 * F) << s;
    EXPECT_LT(f.energy, 0.0);
  }
  std::printf("[ wall bridge ] F(s) against Willett (R = 2a): largest relative difference %.2g\n",
              worst);
  EXPECT_LT(worst, 1e-12);
  // the bridge on an edge of the plate: the pull towards the edge's closest point
  {
    const double ex = 0.3 * sc, ez = a + 0.2 * sc;    // beyond the edge x = 0.05, above it
    f = sphere_on_mesh(m, a, make_vec3(0.05 + ex, 0.0, ez), law, hist, false, P);
    const double dist = std::hypot(ex, ez), s = dist - a;
    const double F = willett(s, 2.0 * a, V, gamma, std::cos(theta));
    EXPECT_NEAR(f.f.x, -F * ex / dist, 1e-12 * F);
    EXPECT_NEAR(f.f.z, -F * ez / dist, 1e-12 * F);
  }
  // beyond s_c: nothing, and the step clears the slot; back within reach: nothing
  f = sphere_on_mesh(m, a, make_vec3(0.01, 0.0, a + 1.001 * sc), law, hist, true, P);
  EXPECT_EQ(f.f.z, 0.0);
  EXPECT_EQ(f.energy, 0.0);
  f = sphere_on_mesh(m, a, make_vec3(0.01, 0.0, a + 0.5 * sc), law, hist, true, P);
  EXPECT_EQ(f.f.z, 0.0);
}
