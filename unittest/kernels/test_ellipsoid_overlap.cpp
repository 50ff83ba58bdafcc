// Exact overlap of a polyhedron and an ellipsoid (polydem_ellipsoid_overlap.h)
// against:
//  - closed forms for a sphere: the ball cut by one plane (cap), centred on
//    a cube's corner (an octant) and edge (a quarter), a cube inside a ball;
//  - an independent quadrature for random poses of shipped and random
//    polyhedra against random ellipsoids: rays from the ellipsoid's centre
//    in the lab frame, each clipped by the polyhedron's half-spaces and the
//    ellipsoid exactly, the radial integrals of t^2 and t^3 u in closed
//    form, the directions by a midpoint rule in (cos theta, phi) on three
//    grids, whose changes bound its error;
//  - central differences of the volume for S_A, M_A, M_B (the energy
//    conservation of the contact rests on these);
//  - invariances: a common rigid motion, a sphere's own rotation (M_B = 0),
//    continuity as the centre crosses a face plane.
#include "polydem_ellipsoid_overlap.h"
#include "pair_gen.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

using namespace polydem;
using namespace polydem_test;

namespace {

struct Shapes {
  std::vector<ShapeData> data;
  std::vector<std::unique_ptr<TypedShape<double>>> d;
  void add(const std::vector<std::array<double, 3>> &pts)
  {
    data.push_back(make_shape(pts));
  }
  void finish()
  {
    for (auto &s : data) d.emplace_back(typed<double>(s));
  }
};

Shapes &shapes()
{
  static Shapes *s = [] {
    auto *p = new Shapes;
    std::mt19937_64 rng(5);
    p->add(cube_points(1.0));
    p->add(dodecahedron_points(1.0));
    p->add(shipped_points("mineral18.shape"));
    p->add(shipped_points("tetrahedron.shape"));
    p->add(cylinder_points(1.0, 1.6, 24));
    p->add(random_points(rng, 30, 2.0));
    p->finish();
    return p;
  }();
  return *s;
}

PosedShape<double> posed(int k, const Pose<double> &p)
{
  return make_posed(shapes().d[k]->view, p);
}

Pose<double> pose(Vec3<double> x, Quat<double> q = Quat<double>{1, 0, 0, 0}, double s = 1.0)
{
  Pose<double> p;
  p.x = x;
  p.q = q;
  p.s = s;
  return p;
}

EllipsoidPose<double> ellipsoid(Vec3<double> x, Vec3<double> axes,
                                Quat<double> q = Quat<double>{1, 0, 0, 0})
{
  EllipsoidPose<double> e;
  e.x = x;
  e.q = q;
  e.axes = axes;
  return e;
}

// Quadrature oracle: V and int x dV of A n B by rays from B's centre.
struct Quad {
  double volume;
  Vec3<double> moment;    // int (x - x_B) dV
};

Quad quadrature(const PosedShape<double> &A, const EllipsoidPose<double> &B, int nt)
{
  const ShapeView<double> &sv = *A.view;
  // A's half-spaces relative to B's centre: n . y <= h
  std::vector<Vec3<double>> n(sv.nfaces);
  std::vector<double> h(sv.nfaces);
  for (int f = 0; f < sv.nfaces; ++f) {
    const double *q = sv.planes + 4 * f;
    n[f] = matvec(A.R, make_vec3(q[0], q[1], q[2]));
    h[f] = A.s * q[3] + dot(n[f], A.x - B.x);
  }
  const Mat3<double> RB = quat_to_mat(B.q);
  const int np = 2 * nt;
  const double dz = 2.0 / nt, dp = 2 * M_PI / np;
  Quad out{0.0, make_vec3(0.0, 0.0, 0.0)};
  for (int i = 0; i < nt; ++i) {
    const double z = -1 + (i + 0.5) * dz, rz = std::sqrt(1 - z * z);
    for (int j = 0; j < np; ++j) {
      const double ph = (j + 0.5) * dp;
      const Vec3<double> u = make_vec3(rz * std::cos(ph), rz * std::sin(ph), z);
      // ellipsoid: |D^-1 R^T t u| = 1
      const Vec3<double> ub = matTvec(RB, u);
      const double g = std::sqrt(ub.x * ub.x / (B.axes.x * B.axes.x) +
                                 ub.y * ub.y / (B.axes.y * B.axes.y) +
                                 ub.z * ub.z / (B.axes.z * B.axes.z));
      double t0 = 0, t1 = 1 / g;
      for (int f = 0; f < sv.nfaces && t0 < t1; ++f) {
        const double c = dot(n[f], u);
        if (c > 0)
          t1 = std::min(t1, h[f] / c);
        else if (c < 0)
          t0 = std::max(t0, h[f] / c);
        else if (h[f] < 0)
          t1 = t0;
      }
      if (t0 >= t1) continue;
      const double w = dz * dp;
      out.volume += w * (t1 * t1 * t1 - t0 * t0 * t0) / 3;
      out.moment += (w * (t1 * t1 * t1 * t1 - t0 * t0 * t0 * t0) / 4) * u;
    }
  }
  return out;
}

Quat<double> rand_quat(std::mt19937_64 &rng)
{
  return random_quat(rng);
}

}    // namespace

// the unit ball against the half-space z <= s of a large cube (its face at
// z = s): V = pi (2 + 3s - s^3) / 3, S_A = pi (1 - s^2) e_z,
// int z dV = pi (s^2/2 - s^4/4 - 1/4)
TEST(KernelEllipsoidOverlap, SphereCapClosedForm)
{
  const double side = 10.0;    // cube_points(1) scaled by 10: faces at +-5
  const double ss[] = {-0.999, -0.9, -0.5, -1e-9, 0.0, 1e-9, 0.3, 0.8, 0.999};
  double emax = 0;
  for (double s : ss) {
    const auto A = posed(0, pose(make_vec3(0.0, 0.0, s - 0.5 * side), Quat<double>{1, 0, 0, 0},
                                 side));
    const auto B = ellipsoid(make_vec3(0.0, 0.0, 0.0), make_vec3(1.0, 1.0, 1.0));
    const auto r = polyhedron_ellipsoid_overlap(A, B);
    const double V = M_PI * (2 + 3 * s - s * s * s) / 3;
    const double Mz = M_PI * (s * s / 2 - s * s * s * s / 4 - 0.25);
    ASSERT_EQ(r.status, STATUS_OK) << "s = " << s;
    const double e1 = std::fabs(r.volume - V);
    const double e2 = norm(r.S_A - make_vec3(0.0, 0.0, M_PI * (1 - s * s)));
    const double e3 = std::fabs(r.centroid.z * r.volume - Mz) + std::fabs(r.centroid.x) +
        std::fabs(r.centroid.y);
    emax = std::max({emax, e1, e2, e3});
    EXPECT_LE(e1, 1e-13) << "s = " << s;
    EXPECT_LE(e2, 1e-13) << "s = " << s;
    EXPECT_LE(e3, 1e-13) << "s = " << s;
    // a sphere's rotation changes nothing
    EXPECT_LE(norm(r.M_B), 1e-13) << "s = " << s;
  }
  std::printf("[ cap ] max abs error %.2e (unit ball)\n", emax);
  // apart by 1e-6: nothing
  const auto A = posed(0, pose(make_vec3(0.0, 0.0, -1.000001 - 5), Quat<double>{1, 0, 0, 0}, side));
  const auto r = polyhedron_ellipsoid_overlap(A, ellipsoid(make_vec3(0.0, 0.0, 0.0),
                                                            make_vec3(1.0, 1.0, 1.0)));
  EXPECT_EQ(r.status, STATUS_SEPARATED);
  EXPECT_EQ(r.volume, 0.0);
}

// ball of radius 0.7 centred on a corner, an edge's midpoint and the centre
// of the unit cube; the unit cube inside a ball of radius 2
TEST(KernelEllipsoidOverlap, SphereOnCubeFeatures)
{
  const double R = 0.7, Vb = 4 * M_PI / 3 * R * R * R;
  const auto A = posed(0, pose(make_vec3(0.0, 0.0, 0.0)));
  auto run = [&](Vec3<double> c, double rad) {
    return polyhedron_ellipsoid_overlap(A, ellipsoid(c, make_vec3(rad, rad, rad)));
  };
  // corner (0.5, 0.5, 0.5): an octant; centroid 3R/8 inwards on each axis
  auto r = run(make_vec3(0.5, 0.5, 0.5), R);
  EXPECT_NEAR(r.volume, Vb / 8, 1e-14);
  EXPECT_LE(norm(r.centroid - make_vec3(0.5 - 3 * R / 8, 0.5 - 3 * R / 8, 0.5 - 3 * R / 8)),
            1e-13);
  EXPECT_LE(norm(r.S_A - (M_PI * R * R / 4) * make_vec3(1.0, 1.0, 1.0)), 1e-13);
  EXPECT_LE(norm(r.M_B), 1e-13);
  // edge midpoint (0.5, 0.5, 0), radius 0.45 (clear of z = +-0.5): a quarter ball
  const double R2 = 0.45;
  r = run(make_vec3(0.5, 0.5, 0.0), R2);
  EXPECT_NEAR(r.volume, M_PI / 3 * R2 * R2 * R2, 1e-14);
  EXPECT_LE(norm(r.S_A - (M_PI * R2 * R2 / 2) * make_vec3(1.0, 1.0, 0.0)), 1e-13);
  // face centre (0, 0, 0.5): half
  r = run(make_vec3(0.0, 0.0, 0.5), 0.4);
  EXPECT_NEAR(r.volume, 2 * M_PI / 3 * 0.064, 1e-14);
  // inside, clear of the faces: the whole ball, no force
  r = run(make_vec3(0.05, -0.02, 0.01), 0.4);
  EXPECT_NEAR(r.volume, 4 * M_PI / 3 * 0.064, 1e-14);
  EXPECT_LE(norm(r.S_A), 1e-14);
  EXPECT_LE(norm(r.centroid - make_vec3(0.05, -0.02, 0.01)), 1e-14);
  // next to the corner, within 1e-9: the ill-conditioned sum is not taken
  r = run(make_vec3(0.5 - 1e-9, 0.5 - 2e-9, 0.5 + 1e-9), R);
  EXPECT_NEAR(r.volume, Vb / 8, 1e-8 * Vb);
  EXPECT_NEAR(polyhedron_ellipsoid_overlap(
                  A, ellipsoid(make_vec3(0.5 - 1e-9, 0.5 - 2e-9, 0.5 + 1e-9),
                               make_vec3(R, R, R)), true).volume, r.volume, 1e-15);
  // the cube inside a ball of radius 2: the cube, no force, its centroid
  r = run(make_vec3(0.1, 0.2, -0.1), 2.0);
  EXPECT_NEAR(r.volume, 1.0, 1e-13);
  EXPECT_LE(norm(r.S_A), 1e-13);
  EXPECT_LE(norm(r.M_A), 1e-13);
  EXPECT_LE(norm(r.centroid), 1e-13);
}

// random poses against the ray quadrature
TEST(KernelEllipsoidOverlap, RandomPosesVsQuadrature)
{
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int tested = 0;
  double worst_v = 0, worst_c = 0;
  for (int it = 0; it < 2000 && tested < 40; ++it) {
    const int k = it % (int) shapes().d.size();
    const auto &sv = shapes().d[k]->view;
    const Vec3<double> ax = make_vec3(0.3 + U(rng), 0.3 + U(rng), 0.3 + U(rng));
    const bool sphere = it % 4 == 0;
    const Vec3<double> axes = sphere ? make_vec3(ax.x, ax.x, ax.x) : ax;
    const double amax = std::max({axes.x, axes.y, axes.z});
    Vec3<double> dir = make_vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
    dir = (1 / norm(dir)) * dir;
    const double dist = (0.3 + 0.7 * U(rng)) * (sv.radius + amax);
    const auto A = posed(k, pose(make_vec3(0.0, 0.0, 0.0), rand_quat(rng)));
    const auto B = ellipsoid(dist * dir, axes, rand_quat(rng));
    const auto r = polyhedron_ellipsoid_overlap(A, B);
    const double VB = 4 * M_PI / 3 * axes.x * axes.y * axes.z;
    const Quad q0 = quadrature(A, B, 200), q1 = quadrature(A, B, 400),
               q2 = quadrature(A, B, 800);
    if (q2.volume < 1e-3 * VB) continue;
    ++tested;
    ASSERT_EQ(r.status, STATUS_OK);
    // the quadrature's error: its midpoint rule converges unevenly (the
    // integrand has kinks where rays graze edges), so the finest grid's
    // error is taken as twice the larger of the last two changes (at most
    // 1.3 times that larger change in the poses below, 15 times the last
    // change alone: it is not monotone)
    const double qerr = std::max(std::fabs(q1.volume - q0.volume),
                                 std::fabs(q2.volume - q1.volume)) + 1e-9 * q2.volume;
    const double ev = std::fabs(r.volume - q2.volume);
    auto centre = [&](const Quad &q) { return B.x + (1 / q.volume) * q.moment; };
    const Vec3<double> cq = centre(q2);
    const double cerr = std::max(norm(centre(q1) - centre(q0)), norm(cq - centre(q1))) +
        1e-9 * std::cbrt(q2.volume);
    const double ec = norm(r.centroid - cq);
    worst_v = std::max(worst_v, ev / qerr);
    worst_c = std::max(worst_c, ec / cerr);
    EXPECT_LE(ev, 2 * qerr) << "shape " << k << " V " << r.volume << " quad " << q2.volume;
    EXPECT_LE(ec, 2 * cerr) << "shape " << k;
  }
  std::printf("[ quadrature ] %d poses: |dV| at most %.2f, |dc| at most %.2f times the "
              "quadrature's own error\n",
              tested, worst_v, worst_c);
  EXPECT_GE(tested, 30);
}

// S_A, M_A, M_B against central differences of V (h = 1e-6 L)
TEST(KernelEllipsoidOverlap, GradientsVsFiniteDifferences)
{
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int tested = 0;
  double emax[3] = {0, 0, 0};
  for (int it = 0; it < 5000 && tested < 300; ++it) {
    const int k = it % (int) shapes().d.size();
    const auto &sv = shapes().d[k]->view;
    const Vec3<double> axes = it % 3 == 0 ? make_vec3(0.6, 0.6, 0.6)
                                          : make_vec3(0.2 + U(rng), 0.2 + U(rng), 0.2 + U(rng));
    const double amax = std::max({axes.x, axes.y, axes.z});
    Vec3<double> dir = make_vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
    dir = (1 / norm(dir)) * dir;
    const double dist = (0.3 + 0.7 * U(rng)) * (sv.radius + amax);
    const Pose<double> pa = pose(make_vec3(0.1, -0.2, 0.3), rand_quat(rng));
    const auto B = ellipsoid(pa.x + dist * dir, axes, rand_quat(rng));
    const auto r = polyhedron_ellipsoid_overlap(posed(k, pa), B);
    const double L = sv.radius + amax;
    if (r.status != STATUS_OK || r.area < 1e-2 * L * L) continue;
    ++tested;
    const double h = 1e-6 * L, ha = 1e-6;
    Vec3<double> fs, fma, fmb, unused;
    pose_differences([&](const Pose<double> &x) { return polyhedron_ellipsoid_overlap(posed(k, x), B).volume; },
                     pa, h, ha, fs, fma);
    // B's rotation about its centre: a Pose with B's centre and orientation
    Pose<double> pb = pose(B.x, B.q);
    pose_differences(
        [&](const Pose<double> &x) {
          auto B1 = B;
          B1.q = x.q;
          return polyhedron_ellipsoid_overlap(posed(k, pa), B1).volume;
        },
        pb, h, ha, unused, fmb);
    expect_gradients(r, fs, fma, fmb, L, emax);
  }
  std::printf("[ gradients ] %d poses: max rel err S_A %.2e, M_A %.2e, M_B %.2e "
              "(M relative to |S_A| L)\n",
              tested, emax[0], emax[1], emax[2]);
  EXPECT_GE(tested, 200);
}

// a common rigid motion of both bodies moves the result with them; the
// volume is continuous as the centre crosses a face plane of the polyhedron
TEST(KernelEllipsoidOverlap, InvarianceAndContinuity)
{
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int tested = 0;
  for (int it = 0; it < 500 && tested < 100; ++it) {
    const int k = it % (int) shapes().d.size();
    const Pose<double> pa = pose(make_vec3(0.0, 0.0, 0.0), rand_quat(rng));
    const auto B = ellipsoid(make_vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5),
                             make_vec3(0.3 + U(rng), 0.3 + U(rng), 0.3 + U(rng)), rand_quat(rng));
    const auto r = polyhedron_ellipsoid_overlap(posed(k, pa), B);
    if (r.status != STATUS_OK) continue;
    ++tested;
    // the two solid-angle sums agree
    const auto rr = polyhedron_ellipsoid_overlap(posed(k, pa), B, true);
    EXPECT_NEAR(rr.volume, r.volume, 1e-13 * (1 + r.volume));
    const Quat<double> g = rand_quat(rng);
    const Mat3<double> G = quat_to_mat(g);
    const Vec3<double> shift = make_vec3(3.0, -1.0, 2.0);
    Pose<double> pa2 = pa;
    pa2.x = matvec(G, pa.x) + shift;
    pa2.q = qmul(g, pa.q);
    auto B2 = B;
    B2.x = matvec(G, B.x) + shift;
    B2.q = qmul(g, B.q);
    const auto r2 = polyhedron_ellipsoid_overlap(posed(k, pa2), B2);
    ASSERT_EQ(r2.status, STATUS_OK);
    const double L = std::cbrt(r.volume);
    EXPECT_NEAR(r2.volume, r.volume, 1e-12 * (1 + r.volume));
    EXPECT_LE(norm(r2.S_A - matvec(G, r.S_A)), 1e-12 * (1 + L * L));
    EXPECT_LE(norm(r2.M_A - matvec(G, r.M_A)), 1e-12 * (1 + L * L * L));
    EXPECT_LE(norm(r2.centroid - (matvec(G, r.centroid) + shift)), 1e-12 * (1 + L));
  }
  EXPECT_GE(tested, 50);
  // the ball's centre through a dodecahedron's face, inside the face
  const auto &sv = shapes().d[1]->view;
  const double *pl = sv.planes;
  const Vec3<double> n = make_vec3(pl[0], pl[1], pl[2]);
  double prev = -1;
  for (double s : {-1e-6, -1e-12, 0.0, 1e-12, 1e-6}) {
    const auto r = polyhedron_ellipsoid_overlap(
        posed(1, pose(make_vec3(0.0, 0.0, 0.0))),
        ellipsoid((pl[3] - s) * n, make_vec3(0.2, 0.25, 0.3)));
    ASSERT_EQ(r.status, STATUS_OK);
    if (prev >= 0) {
      EXPECT_GT(r.volume, prev - 1e-14) << "s " << s;
      EXPECT_LT(r.volume - prev, 1e-6) << "s " << s;
    }
    prev = r.volume;
  }
}

TEST(KernelEllipsoidOverlap, SeparatedAndDegenerate)
{
  const auto A = posed(1, pose(make_vec3(0.0, 0.0, 0.0)));
  const auto &sv = shapes().d[1]->view;
  // beside a face, the face's plane cutting the ball but the face missing it
  const double *pl = sv.planes;
  const Vec3<double> n = make_vec3(pl[0], pl[1], pl[2]);
  Vec3<double> t = cross(n, make_vec3(0.0, 0.0, 1.0));
  if (norm(t) < 0.1) t = cross(n, make_vec3(1.0, 0.0, 0.0));
  t = (1 / norm(t)) * t;
  auto r = polyhedron_ellipsoid_overlap(A, ellipsoid(pl[3] * n + 1.2 * t, make_vec3(0.1, 0.1, 0.1)));
  EXPECT_EQ(r.status, STATUS_SEPARATED);
  r = polyhedron_ellipsoid_overlap(A, ellipsoid(make_vec3(5.0, 0.0, 0.0), make_vec3(1.0, 1.0, 1.0)));
  EXPECT_EQ(r.status, STATUS_SEPARATED);
  r = polyhedron_ellipsoid_overlap(A, ellipsoid(make_vec3(std::nan(""), 0.0, 0.0), make_vec3(1.0, 1.0, 1.0)));
  EXPECT_EQ(r.status, STATUS_DEGENERATE);
  r = polyhedron_ellipsoid_overlap(A, ellipsoid(make_vec3(0.0, 0.0, 0.0), make_vec3(0.0, 1.0, 1.0)));
  EXPECT_EQ(r.status, STATUS_DEGENERATE);
}

// two spheres: the lens volume, S_A = pi a^2 n against central differences,
// the centroid of equal spheres halfway, one inside the other
TEST(KernelEllipsoidOverlap, SpherePairLens)
{
  const double ra = 0.7, rb = 0.4;
  for (double d : {1.09, 1.0, 0.8, 0.5, 0.31}) {
    const Vec3<double> xa = make_vec3(0.1, 0.2, 0.3), n = make_vec3(0.6, 0.0, 0.8);
    const auto r = sphere_pair_overlap(xa, ra, xa + d * n, rb);
    const double V = M_PI * (ra + rb - d) * (ra + rb - d) *
        (d * d + 2 * d * (ra + rb) - 3 * (ra - rb) * (ra - rb)) / (12 * d);
    ASSERT_EQ(r.status, STATUS_OK) << d;
    EXPECT_NEAR(r.volume, V, 1e-15) << d;
    const double h = 1e-6;
    const double dv = (sphere_pair_overlap(xa, ra, xa + (d - h) * n, rb).volume -
                       sphere_pair_overlap(xa, ra, xa + (d + h) * n, rb).volume) / (2 * h);
    EXPECT_LE(norm(r.S_A - dv * n), 1e-8) << d;
    EXPECT_LE(norm(r.M_A) + norm(r.M_B), 0.0);
    // the centroid lies on the line of centres, between the cap bases' ends
    const double z = dot(r.centroid - xa, n);
    EXPECT_LE(norm(r.centroid - xa - z * n), 1e-15);
    EXPECT_GT(z, d - rb);
    EXPECT_LT(z, ra);
  }
  auto r = sphere_pair_overlap(make_vec3(0.0, 0.0, 0.0), 0.5, make_vec3(0.0, 0.0, 0.6), 0.5);
  EXPECT_NEAR(r.centroid.z, 0.3, 1e-15);
  r = sphere_pair_overlap(make_vec3(0.0, 0.0, 0.0), 0.5, make_vec3(0.0, 0.0, 1.0), 0.5);
  EXPECT_EQ(r.status, STATUS_SEPARATED);
  r = sphere_pair_overlap(make_vec3(0.0, 0.0, 0.0), 0.5, make_vec3(0.0, 0.1, 0.0), 0.2);
  EXPECT_NEAR(r.volume, 4 * M_PI / 3 * 0.008, 1e-15);
  EXPECT_EQ(norm(r.S_A), 0.0);
}
